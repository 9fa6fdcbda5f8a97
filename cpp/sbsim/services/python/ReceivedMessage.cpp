#include "sbsim/services/python/ReceivedMessage.h"

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

}  // namespace sbsim::services::python
