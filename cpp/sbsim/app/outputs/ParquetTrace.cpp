#include "sbsim/app/outputs/ParquetTrace.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <variant>

#include "sbsim/app/cli/BadInput.h"

namespace sbsim::app {

namespace {
// The fixed columns, in this order (indices below).
enum Fixed : std::size_t {
    kT,
    kEvent,
    kType,
    kStation,
    kSender,
    kSeq,
    kBytes,
    kFrameBytes,
    kX,
    kY,
    kCbr,
    kDistance,
    kDelay,
    kPower,
    kSinr,
    kReason,
    kPhase,
    kAction,
    kCause,
    kSubcause,
    kState,
    kInterval,
    kSource,
    kHops,
    kNextHop,
    kMore,
    kFixed
};
/// How often (rows) the raw size of the row group is compared with what is left of the budget.
constexpr std::size_t kBudgetEvery = 256;
}  // namespace

ParquetTrace::ParquetTrace(std::unique_ptr<python::ParquetStream> stream, std::string what)
    : stream_(std::move(stream)), what_(std::move(what)) {
    const std::pair<const char*, Type> fixed[] = {
        {"t", Type::Float64},        {"event", Type::String},      {"type", Type::String},
        {"station", Type::String},   {"sender", Type::String},     {"seq", Type::Int64},
        {"bytes", Type::Int64},      {"frame_bytes", Type::Int64}, {"x", Type::Float64},
        {"y", Type::Float64},        {"cbr", Type::Float64},       {"distance", Type::Float64},
        {"delay", Type::Float64},    {"power_dbm", Type::Float64}, {"sinr_db", Type::Float64},
        {"reason", Type::String},    {"phase", Type::String},      {"action", Type::String},
        {"cause", Type::Int64},      {"subcause", Type::Int64},    {"state", Type::String},
        {"interval", Type::Float64}, {"source", Type::String},     {"hops", Type::Int64},
        {"next_hop", Type::String},  {"more", Type::String}};
    for (const auto& [name, type] : fixed) column(name, type);
}

std::size_t ParquetTrace::column(const std::string& name, Type type) {
    const std::size_t index = columns_.size();
    columns_.emplace_back(name, type);
    for (std::size_t k = 0; k < rows_; ++k) columns_.back().appendNull();  // rows before it was seen
    byName_.emplace(name, index);
    set_.push_back(0);
    return index;
}

void ParquetTrace::append(const TraceRecord& l) {
    using Event = TraceRecord::Event;
    std::fill(set_.begin(), set_.end(), 0);
    const auto put = [&](std::size_t i, const auto& value) {
        columns_[i].append(value);
        set_[i] = 1;
    };
    put(kT, l.t.seconds());
    put(kEvent, MessageTraceFilter::eventName(l.event));
    put(kStation, std::string_view(l.station));
    if (l.event == Event::Dcc) {
        put(kState, l.dccState);
        put(kCbr, l.cbr.value_or(0));
        put(kInterval, l.dccInterval);
    } else if (l.event == Event::Denm) {
        put(kPhase, l.phase);
        put(kAction, std::string_view(l.action));
        put(kCause, std::int64_t{l.cause});
    } else {
        put(kType, std::string_view(l.type));
        put(kSeq, static_cast<std::int64_t>(l.seq));
        if (l.event != Event::Tx) {
            put(kSender, std::string_view(l.sender));
            put(kDistance, l.distance);
        }
    }
    switch (l.event) {
        case Event::Tx:
            put(kBytes, static_cast<std::int64_t>(l.bytes));
            put(kFrameBytes, static_cast<std::int64_t>(l.frameBytes));
            put(kX, l.x);
            put(kY, l.y);
            if (l.cbr) put(kCbr, *l.cbr);
            break;
        case Event::Rx:
            put(kDelay, l.delay);
            if (l.powerDbm) put(kPower, *l.powerDbm);
            if (l.sinrDb) put(kSinr, *l.sinrDb);
            break;
        case Event::Lost:
            put(kReason, radio::lossReasonName(l.reason));
            break;
        case Event::Denm:
        case Event::Dcc:
            break;
    }
    if (l.geoBroadcast) {
        put(kSource, std::string_view(l.source));
        put(kHops, static_cast<std::int64_t>(l.hops));
        if (!l.nextHop.empty()) put(kNextHop, std::string_view(l.nextHop));
    }
    nlohmann::json more;
    for (const radio::TraceField& field : l.fields) {
        const Type type = std::holds_alternative<std::int64_t>(field.value) ? Type::Int64
                          : std::holds_alternative<double>(field.value)     ? Type::Float64
                                                                            : Type::String;
        auto it = byName_.find(field.name);
        // A new column only before the first row group: a Parquet file has one schema.
        if (it == byName_.end() && groups_ == 0) it = byName_.find(columns_[column(field.name, type)].name());
        if (it != byName_.end() && columns_[it->second].type() == type && !set_[it->second]) {
            std::visit(
                [&](const auto& v) {
                    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>) {
                        put(it->second, std::string_view(v));
                    } else {
                        put(it->second, v);
                    }
                },
                field.value);
        } else {
            std::visit([&](const auto& v) { more[field.name] = v; }, field.value);
        }
    }
    if (!more.is_null()) put(kMore, std::string_view(more.dump()));
    for (std::size_t i = 0; i < columns_.size(); ++i) {
        if (!set_[i]) columns_[i].appendNull();
    }
    ++rows_;
}

std::size_t ParquetTrace::rawBytes() const {
    std::size_t total = 0;
    for (const auto& c : columns_) total += c.bytes();
    return total;
}

std::uint64_t ParquetTrace::footerReserve() const {
    // The footer: the schema (pyarrow adds its own, ~2 kB) and per row group and column chunk
    // its offsets and statistics; generous, so that the file stays within the budget.
    return 4096 + (groups_ + 1) * columns_.size() * 160;
}

bool ParquetTrace::write(const TraceRecord& line, std::uint64_t budget) {
    if (full_ || finished_) return false;
    if (fileBytes_ + footerReserve() >= budget) {
        full_ = true;
        return false;
    }
    append(line);
    if (rows_ >= kRowsPerGroup || (rows_ % kBudgetEvery == 0 && fileBytes_ + footerReserve() + rawBytes() >= budget)) {
        flush();
        if (fileBytes_ + lastGroupBytes_ + footerReserve() > budget) full_ = true;
    }
    return true;
}

void ParquetTrace::flush() {
    try {
        const std::uint64_t before = fileBytes_;
        fileBytes_ = stream_->writeRowGroup(columns_);
        lastGroupBytes_ = fileBytes_ - before;
    } catch (const python::ParquetStream::WriteError& e) {
        throw OutputError(what_ + ": " + e.what());
    }
    ++groups_;
    for (auto& c : columns_) c.clear();
    rows_ = 0;
}

void ParquetTrace::finish() {
    if (finished_) return;
    finished_ = true;
    // A trace with no line still gets its schema: a reader finds the columns, no rows.
    if (rows_ > 0 || groups_ == 0) flush();
    try {
        fileBytes_ = stream_->close();
    } catch (const python::ParquetStream::WriteError& e) {
        throw OutputError(what_ + ": " + e.what());
    }
}

}  // namespace sbsim::app
