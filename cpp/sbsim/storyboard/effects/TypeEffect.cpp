#include "sbsim/storyboard/effects/TypeEffect.h"

#include <fmt/format.h>

#include <stdexcept>

#include "sbsim/storyboard/CheckContext.h"

namespace sbsim::storyboard {

TypeEffect::TypeEffect(std::string typeId) : typeId_(std::move(typeId)) {
    if (typeId_.empty()) throw std::invalid_argument("TypeEffect: the type id is empty");
}

std::string TypeEffect::describe() const { return fmt::format("TypeEffect('{}')", typeId_); }

void TypeEffect::check(CheckContext& ctx) const { ctx.warnUnknown(typeName(), NetworkObject::VehicleType, {typeId_}); }

}  // namespace sbsim::storyboard
