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

}  // namespace

std::vector<std::string> validate(const ExecutiveConfig& config, std::span<const TaskSpec> tasks) {
  std::vector<std::string> problems;
  if (config.period <= Nanos{0}) {
    problems.push_back("executive period must be > 0");
    return problems;
  }
  if (config.watchdog_periods < 0) problems.push_back("watchdog_periods must be >= 0");
  if (tasks.empty()) problems.push_back("the task table is empty");

  std::set<std::string, std::less<>> names;
  bool shapes_ok = true;
  for (const auto& t : tasks) {
    const std::string who = "task '" + t.name + "': ";
    if (t.name.empty()) problems.push_back("a task has an empty name");
    if (!names.insert(t.name).second) problems.push_back(who + "name used twice");
    if (t.every < 1) {
      problems.push_back(who + "every must be >= 1 (rate = base rate / every), got " + std::to_string(t.every));
      shapes_ok = false;
    } else if (t.phase < 0 || t.phase >= t.every) {
      problems.push_back(who + "phase must be in 0.." + std::to_string(t.every - 1) + ", got " +
                         std::to_string(t.phase));
      shapes_ok = false;
    }
    if (t.budget <= Nanos{0}) {
      problems.push_back(who + "budget must be > 0");
      shapes_ok = false;
    } else if (t.budget > config.period) {
      problems.push_back(who + "budget " + us(t.budget) + " is larger than the period " + us(config.period));
      shapes_ok = false;
    }
  }
  if (!shapes_ok || tasks.empty()) return problems;

  const std::uint64_t h = hyperperiod(tasks);
  if (h == 0) {
    problems.push_back("the rates repeat only after more than " + std::to_string(kMaxHyperperiod) +
                       " frames; choose 'every' values with a smaller common multiple");
    return problems;
  }
  for (std::uint64_t frame = 0; frame < h; ++frame) {
    Nanos load{0};
    std::string who;
    for (const auto& t : tasks) {
      if (!t.active_in(frame)) continue;
      load += t.budget;
      who += (who.empty() ? "" : ", ") + t.name;
    }
    if (load > config.period) {
      problems.push_back("frame " + std::to_string(frame) + " (mod " + std::to_string(h) + ") is overloaded: budgets of " +
                         who + " add up to " + us(load) + " > period " + us(config.period) +
                         "; move a task to another phase or cut its budget");
    }
  }
  return problems;
}

}  // namespace ringlet::executive
