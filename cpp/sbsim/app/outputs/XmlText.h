#pragma once

#include <string>
#include <string_view>

namespace sbsim::app {

/// `text` as XML 1.0 can hold it (a JUnit reader refuses the whole file otherwise): the control
/// characters XML forbids (all below U+0020 but tab, line feed and carriage return) as escapes
/// ("\x01"), U+FFFE and U+FFFF as "\ufffe" and "\uffff", bytes that are not UTF-8 as U+FFFD.
std::string xmlText(std::string_view text);

}  // namespace sbsim::app
