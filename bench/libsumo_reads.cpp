// What reading every vehicle's state through libsumo costs next to SUMO's own step (issue 28, the
// storyboard's floor). It loads a SUMO configuration, steps it, and after every step reads every
// running vehicle's values one of several ways; run it under callgrind once per mode and subtract
// the "none" count for the reads' instructions (the wall-clock figures it prints are a hint only).
//
//   g++ -O2 -std=c++20 bench/libsumo_reads.cpp -o build/libsumo_reads \
//       -I$SUMO_HOME/include -L$SUMO_HOME/lib64 -lsumocpp -Wl,-rpath,$SUMO_HOME/lib64
//   build/libsumo_reads MODE STEPS -c bench/out/bench1k/bench1k.sumocfg --step-length 0.1 \
//       --load-state bench/out/bench1k/state120.xml.gz --begin 120
//
// MODE: none (step only); getters (position, speed, angle: what the six stories read); floor
// (position, speed, road: the least a story on places and speeds reads); position (one getter);
// subscribe (a variable subscription of position, speed and angle per vehicle, its results taken
// each step); context (one context subscription around the first vehicle covering the network).
#include <libsumo/libsumo.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

double sink = 0;  // keeps the reads from being optimised away

void readGetters(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
        sink += p.x + p.y + libsumo::Vehicle::getSpeed(id) + libsumo::Vehicle::getAngle(id);
    }
}

void readFloor(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
        sink += p.x + p.y + libsumo::Vehicle::getSpeed(id) +
                static_cast<double>(libsumo::Vehicle::getRoadID(id).size());
    }
}

void readPosition(const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
        const libsumo::TraCIPosition p = libsumo::Vehicle::getPosition(id);
        sink += p.x + p.y;
    }
}

double valueOf(const libsumo::TraCIResults& results, int variable) {
    const auto it = results.find(variable);
    if (it == results.end()) return 0;
    if (const auto* d = dynamic_cast<const libsumo::TraCIDouble*>(it->second.get())) return d->value;
    if (const auto* p = dynamic_cast<const libsumo::TraCIPosition*>(it->second.get())) return p->x + p->y;
    return 0;
}

void takeResults(const libsumo::SubscriptionResults& all) {
    for (const auto& [id, results] : all) {
        sink += valueOf(results, libsumo::VAR_POSITION) + valueOf(results, libsumo::VAR_SPEED) +
                valueOf(results, libsumo::VAR_ANGLE);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: %s none|getters|floor|position|subscribe|context STEPS SUMO-OPTION...\n", argv[0]);
        return 2;
    }
    const std::string_view mode = argv[1];
    const int steps = std::atoi(argv[2]);
    std::vector<std::string> options{"--no-step-log", "true", "--no-warnings", "true"};
    options.insert(options.end(), argv + 3, argv + argc);
    libsumo::Simulation::load(options);
    const std::vector<int> variables{libsumo::VAR_POSITION, libsumo::VAR_SPEED, libsumo::VAR_ANGLE};

    using Clock = std::chrono::steady_clock;
    double stepping = 0;
    double reading = 0;
    long vehicleSteps = 0;
    bool contextSubscribed = false;
    for (int k = 0; k < steps; ++k) {
        const Clock::time_point a = Clock::now();
        libsumo::Simulation::step();
        const Clock::time_point b = Clock::now();
        const std::vector<std::string> ids = libsumo::Vehicle::getIDList();
        vehicleSteps += static_cast<long>(ids.size());
        if (mode == "getters") {
            readGetters(ids);
        } else if (mode == "floor") {
            readFloor(ids);
        } else if (mode == "position") {
            readPosition(ids);
        } else if (mode == "subscribe") {
            // Subscribed once per vehicle; SUMO fills the results in its next steps.
            for (const std::string& id : libsumo::Simulation::getDepartedIDList())
                libsumo::Vehicle::subscribe(id, variables);
            if (k == 0) {
                for (const std::string& id : ids) libsumo::Vehicle::subscribe(id, variables);
            }
            takeResults(libsumo::Vehicle::getAllSubscriptionResults());
        } else if (mode == "context") {
            if (!contextSubscribed && !ids.empty()) {
                libsumo::Vehicle::subscribeContext(ids.front(), libsumo::CMD_GET_VEHICLE_VARIABLE, 1e6, variables);
                contextSubscribed = true;
            }
            for (const auto& [ego, all] : libsumo::Vehicle::getAllContextSubscriptionResults()) takeResults(all);
        } else if (mode != "none") {
            std::fprintf(stderr, "unknown mode '%s'\n", argv[1]);
            return 2;
        }
        const Clock::time_point c = Clock::now();
        stepping += std::chrono::duration<double>(b - a).count();
        reading += std::chrono::duration<double>(c - b).count();
    }
    libsumo::Simulation::close();
    std::printf("mode %s: %d steps, %ld vehicle-steps, stepping %.3f s, reading %.3f s (%.1f %% of stepping), "
                "%.0f ns per vehicle-step (checksum %g)\n",
                argv[1], steps, vehicleSteps, stepping, reading, 100 * reading / stepping,
                1e9 * reading / static_cast<double>(std::max(vehicleSteps, 1L)), sink);
    return 0;
}
