#include "sbsim/storyboard/effects/ParameterEffect.h"

#include <fmt/format.h>

#include <stdexcept>

namespace sbsim::storyboard {

ParameterEffect::ParameterEffect(std::shared_ptr<ScenarioParameters> parameters, std::string name, Op op,
                                 ScenarioParameters::Value value)
    : parameters_(std::move(parameters)), name_(std::move(name)), op_(op), value_(std::move(value)) {
    if (!parameters_) throw std::invalid_argument("ParameterEffect: the parameters are null");
    if (!parameters_->has(name_)) throw std::invalid_argument(fmt::format("ParameterEffect: no parameter '{}'", name_));
    if (op_ != Op::set && value_.index() != 0)
        throw std::invalid_argument(fmt::format("ParameterEffect: '{}' needs a number to add or multiply", name_));
    if (op_ == Op::set && parameters_->get(name_).index() != value_.index())
        throw std::invalid_argument(fmt::format("ParameterEffect: '{}' holds a {}", name_,
                                                parameters_->get(name_).index() == 0 ? "number" : "text"));
}

void ParameterEffect::apply(WorldScope& /*scope*/) {
    if (op_ == Op::set) {
        parameters_->set(name_, value_);
    } else {
        parameters_->modify(name_, std::get<double>(value_), op_ == Op::multiply);
    }
}

std::string ParameterEffect::describe() const {
    const char* what = op_ == Op::set ? "=" : op_ == Op::add ? "+=" : "*=";
    return fmt::format("ParameterEffect({} {} {})", name_, what, ScenarioParameters::describe(value_));
}

}  // namespace sbsim::storyboard
