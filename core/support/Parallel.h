#pragma once
// A minimal parallel loop for the CPU precomputations and the ground-truth integrator.
// Work is split into contiguous chunks handed out dynamically; results must not depend on which
// thread runs which index (callers write to disjoint outputs and seed per index), so output is
// deterministic whatever the thread count.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace facet {

// Number of worker threads to use: `requested` if > 0, else the machine's hardware concurrency.
inline unsigned workerCount(int requested = 0)
{
    if (requested > 0)
        return unsigned(requested);
    return std::max(1u, std::thread::hardware_concurrency());
}

// Calls fn(i) for i in [0, count), on up to workerCount(threads) threads.
template <typename Fn> void parallelFor(std::size_t count, Fn&& fn, int threads = 0)
{
    const unsigned workers = std::min<std::size_t>(workerCount(threads), std::max<std::size_t>(count, 1));
    if (workers <= 1) {
        for (std::size_t i = 0; i < count; ++i)
            fn(i);
        return;
    }
    std::atomic<std::size_t> next {0};
    auto run = [&] {
        for (std::size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1))
            fn(i);
    };
    std::vector<std::thread> pool;
    pool.reserve(workers - 1);
    for (unsigned w = 1; w < workers; ++w)
        pool.emplace_back(run);
    run();
    for (auto& t : pool)
        t.join();
}

} // namespace facet
