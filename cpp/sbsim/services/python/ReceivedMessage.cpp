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

template <typename T>
const T* sparse(const std::vector<std::pair<std::size_t, T>>& items, std::size_t i) {
    const auto it =
        std::lower_bound(items.begin(), items.end(), i, [](const auto& e, std::size_t k) { return e.first < k; });
    return it != items.end() && it->first == i ? &it->second : nullptr;
}
}  // namespace

void MessageBatch::reserve(std::size_t n) {
    rows_.reserve(n);
    senders_.reserve(n);
}

void MessageBatch::add(const radio::V2xMessage& message, kernel::SimTime now) {
    const std::size_t i = rows_.size();
    const std::string_view type = message.typeName();
    std::uint32_t t = 0;
    while (t < typeNames_.size() && typeNames_[t] != type) ++t;
    if (t == typeNames_.size()) typeNames_.emplace_back(type);
    Row& row = rows_.emplace_back();
    row.receivedAt = now.seconds();
    row.sentAt = message.sentAt().seconds();
    row.sequence = message.sequence();
    row.size = static_cast<std::uint32_t>(message.byteSize());
    row.frameBytes = static_cast<std::uint32_t>(message.frameBytes());
    row.type = t;
    row.cam = false;
    senders_.push_back(message.sender());
    const std::type_info& dynamic = typeid(message);
    if (dynamic == typeid(facilities::Cam)) {
        const facilities::CamContent& c = static_cast<const facilities::Cam&>(message).content();
        row.cam = true;
        row.stationType = static_cast<std::uint8_t>(c.stationType);
        row.camValues[0] = c.position.x();
        row.camValues[1] = c.position.y();
        row.camValues[2] = c.speed;
        row.camValues[3] = c.heading;
        row.camValues[4] = c.acceleration;
        row.camValues[5] = c.length;
        row.camValues[6] = c.width;
        row.camValues[7] = c.yawRate;
        row.camValues[8] = c.generationTime.seconds();
    } else if (dynamic == typeid(PythonMessage)) {
        payloads_.emplace_back(i, static_cast<const PythonMessage&>(message).payload());
    } else if (dynamic == typeid(facilities::Denm)) {
        denms_.emplace_back(
            i, std::make_shared<facilities::DenmContent>(static_cast<const facilities::Denm&>(message).content()));
    }
}

const MessageBatch::Columns& MessageBatch::columns() const {
    if (columns_) return *columns_;
    Columns& c = columns_.emplace();
    const std::size_t n = rows_.size();
    for (auto* column : {&c.receivedAt, &c.sentAt, &c.sizes, &c.camSpeeds, &c.camHeadings}) column->resize(n);
    c.camPositions.resize(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        const Row& r = rows_[i];
        c.receivedAt[i] = r.receivedAt;
        c.sentAt[i] = r.sentAt;
        c.sizes[i] = r.size;
        c.camPositions[2 * i] = r.cam ? r.camValues[0] : kNone;
        c.camPositions[2 * i + 1] = r.cam ? r.camValues[1] : kNone;
        c.camSpeeds[i] = r.cam ? r.camValues[2] : kNone;
        c.camHeadings[i] = r.cam ? r.camValues[3] : kNone;
    }
    return c;
}

ReceivedMessage MessageBatch::at(std::size_t i) const {
    const Row& r = rows_[i];
    ReceivedMessage out;
    out.receivedAt = kernel::SimTime::fromSeconds(r.receivedAt);
    out.type = typeNames_[r.type];
    out.sender = senders_[i];
    out.sentAt = kernel::SimTime::fromSeconds(r.sentAt);
    out.sequence = r.sequence;
    out.size = r.size;
    out.frameBytes = r.frameBytes;
    const pybind11::object* payload = sparse(payloads_, i);
    out.payload = payload != nullptr ? *payload : pybind11::none();
    if (const auto* denm = sparse(denms_, i)) out.denm = *denm;
    if (r.cam) {
        const double* v = r.camValues;
        facilities::CamContent& cam = out.cam.emplace();
        cam.station = senders_[i];  // a CAM is its originator's, sent single-hop
        cam.stationType = static_cast<facilities::StationType>(r.stationType);
        cam.position = {v[0], v[1]};
        cam.speed = v[2];
        cam.heading = v[3];
        cam.acceleration = v[4];
        cam.length = v[5];
        cam.width = v[6];
        cam.yawRate = v[7];
        cam.generationTime = kernel::SimTime::fromSeconds(v[8]);
    }
    return out;
}

std::vector<std::string> MessageBatch::types() const {
    std::vector<std::string> out;
    out.reserve(rows_.size());
    for (const Row& r : rows_) out.push_back(typeNames_[r.type]);
    return out;
}
}  // namespace sbsim::services::python
