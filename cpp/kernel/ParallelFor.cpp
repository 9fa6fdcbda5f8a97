#include "kernel/ParallelFor.h"

#include <algorithm>

namespace sbsim::kernel {

namespace {
std::pair<std::size_t, std::size_t> chunk(std::size_t n, unsigned parts, unsigned k) {
    return {n * k / parts, n * (k + 1) / parts};
}
}  // namespace

ParallelFor::ParallelFor(unsigned threads) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this, i] { workerLoop(i); });
}

ParallelFor::~ParallelFor() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : workers_) t.join();
}

void ParallelFor::run(std::size_t n, const Body& body, std::size_t minChunk) {
    const auto parts =
        static_cast<unsigned>(std::clamp<std::size_t>(n / std::max<std::size_t>(minChunk, 1), 1, workers_.size() + 1));
    if (parts == 1) {
        body(0, n);
        return;
    }
    {
        const std::lock_guard lock(mutex_);
        body_ = &body;
        n_ = n;
        parts_ = parts;
        pending_ = parts - 1;
        error_ = nullptr;
        ++generation_;
    }
    wake_.notify_all();
    std::exception_ptr mine;
    try {
        const auto [b, e] = chunk(n, parts, 0);
        body(b, e);
    } catch (...) {
        mine = std::current_exception();
    }
    std::unique_lock lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
    body_ = nullptr;
    if (mine) std::rethrow_exception(mine);
    if (error_) std::rethrow_exception(error_);
}

void ParallelFor::workerLoop(unsigned index) {
    std::uint64_t seen = 0;
    while (true) {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        if (index >= parts_) continue;  // this round has fewer parts than threads
        const Body* body = body_;
        const auto [b, e] = chunk(n_, parts_, index);
        lock.unlock();
        std::exception_ptr error;
        try {
            (*body)(b, e);
        } catch (...) {
            error = std::current_exception();
        }
        lock.lock();
        if (error && !error_) error_ = error;
        if (--pending_ == 0) done_.notify_one();
    }
}

}  // namespace sbsim::kernel
