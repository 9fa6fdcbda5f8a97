#include "sbsim/storyboard/ScenarioMachine.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sbsim::storyboard {

using kernel::SimTime;

namespace {

/// The kind an element of kind `k` has as its parent.
ScenarioMachine::Kind parentKind(ScenarioMachine::Kind k) {
    using K = ScenarioMachine::Kind;
    switch (k) {
        case K::story:
            return K::storyboard;
        case K::act:
            return K::story;
        case K::maneuverGroup:
            return K::act;
        case K::maneuver:
            return K::maneuverGroup;
        case K::event:
            return K::maneuver;
        case K::storyboard:
            break;
    }
    return K::storyboard;
}

const char* edgeName(ScenarioMachine::Edge e) {
    switch (e) {
        case ScenarioMachine::Edge::none:
            return "none";
        case ScenarioMachine::Edge::rising:
            return "rising";
        case ScenarioMachine::Edge::falling:
            return "falling";
        case ScenarioMachine::Edge::risingOrFalling:
            return "risingOrFalling";
    }
    return "none";
}

void checkTrigger(const ScenarioMachine::Trigger& trigger, const std::string& element) {
    for (const auto& group : trigger) {
        if (group.empty()) throw std::invalid_argument(element + ": a condition group without conditions");
        for (const auto& c : group) {
            if (!c.condition) throw std::invalid_argument(element + ": trigger condition '" + c.name + "' is null");
            if (!c.condition->timeOnly()) {
                throw std::invalid_argument(element + ": trigger condition '" + c.name + "' (" +
                                            c.condition->typeName() +
                                            ") looks at an ego vehicle; wrap it in an EntityCondition");
            }
            if (!std::isfinite(c.delay) || c.delay < 0) {
                throw std::invalid_argument(fmt::format("{}: trigger condition '{}' has delay {:g} s; it must be >= 0",
                                                        element, c.name, c.delay));
            }
        }
    }
}

}  // namespace

const char* ScenarioMachine::kindName(Kind k) {
    switch (k) {
        case Kind::storyboard:
            return "Storyboard";
        case Kind::story:
            return "Story";
        case Kind::act:
            return "Act";
        case Kind::maneuverGroup:
            return "ManeuverGroup";
        case Kind::maneuver:
            return "Maneuver";
        case Kind::event:
            return "Event";
    }
    return "?";
}

const char* ScenarioMachine::stateName(State s) {
    switch (s) {
        case State::standby:
            return "standbyState";
        case State::running:
            return "runningState";
        case State::complete:
            return "completeState";
    }
    return "?";
}

const char* ScenarioMachine::transitionName(Transition t) {
    switch (t) {
        case Transition::none:
            return "none";
        case Transition::start:
            return "startTransition";
        case Transition::end:
            return "endTransition";
        case Transition::stop:
            return "stopTransition";
        case Transition::skip:
            return "skipTransition";
    }
    return "?";
}

std::size_t ScenarioMachine::add(ElementSpec spec) {
    const std::string who = fmt::format("{} '{}'", kindName(spec.kind), spec.name);
    if (elements_.empty()) {
        if (spec.kind != Kind::storyboard || spec.parent) {
            throw std::invalid_argument(who + ": the first element must be the storyboard, without a parent");
        }
    } else {
        if (spec.kind == Kind::storyboard) throw std::invalid_argument(who + ": a second storyboard");
        if (!spec.parent || *spec.parent >= elements_.size()) {
            throw std::invalid_argument(who + ": its parent must be an element added before it");
        }
        if (elements_[*spec.parent].spec.kind != parentKind(spec.kind)) {
            throw std::invalid_argument(
                fmt::format("{}: its parent must be a {}, got {} '{}'", who, kindName(parentKind(spec.kind)),
                            kindName(elements_[*spec.parent].spec.kind), elements_[*spec.parent].spec.name));
        }
    }
    const bool triggered = spec.kind == Kind::act || spec.kind == Kind::event || spec.kind == Kind::storyboard;
    if (!triggered && !spec.start.empty())
        throw std::invalid_argument(who + ": only the storyboard, acts and events have a start trigger");
    if (spec.kind != Kind::act && spec.kind != Kind::storyboard && !spec.stop.empty()) {
        throw std::invalid_argument(who + ": only acts and the storyboard have a stop trigger");
    }
    if (spec.maxExecutions == 0) throw std::invalid_argument(who + ": maximumExecutionCount must be at least 1");
    if (spec.selectTriggeringEntities && spec.kind != Kind::maneuverGroup)
        throw std::invalid_argument(who + ": only a maneuver group selects triggering entities");
    checkTrigger(spec.start, who);
    checkTrigger(spec.stop, who);

    Element e;
    for (const auto& g : spec.start) e.startMemory.emplace_back(g.size());
    for (const auto& g : spec.stop) e.stopMemory.emplace_back(g.size());
    e.spec = std::move(spec);
    const std::size_t index = elements_.size();
    if (e.spec.parent) elements_[*e.spec.parent].children.push_back(index);
    elements_.push_back(std::move(e));
    return index;
}

