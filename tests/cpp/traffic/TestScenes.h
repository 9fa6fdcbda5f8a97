#pragma once

#include <random>
#include <string>
#include <utility>
#include <vector>

#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::traffic::test {

/// Positions for the spatial searches' tests (NeighbourGrid, PairSweep), each checked against
/// brute force on the same scenes.
using Vehicle = VehicleSnapshot::Vehicle;

inline Vehicle car(std::string id, double x, double y) {
    Vehicle v;
    v.id = std::move(id);
    v.x = x;
    v.y = y;
    return v;
}

/// `n` vehicles uniform in [-extent, extent]², or on a lattice of that step when `lattice` > 0:
/// lattice points sit on cell borders and at exact distances (3-4-5 and alike).
inline std::vector<Vehicle> randomVehicles(std::mt19937_64& rng, int n, double extent, double lattice = 0) {
    std::uniform_real_distribution<double> coordinate(-extent, extent);
    const int steps = lattice > 0 ? static_cast<int>(extent / lattice) : 0;
    std::uniform_int_distribution<int> step(-steps, steps);
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < n; ++k) {
        const double x = lattice > 0 ? lattice * step(rng) : coordinate(rng);
        const double y = lattice > 0 ? lattice * step(rng) : coordinate(rng);
        vehicles.push_back(car("v" + std::to_string(k), x, y));
    }
    return vehicles;
}

/// 600 vehicles in fifteen clusters tens of kilometres apart: far more cells than vehicles in the
/// bounding box.
inline std::vector<Vehicle> clustersFarApart() {
    std::mt19937_64 rng(99);
    std::normal_distribution<double> jitter(0, 15);
    std::vector<Vehicle> vehicles;
    for (int k = 0; k < 600; ++k) {
        const double cx = (k % 3) * 40'000.0 - 1e6;
        const double cy = (k % 5) * 25'000.0 + 3e5;
        vehicles.push_back(car("v" + std::to_string(k), cx + jitter(rng), cy + jitter(rng)));
    }
    return vehicles;
}

}  // namespace sbsim::traffic::test
