#include "sbsim/traffic/Transition.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sbsim::traffic {

double Transition::shaped(Shape shape, double progress) {
    const double x = std::clamp(progress, 0.0, 1.0);
    switch (shape) {
        case Shape::Step:
            return 1.0;
        case Shape::Linear:
            return x;
        case Shape::Cubic:
            return x * x * (3 - 2 * x);
        case Shape::Sinusoidal:
            return 0.5 - 0.5 * std::cos(std::numbers::pi * x);
    }
    return 1.0;
}

double Transition::progress(double elapsed, double driven, double delta) const {
    if (shape == Shape::Step) return 1.0;
    double span = value;
    double done = elapsed;
    if (dimension == Dimension::Distance) {
        done = driven;
    } else if (dimension == Dimension::Rate) {
        span = value > 0 ? std::abs(delta) / value : 0;  // the time the change takes at that rate
    }
    if (span <= 0) return 1.0;
    return std::min(1.0, std::max(0.0, done) / span);
}

std::optional<Transition::Shape> Transition::shapeNamed(std::string_view name) {
    for (const Shape s : {Shape::Step, Shape::Linear, Shape::Cubic, Shape::Sinusoidal}) {
        if (Transition::name(s) == name) return s;
    }
    return std::nullopt;
}

std::optional<Transition::Dimension> Transition::dimensionNamed(std::string_view name) {
    for (const Dimension d : {Dimension::Time, Dimension::Distance, Dimension::Rate}) {
        if (Transition::name(d) == name) return d;
    }
    return std::nullopt;
}

std::string_view Transition::name(Shape shape) {
    switch (shape) {
        case Shape::Step:
            return "step";
        case Shape::Linear:
            return "linear";
        case Shape::Cubic:
            return "cubic";
        case Shape::Sinusoidal:
            return "sinusoidal";
    }
    return "step";
}

std::string_view Transition::name(Dimension dimension) {
    switch (dimension) {
        case Dimension::Time:
            return "time";
        case Dimension::Distance:
            return "distance";
        case Dimension::Rate:
            return "rate";
    }
    return "time";
}

std::string Transition::describe(std::string_view rateUnit) const {
    if (shape == Shape::Step) return "step";
    switch (dimension) {
        case Dimension::Time:
            return fmt::format("{} over {:g} s", name(shape), value);
        case Dimension::Distance:
            return fmt::format("{} over {:g} m", name(shape), value);
        case Dimension::Rate:
            return fmt::format("{} at {:g} {}", name(shape), value, rateUnit);
    }
    return std::string(name(shape));
}

}  // namespace sbsim::traffic
