// batch.h - independent jobs on a few threads, their results reported in job order.
//
// `convert a.exr b.hdr ... --out-dir DIR` converts files in parallel, but what it prints must
// not depend on which file finishes first: run_in_order hands each result to `report` on
// the calling thread, in job order, as soon as that job and all before it are done.
#pragma once

#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <future>
#include <system_error>
#include <thread>
#include <vector>

namespace shpack::cli {

// Runs work(0) .. work(count - 1) on up to `workers` threads and calls report(k, result)
// for k = 0, 1, ... in order on the calling thread. An exception from work(k) is rethrown
// by report's caller when job k's turn comes. If no thread can be started, the jobs run on
// the calling thread, one after the other.
template <class Result>
void run_in_order(std::size_t count, unsigned workers, const std::function<Result(std::size_t)>& work,
                  const std::function<void(std::size_t, Result&)>& report) {
  std::vector<std::promise<Result>> promises(count);
  std::vector<std::future<Result>> results;
  results.reserve(count);
  for (auto& p : promises) results.push_back(p.get_future());
  std::atomic<std::size_t> next{0};
  auto drain = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < count;) {
      try {
        promises[k].set_value(work(k));
      } catch (...) {
        promises[k].set_exception(std::current_exception());
      }
    }
  };
  std::vector<std::thread> threads;
  struct Joiner {  // the threads are joined however this function is left
    std::vector<std::thread>& threads;
    ~Joiner() {
      for (std::thread& t : threads) t.join();
    }
  } joiner{threads};
  try {
    for (unsigned w = 0; w < workers && w < count; ++w) threads.emplace_back(drain);
  } catch (const std::system_error&) {
    // Fewer threads than asked for; if none started, the loop below runs the jobs.
  }
  if (threads.empty()) drain();
  for (std::size_t k = 0; k < count; ++k) {
    Result r = results[k].get();
    report(k, r);
  }
}

}  // namespace shpack::cli
