#include "sbsim/services/den/RsuDenService.h"

#include <algorithm>

#include "sbsim/services/ServiceRegistry.h"
#include "sbsim/services/ServicesConfig.h"

namespace sbsim::services {

SBSIM_REGISTER_SERVICE(RsuDenService);

RsuDenService::RsuDenService() = default;

RsuDenService::~RsuDenService() {
    for (kernel::Message* timer : {&startTimer_, &renewTimer_, &endTimer_}) {
        if (timer->isScheduled()) cancelEvent(*timer);
    }
}

void RsuDenService::initialize() {
    const ServiceSpec& spec = this->spec();
    const auto bad = [&](const std::string& what) {
        throw ServicesConfigError(spec.source + ":" + std::to_string(spec.line) + ": RsuDenService: " + what);
    };
    if (!spec.parameter("cause")) bad("needs a 'cause' attribute (the DENM's cause code)");
    denm_.cause = static_cast<int>(spec.number("cause", 0));
    denm_.subcause = static_cast<int>(spec.number("subcause", 0));
    if (spec.parameter("relevance")) denm_.relevanceDistance = spec.number("relevance", 0);
    denm_.trafficClass = static_cast<int>(spec.number("trafficClass", 1));
    const double area = spec.number("area", 1000);
    if (!(area > 0)) bad("'area' must be > 0 m");
    denm_.destination.radius = area;
    if (spec.parameter("x") || spec.parameter("y")) {
        if (!spec.parameter("x") || !spec.parameter("y")) bad("the event's position needs both 'x' and 'y'");
        x_ = spec.number("x", 0);
        y_ = spec.number("y", 0);
    }
    from_ = kernel::SimTime::fromSeconds(spec.number("from", 0));
    if (spec.parameter("until")) {
        until_ = kernel::SimTime::fromSeconds(spec.number("until", 0));
        if (*until_ <= from_) bad("'until' must be after 'from'");
    }
    interval_ = spec.duration("interval", 1);
    validity_ = spec.duration("validity", until_ ? (*until_ - from_).seconds() : 600.0);
    scheduleAt(std::max(from_, simTime()), startTimer_);
    if (until_) scheduleAt(std::max(*until_, simTime()), endTimer_);
}

void RsuDenService::handleMessage(kernel::Message& msg) {
    if (&msg == &startTimer_) return start();
    if (&msg == &renewTimer_) return renew();
    if (&msg == &endTimer_) {
        if (renewTimer_.isScheduled()) cancelEvent(renewTimer_);
        if (event_) terminate(*event_);
        event_.reset();
        return;
    }
    DenService::handleMessage(msg);
}

void RsuDenService::start() {
    if (until_ && simTime() >= *until_) return;
    denm_.action = requestActionId();
    event_ = denm_.action;
    renew();
}

void RsuDenService::renew() {
    const kernel::SimTime now = simTime();
    denm_.detectionTime = now;
    denm_.referenceTime = now;
    denm_.eventPosition = x_ ? Eigen::Vector2d(*x_, *y_) : stationPosition();
    denm_.destination.center = denm_.eventPosition;
    denm_.validity = validity_;
    // Repeated for as long as this version stays valid (or the event lasts); then renewed.
    kernel::SimTime span = validity_;
    if (until_) span = std::min(span, *until_ - now);
    sendDenm(denm_, Repetition{interval_, span});
    if (!until_ || now + validity_ < *until_) scheduleAt(now + validity_, renewTimer_);
}

}  // namespace sbsim::services
