#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/propagation/PathLoss.h"
#include "sbsim/radio/propagation/PathLossModels.h"

namespace sbsim::radio {

/// Every setting of the 802.11p channel model (ChannelMedium), with the defaults of Sepulcre et
/// al.'s highway evaluation (IEEE TVT 2022): 23 dBm, 6 Mbit/s over 10 MHz at 5.89 GHz, WINNER+ B1
/// LOS with 3 dB shadowing, sensing threshold −85 dBm, noise −95 dBm. The radio file (--radio)
/// sets them; see README "Radio".
struct SBSIM_API ChannelSettings {
    enum class Fading { None, Nakagami, NakagamiVeins };
    /// Extra delay per reception for abstracted stacks (as Eclipse MOSAIC's delay models), added to
    /// the airtime and channel access: none, constant `delay`, uniform in [`delayMin`, `delayMax`],
    /// or gamma with mean `delay` and shape `delayShape`.
    enum class ExtraDelay { None, Constant, Uniform, Gamma };

    double powerDbm = 23;
    double rateMbps = 6;  ///< one of 802.11p's 10 MHz rates: 3, 4.5, 6, 9, 12, 18, 24, 27
    double frequencyHz = 5.89e9;
    double bandwidthHz = 10e6;
    double noiseDbm = -95;
    double sensingDbm = -85;  ///< carrier sense and frame detection threshold
    /// Links whose mean power plus two shadowing deviations is below this are not computed at all
    /// (they would add less than a tenth of the noise): it sets the model's cutoff range.
    double interferenceFloorDbm = -105;

    /// A model of PathLossModels (`free-space`, `log-distance`, `two-ray-ground`, `winner-b1`), and
    /// the model keys the radio file set (`antenna_height`, `exponent`, …): the others keep the
    /// defaults the model registered.
    std::string pathLoss = "winner-b1";
    PathLossModels::Keys pathLossKeys;

    double shadowingSigmaDb = 3;  ///< log-normal; 0 = none
    /// m: shadowing per pair of stations correlated over the distance they move (Gudmundson,
    /// propagation/CorrelatedShadowing.h); 0 draws it afresh per link and frame (Sepulcre et al.'s
    /// setting). Presets: 10 m line of sight and 13 m NLOS (3GPP TR 37.885 Table 6.2.3-1), 25 m on
    /// highways (WiLabV2Xsim). Default 10 m: TR 37.885's LOS value, for the default LOS law and σ.
    double shadowingCorrelation = 10;
    Fading fading = Fading::None;
    double nakagamiM = 1.5;  ///< with Fading::Nakagami

    /// Buildings: SUMO polygons of this type (none loaded: no obstacles).
    std::string obstacleType = "building";
    double wallDb = 9;        ///< per wall crossed (Veins' simple obstacle model)
    double perMetreDb = 0.4;  ///< per metre inside

    // 802.11p EDCA for broadcast, 10 MHz channel. Default: the best-effort access category
    // (AIFSN 6, CW 15), which ETSI ITS-G5 uses for CAMs on the control channel.
    int aifsn = 6;
    int contentionWindow = 15;  ///< backoff drawn uniformly in [0, CW] slots
    kernel::SimTime slot = kernel::SimTime::fromNanoseconds(13'000);
    kernel::SimTime sifs = kernel::SimTime::fromNanoseconds(32'000);
    /// Frames a station holds waiting for the channel (the one contending included); a frame
    /// arriving at a full queue is dropped (trace reason "queue").
    std::size_t queueLimit = 16;

    /// FER against Eb/N0 (dB) used at every rate (Eb/N0 = SINR · bandwidth / rate); the default is
    /// Goubet et al.'s 6 Mbit/s table.
    std::vector<std::pair<double, double>> ferTable = {{0, 1},     {5, 1},     {10, 0.4},  {15, 1.5e-2},
                                                       {20, 4e-3}, {25, 3e-3}, {30, 2e-3}, {35, 1e-3}};

    /// The link budget in tiers (Veins' cheapest-first thresholding), on by default: per SUMO step a
    /// link's mean power (path loss, obstacles) decides its tier. Below the interference floor by
    /// the cutoff's margin (2 σ, +5 dB with fading): not computed. Below the sensing threshold by
    /// `tierMarginDb`: the link can neither be detected nor decoded, it only adds its mean power
    /// (shadowing's linear mean, fading's mean of 1) to the receiver's interference and carrier
    /// sense, with no draw per frame. Above: shadowing and fading drawn per frame, as exactly as
    /// with the tiers off (`[performance] link_budget = "exact"`). bench/tiers.py measures the error.
    bool linkTiers = true;
    /// dB between a link's mean power and the sensing threshold below which it is interference
    /// only: with σ = 3 dB a draw reaches it with probability 4·10⁻⁴ (3.3 σ).
    double tierMarginDb = 10;
    /// The far tier, with the tiers and without buildings: m, the side of square cells; 0 = off. A
    /// sender's links to a whole cell beyond the far range — where the mean power is below the
    /// interference-only tier's bound, and at least `traceRange` away — are one figure per frame
    /// and cell: the mean power at the cell's centre, added to a per-cell field. A decoding
    /// receiver's interference includes its cell's field (the largest sum over the frame, as for
    /// the other links), and its carrier sense its links' sum plus its cell's field (a cell's
    /// stations are checked when its field changes). bench/tiers.py measures the error.
    double farCellM = 100;

    /// A frame's links are computed on the thread pool in chunks of this many (fewer links stay on
    /// the calling thread): waking a worker costs more than a few hundred links.
    std::size_t linksPerChunk = 1024;

    ExtraDelay extraDelay = ExtraDelay::None;
    double delay = 0;     ///< s: constant, or the gamma mean
    double delayMin = 0;  ///< s, uniform
    double delayMax = 0;  ///< s, uniform
    double delayShape = 2;

    /// Frames carry the TS 103 097 security envelope (FrameSize.h, CertificatePolicy.h); the radio
    /// file's `[frame] security = "none"` sends them unsecured.
    bool secured = true;

    /// Lost receptions are traced (--messages) only for stations this close to the sender.
    double traceRange = 500;

    kernel::SimTime aifs() const { return sifs + slot * aifsn; }
    /// The time on air of a frame of `frameBytes` (the PSDU: MAC header to FCS, V2xMessage::frameBytes()):
    /// 32 µs preamble and 8 µs SIGNAL, then 8 µs OFDM symbols of rate · 8 µs data bits each carrying
    /// the 16 SERVICE bits, the frame and 6 tail bits, padded to a whole symbol (IEEE 802.11 §17.4.3
    /// at 10 MHz; Vanetza's DataRateG5::data_length).
    kernel::SimTime airtime(std::size_t frameBytes) const;
    /// Throws std::invalid_argument naming the first setting out of range.
    void validate() const;
    std::unique_ptr<PathLoss> makePathLoss() const;
};

}  // namespace sbsim::radio
