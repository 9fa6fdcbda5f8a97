#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Object.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::services {

/// A message one vehicle's service broadcasts to the services of vehicles around it. Subclass it
/// with the content of your application; give it a name (per-type counts in the summary) and a
/// byte size (what it would occupy on the channel).
class SBSIM_API V2xMessage : public kernel::Object {
public:
    /// A short type name for statistics, e.g. "ClearLane".
    virtual std::string_view typeName() const = 0;
    virtual std::size_t byteSize() const = 0;

    /// Filled in by the medium when the message is sent.
    const std::string& sender() const { return sender_; }
    kernel::SimTime sentAt() const { return sentAt_; }

private:
    friend class Medium;
    std::string sender_;
    kernel::SimTime sentAt_;
};

}  // namespace sbsim::services
