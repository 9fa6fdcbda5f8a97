#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sbsim::kernel {

/// Splits a loop over [0, n) into contiguous chunks run on persistent worker threads plus the
/// calling thread, and waits for all of them. Used where per-step work is independent per vehicle
/// (reading the snapshot from libsumo), so the machine's other cores absorb it while SUMO itself
/// steps on one. An exception in any chunk is rethrown in the caller.
class ParallelFor {
public:
    using Body = std::function<void(std::size_t begin, std::size_t end)>;

    /// `threads` in total, the caller included; 0 means the hardware's concurrency.
    explicit ParallelFor(unsigned threads = 0);
    ~ParallelFor();
    ParallelFor(const ParallelFor&) = delete;
    ParallelFor& operator=(const ParallelFor&) = delete;

    unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// Runs body over [0, n); loops shorter than `minChunk` per thread stay on the caller.
    void run(std::size_t n, const Body& body, std::size_t minChunk = 512);

private:
    void workerLoop(unsigned index);

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const Body* body_ = nullptr;
    std::size_t n_ = 0;
    unsigned parts_ = 0;
    std::uint64_t generation_ = 0;
    unsigned pending_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;
};

}  // namespace sbsim::kernel
