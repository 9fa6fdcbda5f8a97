#include "sbsim/storyboard/effects/RemoveVehicleEffect.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

RemoveVehicleEffect::RemoveVehicleEffect(std::string id) : id_(std::move(id)) {
    if (id_.empty()) throw std::invalid_argument("RemoveVehicleEffect needs a vehicle id");
}

std::string RemoveVehicleEffect::describe() const { return fmt::format("RemoveVehicleEffect('{}')", id_); }

}  // namespace sbsim::storyboard
