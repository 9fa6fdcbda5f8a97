#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/storyboard/ConditionArea.h"
#include "sbsim/storyboard/ConditionResult.h"
#include "sbsim/storyboard/EvaluationContext.h"
#include "sbsim/storyboard/TimeWindow.h"
#include "sbsim/storyboard/TypeName.h"

namespace sbsim::storyboard {

class CheckContext;
class Condition;
using ConditionPtr = std::shared_ptr<Condition>;

/// A node of a story's condition tree. A condition object may be shared by several stories (and
/// several places of one tree); it then shares its state, as in Artery. Per-vehicle state is keyed
/// by vehicle id and dropped by forget() when the vehicle leaves.
class SBSIM_API Condition {
public:
    virtual ~Condition() = default;

    /// Evaluates the condition for the ego vehicle at `ego` in ctx.snapshot().
    virtual ConditionResult test(const EvaluationContext& ctx, VehicleIndex ego) = 0;

    /// Called once per step, before any test() of that step (vectorised conditions work here).
    virtual void prepare(const EvaluationContext& /*ctx*/) {}
    /// The vehicle left the simulation: drop whatever is kept for it.
    virtual void forget(std::string_view /*vehicleId*/) {}
    /// How many vehicles this node keeps state for (a leak check: never more than are running).
    virtual std::size_t heldVehicles() const { return 0; }
    /// The radius (m) this condition searches neighbours in, if it uses the neighbour grid.
    virtual std::optional<double> neighbourRadius() const { return std::nullopt; }
    /// True if test() keeps no state and has no side effects, so it may run for any vehicle, in
    /// any order, on any thread (after prepare()). The board evaluates stories whose whole tree
    /// is pure for all vehicles in parallel; the others in Artery's order, one vehicle at a time.
    virtual bool pure() const { return false; }
    /// The snapshot values test() and prepare() read of any vehicle (children declare their own).
    /// The snapshot reads only what some node declared; a condition that cannot know (a Python
    /// one) reads everything, hence the default.
    virtual traffic::SnapshotColumns columns() const { return traffic::SnapshotColumns::all(); }
    /// Calls `visit` on each direct child (And/Or), so the board can reach every node of a tree.
    /// Const: children are shared objects of their own, not parts of this node.
    virtual void forEachChild(const std::function<void(Condition&)>& /*visit*/) const {}
    /// The class name messages show (a Python condition: its Python class's).
    virtual std::string typeName() const { return typeNameOf(typeid(*this)); }

    /// This node in one line, as `sbsim check` prints it: its class name and arguments, e.g.
    /// "TimeCondition(120 s, 420 s)" (children are printed below it, not in it).
    virtual std::string describe() const { return typeName(); }
    /// The place this node ties its story to (what the GUI, the report's map and `check --json`
    /// draw), if any.
    virtual std::optional<ConditionArea> area() const { return std::nullopt; }
    /// Whether test() depends on the time alone, never on the ego: what a WorldStory's tree may
    /// hold. Logic nodes answer from their children.
    virtual bool timeOnly() const { return false; }
    /// The times outside which this node is false for every vehicle, if it bounds them (a
    /// TimeCondition; a conjunction: the intersection of its operands' windows).
    virtual std::optional<TimeWindow> timeWindow() const { return std::nullopt; }
    /// Reports to `sbsim check` what looks wrong in this node itself (its children report their own).
    virtual void check(CheckContext& /*ctx*/) const {}

    /// The deepest a condition tree may be. Trees are evaluated, described (`check --json`) and
    /// destroyed (shared_ptr) recursively; a depth bounded when a node is built bounds the stack
    /// of all three. Far beyond any written story (Python's own recursion limit is 1000 too).
    static constexpr std::size_t kMaxDepth = 1000;
    /// The most nodes a tree may have, a node shared by several branches counted in each: a
    /// tree is evaluated branch by branch, so `c = AndCondition(c, c)` repeated 60 times would
    /// be 2^60 evaluations per vehicle, a hang without this bound.
    static constexpr std::size_t kMaxNodes = 1'000'000;
    /// Levels from this node down to its deepest leaf, itself included (a leaf: 1).
    std::size_t depth() const { return depth_; }
    /// Nodes of the tree under and including this node, shared ones counted each time (a leaf: 1).
    std::size_t nodes() const { return nodes_; }

protected:
    /// For a node's constructor, with its (non-null) children: sets depth() and nodes(), and throws
    /// std::invalid_argument naming `who` and the limit if the tree would pass kMaxDepth or kMaxNodes.
    void setDepthOver(std::string_view who, std::span<const ConditionPtr> children);

private:
    std::size_t depth_ = 1;
    std::size_t nodes_ = 1;
};

}  // namespace sbsim::storyboard
