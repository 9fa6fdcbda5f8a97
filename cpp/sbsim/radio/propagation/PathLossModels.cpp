#include "sbsim/radio/propagation/PathLossModels.h"

#include <stdexcept>
#include <utility>

namespace sbsim::radio {

namespace {
std::map<std::string, PathLossModels::Model, std::less<>>& table() {
    static std::map<std::string, PathLossModels::Model, std::less<>> models;
    return models;
}
std::vector<std::string>& conflictList() {
    static std::vector<std::string> names;
    return names;
}
}  // namespace

bool PathLossModels::add(const std::string& name, Keys defaults, Factory make) {
    if (!table().emplace(name, Model{std::move(defaults), std::move(make)}).second) conflictList().push_back(name);
    return true;
}

const std::map<std::string, PathLossModels::Model, std::less<>>& PathLossModels::all() { return table(); }

const std::vector<std::string>& PathLossModels::conflicts() { return conflictList(); }

std::set<std::string, std::less<>> PathLossModels::keys() {
    std::set<std::string, std::less<>> keys;
    for (const auto& [name, model] : table()) {
        for (const auto& [key, value] : model.defaults) keys.insert(key);
    }
    return keys;
}

std::string PathLossModels::names() {
    std::string text;
    std::size_t k = 0;
    for (const auto& [name, model] : table()) {
        if (k > 0) text += k + 1 == table().size() ? " or " : ", ";
        text += name;
        ++k;
    }
    return text;
}

std::unique_ptr<PathLoss> PathLossModels::make(std::string_view name, double frequencyHz, const Keys& set) {
    const auto it = table().find(name);
    if (it == table().end()) throw std::invalid_argument("must be " + names());
    Keys keys = it->second.defaults;
    for (auto& [key, value] : keys) {
        if (const auto given = set.find(key); given != set.end()) value = given->second;
    }
    return it->second.make(frequencyHz, keys);
}

}  // namespace sbsim::radio
