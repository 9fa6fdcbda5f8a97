#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace re2 {
class RE2;
}

namespace sbsim::services {

/// A services file that cannot be read, is not well-formed XML, or does not follow the format.
/// what() is "<file>:<line>: <message>" ("<file>: cannot read" for an unreadable file).
class SBSIM_API ServicesConfigError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// One <name> or <type> rule of a service's <filters>.
struct SBSIM_API ServiceFilter {
    enum class Subject { VehicleId, VehicleType };

    Subject subject = Subject::VehicleId;
    /// Longest pattern accepted; RE2 also bounds the memory a compiled pattern may take.
    static constexpr std::size_t kMaxPatternLength = 1000;

    std::string pattern;  ///< as written, for messages
    /// RE2, compiled once at load; must match the whole id or type. RE2 matches in time linear in
    /// the id's length whatever the pattern (no backtracking), so no pattern can hang a run.
    std::shared_ptr<const re2::RE2> regex;
    bool inverse = false;  ///< match="inverse": the filter passes when the pattern does not match
    int line = 0;

    bool matches(std::string_view vehicleId, std::string_view vehicleType) const;
};

/// One <service> of a services file: which module to run, its settings, and on which vehicles.
struct SBSIM_API ServiceSpec {
    /// How the filters combine: any one passing is enough (the default, as in Artery), or all must
    /// pass (<filters operator="and">).
    enum class Combine { All, Any };

    std::string type;  ///< the service's type name, the `type` attribute
    /// Every other attribute of <service>, verbatim; std::less<> allows lookups by string_view.
    std::map<std::string, std::string, std::less<>> parameters;
    std::vector<ServiceFilter> filters;
    Combine combine = Combine::Any;
    /// Which vehicles by V2X equipment (--penetration): <equipped/> or no such element: the
    /// equipped ones; <equipped match="inverse"/>: the others; <equipped match="any"/>: all.
    /// It applies on top of the name and type filters, whatever their operator.
    enum class Equipment { Equipped, Unequipped, Any };
    Equipment equipment = Equipment::Equipped;
    bool admits(bool equipped) const {
        return equipment == Equipment::Any || (equipment == Equipment::Equipped) == equipped;
    }
    std::string source;  ///< the file, for messages
    int line = 0;        ///< of the <service> start tag
    /// The type as the file wrote it (Artery's "artery.application.CaService" for "CaService").
    std::string writtenType;
    /// A DenService's use cases (<usecase> elements, each with its attributes and filters): from
    /// its `useCases` attribute (a file relative to the services file), else den-use-cases.xml
    /// beside the services file; null when neither exists: all use cases run.
    std::shared_ptr<const std::vector<ServiceSpec>> useCases;

    /// Whether the service runs on this vehicle. No filters: every vehicle.
    bool matches(std::string_view vehicleId, std::string_view vehicleType) const;

    std::optional<std::string> parameter(std::string_view name) const;
    /// The parameter as a finite number (surrounding blanks allowed), `fallback` if absent; throws
    /// ServicesConfigError naming the file, line, service and text if it is not one.
    double number(std::string_view name, double fallback) const;
    /// "true"/"1" or "false"/"0", `fallback` if absent; throws ServicesConfigError otherwise.
    bool boolean(std::string_view name, bool fallback) const;
    /// A duration (an interval, a validity) in seconds, `fallback` if absent: a number from
    /// kMinDurationSeconds to kMaxDurationSeconds, else ServicesConfigError naming the bounds. The
    /// lower bound keeps a timer from firing at one instant for ever (1e-12 s rounds to 0 ns).
    kernel::SimTime duration(std::string_view name, double fallback) const;
    static constexpr double kMinDurationSeconds = 1e-3;
    static constexpr double kMaxDurationSeconds = 1e9;

private:
    [[noreturn]] void badParameter(std::string_view name, std::string_view expected) const;
};

/// One <rsu> of a services file: stationary stations (roadside units) and the services they run.
/// Either one unit at a position (`id`, `x`, `y`, SUMO network frame) or one per SUMO POI of a
/// type (`poiType`; the unit takes the POI's id and position), e.g.
///
///     <rsu id="rsu0" x="500" y="0"> <service type="RsuCaService"/> </rsu>
///     <rsu poiType="rsu"> <service type="artery.application.RsuCaService"/> </rsu>
struct SBSIM_API RoadsideUnitSpec {
    std::string id;       ///< empty with poiType
    double x = 0, y = 0;  ///< m, SUMO network frame (not with poiType)
    std::optional<std::string> poiType;
    std::vector<ServiceSpec> services;  ///< in file order; no filters
    std::string source;
    int line = 0;
};

/// An Artery-format services file:
///
///     <services>
///       <service type="ClearLaneService" interval="0.5">
///         <listener port="2001"/>          <!-- Artery's; accepted and ignored -->
///         <filters operator="or">          <!-- optional; "or" (the default, as in Artery) or "and" -->
///           <name pattern="police\d+"/>    <!-- regex on the vehicle id -->
///           <type pattern="bus" match="inverse"/>  <!-- regex on the SUMO vehicle type -->
///           <equipped match="any"/>        <!-- sbsim's: also on vehicles --penetration left out -->
///         </filters>
///       </service>
///     </services>
///
/// Roadside units (sbsim's; Artery places them in omnetpp.ini) are <rsu> elements beside the
/// <service> elements (RoadsideUnitSpec); their services run on the unit, not on vehicles.
///
/// Anything else (an unknown element or filter attribute, a bad regex, Artery's random
/// <penetration> filter) is an error, so that a typo cannot silently change which vehicles run what.
class SBSIM_API ServicesConfig {
public:
    ServicesConfig() = default;

    static ServicesConfig load(const std::filesystem::path& path);
    /// `source` names the text in error messages.
    static ServicesConfig parse(std::string_view text, const std::string& source);

    /// In file order, which is the order services are created in on each vehicle.
    const std::vector<ServiceSpec>& services() const { return services_; }
    /// The <rsu> elements, in file order.
    const std::vector<RoadsideUnitSpec>& roadsideUnits() const { return roadsideUnits_; }
    /// The files read besides the services file itself (DenService use-case files), each once: the
    /// run counts them as its inputs, so that no output may overwrite them.
    const std::vector<std::filesystem::path>& otherFiles() const { return otherFiles_; }
    /// Every <service>: the vehicles' entries, then each roadside unit's.
    std::vector<const ServiceSpec*> allServices() const;
    /// The services that run on this vehicle, in file order.
    std::vector<const ServiceSpec*> matching(std::string_view vehicleId, std::string_view vehicleType) const;

private:
    std::vector<ServiceSpec> services_;
    std::vector<RoadsideUnitSpec> roadsideUnits_;
    std::vector<std::filesystem::path> otherFiles_;
};

}  // namespace sbsim::services
