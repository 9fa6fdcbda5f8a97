#include "sbsim/app/run/NetworkQuestions.h"

namespace sbsim::app {

NetworkQuestions::NetworkQuestions(RouteIds routes)
    : network_(traffic::NetworkIds::ofLoadedSumo()), routes_(std::move(routes)) {}

void NetworkQuestions::answer(storyboard::CheckScenario& scenario) const {
    scenario.edgeExists = [this](std::string_view id) { return network_.hasEdge(id); };
    scenario.laneExists = [this](std::string_view id) { return network_.hasLane(id); };
    scenario.trafficLightExists = [this](std::string_view id) { return network_.hasTrafficLight(id); };
    scenario.vehicleTypeExists = [this](std::string_view id) {
        return network_.hasVehicleType(id) || routes_.definesType(id);
    };
}

}  // namespace sbsim::app
