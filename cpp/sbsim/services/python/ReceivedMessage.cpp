#include "sbsim/services/python/ReceivedMessage.h"

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
        out.denm = static_cast<const facilities::Denm&>(message).content();
    }
    return out;
}

const MessageBatch::Columns& MessageBatch::columns() {
    if (columns_) return *columns_;
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    Columns c;
    const std::size_t n = messages.size();
    for (auto* column : {&c.receivedAt, &c.sentAt, &c.size, &c.camSpeed, &c.camHeading}) column->reserve(n);
    c.camPosition.reserve(2 * n);
    for (const ReceivedMessage& m : messages) {
        c.receivedAt.push_back(m.receivedAt.seconds());
        c.sentAt.push_back(m.sentAt.seconds());
        c.size.push_back(static_cast<double>(m.size));
        c.camPosition.push_back(m.cam ? m.cam->position.x() : kNone);
        c.camPosition.push_back(m.cam ? m.cam->position.y() : kNone);
        c.camSpeed.push_back(m.cam ? m.cam->speed : kNone);
        c.camHeading.push_back(m.cam ? m.cam->heading : kNone);
    }
    columns_ = std::move(c);
    return *columns_;
}

}  // namespace sbsim::services::python
