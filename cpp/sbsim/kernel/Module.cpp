#include "sbsim/kernel/Module.h"

#include <stdexcept>

namespace sbsim::kernel {

Module::~Module() = default;

Simulation& Module::simulation() const {
    if (simulation_ == nullptr) throw std::logic_error("module '" + name_ + "' is not part of a simulation");
    return *simulation_;
}

SimTime Module::simTime() const { return simulation().now(); }

void Module::handleMessage(Message& msg) {
    throw std::logic_error("module '" + name_ + "' received message '" + msg.name() + "' but does not handle messages");
}

void Module::scheduleAt(SimTime at, Message& msg) { simulation().schedule(msg, at, *this); }

void Module::cancelEvent(Message& msg) {
    if (msg.isScheduled()) simulation().futureEvents().remove(msg);
}

void Module::sendDirect(std::unique_ptr<Message> msg, SimTime delay, Module& target) {
    if (delay < SimTime::zero()) throw std::invalid_argument("negative delay for message '" + msg->name() + "'");
    simulation().schedule(std::move(msg), simTime() + delay, target);
}

}  // namespace sbsim::kernel
