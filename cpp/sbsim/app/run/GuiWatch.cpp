// The one file that calls libsumo's GUI functions: they are declared only with HAVE_LIBSUMOGUI
// (the eclipse-sumo wheel's libsumocpp.so contains them), defined before libsumo's headers.
#define HAVE_LIBSUMOGUI 1
#include "sbsim/app/run/GuiWatch.h"

#include <dlfcn.h>
#include <fmt/format.h>
#include <libsumo/GUI.h>
#include <libsumo/Polygon.h>
#include <libsumo/TraCIDefs.h>

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "sbsim/app/cli/BadInput.h"
#include "sbsim/app/inputs/FileLedger.h"
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
/// SUMO's polygon layers (drawn as depth): fills below the roads (layers < 0), so that roads and
/// vehicles show through them, outlines above. Each area has layers of its own: a second polygon on
/// the same layer and place (two stories sharing an area) would not show.
constexpr int kFirstFillLayer = -1;
constexpr int kFirstOutlineLayer = 100;

}  // namespace

void GuiWatch::requireDisplay() {
    const char* display = std::getenv("DISPLAY");
    const std::string name = display == nullptr ? "" : display;
    if (name.empty()) {
        throw UsageError("--gui: no X display (DISPLAY is not set); run on a desktop, or under xvfb-run");
    }
    // libX11 is loaded already (libsumocpp.so needs it): ask it as FOX will, but without dying.
    // sumo-gui's event loop runs on a thread of its own while libsumo's calls (a step, closing)
    // come from this one: Xlib must be made thread-safe before its first use, or the connection
    // breaks now and then ("X Fatal error.") and closing SUMO waits forever.
    using InitThreads = int (*)();
    if (const auto initThreads = reinterpret_cast<InitThreads>(dlsym(RTLD_DEFAULT, "XInitThreads"))) initThreads();
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

GuiWatch::GuiWatch(std::vector<GuiScreenshot> screenshots, FileLedger& files) {
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
    int n = 0;  // areas so far: each gets layers of its own
    for (std::size_t story = 0; story < stories.size(); ++story) {
        const std::string& name = stories[story]->name();
        const traffic::Color colour = storyboard::storyColour(story);
        for (const storyboard::StoryArea& area : storyboard::storyAreas(*stories[story])) {
            libsumo::TraCIPositionVector shape;
            for (const Eigen::Vector2d& p : storyboard::outline(area)) {
                libsumo::TraCIPosition position;
                position.x = p.x();
                position.y = p.y();
                shape.value.push_back(position);
            }
            const std::string id = fmt::format("sbsim:{}:{}", name, n);
            libsumo::Polygon::add(id + ":fill", shape, traciColour(colour, kFillAlpha), true, name,
                                  kFirstFillLayer - n);
            // SUMO draws a polygon filled or as an outline, not both: the outline is a polygon of its
            // own, and an open line unless it ends where it starts.
            if (!shape.value.empty()) shape.value.push_back(shape.value.front());
            libsumo::Polygon::add(id + ":outline", shape, traciColour(colour, 255), false, name, kFirstOutlineLayer + n,
                                  kOutlineWidth);
            ++n;
        }
    }
}

void GuiWatch::attach(traffic::SumoBridge& sumo) {
    snapshot_ = &sumo.snapshot();
    sumo.subscribe(traffic::SumoBridge::stepSignal, *this);
}

void GuiWatch::receiveSignal(kernel::Module&, kernel::SignalId, const kernel::Object&) {
    ++steps_;
    const kernel::SimTime now = snapshot_->time();
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

void GuiWatch::closeWithin(traffic::SumoBridge& sumo, std::chrono::seconds grace, int exitCode) {
    std::mutex mutex;
    std::condition_variable closed;
    bool done = false;
    std::thread watchdog([&] {
        std::unique_lock lock(mutex);
        if (closed.wait_for(lock, grace, [&] { return done; })) return;
        fmt::print(stderr,
                   "sbsim: warning: sumo-gui did not close within {} s; ending without it (SUMO's own output "
                   "files may be incomplete)\n",
                   grace.count());
        std::fflush(stdout);
        std::fflush(stderr);
        std::_Exit(exitCode);
    });
    sumo.close();
    {
        const std::lock_guard lock(mutex);
        done = true;
    }
    closed.notify_one();
    watchdog.join();
}

void GuiWatch::wakeBeforeClose() {
    try {
        const libsumo::TraCIPosition offset = libsumo::GUI::getOffset(kView);
        libsumo::GUI::setOffset(kView, offset.x, offset.y);  // the same view: only a redraw
    } catch (const std::exception&) {
        // No view (the user closed it): nothing to wake.
    }
}

}  // namespace sbsim::app
