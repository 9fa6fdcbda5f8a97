#pragma once

#include <string>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::services {

/// A service that names the message types (radio::V2xMessage::typeName()) its indicate() takes,
/// as Artery's services listen on BTP ports: its indicate() is not called for the others. A station none of whose
/// services takes a type is not visited by its messages (they are still received: counted, traced, signed for), unless
/// every station's own layers take them (CAMs and DENMs go into its facilities and then to
/// ItsMessageHandler::indicateCam/indicateDenm) or they are geo-broadcasts (its router forwards
/// them). A service without it takes every type. (A mix-in, as ItsMessageHandler, so that service
/// modules built against an older Service keep their layout.)
class SBSIM_API IndicatedTypes {
public:
    virtual ~IndicatedTypes() = default;
    /// The types indicate() takes; empty: none (it does nothing with a message it is handed).
    virtual std::vector<std::string> indicatedTypes() const = 0;
};

}  // namespace sbsim::services
