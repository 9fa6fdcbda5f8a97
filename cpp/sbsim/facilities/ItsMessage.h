#pragma once

#include <Eigen/Core>
#include <string>

#include "sbsim/facilities/ItsMessageHandler.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/radio/StationIds.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::facilities {

class StationRegistry;

/// A message of ETSI's facilities (CAM, DENM): it knows whether a receiving station at a position
/// takes it (geo-broadcast destination area), what the receiver's facilities keep of it, and which
/// handler call it is — so a station asks the message instead of switching on its type.
class SBSIM_API ItsMessage : public radio::V2xMessage {
public:
    /// Whether a station at `position` passes the message up (single-hop broadcast: always).
    virtual bool reaches(const Eigen::Vector2d& /*position*/) const { return true; }
    /// Stores what station `station` (its index in `stations`) keeps of it (its LDM, its DENM
    /// memory) at `now`. Called on the simulation's thread only.
    virtual void store(StationRegistry& stations, radio::StationIds::Index station, kernel::SimTime now) const = 0;
    /// The same for the station called `station`.
    void store(StationRegistry& stations, std::string_view station, kernel::SimTime now) const;
    /// Calls the handler's method for this message type.
    virtual void dispatch(ItsMessageHandler& handler) const = 0;
};

}  // namespace sbsim::facilities
