#pragma once

namespace sbsim::services {

/// What a service type provides to the rest of a run. The type says it, as a static member of its
/// class (`static constexpr ServiceTraits kProvides{...}`, read by SBSIM_REGISTER_SERVICE), so the
/// run asks the registry instead of knowing services by name.
struct ServiceTraits {
    /// Its stations originate DENMs: the DENM memories of the stations that hear them fill, which
    /// is what a WarnedBefore criterion reads.
    bool sendsDenms = false;
    /// It runs DEN use cases: the services file's use-case list (`useCases`, or den-use-cases.xml
    /// beside it) is read for its entries.
    bool runsUseCases = false;
};

}  // namespace sbsim::services
