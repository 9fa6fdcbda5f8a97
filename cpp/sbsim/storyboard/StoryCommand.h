#pragma once

#include <fmt/format.h>

#include <exception>
#include <string>

#include "sbsim/kernel/OneLine.h"
#include "sbsim/kernel/SimTime.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/StoryError.h"

namespace sbsim::storyboard {

/// Runs one of `story`'s effect commands (an apply or a remove); what it throws becomes a StoryError
/// naming the story, the effect and the time, so a wrong id in a script (an unknown vehicle type,
/// edge or light that SUMO refuses) ends the run with exit code 2, one line. The effect's type name
/// (`effect.typeName()`, a demangled name: thousands of instructions) is made only then.
template <typename E, typename F>
void storyCommand(const Story& story, const E& effect, kernel::SimTime now, F command) {
    try {
        command();
    } catch (const StoryError&) {
        throw;
    } catch (const std::exception& e) {
        throw StoryError(fmt::format("story '{}': {} at t={} s: {}", story.name(), effect.typeName(), now.str(),
                                     kernel::oneLine(e.what())));
    }
}

}  // namespace sbsim::storyboard
