#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/MessageTrace.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/radio/channel/FarCells.h"
#include "sbsim/radio/channel/FrameErrorTable.h"
#include "sbsim/radio/channel/Link.h"
#include "sbsim/radio/channel/StepLinks.h"

namespace sbsim::radio {

/// 802.11p reception at every station, struct-of-arrays by slot: the frames it hears and their
/// power, the power it senses (carrier sense: busy at or above the sensing threshold), the frame
/// it locked onto (the first it detects while not sending), whether it sends (half-duplex); at a
/// frame's end, whether it decoded it: probability 1 − FER(SINR), the interference being the
/// largest sum of the other frames overlapping it.
///
/// Per station the power it hears is one exact fixed-point sum (units of 2^-64 mW in 128 bits):
/// a frame adds its link's power when it starts and subtracts the same integer when it ends, so
/// the sum neither drifts nor depends on the order frames came and went, and no station keeps a
/// list of the frames it hears (on a saturated channel such lists were tens of frames long, and
/// walking them per link was a quarter of the run). Only the frame a station decodes needs its
/// interference, so only that one is updated when another frame starts.
class Reception {
public:
    using Slot = std::int32_t;
    using FrameId = std::uint64_t;  // 0 = none
    /// Told when a station's carrier sense changes.
    class Listener {
    public:
        virtual void channelSensed(Slot s, bool busy) = 0;

    protected:
        ~Listener() = default;
    };

    /// Throws std::invalid_argument for a malformed FER table. The references must outlive this.
    Reception(const ChannelSettings& settings, Listener& listener);

    /// A new station, slot size().
    void addStation();
    bool sensesBusy(Slot s) const { return sensedBusy_[s] != 0; }
    bool sending(Slot s) const { return sending_[s] != 0; }

    /// Station `s` starts sending frame `id` at `now`: whatever it was receiving is lost
    /// (half-duplex; frameEnds() tells the frames that overlapped the sending).
    void startSending(Slot s, FrameId id, kernel::SimTime now);
    void stopSending(Slot s) { sending_[s] = 0; }
    /// Frame `id` reaches the receivers of `step` (which stay where they are until it ends), its
    /// drawn links in `drawn`: each link above the floor adds to its receiver's power and to the
    /// interference of the frame it decodes, and a drawn one may lock it (only a locked link's
    /// maxInterferenceMw is kept: no other is decoded). With `halfAtStart`, the interference-only
    /// links (by index in `step`) whose receiver was sending are added to it.
    void frameStarts(FrameId id, const StepLinks& step, std::vector<Link>& drawn,
                     std::vector<std::uint32_t>* halfAtStart = nullptr);
    /// A counted link of `units` left station `r`: the power it hears without it.
    double leave(Slot r, StepLinks::Units units) {
        if (locked_[r] != 0 && lockCell_[r] >= 0) {
            // A fall opens a segment only if the field rose during the last (else the last's
            // largest, taken at its opening, stands).
            const std::int32_t c = lockCell_[r];
            if (logged_[c] != segmentFrom_[r]) {
                closeSegment(r);
                segmentFrom_[r] = logged_[c];
            }
            heard_[r] -= units;
            segmentNearMw_[r] = roughMwOf(heard_[r] - lockOwn_[r]);
        } else {
            heard_[r] -= units;
        }
        return mwOf(heard_[r] + fieldAt(r));
    }
    /// The stations' far cells changed with a SUMO step (`cells`, kept until the next call): each
    /// senses its links and its new cell's field.
    void moveStations(const FarCells& cells);
    /// The far tier of a frame's step (StepLinks::farCell): its cells' fields rise when it starts,
    /// fall by the same integers when it ends.
    void farStarts(const StepLinks& step);
    void farEnds(const StepLinks& step);
    /// The far field of `cell` now, in mW (0 for a cell no frame reached).
    double farFieldMw(std::int32_t cell) const {
        return cell >= 0 && static_cast<std::size_t>(cell) < field_.size() ? mwOf(field_[cell]) : 0.0;
    }
    /// Times a decoding receiver's segment outlived its cell's log (the largest far field may then be missed).
    std::uint64_t logOverflows() const { return logOverflows_; }
    /// Whether station `r` began sending at or after `start`.
    bool sentSince(Slot r, kernel::SimTime start) const { return sendStart_[r] >= start; }
    /// Whether `mw` would change station `r`'s carrier sense.
    bool changesSense(Slot r, double mw) const { return (mw >= sensingMw_) != sensesBusy(r); }
    void setSensedPower(Slot r, double mw);
    /// Frame `id`, which started at `start`, ended at `link`'s receiver: it no longer decodes it, a
    /// counted link leaves the power the receiver hears and is half-duplex if the receiver began
    /// sending while it was on the air. Returns the power the receiver hears without it (for a
    /// counted link; it takes effect with setSensedPower()).
    double frameEnds(FrameId id, kernel::SimTime start, Link& link);
    /// Whether `link`'s receiver decoded the frame (none) or why it lost it; `sinrDb` is set when
    /// it tried. The draw is keyed by the frame and the receiver.
    std::optional<LossReason> decode(const Link& link, std::uint64_t frameKey, std::uint64_t receiverKey,
                                     double& sinrDb) const;

