#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/StudyParameters.h"
#include "sbsim/radio/channel/ChannelSettings.h"

namespace sbsim::radio {

/// A radio file or a `radio_<key>` study parameter refused: the message names the file, line and
/// key (or the parameter) and what is wrong, as one line.
class SBSIM_API RadioFileError : public std::runtime_error {
public:
    RadioFileError(const std::string& message, bool fromParameter)
        : std::runtime_error(message), fromParameter_(fromParameter) {}
    /// The bad value came from the command line (--param radio_<key>), not from the file.
    bool fromParameter() const { return fromParameter_; }

private:
    bool fromParameter_;
};

/// The radio file (--radio, TOML): ChannelSettings' defaults overridden by the file's keys, then by
/// study parameters `radio_<key>` (`--param radio_power_dbm=30`), so a study sweeps them. The
/// path-loss models' keys are those PathLossModels registers. Throws RadioFileError.
SBSIM_API ChannelSettings readRadioFile(const std::optional<std::filesystem::path>& file,
                                        const kernel::StudyParameters& parameters);

}  // namespace sbsim::radio
