#pragma once
// One parallel loop for the library's independent work items (diagram predictors, paper figures).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rbcstab {

// Runs f(k) for k in [0, n) on up to `threads` workers, each index once. Each f(k) writes only its own result,
// so the outcome does not depend on the thread count or the order; the first exception is rethrown after all
// workers have joined (an exception must not escape a std::thread).
template <class F>
void parallel_for(std::size_t n, int threads, F&& f) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex m;
  auto work = [&] {
    for (std::size_t k; (k = next++) < n;) {
      try {
        f(k);
      } catch (...) {
        std::lock_guard lock(m);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  const std::size_t workers = std::min<std::size_t>(n, std::size_t(std::max(threads, 1)));
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace rbcstab
