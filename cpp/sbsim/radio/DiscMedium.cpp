#include "sbsim/radio/DiscMedium.h"

#include <cmath>
#include <stdexcept>

#include "sbsim/radio/Delivery.h"

namespace sbsim::radio {

namespace {
/// A stream of its own, so radio losses never shift the storyboard's random draws.
constexpr unsigned kMediumStream = 0x7632'7800;
}  // namespace

DiscMedium::DiscMedium(DiscSettings settings, const traffic::VehicleSnapshot& snapshot, Directory directory)
    : Medium(std::move(directory)), settings_(settings), snapshot_(snapshot) {
    if (!(settings_.range > 0) || !std::isfinite(settings_.range))
        throw std::invalid_argument("V2X range must be > 0 m");
    if (settings_.latency < kernel::SimTime::zero()) throw std::invalid_argument("V2X latency must be >= 0 s");
    if (settings_.fadeStart && (*settings_.fadeStart < 0 || *settings_.fadeStart > settings_.range)) {
        throw std::invalid_argument("V2X fade start must be between 0 m and the range");
    }
}

void DiscMedium::initialize() { random_ = simulation().randomStream(kMediumStream); }

double DiscMedium::receptionProbability(double distance) const {
    if (distance > settings_.range) return 0.0;
    if (!settings_.fadeStart || distance <= *settings_.fadeStart) return 1.0;
    return (settings_.range - distance) / (settings_.range - *settings_.fadeStart);
}

void DiscMedium::broadcast(const std::string& sender, std::unique_ptr<V2xMessage> message) {
    if (!message) throw std::invalid_argument("cannot send a null V2X message");
    stamp(*message, sender);

    const auto self = snapshot_.indexOf(sender);
    if (!self) return;  // not on the road (yet): nobody hears it
    if (gridTime_ != snapshot_.time()) {
        grid_.build(snapshot_, settings_.range);
        gridTime_ = snapshot_.time();
    }
    const std::shared_ptr<const V2xMessage> shared(std::move(message));
    const auto& positions = snapshot_.positions();
    for (const auto other : grid_.within(*self, settings_.range)) {
        kernel::Module* receiver = receiverOf(snapshot_.ids()[other]);
        if (receiver == nullptr) continue;  // a vehicle without services
        const double p = receptionProbability((positions.col(other) - positions.col(*self)).norm());
        // Draw only where loss is possible, so a lossless medium consumes no random numbers.
        if (p < 1.0 && !(random_->uniform01() < p)) continue;
        sendDirect(std::make_unique<Delivery>(shared), settings_.latency, *receiver);
    }
}

}  // namespace sbsim::radio
