// batch.h - independent jobs on a few threads, their results reported in job order.
//
// `convert a.exr b.hdr ... --out-dir DIR` converts files in parallel, but what it prints must
// not depend on which file finishes first: run_in_order hands each result to `report` on
// the calling thread, in job order, as soon as that job and all before it are done. The jobs
// go through the core's work queue (shpack/work_queue.h), run on a thread of its own so that
// the calling thread is free to report.
#pragma once

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <future>
#include <limits>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "shpack/work_queue.h"

namespace shpack::cli {

// Runs work(0) .. work(count - 1) on up to `workers` threads and calls report(k, result)
// for k = 0, 1, ... in order on the calling thread. An exception from work(k) is rethrown
// by report's caller when job k's turn comes. If no thread can be started (or workers is
// 0), the jobs run on the calling thread, one after the other, and are reported after.
template <class Result>
void run_in_order(std::size_t count, unsigned workers, const std::function<Result(std::size_t)>& work,
                  const std::function<void(std::size_t, Result&)>& report) {
  if (count > std::numeric_limits<std::uint32_t>::max()) throw std::length_error("run_in_order: too many jobs");
  std::vector<std::promise<Result>> promises(count);
  std::vector<std::future<Result>> results;
  results.reserve(count);
  for (auto& p : promises) results.push_back(p.get_future());
  auto run_all = [&]() noexcept {
    detail::run_queue(static_cast<std::uint32_t>(count), workers, [&](std::uint32_t k, unsigned) noexcept {
      try {
        promises[k].set_value(work(k));
      } catch (...) {
        promises[k].set_exception(std::current_exception());
      }
    });
  };
  std::thread queue;
  struct Joiner {  // the queue's thread is joined however this function is left
    std::thread& thread;
    ~Joiner() {
      if (thread.joinable()) thread.join();
    }
  } joiner{queue};
  if (workers > 0 && count > 0) {
    try {
      queue = std::thread(run_all);
    } catch (const std::system_error&) {
      // No thread: the calling thread runs the queue below.
    }
  }
  if (!queue.joinable()) run_all();
  for (std::size_t k = 0; k < count; ++k) {
    Result r = results[k].get();
    report(k, r);
  }
}

}  // namespace shpack::cli