void ScenarioMachine::addAction(std::size_t event, std::shared_ptr<const Effect> action) {
    Element& e = elements_.at(event);
    if (e.spec.kind != Kind::event) {
        throw std::invalid_argument(
            fmt::format("{} '{}': only an event has actions", kindName(e.spec.kind), e.spec.name));
    }
    if (!action) throw std::invalid_argument(fmt::format("Event '{}': a null action", e.spec.name));
    e.actions.push_back(std::move(action));
}

const ScenarioMachine::Element& ScenarioMachine::at(std::size_t element) const {
    if (element >= elements_.size()) throw std::out_of_range(fmt::format("no storyboard element {}", element));
    return elements_[element];
}

bool ScenarioMachine::transitionedAt(std::size_t element, Transition t, SimTime now) const {
    const Element& e = at(element);
    return e.transition == t && e.transitionTime == now;
}

void ScenarioMachine::prepare(const EvaluationContext& ctx) { prepared_ = &ctx; }

void ScenarioMachine::advance(const EvaluationContext& ctx) {
    const EvaluationContext& use = (prepared_ != nullptr && prepared_->now() == ctx.now()) ? *prepared_ : ctx;
    if (advanced_ && *advanced_ >= use.now()) return;
    step(use);
    advanced_ = use.now();
}

bool ScenarioMachine::parentRunning(const Element& e) const {
    if (!e.spec.parent) return !ended_;
    return elements_[*e.spec.parent].state == State::running;
}

void ScenarioMachine::move(Element& e, State to, Transition t) {
    e.state = to;
    e.transition = t;
    e.transitionTime = advanced_;  // set to the step's time by step() before any move
}

void ScenarioMachine::stopSubtree(std::size_t element) {
    Element& e = elements_[element];
    if (e.state == State::running) move(e, State::complete, Transition::stop);
    for (const std::size_t c : e.children) stopSubtree(c);
}

std::optional<std::size_t> ScenarioMachine::groupOf(std::size_t element) const {
    std::optional<std::size_t> e = element;
    while (e && elements_[*e].spec.kind != Kind::maneuverGroup) {
        const Kind k = elements_[*e].spec.kind;
        if (k != Kind::event && k != Kind::maneuver) return std::nullopt;
        e = elements_[*e].spec.parent;
    }
    return e;
}

bool ScenarioMachine::selectsTriggeringEntities(std::size_t element) const {
    at(element);
    const auto group = groupOf(element);
    return group && elements_[*group].spec.selectTriggeringEntities;
}

const std::vector<std::string>& ScenarioMachine::selectedActors(std::size_t element) const {
    static const std::vector<std::string> none;
    if (!selectsTriggeringEntities(element)) return none;
    return elements_[*elements_[*groupOf(element)].spec.parent].triggeredBy;  // its Act's
}

