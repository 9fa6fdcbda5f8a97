#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/trampoline_self_life_support.h>

#include <string>

#include "sbsim/storyboard/Criterion.h"

namespace sbsim::storyboard {

/// Trampoline for criteria written in Python: evaluate(self, run) at the end of the run, with
/// `run.events` (the event log's lines as dicts), `run.statistics` (per name: count, sum, mean,
/// min, max) and `run.activations` (per story); it returns a bool, or (passed, actual, expected).
class PythonCriterion : public Criterion, public pybind11::trampoline_self_life_support {
public:
    /// The script's class name.
    std::string describe() const override;
    bool needsEvents() const override { return true; }
    CriterionVerdict verdict(const CriterionRun& run) const override;
};

}  // namespace sbsim::storyboard
