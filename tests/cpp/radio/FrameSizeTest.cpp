#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sbsim/radio/CertificatePolicy.h"
#include "sbsim/radio/FrameSize.h"
#include "sbsim/radio/channel/ChannelSettings.h"

namespace sbsim::radio {
namespace {

using kernel::SimTime;
using enum GnTransport;
using enum SecurityProfile;

constexpr std::size_t kCam = 45;   // facilities::Cam::kHighFrequencyBytes
constexpr std::size_t kDenm = 54;  // a plain DENM

TEST(FrameSize, TheEnvelopeOfARealSignedCamHasItsSize) {
    // Vanetza's test vector: a VW Golf 8's CAM with its certificate, 321 bytes around 86.
    EXPECT_EQ(86 + securityEnvelopeBytes(86, Cam, SignerIdentifier::Certificate), 321u);
}

TEST(FrameSize, LengthDeterminantsAsCoer) {
    EXPECT_EQ(lengthDeterminantBytes(0), 1u);
    EXPECT_EQ(lengthDeterminantBytes(127), 1u);
    EXPECT_EQ(lengthDeterminantBytes(128), 2u);
    EXPECT_EQ(lengthDeterminantBytes(255), 2u);
    EXPECT_EQ(lengthDeterminantBytes(256), 3u);
}

TEST(FrameSize, UnsecuredFramesAddEveryHeader) {
    // MAC 26 + LLC/SNAP 8 + GN basic 4 + common 8 + SHB 28 + BTP-B 4 + FCS 4.
    EXPECT_EQ(frameBytes(kCam, SingleHopBroadcast, Cam, SignerIdentifier::None), kCam + 82);
    // GBC's extended header is 44.
    EXPECT_EQ(frameBytes(kDenm, GeoBroadcast, Denm, SignerIdentifier::None), kDenm + 98);
    EXPECT_EQ(frameBytes(100, SingleHopBroadcast, Other, SignerIdentifier::None), 182u);
}

TEST(FrameSize, SecuredFramesPerMessageKind) {
    // CAM: payload 8 + 28 + 4 + 45 = 85 (< 128: one length byte); head 6 + 1, header info 11,
    // signature 66, then a digest (9) or the certificate (151).
    EXPECT_EQ(frameBytes(kCam, SingleHopBroadcast, Cam, SignerIdentifier::Digest), kCam + 82 + 93);
    EXPECT_EQ(frameBytes(kCam, SingleHopBroadcast, Cam, SignerIdentifier::Certificate), kCam + 82 + 235);
    // DENM: payload 8 + 44 + 4 + 54 = 110; header info gains the generation location (10).
    EXPECT_EQ(frameBytes(kDenm, GeoBroadcast, Denm, SignerIdentifier::Certificate), kDenm + 98 + 245);
    // A long CAM (path history): payload 8 + 28 + 4 + 200 = 240 takes a two-byte length.
    EXPECT_EQ(frameBytes(200, SingleHopBroadcast, Cam, SignerIdentifier::Digest), 200u + 82 + 94);
}

TEST(CertificatePolicy, ACamCarriesTheCertificateOncePerSecond) {
    CertificatePolicy policy;
    std::vector<int> withCertificate;
    for (int k = 0; k < 50; ++k) {  // a CAM every 100 ms for 5 s
        if (policy.sign("v", Cam, SimTime::fromMilliseconds(100 * k)) == SignerIdentifier::Certificate)
            withCertificate.push_back(k);
        else
            EXPECT_EQ(policy.sign("other", Denm, SimTime::fromMilliseconds(100 * k)), SignerIdentifier::Certificate);
    }
    EXPECT_EQ(withCertificate, (std::vector<int>{0, 10, 20, 30, 40}));
    // At 1 Hz every CAM carries it (Vanetza's 50 ms tolerance); at 2 Hz every other one.
    CertificatePolicy slow;
    for (int k = 0; k < 5; ++k)
        EXPECT_EQ(slow.sign("v", Cam, SimTime::fromMilliseconds(1000 * k)), SignerIdentifier::Certificate);
    CertificatePolicy half;
    for (int k = 0; k < 6; ++k)
        EXPECT_EQ(half.sign("v", Cam, SimTime::fromMilliseconds(500 * k)),
                  k % 2 == 0 ? SignerIdentifier::Certificate : SignerIdentifier::Digest);
}

TEST(CertificatePolicy, ANewStationHeardBringsTheCertificateForward) {
    CertificatePolicy policy;
    EXPECT_EQ(policy.sign("a", Cam, SimTime::zero()), SignerIdentifier::Certificate);
    policy.heard("a", "b", Cam, SimTime::fromMilliseconds(50));
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(100)), SignerIdentifier::Certificate);
    // b is known now; a DENM of a new station asks nothing (Vanetza reacts to CAMs).
    policy.heard("a", "b", Cam, SimTime::fromMilliseconds(150));
    policy.heard("a", "c", Denm, SimTime::fromMilliseconds(150));
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(200)), SignerIdentifier::Digest);
    // c, known since its DENM, is not new either.
    policy.heard("a", "c", Cam, SimTime::fromMilliseconds(250));
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(300)), SignerIdentifier::Digest);
}

