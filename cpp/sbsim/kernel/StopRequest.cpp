#include "sbsim/kernel/StopRequest.h"

#include <atomic>

namespace sbsim::kernel {

namespace {
std::atomic<bool> stopRequested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
}  // namespace

void StopRequest::request() noexcept { stopRequested.store(true, std::memory_order_relaxed); }

bool StopRequest::requested() noexcept { return stopRequested.load(std::memory_order_relaxed); }

void StopRequest::clear() noexcept { stopRequested.store(false, std::memory_order_relaxed); }

}  // namespace sbsim::kernel
