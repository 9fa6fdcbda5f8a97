#include "sbsim/storyboard/effects/TypeEffect.h"

#include <stdexcept>

namespace sbsim::storyboard {

TypeEffect::TypeEffect(std::string typeId) : typeId_(std::move(typeId)) {
    if (typeId_.empty()) throw std::invalid_argument("TypeEffect: the type id is empty");
}

}  // namespace sbsim::storyboard
