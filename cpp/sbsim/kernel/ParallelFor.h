#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "sbsim/kernel/Export.h"

namespace sbsim::kernel {

/// Splits a loop over [0, n) into contiguous chunks run on persistent worker threads plus the
/// calling thread, and waits for all of them. Used where per-step work is independent per vehicle
/// (reading the snapshot from libsumo, evaluating pure stories), so the machine's other cores
/// absorb it while SUMO itself steps on one. Chunks are handed out one at a time, so a worker
/// that wakes late takes fewer of them instead of holding up the caller; a worker that wakes after
/// the caller has run out of chunks takes none. An exception in any chunk is rethrown in the caller.
class SBSIM_API ParallelFor {
public:
    using Body = std::function<void(std::size_t begin, std::size_t end)>;

    /// `threads` in total, the caller included; 0 means the hardware's concurrency.
    explicit ParallelFor(unsigned threads = 0);
    ~ParallelFor();
    ParallelFor(const ParallelFor&) = delete;
    ParallelFor& operator=(const ParallelFor&) = delete;

    unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// Runs body over [0, n) in chunks of at least `minChunk` (shorter loops stay on the caller).
    void run(std::size_t n, const Body& body, std::size_t minChunk = 512);

private:
    void workerLoop();
    /// Takes chunks until none is left; returns the first exception a chunk threw.
    std::exception_ptr drain() noexcept;

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    // The current round. Set by the caller under mutex_ before the generation moves on.
    const Body* body_ = nullptr;
    std::size_t n_ = 0;
    std::size_t chunks_ = 0;
    std::atomic<std::size_t> nextChunk_{0};
    bool open_ = false;    // workers may still join the round
    unsigned joined_ = 0;  // workers inside the round
    std::atomic<std::uint64_t> generation_{0};
    bool stopping_ = false;
    std::exception_ptr error_;
};

}  // namespace sbsim::kernel
