#pragma once

#include <exception>
#include <string>

namespace sbsim::testing_support {

/// What `f` throws as E, or a note that it threw nothing: for tests that pin an error's wording.
template <class E = std::exception, class F>
std::string thrownMessage(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    return "(nothing thrown)";
}

}  // namespace sbsim::testing_support
