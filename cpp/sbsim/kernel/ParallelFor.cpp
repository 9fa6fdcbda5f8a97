#include "sbsim/kernel/ParallelFor.h"

#include <algorithm>

namespace sbsim::kernel {

namespace {
/// Chunks per thread: enough to even out a late start, few enough to keep hand-outs cheap.
constexpr std::size_t kChunksPerThread = 8;
}  // namespace

ParallelFor::ParallelFor(unsigned threads) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { workerLoop(); });
}

ParallelFor::~ParallelFor() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        generation_.fetch_add(1);
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

std::exception_ptr ParallelFor::drain() noexcept {
    std::exception_ptr error;
    for (std::size_t k = nextChunk_.fetch_add(1); k < chunks_; k = nextChunk_.fetch_add(1)) {
        try {
            (*body_)(n_ * k / chunks_, n_ * (k + 1) / chunks_);
        } catch (...) {
            if (!error) error = std::current_exception();
        }
    }
    return error;
}

void ParallelFor::run(std::size_t n, const Body& body, std::size_t minChunk) {
    // Equal chunks of at least minChunk each (the rounding spread over them).
    const std::size_t chunk = std::max({std::size_t{1}, minChunk, n / (threads() * kChunksPerThread)});
    const std::size_t chunks = n / chunk;
    if (workers_.empty() || chunks <= 1) {
        body(0, n);
        return;
    }
    {
        const std::lock_guard lock(mutex_);
        body_ = &body;
        n_ = n;
        chunks_ = chunks;
        nextChunk_.store(0);
        open_ = true;
        joined_ = 0;
        error_ = nullptr;
        generation_.fetch_add(1);
    }
    wake_.notify_all();
    const std::exception_ptr mine = drain();
    std::unique_lock lock(mutex_);
    open_ = false;  // chunks are all taken: late workers stay out
    done_.wait(lock, [this] { return joined_ == 0; });
    body_ = nullptr;
    if (mine) std::rethrow_exception(mine);
    if (error_) std::rethrow_exception(error_);
}

void ParallelFor::workerLoop() {
    std::uint64_t seen = 0;
    while (true) {
        // Sleep until the next round. No spinning first: on a machine with few cores a spinning
        // worker takes the core SUMO steps on (measured: bench/README.md, "One pool, no spin").
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return generation_.load() != seen; });
        seen = generation_.load();
        if (stopping_) return;
        if (!open_) continue;  // the caller already finished this round alone
        ++joined_;
        lock.unlock();
        const std::exception_ptr error = drain();
        lock.lock();
        if (error && !error_) error_ = error;
        if (--joined_ == 0) done_.notify_one();
    }
}

}  // namespace sbsim::kernel
