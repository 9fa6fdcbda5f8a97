#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "sbsim/kernel/Export.h"

namespace sbsim::traffic {

/// How a commanded value goes from where it was to its target (OpenSCENARIO's TransitionDynamics):
/// a shape over a progress from 0 to 1, the progress measured in time, in distance driven, or (for
/// speed) in time at an average rate of change.
struct SBSIM_API Transition {
    enum class Shape { Step, Linear, Cubic, Sinusoidal };
    enum class Dimension { Time, Distance, Rate };

    Shape shape = Shape::Step;
    Dimension dimension = Dimension::Time;
    double value = 0;  ///< s, m, or (rate) units of the value per second

    /// The share of the change done at `progress` (clamped to [0, 1]): step 1 at once, linear x,
    /// cubic 3x² − 2x³ (no jump in rate at either end), sinusoidal (1 − cos πx) / 2.
    static double shaped(Shape shape, double progress);
    /// The progress after `elapsed` s and `driven` m for a change of `delta` (|Δ| for the rate).
    double progress(double elapsed, double driven, double delta) const;
    /// Whether it has run: progress reached 1.
    bool done(double elapsed, double driven, double delta) const { return progress(elapsed, driven, delta) >= 1; }

    /// The names the story API takes ("step", "linear", "cubic", "sinusoidal"; "time", "distance",
    /// "rate"); none for another name.
    static std::optional<Shape> shapeNamed(std::string_view name);
    static std::optional<Dimension> dimensionNamed(std::string_view name);
    static std::string_view name(Shape shape);
    static std::string_view name(Dimension dimension);
    /// "linear over 4 s", "cubic over 50 m", "linear at 2 /s", "step".
    std::string describe(std::string_view rateUnit = "/s") const;
};

}  // namespace sbsim::traffic
