#include "sbsim/services/python/ReceivedMessage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <typeinfo>

#include "sbsim/services/python/PythonMessage.h"

namespace sbsim::services::python {

ReceivedMessage ReceivedMessage::of(const radio::V2xMessage& message, kernel::SimTime now) {
    ReceivedMessage out;
    out.receivedAt = now;
    out.type = std::string(message.typeName());
    out.sender = message.sender();
    out.sentAt = message.sentAt();
    out.sequence = message.sequence();
    out.size = message.byteSize();
    out.frameBytes = message.frameBytes();
    // The concrete types sbsim knows, by exact type (a failed dynamic_cast walks the hierarchy
    // by name, per reception); a plugin's message shows its header only.
    const std::type_info& type = typeid(message);
    if (type == typeid(PythonMessage)) {
        out.payload = static_cast<const PythonMessage&>(message).payload();
        return out;
    }
    out.payload = pybind11::none();
    if (type == typeid(facilities::Cam)) {
        // All but the low-frequency container (its path history is a vector per CAM; Python sees none of it).
        const facilities::CamContent& c = static_cast<const facilities::Cam&>(message).content();
        out.cam.emplace();
        out.cam->station = c.station;
        out.cam->stationType = c.stationType;
        out.cam->generationTime = c.generationTime;
        out.cam->position = c.position;
        out.cam->speed = c.speed;
        out.cam->heading = c.heading;
        out.cam->acceleration = c.acceleration;
        out.cam->length = c.length;
        out.cam->width = c.width;
        out.cam->yawRate = c.yawRate;
    } else if (type == typeid(facilities::Denm)) {
        out.denm = std::make_shared<facilities::DenmContent>(static_cast<const facilities::Denm&>(message).content());
    }
    return out;
}

namespace {
constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kRest = 6;

template <typename T>
const T* sparse(const std::vector<std::pair<std::size_t, T>>& items, std::size_t i) {
    const auto it =
        std::lower_bound(items.begin(), items.end(), i, [](const auto& e, std::size_t k) { return e.first < k; });
    return it != items.end() && it->first == i ? &it->second : nullptr;
}
}  // namespace

void MessageBatch::reserve(std::size_t n) {
    for (auto* c : {&receivedAt_, &sentAt_, &sizes_, &camSpeed_, &camHeading_}) c->reserve(n);
    camPosition_.reserve(2 * n);
    camRest_.reserve(kRest * n);
    sequences_.reserve(n);
    frameBytes_.reserve(n);
    types_.reserve(n);
    senders_.reserve(n);
}

void MessageBatch::add(const radio::V2xMessage& message, kernel::SimTime now) {
    const std::size_t i = size();
    receivedAt_.push_back(now.seconds());
    sentAt_.push_back(message.sentAt().seconds());
    sizes_.push_back(static_cast<double>(message.byteSize()));
    sequences_.push_back(message.sequence());
    frameBytes_.push_back(message.frameBytes());
    const std::string_view type = message.typeName();
    std::uint32_t t = 0;
    while (t < typeNames_.size() && typeNames_[t] != type) ++t;
    if (t == typeNames_.size()) typeNames_.emplace_back(type);
    types_.push_back(t);
    senders_.push_back(message.sender());
    const std::type_info& dynamic = typeid(message);
    if (dynamic == typeid(facilities::Cam)) {
        const facilities::CamContent& c = static_cast<const facilities::Cam&>(message).content();
        camPosition_.insert(camPosition_.end(), {c.position.x(), c.position.y()});
        camSpeed_.push_back(c.speed);
        camHeading_.push_back(c.heading);
        camRest_.insert(camRest_.end(), {c.acceleration, c.length, c.width, c.yawRate, c.generationTime.seconds(),
                                         static_cast<double>(c.stationType)});
        return;
    }
    camPosition_.insert(camPosition_.end(), {kNone, kNone});
    camSpeed_.push_back(kNone);
    camHeading_.push_back(kNone);
    camRest_.insert(camRest_.end(), kRest, kNone);
    if (dynamic == typeid(PythonMessage)) {
        payloads_.emplace_back(i, static_cast<const PythonMessage&>(message).payload());
    } else if (dynamic == typeid(facilities::Denm)) {
        denms_.emplace_back(
            i, std::make_shared<facilities::DenmContent>(static_cast<const facilities::Denm&>(message).content()));
    }
}

ReceivedMessage MessageBatch::at(std::size_t i) const {
    ReceivedMessage out;
    out.receivedAt = kernel::SimTime::fromSeconds(receivedAt_[i]);
    out.type = typeNames_[types_[i]];
    out.sender = senders_[i];
    out.sentAt = kernel::SimTime::fromSeconds(sentAt_[i]);
    out.sequence = sequences_[i];
    out.size = static_cast<std::size_t>(sizes_[i]);
    out.frameBytes = frameBytes_[i];
    const pybind11::object* payload = sparse(payloads_, i);
    out.payload = payload != nullptr ? *payload : pybind11::none();
    if (const auto* denm = sparse(denms_, i)) out.denm = *denm;
    if (!std::isnan(camPosition_[2 * i])) {
        out.cam.emplace();
        const double* rest = &camRest_[kRest * i];
        out.cam->station = senders_[i];  // a CAM is its originator's, sent single-hop
        out.cam->position = {camPosition_[2 * i], camPosition_[2 * i + 1]};
        out.cam->speed = camSpeed_[i];
        out.cam->heading = camHeading_[i];
        out.cam->acceleration = rest[0];
        out.cam->length = rest[1];
        out.cam->width = rest[2];
        out.cam->yawRate = rest[3];
        out.cam->generationTime = kernel::SimTime::fromSeconds(rest[4]);
        out.cam->stationType = static_cast<facilities::StationType>(static_cast<int>(rest[5]));
    }
    return out;
}

std::vector<std::string> MessageBatch::types() const {
    std::vector<std::string> out;
    out.reserve(types_.size());
    for (const std::uint32_t t : types_) out.push_back(typeNames_[t]);
    return out;
}

}  // namespace sbsim::services::python
