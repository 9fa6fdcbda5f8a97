#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/facilities/ActionId.h"
#include "sbsim/facilities/GeoCircle.h"
#include "sbsim/facilities/ItsMessage.h"
#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::facilities {

/// EN 302 637-3 RelevanceTrafficDirection.
enum class TrafficDirection : std::uint8_t { All = 0, Upstream = 1, Downstream = 2, Opposite = 3 };

/// How a DENM ends its event: the originator cancels it, or another station negates it.
enum class Termination : std::uint8_t { Cancellation = 0, Negation = 1 };

/// The impact-reduction container's request/response indication (ImpactReductionContainerExchange).
enum class ImpactReduction : std::uint8_t { Request = 0, Response = 1 };

/// What one DENM carries (management, situation and à-la-carte containers, as far as sbsim's use
/// cases fill them).
struct SBSIM_API DenmContent {
    /// Validity when the message gives none (EN 302 637-3).
    static constexpr kernel::SimTime kDefaultValidity = kernel::SimTime::fromMilliseconds(600'000);

    ActionId action;
    kernel::SimTime detectionTime;
    kernel::SimTime referenceTime;  ///< a newer one replaces an older one of the same action
    Eigen::Vector2d eventPosition = Eigen::Vector2d::Zero();
    int cause = 0;
    int subcause = 0;
    /// The relevance distance's upper bound (RelevanceDistance lessThan…m), if given.
    std::optional<double> relevanceDistance;
    TrafficDirection trafficDirection = TrafficDirection::All;
    std::optional<kernel::SimTime> validity;
    GeoCircle destination;  ///< the geo-broadcast area
    int trafficClass = 0;
    std::optional<Termination> termination;
    std::optional<ImpactReduction> impactReduction;

    /// Detection time + validity (600 s when absent): receivers keep the event until then.
    kernel::SimTime expiry() const { return detectionTime + validity.value_or(kDefaultValidity); }
};

/// A decentralized environmental notification message, sent as geo-broadcast to a circle.
class SBSIM_API Denm : public ItsMessage {
public:
    explicit Denm(DenmContent content) : content_(std::move(content)) { geoBroadcastTo(content_.destination); }
    const DenmContent& content() const { return content_; }

    std::string_view typeName() const override { return "DENM"; }
    /// The ASN.1 UPER size from the fields' widths: header (6), management container (36),
    /// situation (4), location with an empty trace (8); the impact-reduction container 20 more.
    /// A termination DENM carries the management container only.
    std::size_t byteSize() const override;
    radio::SecurityProfile securityProfile() const override { return radio::SecurityProfile::Denm; }
    /// `cause`, `subcause` and `action` ("<station>:<sequence>").
    std::vector<radio::TraceField> traceFields() const override;
    /// Stations inside the destination circle take it (GeoNetworking's geo-broadcast).
    bool reaches(const Eigen::Vector2d& position) const override { return content_.destination.contains(position); }
    using ItsMessage::store;
    void store(StationRegistry& stations, radio::StationIds::Index station, kernel::SimTime now) const override;
    void dispatch(ItsMessageHandler& handler) const override { handler.indicateDenm(*this); }
    /// Forwarders rebroadcast a copy.
    std::unique_ptr<radio::V2xMessage> clone() const override { return std::make_unique<Denm>(*this); }

private:
    DenmContent content_;
};

}  // namespace sbsim::facilities
