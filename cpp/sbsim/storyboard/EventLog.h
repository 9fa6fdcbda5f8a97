#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "sbsim/kernel/Export.h"
#include "sbsim/kernel/SimTime.h"

namespace sbsim::storyboard {

/// Writes storyboard events as JSON Lines (one object per line, flushed at each step's end), e.g.
/// {"t":12.3,"type":"activate","story":"rain","vehicle":"flow0.1"}. Times are rounded to 1 ms.
/// Bytes that are not UTF-8 in names and causes become U+FFFD. pandas.read_json(path, lines=True)
/// reads the file. A WorldStory's activate and deactivate lines have "vehicle": null; an equipped
/// line, of no story, "story": null.
class SBSIM_API EventLog {
public:
    explicit EventLog(std::ostream& out) : out_(out) {}

    /// `vehicle`: none for a WorldStory.
    void activate(kernel::SimTime t, std::string_view story, std::optional<std::string_view> vehicle);
    void deactivate(kernel::SimTime t, std::string_view story, std::optional<std::string_view> vehicle,
                    std::string_view reason);
    /// `onExit`: sent as the story deactivated; the line gets "phase":"exit".
    void signal(kernel::SimTime t, std::string_view story, std::string_view vehicle, std::string_view cause,
                const std::vector<std::string>& others, bool onExit = false);
    /// A vehicle became V2X-equipped (it departed with equipment): {"t":…,"type":"equipped",
    /// "story":null,"vehicle":…}. Only runs with services write these.
    void equipped(kernel::SimTime t, std::string_view vehicle);
    void flush() { out_.flush(); }
    /// From now on, also keep the lines in memory (for criteria that read the event log).
    void keepLines() { keep_ = true; }
    /// The lines written since keepLines().
    const std::string& keptLines() const { return kept_; }

private:
    void write(const std::string& text);

    std::ostream& out_;
    bool keep_ = false;
    std::string kept_;
};

}  // namespace sbsim::storyboard
