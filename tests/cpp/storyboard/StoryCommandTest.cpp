#include "sbsim/storyboard/StoryCommand.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "sbsim/storyboard/Effect.h"
#include "sbsim/storyboard/Story.h"
#include "sbsim/storyboard/conditions/TimeCondition.h"

namespace sbsim::storyboard::test {
namespace {

/// An effect that counts how often its type name is asked for.
class NamedEffect : public Effect {
public:
    void apply(EffectScope& /*scope*/) override {}
    void remove(EffectScope& /*scope*/) override {}
    std::string typeName() const override {
        ++names;
        return "NamedEffect";
    }
    mutable int names = 0;
};

TEST(StoryCommand, TheEffectsTypeNameIsMadeOnlyForAnError) {
    const Story story(std::make_shared<TimeCondition>(kernel::SimTime::zero()), {}, "rain");
    const NamedEffect effect;
    int ran = 0;
    for (int k = 0; k < 3; ++k) storyCommand(story, effect, kernel::SimTime::fromSeconds(2), [&] { ++ran; });
    EXPECT_EQ(ran, 3);
    EXPECT_EQ(effect.names, 0);  // no error: no name made

    try {
        storyCommand(story, effect, kernel::SimTime::fromSeconds(2),
                     [] { throw std::runtime_error("unknown vehicle type\n'bus'"); });
        FAIL() << "no StoryError";
    } catch (const StoryError& e) {
        EXPECT_EQ(std::string(e.what()), "story 'rain': NamedEffect at t=2 s: unknown vehicle type 'bus'");
    }
    EXPECT_EQ(effect.names, 1);
}

}  // namespace
}  // namespace sbsim::storyboard::test
