#include "sbsim/services/Medium.h"

#include <cmath>
#include <stdexcept>

#include "sbsim/services/Middleware.h"
#include "sbsim/services/V2xMessage.h"

namespace sbsim::services {

namespace {
/// A stream of its own, so radio losses never shift the storyboard's random draws.
constexpr unsigned kMediumStream = 0x7632'7800;
}  // namespace

Medium::Medium(MediumSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory)
    : kernel::Module("medium"), settings_(settings), snapshot_(snapshot), directory_(std::move(directory)) {
    if (!(settings_.range > 0) || !std::isfinite(settings_.range))
        throw std::invalid_argument("V2X range must be > 0 m");
    if (settings_.latency < kernel::SimTime::zero()) throw std::invalid_argument("V2X latency must be >= 0 s");
    if (settings_.fadeStart && (*settings_.fadeStart < 0 || *settings_.fadeStart > settings_.range)) {
        throw std::invalid_argument("V2X fade start must be between 0 m and the range");
    }
}

void Medium::initialize() { random_ = simulation().randomStream(kMediumStream); }

double Medium::receptionProbability(double distance) const {
    if (distance > settings_.range) return 0.0;
    if (!settings_.fadeStart || distance <= *settings_.fadeStart) return 1.0;
    return (settings_.range - distance) / (settings_.range - *settings_.fadeStart);
}

void Medium::broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    message->sender_ = sender;
    message->sentAt_ = simTime();
    Counts& counts = counts_[std::string(message->typeName())];
    ++counts.sent;

    const auto self = snapshot_.indexOf(sender);
    if (!self) return;  // not on the road (yet): nobody hears it
    if (gridTime_ != snapshot_.time()) {
        grid_.build(snapshot_, settings_.range);
        gridTime_ = snapshot_.time();
    }
    const std::shared_ptr<const V2xMessage> shared(std::move(message));
    const auto& positions = snapshot_.positions();
    for (const auto other : grid_.within(*self, settings_.range)) {
        Middleware* receiver = directory_(snapshot_.ids()[other]);
        if (receiver == nullptr) continue;  // a vehicle without services
        const double p = receptionProbability((positions.col(other) - positions.col(*self)).norm());
        // Draw only where loss is possible, so a lossless medium consumes no random numbers.
        if (p < 1.0 && !(random_->uniform01() < p)) continue;
        sendDirect(std::make_unique<Middleware::Delivery>(shared), settings_.latency, *receiver);
    }
}

void Medium::delivered(const V2xMessage& message) {
    const auto it = counts_.find(message.typeName());
    if (it != counts_.end()) ++it->second.delivered;
}

}  // namespace sbsim::services
