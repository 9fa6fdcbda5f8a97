#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/facilities/ItsMessage.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// ETSI station types (EN 302 637-2) sbsim's stations take.
enum class StationType : std::uint8_t { Unknown = 0, PassengerCar = 5, RoadSideUnit = 15 };

/// The CAM's low-frequency container: sent in the first CAM and then at most every 500 ms.
struct SBSIM_API CamLowFrequency {
    std::uint8_t vehicleRole = 0;     ///< 0: default (sbsim's vehicles have no special role)
    std::uint8_t exteriorLights = 0;  ///< bit field; SUMO's signals are not read, so all off
    /// The station's positions at its last CAMs, newest first (at most kPathHistoryLength).
    std::vector<Eigen::Vector2d> pathHistory;
    static constexpr std::size_t kPathHistoryLength = 23;  ///< Artery's default
};

/// What one CAM carries (EN 302 637-2's basic and high-frequency containers).
struct SBSIM_API CamContent {
    std::string station;
    StationType stationType = StationType::PassengerCar;
    kernel::SimTime generationTime;
    Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< SUMO network frame, m
    double speed = 0;                                    ///< m/s
    double heading = 0;                                  ///< degrees, 0 = north, clockwise (as SUMO's angle)
    double acceleration = 0;                             ///< m/s², longitudinal
    double length = 0;                                   ///< m
    double width = 0;                                    ///< m
    double yawRate = 0;                                  ///< degrees/s, clockwise positive
    std::optional<CamLowFrequency> lowFrequency;
};

/// A cooperative awareness message.
class SBSIM_API Cam : public ItsMessage {
public:
    explicit Cam(CamContent content) : content_(std::move(content)) {}
    const CamContent& content() const { return content_; }

    std::string_view typeName() const override { return "CAM"; }
    /// The ASN.1 UPER encoding's size, from the fields' widths rounded up to bytes: ITS PDU header
    /// (6), generation delta time (2), basic container (15), high-frequency container (22); the
    /// low-frequency container adds role and lights (3), its list length (1) and 7 per path point.
    /// A roadside unit's CAM has the RSU high-frequency container instead, without protected
    /// zones (1): kRoadSideUnitBytes.
    std::size_t byteSize() const override;
    radio::SecurityProfile securityProfile() const override { return radio::SecurityProfile::Cam; }
    using ItsMessage::store;
    /// Into the receiver's LDM, under the index of content().station (looked up once per frame:
    /// the receivers of one frame share the message).
    void store(StationRegistry& stations, radio::StationIds::Index station, kernel::SimTime now) const override;
    void dispatch(ItsMessageHandler& handler) const override { handler.indicateCam(*this); }

    static constexpr std::size_t kHighFrequencyBytes = 45;
    static constexpr std::size_t kRoadSideUnitBytes = 24;

private:
    CamContent content_;
    // content_.station's index in the registry it was last stored through.
    mutable std::uint64_t indexedIn_ = 0;  // the registry's identity(); 0: none
    mutable radio::StationIds::Index index_ = 0;
};

}  // namespace sbsim::facilities
