#include "ringlet/executive/task_table.hpp"

#include <numeric>
#include <set>
#include <sstream>

namespace ringlet::executive {

std::string_view to_string(OverrunPolicy p) noexcept {
  switch (p) {
    case OverrunPolicy::kWarn: return "warn";
    case OverrunPolicy::kSkip: return "skip";
    case OverrunPolicy::kDegrade: return "degrade";
    case OverrunPolicy::kFailsafe: return "failsafe";
  }
  return "?";
}

bool parse_policy(std::string_view text, OverrunPolicy& out) noexcept {
  for (auto p : {OverrunPolicy::kWarn, OverrunPolicy::kSkip, OverrunPolicy::kDegrade, OverrunPolicy::kFailsafe}) {
    if (text == to_string(p)) {
      out = p;
      return true;
    }
  }
  return false;
}

namespace {

std::string us(Nanos d) {
  std::ostringstream s;
  s << static_cast<double>(d.count()) / 1000.0 << " us";
  return s.str();
}

// Frames in one hyperperiod (the pattern of active tasks repeats after it), or 0 when it is
// longer than kMaxHyperperiod.
std::uint64_t hyperperiod(std::span<const TaskSpec> tasks) {
  std::uint64_t h = 1;
  for (const auto& t : tasks) {
    h = std::lcm(h, static_cast<std::uint64_t>(t.every));
    if (h > kMaxHyperperiod) return 0;
  }
  return h;
}

// Collects problems, keeping the first kMaxProblemsListed and counting the rest, so that a
// pathological table costs bounded memory and output.
class Problems {
 public:
  [[nodiscard]] bool full() const noexcept { return listed_.size() >= kMaxProblemsListed; }
  void add(std::string problem) {
    if (full()) {
      ++more_;
    } else {
      listed_.push_back(std::move(problem));
    }
  }
  /// Counts one more problem without building its message (the caller saw full()).
  void count() noexcept { ++more_; }
  [[nodiscard]] bool empty() const noexcept { return listed_.empty(); }
  std::vector<std::string> finish() {
    if (more_ > 0) listed_.push_back("... and " + std::to_string(more_) + " more problems");
    return std::move(listed_);
  }

 private:
  std::vector<std::string> listed_;
  std::uint64_t more_ = 0;
};

}  // namespace

std::string list_problems(std::span<const std::string> problems, std::size_t max_listed) {
  std::string text;
  for (std::size_t i = 0; i < problems.size() && i < max_listed; ++i) text += "\n  - " + problems[i];
  if (problems.size() > max_listed) text += "\n  - ... and " + std::to_string(problems.size() - max_listed) + " more";
  return text;
}

std::vector<std::string> validate(const ExecutiveConfig& config, std::span<const TaskSpec> tasks) {
  Problems problems;
  if (config.period <= Nanos{0}) {
    problems.add("executive period must be > 0");
    return problems.finish();
  }
  if (config.watchdog_periods < 0) problems.add("watchdog_periods must be >= 0");
  if (tasks.empty()) problems.add("the task table is empty");
  if (tasks.size() > kMaxTasks) {
    problems.add("the task table has " + std::to_string(tasks.size()) + " rows; at most " + std::to_string(kMaxTasks) +
                 " are allowed");
    return problems.finish();
  }

  std::set<std::string, std::less<>> names;
  bool shapes_ok = true;
  for (const auto& t : tasks) {
    const std::string who = "task '" + t.name + "': ";
    if (t.name.empty()) problems.add("a task has an empty name");
    if (!names.insert(t.name).second) problems.add(who + "name used twice");
    if (t.every < 1) {
      problems.add(who + "every must be >= 1 (rate = base rate / every), got " + std::to_string(t.every));
      shapes_ok = false;
    } else if (t.phase < 0 || t.phase >= t.every) {
      problems.add(who + "phase must be in 0.." + std::to_string(t.every - 1) + ", got " + std::to_string(t.phase));
      shapes_ok = false;
    }
    if (t.budget <= Nanos{0}) {
      problems.add(who + "budget must be > 0");
      shapes_ok = false;
    } else if (t.budget > config.period) {
      problems.add(who + "budget " + us(t.budget) + " is larger than the period " + us(config.period));
      shapes_ok = false;
    }
  }
  if (!shapes_ok || tasks.empty()) return problems.finish();

  const std::uint64_t h = hyperperiod(tasks);
  if (h == 0) {
    problems.add("the rates repeat only after more than " + std::to_string(kMaxHyperperiod) +
                 " frames; choose 'every' values with a smaller common multiple");
    return problems.finish();
  }
  for (std::uint64_t frame = 0; frame < h; ++frame) {
    Nanos load{0};
    for (const auto& t : tasks) {
      if (t.active_in(frame)) load += t.budget;
    }
    if (load <= config.period) continue;
    if (problems.full()) {
      problems.count();
      continue;
    }
    std::string who;
    for (const auto& t : tasks) {
      if (t.active_in(frame)) who += (who.empty() ? "" : ", ") + t.name;
    }
    problems.add("frame " + std::to_string(frame) + " (mod " + std::to_string(h) + ") is overloaded: budgets of " + who +
                 " add up to " + us(load) + " > period " + us(config.period) +
                 "; move a task to another phase or cut its budget");
  }
  return problems.finish();
}

}  // namespace ringlet::executive
