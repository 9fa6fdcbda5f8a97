#pragma once

#include <cstddef>
#include <span>

#include "sbsim/kernel/Export.h"

namespace sbsim::radio {

/// A deterministic (mean) path-loss law: what a link loses over `distance` metres in free air,
/// before shadowing, fading and obstacles. Evaluated for every link of every transmission, so
/// implementations are small, const and thread-safe. Every law is a function of the distance
/// alone, so a link's loss is the same both ways.
class SBSIM_API PathLoss {
public:
    virtual ~PathLoss() = default;
    /// Loss in dB at `distance` m (> 0; distances below 1 m are taken as 1 m).
    virtual double lossDb(double distance) const = 0;
    /// lossDb at each of `distances` into `out` (as many), the same values: a sender's
    /// neighbourhood in one call instead of a virtual call per link.
    virtual void lossesDb(std::span<const double> distances, std::span<double> out) const {
        for (std::size_t k = 0; k < distances.size(); ++k) out[k] = lossDb(distances[k]);
    }
};

/// A law whose lossesDb calls Model::lossDb directly (inlined in the model's own .cpp, where its
/// vtable is emitted): derive as `class M : public BatchedPathLoss<M>`.
template <typename Model>
class BatchedPathLoss : public PathLoss {
public:
    void lossesDb(std::span<const double> distances, std::span<double> out) const final {
        const Model& model = static_cast<const Model&>(*this);
        for (std::size_t k = 0; k < distances.size(); ++k) out[k] = model.Model::lossDb(distances[k]);
    }
};

}  // namespace sbsim::radio