void ScenarioMachine::resetSubtree(std::size_t element) {
    Element& e = elements_[element];
    e.state = State::standby;
    e.transition = Transition::none;
    e.transitionTime.reset();
    e.started.reset();
    e.executions = 0;
    e.triggeredBy.clear();
    for (auto& group : e.startMemory) std::fill(group.begin(), group.end(), ConditionMemory{});
    for (auto& group : e.stopMemory) std::fill(group.begin(), group.end(), ConditionMemory{});
    for (const std::size_t c : e.children) resetSubtree(c);
}

bool ScenarioMachine::fires(const Trigger& trigger, std::vector<std::vector<ConditionMemory>>& memory,
                            const EvaluationContext& ctx, VehicleIndex ego, std::vector<std::string>* entities) {
    const SimTime now = ctx.now();
    bool any = false;
    std::vector<std::string> groupEntities;
    // Every condition is evaluated every step its element waits, so edges and delays see each
    // step (no short-circuit across conditions).
    for (std::size_t g = 0; g < trigger.size(); ++g) {
        bool all = true;
        groupEntities.clear();
        for (std::size_t c = 0; c < trigger[g].size(); ++c) {
            const TriggerCondition& tc = trigger[g][c];
            ConditionMemory& m = memory[g][c];
            if (m.evaluated != previous_) m.last = false;  // not evaluated at the step before
            const ConditionResult result = tc.condition->test(ctx, ego);
            const bool value = result.isTrue();
            bool edged = false;
            switch (tc.edge) {
                case Edge::none:
                    edged = value;
                    break;
                case Edge::rising:
                    edged = value && !m.last;
                    break;
                case Edge::falling:
                    edged = !value && m.last;
                    break;
                case Edge::risingOrFalling:
                    edged = value != m.last;
                    break;
            }
            m.last = value;
            m.evaluated = now;
            // The entities a true result holds for (its others), as the snapshot names them.
            std::vector<std::string> held;
            if (edged && value) {
                for (const VehicleIndex o : result.others()) held.push_back(ctx.snapshot().ids()[o]);
            }
            bool seen = edged;
            if (tc.delay > 0) {
                if (edged) m.pending.emplace_back(now + SimTime::fromSeconds(tc.delay), std::move(held));
                seen = false;
                held.clear();
                while (!m.pending.empty() && m.pending.front().first <= now) {
                    held = std::move(m.pending.front().second);
                    m.pending.pop_front();
                    seen = true;
                }
            }
            all = all && seen;
            if (seen) groupEntities.insert(groupEntities.end(), held.begin(), held.end());
        }
        any = any || all;
        if (all && entities != nullptr) entities->insert(entities->end(), groupEntities.begin(), groupEntities.end());
    }
    return any;
}

