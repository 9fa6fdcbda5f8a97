#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

#include "sbsim/radio/V2xMessage.h"

namespace sbsim::services::python {

/// A message a Python service sends: a type name and a byte size (what the trace, the counts and
/// the channel see) and a payload of plain Python values (frozen: tuples and read-only mappings),
/// which receiving Python services read. Single-hop broadcast; signed as a CAM (certificate digest
/// between certificates) when `camSecurity`, else with the full certificate.
class PythonMessage : public radio::V2xMessage {
public:
    PythonMessage(std::string type, std::size_t bytes, pybind11::object payload, bool camSecurity)
        : type_(std::move(type)), bytes_(bytes), payload_(std::move(payload)), camSecurity_(camSecurity) {}
    // Frames are freed on the simulation's thread, which holds the interpreter's lock.
    ~PythonMessage() override = default;

    std::string_view typeName() const override { return type_; }
    std::size_t byteSize() const override { return bytes_; }
    radio::SecurityProfile securityProfile() const override {
        return camSecurity_ ? radio::SecurityProfile::Cam : radio::SecurityProfile::Other;
    }
    const pybind11::object& payload() const { return payload_; }

private:
    std::string type_;
    std::size_t bytes_;
    pybind11::object payload_;
    bool camSecurity_;
};

}  // namespace sbsim::services::python
