#pragma once

#include <array>
#include <cstdint>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// Marsaglia and Tsang's ziggurat for the standard normal ("The Ziggurat Method for Generating
/// Random Variables", J. Stat. Softw. 5(8), 2000), built here from its definition: kLayers boxes of
/// equal area v under f(x) = exp(−x²/2), x ≥ 0. Box i spans [0, x[i]] × [f(x[i]), f(x[i+1])];
/// box 0 is the base strip [0, r] × [0, f(r)] plus the tail beyond r, given the width v / f(r).
/// A point uniform in a box lies under the curve for sure when its abscissa is below x[i+1]
/// (about 99 % of draws: one 64-bit word, a multiply and a compare); otherwise the wedge or the
/// tail decides (CounterRandom::normal). Exact: no approximation of the distribution.
class SBSIM_API Ziggurat {
public:
    static constexpr int kLayers = 256;

    /// The tables, built once (r by bisection, so the boxes exactly fill the area under f).
    static const Ziggurat& instance();

    static double density(double t);

    std::array<double, kLayers + 1> x{};  ///< box widths; x[kLayers] = 0
    std::array<double, kLayers + 1> f{};  ///< f(x[i]); f[0] = 0 (the base strip starts at the axis)
    double r = 0;                         ///< where the tail begins

private:
    Ziggurat();
    /// Builds the boxes from r = `tail`; > 0 when they reach the top before the last layer (r too
    /// small), < 0 when the last box is too small to close the top.
    double fill(double tail);
};

}  // namespace sbsim::radio
