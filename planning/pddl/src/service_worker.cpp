#include "ringlet/pddl/service_worker.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

#include "ringlet/pddl/grounder.hpp"

namespace ringlet::pddl {
namespace {

std::size_t words_for(std::int32_t facts) { return static_cast<std::size_t>(std::max(facts, 1) + 63) / 64; }

// A problem name is a file in the problems folder, never a path out of it.
bool plain_name(std::string_view n) {
  return !n.empty() && n.find('/') == std::string_view::npos && n.find('\\') == std::string_view::npos &&
         n != "." && n != "..";
}

}  // namespace

ServiceWorker::ServiceWorker(ServiceSettings settings)
    : settings_(std::move(settings)),
      arenas_{Arena(settings_.arena_bytes), Arena(settings_.arena_bytes)},
      belief_(words_for(settings_.max_facts), 0) {
  thread_ = std::thread([this] { loop(); });
}

ServiceWorker::~ServiceWorker() {
  stop_.store(true, std::memory_order_release);
  requested_.fetch_add(1, std::memory_order_acq_rel);  // wakes the thread
  requested_.notify_one();
  thread_.join();
}

void ServiceWorker::load(std::string_view problem_name) noexcept {
  job_ = Job::kLoad;
  const std::size_t n = std::min(problem_name.size(), name_.size() - 1);
  std::memcpy(name_.data(), problem_name.data(), n);
  name_[n] = '\0';
  requested_.fetch_add(1, std::memory_order_acq_rel);
  requested_.notify_one();
}

void ServiceWorker::obstacle(double x, double y, const Task& front, ConstState belief) noexcept {
  job_ = Job::kObstacle;
  x_ = x;
  y_ = y;
  front_task_ = &front;
  std::fill(belief_.begin(), belief_.end(), 0);
  std::copy_n(belief.begin(), std::min(belief.size(), belief_.size()), belief_.begin());
  requested_.fetch_add(1, std::memory_order_acq_rel);
  requested_.notify_one();
}

void ServiceWorker::wait_idle() const noexcept {
  for (;;) {
    const std::uint64_t done = done_.load(std::memory_order_acquire);
    if (done == requested_.load(std::memory_order_acquire)) return;
    done_.wait(done, std::memory_order_acquire);
  }
}

void ServiceWorker::loop() {
  std::uint64_t seen = 0;
  for (;;) {
    requested_.wait(seen, std::memory_order_acquire);
    if (stop_.load(std::memory_order_acquire)) return;
    seen = requested_.load(std::memory_order_acquire);
    result_ = ServiceResult{};
    try {
      if (job_ == Job::kLoad) {
        run_load();
      } else {
        run_obstacle();
      }
    } catch (const std::exception& e) {  // out of host memory, say: a reply, never a crash
      finish(false, std::string("the service failed: ") + e.what());
    }
    done_.store(seen, std::memory_order_release);
    done_.notify_all();
  }
}

void ServiceWorker::finish(bool ok, const std::string& message) {
  result_.ok = ok;
  const std::size_t n = std::min(message.size(), result_.message.size() - 1);
  std::memcpy(result_.message.data(), message.data(), n);
  result_.message[n] = '\0';
}

void ServiceWorker::run_load() {
  const std::string name(name_.data());
  if (!plain_name(name)) {
    finish(false, "LOAD_PDDL takes the name of a file in " + settings_.problems.string() + ", not \"" + name + "\"");
    return;
  }
  auto loaded = load_files(settings_.domain.string(), (settings_.problems / name).string());
  if (auto* e = std::get_if<Error>(&loaded)) {
    finish(false, e->to_string());
    return;
  }
  LoadedFiles& files = std::get<LoadedFiles>(loaded);
  if (files.problem.init.empty() && files.problem.goal.empty()) {
    finish(false, (settings_.problems / name).string() + ": the problem has neither an initial state nor a goal");
    return;
  }
  Arena& back = arenas_[static_cast<std::size_t>(1 - front_)];
  GroundResult g = ground(files.domain, files.problem, back);
  if (g.status != GroundStatus::kOk) {
    finish(false, g.message);
    return;
  }
  if (g.task.fact_count > settings_.max_facts) {
    finish(false, name + " grounds to " + std::to_string(g.task.fact_count) + " facts, more than [pddl] max_facts " +
                      std::to_string(settings_.max_facts));
    return;
  }
  files_ = std::move(files);
  loaded_ = true;
  result_.task = g.task;
  result_.has_task = true;
  finish(true, files_.problem.name + ": " + std::to_string(g.task.fact_count) + " facts, " +
                   std::to_string(g.task.operator_count()) + " operators");
}

void ServiceWorker::run_obstacle() {
  if (!loaded_ || front_task_ == nullptr) {
    finish(false, "no problem loaded (LOAD_PDDL first)");
    return;
  }
  Problem problem = files_.problem;  // the edit is kept only if it grounds
  set_initial_state(files_.domain, problem, *front_task_, belief_);
  ObstacleEdit edit = add_obstacle(files_.domain, problem, settings_.places, x_, y_, settings_.obstacle_radius);
  if (!edit.ok) {
    finish(false, edit.message);
    return;
  }
  result_.known = edit.known;
  if (edit.known) {  // nothing new: the cycle keeps its task, plan and belief
    finish(true, edit.message);
    return;
  }
  Arena& back = arenas_[static_cast<std::size_t>(1 - front_)];
  GroundResult g = ground(files_.domain, problem, back);
  if (g.status != GroundStatus::kOk) {
    finish(false, g.message);
    return;
  }
  files_.problem = std::move(problem);
  result_.task = g.task;
  result_.has_task = true;
  finish(true, edit.message);
}

}  // namespace ringlet::pddl
