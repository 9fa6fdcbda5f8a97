#pragma once

#include <memory>
#include <utility>

#include "sbsim/kernel/Message.h"
#include "sbsim/radio/V2xMessage.h"

namespace sbsim::radio {

/// A received V2X message on its way to the receiving station's module (its middleware), which
/// hands it to its services and tells the medium it arrived.
struct Delivery : kernel::Message {
    explicit Delivery(std::shared_ptr<const V2xMessage> m) : kernel::Message("v2x"), message(std::move(m)) {}
    std::shared_ptr<const V2xMessage> message;
};

}  // namespace sbsim::radio
