#include "sbsim/app/outputs/Summary.h"

#include <fmt/format.h>

#include "sbsim/app/run/Interruption.h"
#include "sbsim/kernel/OneLine.h"
#include "sbsim/kernel/StudyParameters.h"

#include <variant>

namespace sbsim::app {

namespace {

const char* endReasonText(traffic::SumoBridge::EndReason r) {
    switch (r) {
        case traffic::SumoBridge::EndReason::EndTime:
            return "end time reached";
        case traffic::SumoBridge::EndReason::NoMoreVehicles:
            return "no more vehicles expected";
        case traffic::SumoBridge::EndReason::Running:
            break;
    }
    return "stopped";
}

double meanReceivers(const radio::Medium::Counts& c) {
    const std::uint64_t frames = c.sent + c.forwarded;
    return frames == 0 ? 0.0 : static_cast<double>(c.delivered) / static_cast<double>(frames);
}

/// Distance bins (of 50 m) the text summary shows; the JSON has them all.
constexpr std::size_t kSummaryBins = 20;
/// Equipped vehicles the text summary names; the JSON names them all.
constexpr std::size_t kSummaryEquipped = 10;

/// "12 of 40 (penetration 0.3): a at t=0 s, b at t=1.5 s and 10 more".
std::string equippedLine(const traffic::EquippedVehicles& e) {
    const auto& list = e.equipped();
    std::string out = fmt::format("{} of {} (penetration {:g})", list.size(), e.seen(), e.penetration().share());
    for (std::size_t k = 0; k < list.size() && k < kSummaryEquipped; ++k) {
        out += fmt::format("{}{} at t={} s", k == 0 ? ": " : ", ", kernel::escapeControls(list[k].vehicle),
                           list[k].since.str());
    }
    if (list.size() > kSummaryEquipped) out += fmt::format(" and {} more", list.size() - kSummaryEquipped);
    return out;
}

}  // namespace

void printSummary(const RunFigures& f) {
    fmt::print("sbsim {}: {}\n", SBSIM_VERSION, f.sumocfg.filename().string());
    fmt::print("end: {} s ({})\n", f.sim.now().str(),
               Interruption::requested() ? "interrupted" : endReasonText(f.sumo.endReason()));
    fmt::print("steps: {}\n", f.sumo.steps());
    fmt::print("vehicles seen: {}\n", f.sumo.vehiclesSeen());
    fmt::print("peak running: {}\n", f.sumo.peakRunning());
    fmt::print("seed: {}\n", f.sim.seed());
    for (const auto& [name, value] : f.sim.parameters().all()) {
        fmt::print("parameter {}: {}\n", name, kernel::StudyParameters::format(value));
    }
    if (f.board != nullptr) {
        for (const auto& story : f.board->stories()) {
            fmt::print("activations {}: {}\n", kernel::escapeControls(story->name()), story->counters().activations());
        }
    }
    if (f.services != nullptr) {
        fmt::print("services created: {}\n", f.services->servicesCreated());
        if (f.equipped != nullptr) fmt::print("equipped vehicles: {}\n", equippedLine(*f.equipped));
        if (f.services->roadsideUnits() > 0) fmt::print("roadside units: {}\n", f.services->roadsideUnits());
        if (f.obstacles != nullptr)
            fmt::print("obstacles: {} (polygon type '{}')\n", f.obstacles->count, f.obstacles->polygonType);
        if (f.obstacles != nullptr && f.obstacles->model && f.obstacles->count > 0)
            fmt::print("obstacle links: {} evaluated\n", f.obstacles->model->linksEvaluated());
        if (f.services->signalsWithoutServices() > 0)
            fmt::print("signals without services: {}\n", f.services->signalsWithoutServices());
        for (const auto& [type, counts] : f.medium->counts()) {
            if (counts.forwarded > 0) {
                fmt::print("messages {}: sent {}, forwarded {}, delivered {}\n", type, counts.sent, counts.forwarded,
                           counts.delivered);
            } else {
                fmt::print("messages {}: sent {}, delivered {}\n", type, counts.sent, counts.delivered);
            }
            fmt::print("mean receivers {}: {:.2f}\n", type, meanReceivers(counts));
            if (!counts.linkStations.empty()) {
                std::string ratios;
                for (std::size_t k = 0; k < counts.linkStations.size() && k < kSummaryBins; ++k) {
                    if (counts.linkStations[k] == 0) continue;
                    ratios += fmt::format("{}{}: {:.3f}", ratios.empty() ? "" : ", ", k * 50,
                                          static_cast<double>(counts.linkReceptions[k]) / counts.linkStations[k]);
                }
                fmt::print("delivery ratio {} by metres: {}\n", type, ratios);
            }
        }
        if (const auto load = f.medium->loadFigures())
            fmt::print("channel busy ratio: mean {:.4f}, max {:.4f}\n", load->meanCbr, load->maxCbr);
        if (const auto links = f.medium->linkFigures()) {
            fmt::print("links: {} drawn in full, {} interference only, {} skipped below the floor\n", links->full,
                       links->interference, links->skipped);
        }
    }
    if (f.messageTrace && f.messageTrace->truncatedAt) {
        fmt::print("message trace: truncated at t={} s (--messages-max-bytes {})\n", f.messageTrace->truncatedAt->str(),
                   f.messageTrace->maxBytes);
    }
    if (f.statistics != nullptr) {
        for (const auto& [name, a] : f.statistics->aggregates()) {
            fmt::print("statistic {}: count {}, mean {:g}, min {:g}, max {:g}, sum {:g}\n", name, a.count, a.mean(),
                       a.min, a.max, a.sum);
        }
    }
    for (const auto& [name, v] : f.verdicts) {
        fmt::print("criterion {}: {} (actual: {}; expected: {})\n", name, v.passed ? "passed" : "FAILED", v.actual,
                   v.expected);
    }
    if (const std::size_t warnings = f.sumo.warnings().total(); warnings > 0) {
        const auto kinds = f.sumo.warnings().kinds();
        fmt::print("sumo warnings: {} of {} kind{}, most: {} × {}\n", warnings, kinds.size(),
                   kinds.size() == 1 ? "" : "s", kinds.front().count, kinds.front().pattern);
    }
    const double simulated = (f.sim.now() - f.sumo.beginTime()).seconds();
    fmt::print("wall time: {:.3f} s\n", f.wall);
    fmt::print("time in sumo: {:.3f} s\n", f.sumo.sumoSeconds());
    fmt::print("time reading vehicles: {:.3f} s\n", f.sumo.snapshotSeconds());
    if (f.board != nullptr) fmt::print("time in storyboard: {:.3f} s\n", f.board->updateSeconds());
    fmt::print("real-time factor: {:.1f}\n", f.wall > 0 ? simulated / f.wall : 0.0);
}

nlohmann::ordered_json summaryJson(const RunFigures& f) {
    using nlohmann::ordered_json;
    ordered_json out;
    out["sbsim"] = SBSIM_VERSION;
    out["sumo"] = f.sumo.sumoVersion();
    out["command"] = f.arguments;
    out["sumocfg"] = f.sumocfg.string();
    out["seed"] = f.sim.seed();
    ordered_json parameters = ordered_json::object();
    for (const auto& [name, value] : f.sim.parameters().all()) {
        std::visit([&](const auto& v) { parameters[name] = v; }, value);
    }
    out["parameters"] = std::move(parameters);
    out["end"] = {{"time", f.sim.now().seconds()},
                  {"reason", Interruption::requested() ? "interrupted" : endReasonText(f.sumo.endReason())}};
    out["steps"] = f.sumo.steps();
    out["vehicles_seen"] = f.sumo.vehiclesSeen();
    out["peak_running"] = f.sumo.peakRunning();
    ordered_json stories = ordered_json::array();
    if (f.board != nullptr) {
        for (const auto& story : f.board->stories()) {
            stories.push_back({{"name", story->name()},
                               {"activations", story->counters().activations()},
                               {"active_vehicle_seconds", story->counters().activeVehicleSeconds()}});
        }
    }
    out["stories"] = std::move(stories);
    ordered_json signals = ordered_json::object();
    if (f.board != nullptr) {
        for (const auto& [cause, count] : f.board->signalsByCause()) signals[cause] = count;
    }
    out["signals"] = std::move(signals);
    ordered_json messages = ordered_json::object();
    if (f.services != nullptr) {
        out["services_created"] = f.services->servicesCreated();
        if (f.equipped != nullptr) {
            ordered_json vehicles = ordered_json::array();
            for (const auto& entry : f.equipped->equipped())
                vehicles.push_back({{"vehicle", entry.vehicle}, {"since", entry.since.seconds()}});
            out["equipped"] = {{"penetration", f.equipped->penetration().share()},
                               {"count", f.equipped->equipped().size()},
                               {"of", f.equipped->seen()},
                               {"vehicles", std::move(vehicles)}};
        }
        if (f.services->roadsideUnits() > 0) out["roadside_units"] = f.services->roadsideUnits();
        if (f.obstacles != nullptr)
            out["obstacles"] = {{"polygon_type", f.obstacles->polygonType}, {"count", f.obstacles->count}};
        if (f.obstacles != nullptr && f.obstacles->model && f.obstacles->count > 0)
            out["obstacle_links"] = f.obstacles->model->linksEvaluated();
        out["signals_without_services"] = f.services->signalsWithoutServices();
        for (const auto& [type, counts] : f.medium->counts()) {
            ordered_json bins = ordered_json::array();
            for (std::size_t k = 0; k < counts.linkStations.size(); ++k) {
                if (counts.linkStations[k] == 0) continue;
                bins.push_back({{"from_m", k * 50},
                                {"stations", counts.linkStations[k]},
                                {"received", counts.linkReceptions[k]},
                                {"ratio", static_cast<double>(counts.linkReceptions[k]) / counts.linkStations[k]}});
            }
            messages[type] = {{"sent", counts.sent},
                              {"delivered", counts.delivered},
                              {"mean_receivers", meanReceivers(counts)},
                              {"delivery_ratio", std::move(bins)}};
            if (counts.forwarded > 0) messages[type]["forwarded"] = counts.forwarded;
        }
        if (const auto load = f.medium->loadFigures())
            out["channel_busy_ratio"] = {{"mean", load->meanCbr}, {"max", load->maxCbr}, {"samples", load->samples}};
        if (const auto links = f.medium->linkFigures()) {
            out["links"] = {{"full", links->full}, {"interference", links->interference}, {"skipped", links->skipped}};
        }
    }
    out["messages"] = std::move(messages);
    if (f.messageTrace) {
        const TraceFigures& t = *f.messageTrace;
        out["message_trace"] = {
            {"format", std::string(t.format)},
            {"lines", t.lines},
            {"bytes", t.bytes},
            {"max_bytes", t.maxBytes == UINT64_MAX ? ordered_json(nullptr) : ordered_json(t.maxBytes)},
            {"truncated", t.truncatedAt.has_value()},
            {"truncated_at", t.truncatedAt ? ordered_json(t.truncatedAt->seconds()) : ordered_json(nullptr)}};
    }
    ordered_json statistics = ordered_json::object();
    if (f.statistics != nullptr) {
        for (const auto& [name, a] : f.statistics->aggregates()) {
            statistics[name] = {{"count", a.count}, {"sum", a.sum}, {"mean", a.mean()}, {"min", a.min}, {"max", a.max}};
        }
    }
    out["statistics"] = std::move(statistics);
    ordered_json criteria = ordered_json::array();
    bool allPassed = true;
    for (const auto& [name, v] : f.verdicts) {
        criteria.push_back({{"name", name}, {"passed", v.passed}, {"actual", v.actual}, {"expected", v.expected}});
        allPassed = allPassed && v.passed;
    }
    out["criteria"] = std::move(criteria);
    // null: no criteria, so no verdict.
    out["verdict"] = f.verdicts.empty() ? ordered_json(nullptr) : ordered_json(allPassed ? "passed" : "failed");
    ordered_json warningKinds = ordered_json::array();
    for (const auto& kind : f.sumo.warnings().kinds()) {
        warningKinds.push_back({{"kind", kind.pattern}, {"count", kind.count}});
    }
    out["sumo_warnings"] = {{"total", f.sumo.warnings().total()}, {"kinds", std::move(warningKinds)}};
    // Per-vehicle state still held when the run ended: a leak shows as more than are running.
    out["held_at_end"] = {{"running", f.sumo.snapshot().size()},
                          {"storyboard_vehicles", f.board != nullptr ? f.board->vehicleStates() : 0},
                          {"condition_vehicles_max", f.board != nullptr ? f.board->maxConditionStates() : 0},
                          {"middlewares", f.services != nullptr ? f.services->middlewares() : 0}};
    const double simulated = (f.sim.now() - f.sumo.beginTime()).seconds();
    out["timing"] = {{"wall_s", f.wall},
                     {"sumo_s", f.sumo.sumoSeconds()},
                     {"reading_vehicles_s", f.sumo.snapshotSeconds()},
                     {"storyboard_s", f.board != nullptr ? f.board->updateSeconds() : 0.0},
                     {"real_time_factor", f.wall > 0 ? simulated / f.wall : 0.0}};
    return out;
}

}  // namespace sbsim::app
