#pragma once

#include <stdexcept>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/Statistics.h"

namespace sbsim::storyboard {

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

    /// One Parquet file's bytes: columns vehicle, source, name (strings), time (s), value (floats),
    /// a row per recorded value in the order recorded.
    std::string bytes(const kernel::Statistics& statistics) const;
};

}  // namespace sbsim::storyboard
