#pragma once

#include <cstddef>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// How GeoNetworking carries a message (EN 302 636-4-1): single-hop broadcast (CAMs) or
/// geo-broadcast to an area (DENMs). It decides the size of the GeoNetworking extended header.
enum class GnTransport { SingleHopBroadcast, GeoBroadcast };

/// Which header the security envelope (ETSI TS 103 097 v2.1.1 §7.1, as Vanetza's v3
/// DefaultSignHeaderPolicy fills it) gives a message:
///  - Cam: psid and generation time; the signer is the full certificate at most once per second
///    (and when a new station was heard), its 8-byte digest otherwise;
///  - Denm: psid, generation time and generation location; always the full certificate;
///  - Other: psid and generation time; always the full certificate (Vanetza's default branch).
enum class SecurityProfile { Cam, Denm, Other };

/// How a secured message names its signer; None: the frame is not secured at all.
enum class SignerIdentifier { None, Digest, Certificate };

/// The bytes every layer adds to a facilities message on an ITS-G5 channel, from the MAC header to
/// the FCS (the PSDU; the PHY's preamble, SIGNAL, SERVICE and tail bits are ChannelSettings::airtime's).
/// Sizes and where they come from:
///  - IEEE 802.11 QoS data header 26 (frame control 2, duration 2, three addresses 18, sequence
///    control 2, QoS control 2; ITS-G5 sends QoS data frames for its EDCA categories, as Vanetza's
///    access/g5_link_layer.hpp QosDataHeader) and FCS 4;
///  - LLC/SNAP 8 (DSAP, SSAP, control, OUI 3, EtherType 0x8947: Vanetza's LlcSnapHeader);
///  - GeoNetworking (EN 302 636-4-1 §9.6–9.8; Vanetza geonet/*_header.hpp): basic header 4, common
///    header 8, SHB extended header 28 (source long position vector 24 + 4 reserved), GBC extended
///    header 44 (sequence number 2, reserved 2, source position vector 24, area centre 8, distances
///    a and b 4, angle 2, reserved 2);
///  - BTP-B 4 (EN 302 636-5-1: destination port and port info; Vanetza btp/header.hpp);
///  - the security envelope (TS 103 097 v2.1.1, IEEE 1609.2 COER, as Vanetza v3 builds it): see
///    securityEnvelopeBytes(). The basic header stays outside the envelope; the common and extended
///    headers, BTP and the message are its payload.
namespace frame_bytes {
inline constexpr std::size_t kMacHeader = 26;
inline constexpr std::size_t kFcs = 4;
inline constexpr std::size_t kLlcSnap = 8;
inline constexpr std::size_t kGnBasic = 4;
inline constexpr std::size_t kGnCommon = 8;
inline constexpr std::size_t kGnShb = 28;
inline constexpr std::size_t kGnGbc = 44;
inline constexpr std::size_t kBtpB = 4;

// The security envelope, byte for byte as a signed CAM of a production vehicle in Vanetza's tests
// (security/tests/secured_message_v3.cpp, "a CAM signed by a VW Golf 8": 321 bytes for an 86-byte
// payload, certificate 148 bytes):
/// Ieee1609Dot2Data version 1, content choice 1, SignedData hashId 1, SignedDataPayload preamble 1,
/// inner Ieee1609Dot2Data version 1 and unsecuredData choice 1 (then the payload's length).
inline constexpr std::size_t kEnvelopeHead = 6;
/// HeaderInfo preamble 1, psid 2 (length and value), generationTime 8.
inline constexpr std::size_t kHeaderInfo = 11;
/// generationLocation (latitude 4, longitude 4, elevation 2), DENMs only.
inline constexpr std::size_t kGenerationLocation = 10;
/// SignerIdentifier choice 1 + HashedId8.
inline constexpr std::size_t kSignerDigest = 9;
/// An authorization ticket (explicit, NIST P-256, CAM and DENM permissions) as the Golf's.
inline constexpr std::size_t kCertificate = 148;
/// SignerIdentifier choice 1, SequenceOfCertificate quantity 2, the certificate.
inline constexpr std::size_t kSignerCertificate = 3 + kCertificate;
/// Signature choice 1, r as a compressed point 33, s 32 (ECDSA NIST P-256).
inline constexpr std::size_t kSignature = 66;
}  // namespace frame_bytes

/// The COER length determinant of an OCTET STRING of `bytes`: 1 byte below 128, else 1 + the
/// bytes of the length.
SBSIM_API std::size_t lengthDeterminantBytes(std::size_t bytes);

/// The bytes a security envelope adds around `payload` bytes (GeoNetworking common and extended
/// headers, BTP, message); 0 for SignerIdentifier::None.
SBSIM_API std::size_t securityEnvelopeBytes(std::size_t payload, SecurityProfile profile, SignerIdentifier signer);

/// The 802.11 frame (MAC header to FCS) that carries a message of `content` bytes.
SBSIM_API std::size_t frameBytes(std::size_t content, GnTransport transport, SecurityProfile profile,
                                 SignerIdentifier signer);

}  // namespace sbsim::radio
