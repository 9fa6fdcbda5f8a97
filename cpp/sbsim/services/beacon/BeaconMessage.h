#pragma once

#include <cstddef>
#include <string_view>

#include "sbsim/radio/V2xMessage.h"

namespace sbsim::services {

/// A fixed-size periodic beacon with no content of its own: channel load for radio studies. Framed
/// and signed as a CAM (single-hop broadcast, certificate digest between certificates).
class BeaconMessage : public radio::V2xMessage {
public:
    explicit BeaconMessage(std::size_t bytes) : bytes_(bytes) {}
    std::string_view typeName() const override { return "Beacon"; }
    std::size_t byteSize() const override { return bytes_; }
    /// Signed as a CAM: a beacon stands for one in channel-load studies.
    radio::SecurityProfile securityProfile() const override { return radio::SecurityProfile::Cam; }

private:
    std::size_t bytes_;
};

}  // namespace sbsim::services
