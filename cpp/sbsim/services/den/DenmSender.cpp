#include "sbsim/services/den/DenmSender.h"

#include "sbsim/services/Service.h"

namespace sbsim::services {

namespace {
/// A repetition timer names its event.
struct RepetitionTimer : kernel::Message {
    static constexpr int kKind = 0x4465'6e6d;
    explicit RepetitionTimer(facilities::ActionId a)
        : kernel::Message("denm repetition", kKind), action(std::move(a)) {}
    facilities::ActionId action;
};
}  // namespace

DenmSender::~DenmSender() {
    for (auto& [action, active] : active_) {
        if (active.timer) owner_.cancelEvent(*active.timer);
    }
}

facilities::ActionId DenmSender::requestActionId() { return {owner_.stationId(), ++sequence_}; }

void DenmSender::transmit(const facilities::DenmContent& denm) {
    owner_.send(std::make_unique<facilities::Denm>(denm));
    ++sent_;
}

void DenmSender::send(const facilities::DenmContent& denm, std::optional<Repetition> repetition) {
    const kernel::SimTime now = owner_.simTime();
    const bool update = sentEvents_.count(denm.action) != 0;
    sentEvents_[denm.action] = denm;
    transmit(denm);
    owner_.stations().report({now, update ? facilities::DenmPhase::Update : facilities::DenmPhase::New,
                              owner_.stationId(), denm.action, denm.cause});
    if (!repetition || repetition->interval <= kernel::SimTime::zero() ||
        repetition->interval >= repetition->duration) {
        return;
    }
    Active& active = active_[denm.action];
    if (active.timer) owner_.cancelEvent(*active.timer);
    active.denm = denm;
    active.repetition = *repetition;
    active.first = now;
    active.timer = std::make_unique<RepetitionTimer>(denm.action);
    owner_.scheduleAfter(repetition->interval, *active.timer);
}

bool DenmSender::handle(kernel::Message& msg) {
    if (msg.kind() != RepetitionTimer::kKind) return false;
    auto* timer = dynamic_cast<RepetitionTimer*>(&msg);
    if (timer == nullptr) return false;
    const auto it = active_.find(timer->action);
    if (it == active_.end()) return true;
    Active& active = it->second;
    transmit(active.denm);
    const kernel::SimTime next = owner_.simTime() + active.repetition.interval;
    if (next - active.first < active.repetition.duration) {
        owner_.scheduleAt(next, *active.timer);
    } else {
        active_.erase(it);  // the timer is not scheduled: it may go
    }
    return true;
}

bool DenmSender::terminate(const facilities::ActionId& action) {
    const auto last = sentEvents_.find(action);
    if (last == sentEvents_.end()) return false;
    facilities::DenmContent cancel = last->second;
    sentEvents_.erase(last);
    const auto it = active_.find(action);
    if (it != active_.end()) {
        if (it->second.timer) owner_.cancelEvent(*it->second.timer);
        active_.erase(it);
    }
    const kernel::SimTime now = owner_.simTime();
    cancel.referenceTime = now;
    cancel.termination = facilities::Termination::Cancellation;
    transmit(cancel);
    owner_.stations().report({now, facilities::DenmPhase::Terminate, owner_.stationId(), action, cancel.cause});
    return true;
}

}  // namespace sbsim::services
