#pragma once
// The planner service's thread: LOAD_PDDL's reading, parsing and grounding, and
// IS_OBSTACLE_KNOWN's problem update and new grounding, off the cycle (they allocate and take
// milliseconds). It grounds into one of two arenas sized at start-up: the cycle plans on the
// front one while the worker fills the back one, and takes the result over at a defined frame
// (lockstep: the activation after the request, waiting for the worker if it is late, since
// virtual time stands still meanwhile; the real clock takes it at the first activation that finds
// it done and never waits). Requests and results pass through atomics only: the cycle never
// takes a lock or allocates here.
#include <array>
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <thread>
#include <vector>

#include "ringlet/pddl/arena.hpp"
#include "ringlet/pddl/loader.hpp"
#include "ringlet/pddl/problem_edit.hpp"
#include "ringlet/pddl/task.hpp"

namespace ringlet::pddl {

struct ServiceSettings {
  std::filesystem::path domain;    ///< the domain file every problem is for
  std::filesystem::path problems;  ///< the folder LOAD_PDDL's names are looked up in
  std::vector<Place> places;
  double obstacle_radius = 0.6;    ///< m: a connection within this of an obstacle is blocked by it
  std::size_t arena_bytes = 4U << 20U;  ///< each of the two arenas
  std::int32_t max_facts = 4096;   ///< the belief states' size (words = max_facts / 64 rounded up)
};

/// What a finished job produced. Read by the cycle only while the worker is idle.
struct ServiceResult {
  bool ok = false;
  bool has_task = false;  ///< a new task in the back arena (else the front one stands)
  bool known = false;     ///< IS_OBSTACLE_KNOWN: nothing had to be added
  Task task;
  std::array<char, 120> message{};  ///< "" or why not / what was done, file:line:col for PDDL errors
};

class ServiceWorker {
 public:
  /// Allocates both arenas and starts the thread (start-up).
  explicit ServiceWorker(ServiceSettings settings);
  ~ServiceWorker();
  ServiceWorker(const ServiceWorker&) = delete;
  ServiceWorker& operator=(const ServiceWorker&) = delete;

  /// LOAD_PDDL(name): the domain and problems/name. No allocation, no lock. Only when idle().
  void load(std::string_view problem_name) noexcept;
  /// IS_OBSTACLE_KNOWN(x, y) on the front task, whose believed state is `belief` (copied here).
  void obstacle(double x, double y, const Task& front, ConstState belief) noexcept;

  [[nodiscard]] bool idle() const noexcept {
    return done_.load(std::memory_order_acquire) == requested_.load(std::memory_order_acquire);
  }
  /// Blocks until idle() (lockstep only: its time is virtual).
  void wait_idle() const noexcept;
  [[nodiscard]] const ServiceResult& result() const noexcept { return result_; }
  /// The cycle takes the result's new task: its arena becomes the front one.
  void accept() noexcept { front_ = 1 - front_; }

  [[nodiscard]] const ServiceSettings& settings() const noexcept { return settings_; }
  [[nodiscard]] std::size_t arena_used() const noexcept { return arenas_[static_cast<std::size_t>(front_)].used(); }

 private:
  enum class Job : std::uint8_t { kLoad, kObstacle };
  void loop();
  void run_load();
  void run_obstacle();
  void finish(bool ok, const std::string& message);

  ServiceSettings settings_;
  std::array<Arena, 2> arenas_;
  int front_ = 0;  // the cycle's; the worker reads it only while a job runs, when it is stable
  // The job's input, written by the cycle before requested_ is raised.
  Job job_ = Job::kLoad;
  std::array<char, 64> name_{};
  double x_ = 0.0, y_ = 0.0;
  const Task* front_task_ = nullptr;
  std::vector<std::uint64_t> belief_;  // sized at start-up
  // The worker's own: the files of the front task (after the last successful job).
  bool loaded_ = false;
  LoadedFiles files_;
  ServiceResult result_;
  std::atomic<std::uint64_t> requested_{0};
  std::atomic<std::uint64_t> done_{0};
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ringlet::pddl
