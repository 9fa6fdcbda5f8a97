#pragma once

#include <string>

#include "sbsim/radio/V2xMessage.h"

namespace sbsim::services {

/// "Clear my lane": an emergency vehicle's road and lane, for the vehicles around it.
class ClearLaneMessage : public radio::V2xMessage {
public:
    ClearLaneMessage(std::string road, int lane) : road_(std::move(road)), lane_(lane) {}

    std::string_view typeName() const override { return "ClearLane"; }
    // Station id, position, road id and lane: about what a DENM's relevant fields take.
    std::size_t byteSize() const override { return 64 + road_.size(); }

    const std::string& road() const { return road_; }
    int lane() const { return lane_; }

private:
    std::string road_;
    int lane_;
};

}  // namespace sbsim::services
