#include "sbsim/facilities/Denm.h"

#include "sbsim/facilities/StationRegistry.h"

namespace sbsim::facilities {

std::size_t Denm::byteSize() const {
    constexpr std::size_t kHeader = 6, kManagement = 36, kSituation = 4, kLocation = 8, kImpactReduction = 20;
    if (content_.termination) return kHeader + kManagement;
    return kHeader + kManagement + kSituation + kLocation + (content_.impactReduction ? kImpactReduction : 0);
}

std::vector<radio::TraceField> Denm::traceFields() const {
    return {{"cause", std::int64_t{content_.cause}},
            {"subcause", std::int64_t{content_.subcause}},
            {"action", content_.action.str()}};
}

void Denm::store(StationRegistry& stations, radio::StationIds::Index station, kernel::SimTime now) const {
    const auto phase = stations.of(station).denms.received(content_, now);
    if (phase) stations.report({now, *phase, stations.name(station), content_.action, content_.cause});
}

}  // namespace sbsim::facilities
