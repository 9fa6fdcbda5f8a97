// The one file that calls libsumo's GUI functions: they are declared only with HAVE_LIBSUMOGUI
// (the eclipse-sumo wheel's libsumocpp.so contains them), defined before libsumo's headers.
#define HAVE_LIBSUMOGUI 1
#include "sbsim/app/GuiWatch.h"

#include <dlfcn.h>
#include <fmt/format.h>
#include <libsumo/GUI.h>
#include <libsumo/Polygon.h>
#include <libsumo/TraCIDefs.h>

#include <algorithm>
#include <cstdlib>

#include "sbsim/app/BadInput.h"
#include "sbsim/app/RunFiles.h"
#include "sbsim/kernel/OneLine.h"
#include "sbsim/storyboard/StoryAreas.h"
#include "sbsim/storyboard/StoryPalette.h"
#include "sbsim/traffic/VehicleSnapshot.h"

namespace sbsim::app {

namespace fs = std::filesystem;

namespace {

libsumo::TraCIColor traciColour(const traffic::Color& c, std::uint8_t alpha) { return {c.r, c.g, c.b, alpha}; }

/// Outline width in metres: visible at the zoom that shows a whole town.
constexpr double kOutlineWidth = 3;
/// SUMO's polygon layer of the first area, above the roads (fills are translucent). Each area
/// gets two layers of its own, fill then outline: SUMO draws the layer as depth, so a second
/// polygon on the same layer and place (two stories sharing an area) would not show.
constexpr int kFirstLayer = 100;

}  // namespace

void GuiWatch::requireDisplay() {
    const char* display = std::getenv("DISPLAY");
    const std::string name = display == nullptr ? "" : display;
    if (name.empty()) {
        throw UsageError("--gui: no X display (DISPLAY is not set); run on a desktop, or under xvfb-run");
    }
    // libX11 is loaded already (libsumocpp.so needs it): ask it as FOX will, but without dying.
    using Open = void* (*)(const char*);
    using Close = int (*)(void*);
    const auto open = reinterpret_cast<Open>(dlsym(RTLD_DEFAULT, "XOpenDisplay"));
    const auto close = reinterpret_cast<Close>(dlsym(RTLD_DEFAULT, "XCloseDisplay"));
    if (open == nullptr || close == nullptr) return;  // cannot ask: let sumo-gui try
    void* connection = open(name.c_str());
    if (connection == nullptr) {
        throw UsageError(fmt::format("--gui: cannot open the X display '{}'; run on a desktop, or under xvfb-run",
                                     kernel::escapeControls(name)));
    }
    close(connection);
}

GuiWatch::GuiWatch(std::vector<GuiScreenshot> screenshots, RunFiles& files) {
    for (GuiScreenshot& shot : screenshots) {
        shot.file = fs::absolute(shot.file);  // SUMO writes it; the path must not depend on SUMO's folder
        const fs::path folder = shot.file.parent_path();
        std::error_code ec;
        if (!fs::is_directory(folder, ec)) {
            throw OutputError(fmt::format("--gui-screenshot: the folder of '{}' does not exist", shot.file.string()));
        }
        files.claimOutput("--gui-screenshot", shot.file);
        shots_.push_back({std::move(shot), std::nullopt});
    }
    std::stable_sort(shots_.begin(), shots_.end(),
                     [](const Shot& a, const Shot& b) { return a.request.seconds < b.request.seconds; });
}

void GuiWatch::drawAreas(const std::vector<storyboard::StoryPtr>& stories) {
    const std::vector<storyboard::StoryArea> areas = storyboard::storyAreas(stories);
    for (std::size_t k = 0; k < areas.size(); ++k) {
        const storyboard::StoryArea& area = areas[k];
        libsumo::TraCIPositionVector shape;
        for (const Eigen::Vector2d& p : area.outline) {
            libsumo::TraCIPosition position;
            position.x = p.x();
            position.y = p.y();
            shape.value.push_back(position);
        }
        const traffic::Color colour = storyboard::storyColour(area.story);
        const std::string id = fmt::format("sbsim:{}:{}", area.name, k);
        const int layer = kFirstLayer + 2 * static_cast<int>(k);
        libsumo::Polygon::add(id + ":fill", shape, traciColour(colour, kFillAlpha), true, area.name, layer);
        // SUMO draws a polygon filled or as an outline, not both: the outline is a polygon of its own.
        libsumo::Polygon::add(id + ":outline", shape, traciColour(colour, 255), false, area.name, layer + 1,
                              kOutlineWidth);
    }
}

void GuiWatch::receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object& value) {
    ++steps_;
    const kernel::SimTime now = dynamic_cast<const traffic::VehicleSnapshot&>(value).time();
    for (Shot& shot : shots_) {
        if (shot.requestedAtStep || kernel::SimTime::fromSeconds(shot.request.seconds) > now) continue;
        libsumo::GUI::screenshot(kView, shot.request.file.string());
        shot.requestedAtStep = steps_;
    }
}

void GuiWatch::finish(kernel::SimTime now) const {
    for (const Shot& shot : shots_) {
        if (!shot.requestedAtStep) {
            fmt::print(stderr, "sbsim: warning: --gui-screenshot {:g}:{}: the run ended at t={} s, before that time\n",
                       shot.request.seconds, shot.request.file.string(), now.str());
        } else if (*shot.requestedAtStep == steps_) {
            fmt::print(stderr,
                       "sbsim: warning: --gui-screenshot {:g}:{}: the run ended with that step; sumo-gui saves a "
                       "picture during the next step\n",
                       shot.request.seconds, shot.request.file.string());
        }
    }
}

}  // namespace sbsim::app
