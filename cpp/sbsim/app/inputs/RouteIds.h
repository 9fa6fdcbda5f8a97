#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace sbsim::app {

/// The vehicle ids and vehicle types the route files define: <vehicle>/<trip> ids, and <flow> ids
/// as prefixes of the "<flow>.<n>" ids SUMO gives a flow's vehicles. The files are read at the first
/// question (a city's route files are large; most runs never ask). A file that does not parse adds
/// nothing (SUMO itself reported it when it loaded).
class RouteIds {
public:
    explicit RouteIds(std::vector<std::filesystem::path> files) : files_(std::move(files)) {}

    /// Whether a route file defines this vehicle (or the flow it belongs to).
    bool defines(std::string_view id) const;
    /// Whether a route file defines this vehicle type (SUMO reads a route file's types only as it
    /// reaches them).
    bool definesType(std::string_view id) const;

private:
    void read() const;

    std::vector<std::filesystem::path> files_;
    mutable bool read_ = false;
    mutable std::set<std::string, std::less<>> ids_;
    mutable std::set<std::string, std::less<>> types_;
    mutable std::set<std::string, std::less<>> flows_;
};

}  // namespace sbsim::app
