#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Statistics.h"

namespace sbsim::python {

/// The statistics file (--statistics) is written by pyarrow in the embedded interpreter (a
/// PythonRuntime must be running): no Parquet library of our own.
class SBSIM_API StatisticsParquet {
public:
    /// Thrown when pyarrow cannot be imported; what() says what is missing, in one line.
    class Unavailable : public std::runtime_error {
    public:
        using std::runtime_error::runtime_error;
    };

    /// Checks that pyarrow.parquet can be imported, so that a missing pyarrow fails before the run starts.
    StatisticsParquet();

    /// Whether a row's vehicle carries V2X equipment; none for a row of no vehicle (a roadside
    /// unit, a story's own value).
    using Equipped = std::function<std::optional<bool>(std::string_view vehicle)>;

    /// One Parquet file's bytes: columns vehicle, source, name (strings), time (s), value (floats),
    /// equipped (booleans, null where `equipped` says none), a row per recorded value in the order
    /// recorded.
    std::string bytes(const kernel::Statistics& statistics, const Equipped& equipped) const;
};

}  // namespace sbsim::python
