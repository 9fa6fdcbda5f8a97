#include "sbsim/services/den/UseCaseFactory.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <functional>
#include <map>
#include <stdexcept>

#include "sbsim/services/den/EmergencyBrakeLight.h"
#include "sbsim/services/den/ImpactReductionContainerExchange.h"
#include "sbsim/services/den/StoryboardEvent.h"
#include "sbsim/services/den/TractionLoss.h"
#include "sbsim/services/den/TrafficJamAhead.h"
#include "sbsim/services/den/TrafficJamEndOfQueue.h"

namespace sbsim::services {

namespace {
const std::map<std::string, std::function<std::unique_ptr<UseCase>()>>& factories() {
    static const std::map<std::string, std::function<std::unique_ptr<UseCase>()>> all{
        {"EmergencyBrakeLight", [] { return std::make_unique<EmergencyBrakeLight>(); }},
        {"ImpactReductionContainerExchange", [] { return std::make_unique<ImpactReductionContainerExchange>(); }},
        {"StoryboardEvent", [] { return std::make_unique<StoryboardEvent>(); }},
        {"TractionLoss", [] { return std::make_unique<TractionLoss>(); }},
        {"TrafficJamAhead", [] { return std::make_unique<TrafficJamAhead>(); }},
        {"TrafficJamEndOfQueue", [] { return std::make_unique<TrafficJamEndOfQueue>(); }},
    };
    return all;
}
}  // namespace

std::vector<std::string> useCaseNames() {
    std::vector<std::string> names;
    for (const auto& [name, f] : factories()) {
        // StoryboardEvent needs its signal and cause: it runs only where a file lists it.
        if (name != "StoryboardEvent") names.push_back(name);
    }
    return names;
}

bool isUseCase(const std::string& name) { return factories().count(name) != 0; }

std::unique_ptr<UseCase> makeUseCase(const std::string& name) {
    const auto it = factories().find(name);
    if (it == factories().end()) {
        std::vector<std::string> known;
        for (const auto& [n, f] : factories()) known.push_back(n);
        throw std::out_of_range(fmt::format("unknown DEN use case '{}' (known: {})", name, fmt::join(known, ", ")));
    }
    return it->second();
}

}  // namespace sbsim::services
