#pragma once

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::radio {

/// A station's receiving side (its middleware): the medium hands it each message it receives,
/// all the receivers of one frame from one kernel event, in the order the medium found them.
class SBSIM_API Receiver {
public:
    /// `message` reached this station now.
    virtual void receive(const V2xMessage& message) = 0;

protected:
    ~Receiver() = default;
};

}  // namespace sbsim::radio