TEST(CertificatePolicy, StationsUnheardForTwentySecondsAreForgotten) {
    CertificatePolicy policy;
    policy.sign("a", Cam, SimTime::zero());
    policy.heard("a", "b", Cam, SimTime::zero());
    for (int k = 0; k < 100; ++k) policy.heard("s" + std::to_string(k), "a", Cam, SimTime::fromMilliseconds(k));
    EXPECT_EQ(policy.stations(), 101u);
    EXPECT_EQ(policy.remembered(), 101u);  // a heard b, a hundred heard a
    // 25 s on, only a signs: everyone else is dropped, and b counts as new again for a.
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(25'000)), SignerIdentifier::Certificate);
    policy.sign("a", Cam, SimTime::fromMilliseconds(41'000));
    EXPECT_EQ(policy.stations(), 1u);
    EXPECT_EQ(policy.remembered(), 0u);
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(41'100)), SignerIdentifier::Digest);
    policy.heard("a", "b", Cam, SimTime::fromMilliseconds(41'200));
    EXPECT_EQ(policy.remembered(), 1u);
    EXPECT_EQ(policy.sign("a", Cam, SimTime::fromMilliseconds(41'300)), SignerIdentifier::Certificate);
}

TEST(CertificatePolicy, UnsecuredSendsNoEnvelope) {
    CertificatePolicy policy(false);
    EXPECT_EQ(policy.sign("a", Cam, SimTime::zero()), SignerIdentifier::None);
    EXPECT_EQ(policy.sign("a", Denm, SimTime::zero()), SignerIdentifier::None);
    policy.heard("a", "b", Cam, SimTime::zero());
    EXPECT_EQ(policy.stations(), 0u);
}

TEST(Airtime, CountsWholeOfdmSymbols) {
    ChannelSettings s;
    // 6 Mbit/s over 10 MHz: 48 data bits per 8 µs symbol; 16 + 8 · 220 + 6 = 1782 bits, 38 symbols.
    EXPECT_EQ(s.airtime(220).raw(), 40'000 + 38 * 8'000);
    // Five bytes more still fit the 38th symbol's padding (1822 of 1824 bits); six do not.
    EXPECT_EQ(s.airtime(225).raw(), 40'000 + 38 * 8'000);
    EXPECT_EQ(s.airtime(226).raw(), 40'000 + 39 * 8'000);
    s.rateMbps = 18;  // 144 bits per symbol: 13 symbols
    EXPECT_EQ(s.airtime(220).raw(), 40'000 + 13 * 8'000);
    s.rateMbps = 4.5;  // 36 bits per symbol: 50 symbols
    EXPECT_EQ(s.airtime(220).raw(), 40'000 + 50 * 8'000);
}

}  // namespace
}  // namespace sbsim::radio
