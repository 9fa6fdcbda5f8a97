#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "sbsim/app/cli/CommandLine.h"
#include "sbsim/kernel/Signal.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/traffic/SumoBridge.h"

namespace sbsim::app {

class FileLedger;

/// sumo-gui's part in a run with --gui; it only watches, commanding nothing that changes the
/// traffic. It draws every story's areas as SUMO polygons (a semi-transparent fill and an
/// outline in the story's colour, the story's name as the polygon type) and takes the
/// --gui-screenshot pictures after the steps of the bridge it is attached to. The vehicles' story
/// colours are a storyboard::StoryPainter's, which the run gives the board.
class GuiWatch : public kernel::Listener {
public:
    /// Alpha of an area's fill: the roads and vehicles under it stay visible.
    static constexpr std::uint8_t kFillAlpha = 70;
    /// The view libsumo's GUI opens.
    static constexpr const char* kView = "View #0";

    /// Throws UsageError unless an X display can be opened: without one, sumo-gui's toolkit (FOX)
    /// ends the whole process. Call before SUMO loads.
    static void requireDisplay();

    /// Claims the screenshot files as outputs of the run (never an input, their folder must exist).
    GuiWatch(std::vector<GuiScreenshot> screenshots, FileLedger& files);

    /// Adds the stories' areas to SUMO (once it is loaded and the stories are registered).
    void drawAreas(const std::vector<storyboard::StoryPtr>& stories);
    /// Takes the screenshots after `sumo`'s steps.
    void attach(traffic::SumoBridge& sumo);
    void receiveSignal(kernel::Module& source, kernel::SignalId id, const kernel::Object& value) override;
    /// Warns (stderr) about screenshots the run ended before sumo-gui could take.
    void finish(kernel::SimTime now) const;
    /// Closes SUMO, giving sumo-gui `grace` to end: libsumo's GUI sometimes never returns from
    /// closing (its event loop misses the request to stop). Past that, this prints a warning and
    /// ends the process with `exitCode`, everything of sbsim's own having been written already.
    static void closeWithin(traffic::SumoBridge& sumo, std::chrono::seconds grace, int exitCode);
    /// Wakes sumo-gui's event loop (a redraw of the view), so that closing SUMO, which waits for
    /// that loop to end, does not wait forever when no X event comes after the last step.
    static void wakeBeforeClose();

private:
    struct Shot {
        GuiScreenshot request;
        std::optional<std::uint64_t> requestedAtStep;  // sumo-gui writes it during the step after
    };
    std::vector<Shot> shots_;  // ascending time
    std::uint64_t steps_ = 0;
    const traffic::VehicleSnapshot* snapshot_ = nullptr;  // the attached bridge's
};

}  // namespace sbsim::app
