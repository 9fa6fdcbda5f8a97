#include "sbsim/radio/FrameSize.h"

namespace sbsim::radio {

std::size_t lengthDeterminantBytes(std::size_t bytes) {
    if (bytes < 128) return 1;
    std::size_t octets = 0;
    for (std::size_t n = bytes; n > 0; n >>= 8) ++octets;
    return 1 + octets;
}

std::size_t securityEnvelopeBytes(std::size_t payload, SecurityProfile profile, SignerIdentifier signer) {
    using namespace frame_bytes;
    if (signer == SignerIdentifier::None) return 0;
    std::size_t bytes = kEnvelopeHead + lengthDeterminantBytes(payload) + kHeaderInfo + kSignature;
    if (profile == SecurityProfile::Denm) bytes += kGenerationLocation;
    bytes += signer == SignerIdentifier::Digest ? kSignerDigest : kSignerCertificate;
    return bytes;
}

std::size_t frameBytes(std::size_t content, GnTransport transport, SecurityProfile profile, SignerIdentifier signer) {
    using namespace frame_bytes;
    const std::size_t extended = transport == GnTransport::GeoBroadcast ? kGnGbc : kGnShb;
    const std::size_t secured = kGnCommon + extended + kBtpB + content;
    return kMacHeader + kLlcSnap + kGnBasic + secured + securityEnvelopeBytes(secured, profile, signer) + kFcs;
}

}  // namespace sbsim::radio