    using Units = StepLinks::Units;
    /// `mw` in units of 2^-64 mW, truncated: whole milliwatts and the fraction apart, each exact in
    /// 64 bits (a link's power is far below 2^64 mW), the value a direct conversion gives without
    /// libgcc's out-of-line one.
    static Units unitsOf(double mw) {
        constexpr double kUnitsPerMw = 18446744073709551616.0;  // 2^64: scaling by it is exact
        const auto whole = static_cast<std::uint64_t>(mw);
        const auto fraction = static_cast<std::uint64_t>((mw - static_cast<double>(whole)) * kUnitsPerMw);
        return (static_cast<Units>(whole) << 64) + fraction;
    }

private:
    /// `units` in mW. Below 2^64 units (1 mW: every sum near the sensing threshold) the low word is the whole
    /// value and converting it rounds exactly as the 128-bit conversion does; scaling by 2^-64 is exact like the
    /// division. Only larger sums pay libgcc's out-of-line __floatuntidf: the same double either way.
    static double mwOf(Units units) {
        const auto high = static_cast<std::uint64_t>(units >> 64);
        if (high == 0) [[likely]]
            return static_cast<double>(static_cast<std::uint64_t>(units)) * 0x1p-64;
        return static_cast<double>(units) * 0x1p-64;
    }
    /// mwOf to within a rounding, without libgcc's 128-bit conversion: for the far tier's maxima.
    static double roughMwOf(Units units) {
        return static_cast<double>(static_cast<std::uint64_t>(units >> 64)) +
               static_cast<double>(static_cast<std::uint64_t>(units)) * 0x1p-64;
    }
    void linkStarts(FrameId id, Link& link);
    /// Adds `units` to what station `r` hears, and to the interference of the frame it decodes; the new sum.
    Units hear(Slot r, Units units);
    /// A decoding station's interference with a far field (lockCell_ >= 0) is the largest of
    /// (its other links' sum + its cell's field) over the frame. Its other links change only at
    /// its own links' events: between two, a segment, whose largest is that sum plus the largest
    /// field its cell's log holds since the segment opened.
    void openSegment(Slot r);
    void closeSegment(Slot r);
    void growField(std::int32_t cell);
    /// The far field station `r` hears in its cell this step (0 without one).
    Units fieldAt(Slot r) const {
        const std::int32_t c = cell_[r];
        return c >= 0 && static_cast<std::size_t>(c) < field_.size() ? field_[c] : Units{0};
    }
    /// Carrier sense of `cell`'s stations after its field changed.
    void senseCell(std::int32_t cell);

    Listener& listener_;
    FrameErrorTable fer_;
    double sensingMw_, noiseMw_, floorMw_;
    double ratioDb_;  // Eb/N0 − SINR: bandwidth over bit rate, in dB

    std::vector<Units> heard_;  // the power each station hears, in units of 2^-64 mW
    std::vector<std::uint8_t> sensedBusy_;
    std::vector<FrameId> sending_;            // 0 = not sending
    std::vector<FrameId> locked_;             // the frame being decoded, 0 = none
    std::vector<Link*> lockedLink_;           // its link (valid while locked_ names it)
    std::vector<kernel::SimTime> sendStart_;  // when each station last began sending
    // The far tier, by cell: the field (units), and a ring of its values after each rise with their count.
    static constexpr std::size_t kLog = 32;
    std::vector<Units> field_;
    std::vector<double> log_;  // kLog a cell, mW (roughMwOf): a decoding station's maximum needs no exact sum
    std::vector<std::uint64_t> logged_;
    std::uint64_t logOverflows_ = 0;
    // A decoding station's segment: its cell (-1: no far field), own link's units, others' sum and the log's count at
    // its opening.
    std::vector<std::int32_t> lockCell_;
    std::vector<Units> lockOwn_;
    std::vector<double> segmentNearMw_;
    std::vector<std::uint64_t> segmentFrom_;
    // Its largest interference so far, into its Link when the frame ends (a Link is a cache miss).
    std::vector<double> lockedMaxMw_;
    // Carrier sense with the far field: each station's cell this step and the cells' members.
    std::vector<std::int32_t> cell_;
    const FarCells* cells_ = nullptr;
    Units sensingUnits_ = 0;
};

}  // namespace sbsim::radio
