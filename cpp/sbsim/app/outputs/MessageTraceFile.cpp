#include "sbsim/app/outputs/MessageTraceFile.h"

#include <fmt/format.h>

#include <cstdio>

namespace sbsim::app {

MessageTraceFile::MessageTraceFile(std::unique_ptr<TraceWriter> writer, MessageTraceFilter filter,
                                   std::uint64_t maxBytes)
    : writer_(std::move(writer)), filter_(std::move(filter)), maxBytes_(maxBytes) {}

void MessageTraceFile::emit(const TraceRecord& record) {
    if (truncatedAt_) return;
    if (writer_->write(record, maxBytes_)) {
        ++lines_;
        return;
    }
    truncatedAt_ = record.t;
    std::fprintf(stderr,
                 "sbsim: warning: --messages: the trace reached --messages-max-bytes (%llu bytes) at t=%s s; the "
                 "run goes on without tracing\n",
                 static_cast<unsigned long long>(maxBytes_), truncatedAt_->str().c_str());
    std::fflush(stderr);
}

void MessageTraceFile::writeUpTo(kernel::SimTime now) {
    while (!pending_.empty() && pending_.top().t <= now) {
        emit(*pending_.top().record);
        pending_.pop();
    }
    if (truncatedAt_) pending_ = {};  // nothing waiting will be written
}

void MessageTraceFile::record(const radio::TraceLine& line, kernel::SimTime now) {
    if (truncatedAt_ || !filter_.keeps(TraceRecord::eventOf(line.event), line.message->typeName())) return;
    // Nothing reported later can be earlier than now, so what waits up to now can go.
    writeUpTo(now);
    if (line.t <= now && pending_.empty()) {
        emit(TraceRecord::of(line));
        return;
    }
    pending_.push({line.t, order_++, std::make_unique<TraceRecord>(TraceRecord::of(line))});
    writeUpTo(now);
}

void MessageTraceFile::denmPhase(const facilities::DenmPhaseEvent& event) {
    if (truncatedAt_ || !filter_.keeps(MessageTraceFilter::Event::Denm, "DENM")) return;
    writeUpTo(event.time);
    emit(TraceRecord::of(event));
}

void MessageTraceFile::dccChanged(const radio::DccChange& change) {
    if (truncatedAt_ || !filter_.keeps(MessageTraceFilter::Event::Dcc)) return;
    writeUpTo(change.t);
    emit(TraceRecord::of(change));
}

void MessageTraceFile::finish(kernel::SimTime end) {
    writeUpTo(end);
    pending_ = {};
    writer_->finish();
}

TraceFigures MessageTraceFile::figures() const {
    return {writer_->format(), lines_, writer_->bytes(), maxBytes_, truncatedAt_};
}

}  // namespace sbsim::app