void ScenarioMachine::step(const EvaluationContext& given) {
    const SimTime now = given.now();
    advanced_ = now;
    // With no vehicle running, conditions are evaluated on a one-row snapshot (id ""), as a
    // WorldStory's are: an EntityCondition finds no entity there, a TimeCondition the time.
    const EvaluationContext* ctx = &given;
    std::optional<EvaluationContext> world;
    if (given.snapshot().size() == 0) {
        empty_.assign({traffic::VehicleSnapshot::Vehicle{}}, now);
        emptyGrid_.build(empty_, 100);
        world.emplace(empty_, emptyGrid_);
        ctx = &*world;
    }
    const VehicleIndex ego = 0;

    for (std::size_t i = 0; i < elements_.size(); ++i) {
        Element& e = elements_[i];
        const bool justMoved = e.transitionTime == now;
        // A start trigger is evaluated every step its element may start again (running included),
        // so that its edges compare consecutive steps; it acts only on an element in standby.
        const bool triggered =
            e.spec.kind == Kind::act || e.spec.kind == Kind::event || e.spec.kind == Kind::storyboard;
        bool fired = !triggered || e.spec.start.empty();
        std::vector<std::string> firing;  // the entities that fired it
        if (triggered && !e.spec.start.empty() && e.state != State::complete && parentRunning(e)) {
            fired = fires(e.spec.start, e.startMemory, *ctx, ego, &firing);
        }
        if (e.state == State::running) {
            if (!parentRunning(e)) {
                stopSubtree(i);
                continue;
            }
            if (!e.spec.stop.empty() && fires(e.spec.stop, e.stopMemory, *ctx, ego)) {
                stopSubtree(i);
                if (e.spec.kind == Kind::storyboard && !ended_) {
                    ended_ = true;
                    if (onEnd_) onEnd_();
                }
                continue;
            }
            const auto complete = [](const std::shared_ptr<const Effect>& a) { return a->complete(); };
            if (e.spec.kind == Kind::event && e.started && *e.started < now &&
                std::all_of(e.actions.begin(), e.actions.end(), complete)) {
                move(e, e.executions < e.spec.maxExecutions ? State::standby : State::complete, Transition::end);
            }
            continue;
        }
        if (e.state != State::standby || justMoved || !parentRunning(e)) continue;
        if (!fired) continue;
        if (e.spec.kind == Kind::event && e.spec.priority != Priority::parallel) {
            const Element& maneuver = elements_[*e.spec.parent];
            bool siblingRuns = false;
            for (const std::size_t s : maneuver.children) {
                if (s != i && elements_[s].state == State::running) siblingRuns = true;
            }
            if (siblingRuns && e.spec.priority == Priority::skip) {
                move(e, State::standby, Transition::skip);
                continue;
            }
            if (siblingRuns) {  // overwrite
                for (const std::size_t s : maneuver.children) {
                    if (s != i) stopSubtree(s);
                }
            }
        }
        move(e, State::running, Transition::start);
        e.started = now;
        ++e.executions;
        std::sort(firing.begin(), firing.end());
        firing.erase(std::unique(firing.begin(), firing.end()), firing.end());
        e.triggeredBy = std::move(firing);
    }
    // Completions bottom up: children come after their parent, so a reverse pass sees a
    // maneuver's events before the maneuver.
    for (std::size_t i = elements_.size(); i-- > 0;) {
        Element& e = elements_[i];
        if (e.state != State::running || e.spec.kind == Kind::event || e.spec.kind == Kind::storyboard) continue;
        const bool allComplete = std::all_of(e.children.begin(), e.children.end(),
                                             [this](std::size_t c) { return elements_[c].state == State::complete; });
        if (!allComplete) continue;
        if (e.spec.kind == Kind::maneuverGroup && e.executions < e.spec.maxExecutions) {
            // Again from the next step: its maneuvers and events as new.
            move(e, State::standby, Transition::end);
            for (const std::size_t c : e.children) resetSubtree(c);
        } else {
            move(e, State::complete, Transition::end);
        }
    }
    previous_ = now;
}

void ScenarioMachine::forEachCondition(std::size_t element, const std::function<void(Condition&)>& visit) const {
    const Element& e = at(element);
    for (const Trigger* t : {&e.spec.start, &e.spec.stop}) {
        for (const auto& g : *t) {
            for (const auto& c : g) visit(*c.condition);
        }
    }
}

std::string ScenarioMachine::describeTriggers(std::size_t element) const {
    const Element& e = at(element);
    std::string out;
    const auto one = [](const Trigger& t) {
        std::string s;
        for (std::size_t g = 0; g < t.size(); ++g) {
            if (g > 0) s += " or ";
            s += "(";
            for (std::size_t c = 0; c < t[g].size(); ++c) {
                if (c > 0) s += " and ";
                s += t[g][c].name;
                if (t[g][c].edge != Edge::none) s += fmt::format(" {}", edgeName(t[g][c].edge));
                if (t[g][c].delay > 0) s += fmt::format(" after {:g} s", t[g][c].delay);
            }
            s += ")";
        }
        return s;
    };
    if (!e.spec.start.empty()) out += "start " + one(e.spec.start);
    if (!e.spec.stop.empty()) out += std::string(out.empty() ? "" : "; ") + "stop " + one(e.spec.stop);
    return out;
}

}  // namespace sbsim::storyboard
