#pragma once

#include <stdexcept>

namespace sbsim::app {

/// Bad input: the program prints the message after "sbsim: " as one line and exits with code 2.
class BadInput : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Bad command-line input: a value, a combination of options.
class UsageError : public BadInput {
public:
    using BadInput::BadInput;
};

/// Bad input found after parsing: an unreadable file, a services file sbsim or SUMO refuses.
class InputError : public BadInput {
public:
    using BadInput::BadInput;
};

/// An output that cannot be written: a missing folder, a full disk, the path of an input.
class OutputError : public BadInput {
public:
    using BadInput::BadInput;
};

}  // namespace sbsim::app
