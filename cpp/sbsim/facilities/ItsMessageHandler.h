#pragma once

#include "sbsim/kernel/Export.h"

namespace sbsim::facilities {

class Cam;
class Denm;

/// Who is handed the ITS messages a station receives (a service): one call per message type.
class SBSIM_API ItsMessageHandler {
public:
    virtual ~ItsMessageHandler() = default;
    /// A CAM another station sent, after the station's local dynamic map took it in.
    virtual void indicateCam(const Cam& /*cam*/) {}
    /// A DENM whose destination area holds this station, after its DENM memory took it in.
    virtual void indicateDenm(const Denm& /*denm*/) {}
};

}  // namespace sbsim::facilities
