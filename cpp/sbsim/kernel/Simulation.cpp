#include "sbsim/kernel/Simulation.h"

#include <algorithm>
#include <stdexcept>

#include "sbsim/kernel/Module.h"
#include "sbsim/kernel/StopRequest.h"

namespace sbsim::kernel {

Simulation::Simulation(std::uint64_t seed, unsigned threads) : seed_(seed), parallel_(threads) {}

std::shared_ptr<RandomStream> Simulation::randomStream(unsigned index) {
    std::shared_ptr<RandomStream>& stream = streams_[index];
    if (!stream) stream = std::make_shared<RandomStream>(seed_, index);
    return stream;
}

Simulation::~Simulation() {
    // The events go first, all in one pass (one removeAllFor() per module walked the whole set once
    // per module, quadratic in the modules); then the modules, newest first, while the event set and
    // signal tables they refer to still exist.
    fes_.clear();
    while (!modules_.empty()) modules_.pop_back();
}

Module& Simulation::addModule(std::unique_ptr<Module> module) {
    if (!module) throw std::invalid_argument("null module");
    if (module->simulation_ != nullptr) throw std::logic_error("module '" + module->name() + "' already added");
    module->simulation_ = this;
    Module& m = *module;
    modules_.push_back(std::move(module));
    ++moduleChanges_;
    if (initialized_ && !finished_) {
        m.initialized_ = true;
        try {
            m.initialize();
        } catch (...) {
            m.failed();
        }
    }
    return m;
}

void Simulation::removeModule(Module& module) {
    const auto it = std::find_if(modules_.begin(), modules_.end(), [&](const auto& p) { return p.get() == &module; });
    if (it == modules_.end()) throw std::logic_error("module '" + module.name() + "' is not part of this simulation");
    if (module.initialized_ && !finished_) {
        try {
            module.finish();
        } catch (...) {
            module.failed();
        }
    }
    fes_.removeAllFor(module);
    modules_.erase(it);
    ++moduleChanges_;
}

void Simulation::startAt(SimTime begin) {
    if (events_ > 0) throw std::logic_error("the simulation's start time is set before its first event");
    if (!fes_.empty() && fes_.peek().arrivalTime() < begin) {
        throw std::logic_error("message '" + fes_.peek().name() + "' is scheduled before the start time " +
                               begin.str() + " s");
    }
    now_ = begin;
}

void Simulation::initialize() {
    if (initialized_) return;
    initialized_ = true;
    // Index loop: initialize() may add modules, which are then initialized by addModule.
    const std::size_t n = modules_.size();
    for (std::size_t i = 0; i < n; ++i) {
        Module& m = *modules_[i];
        if (!m.initialized_) {
            m.initialized_ = true;
            try {
                m.initialize();
            } catch (...) {
                m.failed();
            }
        }
    }
}

Simulation::StopReason Simulation::run(SimTime limit) {
    initialize();
    // The request is used up when honoured, not reset on entry: a stop() from initialize() (say, an
    // end time before the first SUMO step) must end this run before any event.
    while (true) {
        // The program's stop request (SIGINT, SIGTERM) too, between any two events: events that
        // keep coming at one instant (a timer of period 0) would otherwise never reach a step's end,
        // where the program asks for the stop.
        if (stopRequested_ || StopRequest::requested()) {
            stopRequested_ = false;
            return StopReason::Requested;
        }
        if (fes_.empty()) return StopReason::NoMoreEvents;
        if (fes_.peekTime() > limit) return StopReason::TimeLimit;
        std::unique_ptr<Message> owned;
        Message& msg = fes_.pop(owned);
        now_ = msg.arrivalTime();
        ++events_;
        Module& target = *msg.arrivalModule();
        try {
            target.handleMessage(msg);
        } catch (...) {
            target.failed();
        }
    }
}

void Simulation::finish() {
    if (finished_) return;
    finished_ = true;
    for (const auto& m : modules_) {
        if (!m->initialized_) continue;
        try {
            m->finish();
        } catch (...) {
            m->failed();
        }
    }
}

void Simulation::schedule(Message& msg, SimTime at, Module& target) {
    if (at < now_) {
        throw std::logic_error("message '" + msg.name() + "' scheduled in the past (" + at.str() + " s < " +
                               now_.str() + " s)");
    }
    fes_.insert(msg, at, &target);
}

void Simulation::schedule(std::unique_ptr<Message> msg, SimTime at, Module& target) {
    if (at < now_) {
        throw std::logic_error("message '" + msg->name() + "' scheduled in the past (" + at.str() + " s < " +
                               now_.str() + " s)");
    }
    fes_.insert(std::move(msg), at, &target);
}

}  // namespace sbsim::kernel
