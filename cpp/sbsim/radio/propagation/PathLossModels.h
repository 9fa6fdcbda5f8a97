#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/radio/propagation/PathLoss.h"

namespace sbsim::radio {

/// The path-loss models a radio file can name (`[propagation] path_loss = "NAME"`), by name. Each
/// model registers itself once in its own .cpp, with the [propagation] keys it reads and their
/// defaults, and a factory:
///
///     [[maybe_unused]] const bool registered = PathLossModels::add(
///         "free-space", {}, [](double frequencyHz, const PathLossModels::Keys&) { ... });
///
/// The radio file accepts every registered key whichever model it names, so a key two models
/// read (antenna_height) is one setting.
class SBSIM_API PathLossModels {
public:
    /// Key → value (at registration: the default).
    using Keys = std::map<std::string, double, std::less<>>;
    /// Builds the model at the carrier frequency from its keys (every one it declared, set or
    /// default); throws std::invalid_argument naming a value out of range.
    using Factory = std::function<std::unique_ptr<PathLoss>(double frequencyHz, const Keys& keys)>;
    struct Model {
        Keys defaults;
        Factory make;
    };

    /// Registers `name`; a second model of the same name is kept out and noted (registration runs
    /// while the library loads, where an exception would abort the program): see conflicts().
    static bool add(const std::string& name, Keys defaults, Factory make);
    static const std::map<std::string, Model, std::less<>>& all();
    /// Names registered twice (none in a sound build).
    static const std::vector<std::string>& conflicts();
    /// Every key some model reads, in name order.
    static std::set<std::string, std::less<>> keys();
    /// The names for a message: "a, b, c or d", in name order.
    static std::string names();
    /// Builds model `name` with `set` over its defaults (keys it does not read are ignored).
    /// Throws std::invalid_argument for an unknown name ("must be …") or a value out of range.
    static std::unique_ptr<PathLoss> make(std::string_view name, double frequencyHz, const Keys& set);
};

}  // namespace sbsim::radio
