#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "sbsim/kernel/ParallelFor.h"

namespace sbsim::kernel {
namespace {

/// How often each index of [0, n) was visited.
std::vector<int> visits(ParallelFor& pf, std::size_t n, std::size_t minChunk) {
    std::vector<std::atomic<int>> counts(n);
    pf.run(
        n,
        [&](std::size_t begin, std::size_t end) {
            ASSERT_LE(begin, end);
            ASSERT_LE(end, n);
            for (std::size_t i = begin; i < end; ++i) counts[i].fetch_add(1, std::memory_order_relaxed);
        },
        minChunk);
    std::vector<int> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = counts[i].load();
    return out;
}

/// The distinct threads that ran a loop.
std::set<std::thread::id> threadsUsed(ParallelFor& pf, std::size_t n, std::size_t minChunk) {
    std::mutex mutex;
    std::set<std::thread::id> ids;
    pf.run(
        n,
        [&](std::size_t, std::size_t) {
            const std::lock_guard lock(mutex);
            ids.insert(std::this_thread::get_id());
        },
        minChunk);
    return ids;
}

TEST(ParallelFor, ThreadCount) {
    EXPECT_EQ(ParallelFor(1).threads(), 1u);
    EXPECT_EQ(ParallelFor(3).threads(), 3u);
    EXPECT_EQ(ParallelFor(0).threads(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST(ParallelFor, VisitsEveryIndexExactlyOnce) {
    for (unsigned threads : {1u, 2u, 4u}) {
        ParallelFor pf(threads);
        for (std::size_t n : {0, 1, 7, 511, 512, 1024, 1537, 5000}) {
            for (std::size_t minChunk : {1, 100, 512}) {
                const std::vector<int> v = visits(pf, n, minChunk);
                EXPECT_EQ(std::count(v.begin(), v.end(), 1), static_cast<std::ptrdiff_t>(n))
                    << threads << " threads, n " << n << ", minChunk " << minChunk;
            }
        }
    }
}

/// The [begin, end) ranges a loop was cut into, in ascending order.
std::vector<std::pair<std::size_t, std::size_t>> chunksOf(ParallelFor& pf, std::size_t n, std::size_t minChunk) {
    std::mutex mutex;
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    pf.run(
        n,
        [&](std::size_t begin, std::size_t end) {
            const std::lock_guard lock(mutex);
            chunks.emplace_back(begin, end);
        },
        minChunk);
    std::sort(chunks.begin(), chunks.end());
    return chunks;
}

TEST(ParallelFor, SplitsOnlyLoopsLongEnough) {
    ParallelFor pf(4);
    const std::thread::id caller = std::this_thread::get_id();
    EXPECT_EQ(threadsUsed(pf, 1023, 512), std::set<std::thread::id>{caller});  // under 2 chunks: caller only
    EXPECT_EQ(chunksOf(pf, 1023, 512), (std::vector<std::pair<std::size_t, std::size_t>>{{0, 1023}}));
    for (const std::size_t n : {1024, 5000, 100'000}) {
        const auto chunks = chunksOf(pf, n, 512);
        EXPECT_GE(chunks.size(), 2u);
        for (std::size_t k = 0; k < chunks.size(); ++k) {
            EXPECT_EQ(chunks[k].first, k == 0 ? 0 : chunks[k - 1].second);  // contiguous, no overlap
            if (k + 1 < chunks.size()) EXPECT_GE(chunks[k].second - chunks[k].first, 512u);
        }
        EXPECT_EQ(chunks.back().second, n);
    }
    EXPECT_LE(threadsUsed(pf, 100'000, 512).size(), 4u);  // never more than the pool
}

TEST(ParallelFor, WorkersTakeChunksWhileTheCallerIsBusy) {
    // The caller's chunk waits until another thread has run a chunk: that only ends if the
    // worker joins the round and takes chunks the caller has not reached.
    ParallelFor pf(2);
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<bool> workerRan{false};
    std::atomic<bool> callerWaited{false};
    pf.run(
        8,
        [&](std::size_t, std::size_t) {
            if (std::this_thread::get_id() != caller) {
                workerRan = true;
                return;
            }
            if (callerWaited.exchange(true)) return;
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
            while (!workerRan && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
        },
        1);
    // The worker may well take all chunks before the caller reaches one (callerWaited then stays
    // false): either way a worker ran, and a caller that did wait was released by it.
    EXPECT_TRUE(workerRan);
}

TEST(ParallelFor, ManyRoundsInARow) {
    // Rounds of different sizes back to back: workers must neither miss a round nor run one twice.
    ParallelFor pf(3);
    std::atomic<long> total{0};
    long expected = 0;
    for (int round = 0; round < 2000; ++round) {
        const std::size_t n = static_cast<std::size_t>(round % 7) * 3;  // 0..18: 1 to 3 parts
        pf.run(
            n,
            [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) total.fetch_add(static_cast<long>(i) + 1);
            },
            4);
        expected += static_cast<long>(n * (n + 1) / 2);
        ASSERT_EQ(total.load(), expected) << "round " << round;
    }
}

TEST(ParallelFor, ExceptionsReachTheCaller) {
    ParallelFor pf(3);
    const std::size_t n = 3000;
    // In the last chunk, then in the first (which the caller usually takes).
    EXPECT_THROW(pf.run(
                     n,
                     [&](std::size_t, std::size_t end) {
                         if (end == n) throw std::runtime_error("worker");
                     },
                     512),
                 std::runtime_error);
    EXPECT_THROW(pf.run(
                     n,
                     [&](std::size_t begin, std::size_t) {
                         if (begin == 0) throw std::logic_error("caller");
                     },
                     512),
                 std::logic_error);
    // Still usable.
    const std::vector<int> v = visits(pf, n, 512);
    EXPECT_EQ(std::count(v.begin(), v.end(), 1), static_cast<std::ptrdiff_t>(n));
}

}  // namespace
}  // namespace sbsim::kernel
