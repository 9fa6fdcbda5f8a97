#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sbsim/radio/MessageTrace.h"
#include "sbsim/radio/channel/ChannelSettings.h"
#include "sbsim/radio/channel/FrameErrorTable.h"
#include "sbsim/radio/channel/Link.h"

namespace sbsim::radio {

/// 802.11p reception at every station, struct-of-arrays by slot: the frames it hears and their
/// power, the power it senses (carrier sense: busy at or above the sensing threshold), the frame
/// it locked onto (the first it detects while not sending), whether it sends (half-duplex); at a
/// frame's end, whether it decoded it: probability 1 − FER(SINR), the interference being the
/// largest sum of the other frames overlapping it.
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

    /// Station `s` starts sending frame `id`: whatever it was receiving is lost (half-duplex).
    void startSending(Slot s, FrameId id);
    void stopSending(Slot s) { sending_[s] = 0; }
    /// Frame `id` reaches the receivers of `links` (which stay where they are until it ends): each
    /// link above the floor adds to its receiver's power and interference, and may lock it.
    void frameStarts(FrameId id, std::vector<Link>& links);
    /// The power station `r` hears once the frame of `links` has left it (summed afresh, so no
    /// rounding drift accumulates); it takes effect with setSensedPower().
    double powerWithout(Slot r, const std::vector<Link>& links);
    /// Whether `mw` would change station `r`'s carrier sense.
    bool changesSense(Slot r, double mw) const { return (mw >= sensingMw_) != sensesBusy(r); }
    void setSensedPower(Slot r, double mw);
    /// Frame `id` ended at station `r`: it no longer decodes it.
    void unlock(Slot r, FrameId id) {
        if (locked_[r] == id) locked_[r] = 0;
    }
    /// Whether `link`'s receiver decoded the frame (none) or why it lost it; `sinrDb` is set when
    /// it tried. The draw is keyed by the frame and the receiver.
    std::optional<LossReason> decode(const Link& link, std::uint64_t frameKey, std::uint64_t receiverKey,
                                     double& sinrDb) const;

private:
    /// A frame a station hears: its links (the frame's) and which is the station's.
    struct Incoming {
        std::vector<Link>* links;
        std::uint32_t link;
        double mw;
    };

    Listener& listener_;
    FrameErrorTable fer_;
    double sensingMw_, noiseMw_, floorMw_;
    double ratioDb_;  // Eb/N0 − SINR: bandwidth over bit rate, in dB

    std::vector<double> sensedMw_;
    std::vector<std::uint8_t> sensedBusy_;
    std::vector<FrameId> sending_;  // 0 = not sending
    std::vector<FrameId> locked_;   // the frame being decoded, 0 = none
    std::vector<std::vector<Incoming>> incoming_;
};

}  // namespace sbsim::radio
