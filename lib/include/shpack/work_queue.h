// work_queue.h - items 0 .. count-1 handed out to up to `workers` threads, the caller being
// worker 0. Which worker runs which item changes from run to run, so callers give each item
// its own output slot (a tile) and combine the slots in item order afterwards: the result
// does not depend on the thread count or on scheduling. If a thread cannot be started, the
// threads that did start (and the caller) drain the queue: the result is the same.
//
// The one work queue of shpack: the projectors run their tiles on it, and the shpack
// command its files (cli/batch.h). Public so that the command can use it; namespace detail
// because it is a mechanism, not part of the conversion API.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace shpack::detail {

// run(item, worker) is called once per item; it must not throw.
template <class Run>
void run_queue(std::uint32_t count, unsigned workers, Run&& run) noexcept {
  std::atomic<std::uint32_t> next{0};
  auto drain = [&](unsigned worker) noexcept {
    for (std::uint32_t k; (k = next.fetch_add(1)) < count;) run(k, worker);
  };
  const unsigned extra = std::max(1u, std::min<unsigned>(workers, count)) - 1;
  std::vector<std::thread> threads;
  try {
    threads.reserve(extra);
    for (unsigned w = 1; w <= extra; ++w) threads.emplace_back(drain, w);
  } catch (...) {
    // Fewer workers than asked for; the queue is still drained below.
  }
  drain(0);
  for (std::thread& t : threads) t.join();
}

}  // namespace shpack::detail
