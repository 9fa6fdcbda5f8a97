#pragma once

#include <memory>
#include <string>

#include "sbsim/storyboard/Condition.h"
#include "sbsim/storyboard/conditions/InternedVerdicts.h"

namespace re2 {
class RE2;
}

namespace sbsim::storyboard {

/// True if the ego's vehicle type id (the one it departed with, see VehicleSnapshot::typeId)
/// matches the regular expression as a whole (RE2 syntax, as the services file's type filter).
class TypeCondition : public Condition {
public:
    /// Throws std::invalid_argument for a pattern RE2 rejects, with its reason.
    explicit TypeCondition(const std::string& pattern);
    ~TypeCondition() override;

    traffic::SnapshotColumns columns() const override { return {traffic::SnapshotColumns::Type}; }
    ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) override;
    void prepare(const EvaluationContext& ctx) override;
    bool pure() const override { return true; }
    std::string describe() const override;
    const std::string& pattern() const { return pattern_; }

private:
    std::string pattern_;
    std::unique_ptr<re2::RE2> regex_;  // RE2 stays out of sbsim's public headers
    InternedVerdicts verdicts_;
};

}  // namespace sbsim::storyboard
