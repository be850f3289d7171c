#pragma once
// A small pool over independent jobs: `threads` workers take job indexes in turn and each result
// is stored at its job's index, so the output is the same whatever the scheduling and the number
// of threads. The first exception a job throws is rethrown (for the lowest failing index) once
// every worker has stopped.
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

namespace ringlet::experiments {

template <typename Result>
std::vector<Result> run_indexed(std::size_t jobs, int threads, const std::function<Result(std::size_t)>& job) {
  std::vector<std::optional<Result>> slots(jobs);
  std::vector<std::exception_ptr> errors(jobs);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  const auto work = [&] {
    for (std::size_t i = next++; i < jobs && !failed.load(); i = next++) {
      try {
        slots[i].emplace(job(i));
      } catch (...) {
        errors[i] = std::current_exception();
        failed = true;
      }
    }
  };
  const std::size_t n = threads < 1 ? 1U : static_cast<std::size_t>(threads);
  std::vector<std::thread> workers;
  for (std::size_t t = 1; t < n && t < jobs; ++t) workers.emplace_back(work);
  work();
  for (auto& w : workers) w.join();
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  std::vector<Result> out;
  out.reserve(jobs);
  for (auto& s : slots) out.push_back(std::move(*s));
  return out;
}

}  // namespace ringlet::experiments
