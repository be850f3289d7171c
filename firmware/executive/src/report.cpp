#include "ringlet/executive/report.hpp"

#include <cstdio>
#include <string>

namespace ringlet::executive {

namespace {

double us(Nanos d) { return static_cast<double>(d.count()) / 1000.0; }

std::string fmt_us(Nanos d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", us(d));
  return buf;
}

double rate_hz(const ExecutiveConfig& c, const TaskSpec& t) {
  return 1e9 / static_cast<double>(c.period.count()) / t.every;
}

// Average share of every frame the task occupies, in percent.
double frame_share(const ExecutiveConfig& c, const TaskSpec& t, const TaskStats& s) {
  return 100.0 * static_cast<double>(s.wall.mean().count()) / t.every / static_cast<double>(c.period.count());
}

// What the policies acted on, in words and as the JSON tag.
std::string judged_on_text(const ExecutiveConfig& c) {
  if (c.judge_on_model) return "the modelled cost (lockstep)";
  return c.overrun_on_cpu_time ? "thread CPU time" : "wall time";
}
const char* judged_on_tag(const ExecutiveConfig& c) {
  if (c.judge_on_model) return "model";
  return c.overrun_on_cpu_time ? "cpu" : "wall";
}

}  // namespace

nlohmann::json histogram_json(const DurationHistogram& h) {
  return {{"min_us", us(h.min())},       {"mean_us", us(h.mean())},         {"p50_us", us(h.percentile(0.50))},
          {"p99_us", us(h.percentile(0.99))}, {"p999_us", us(h.percentile(0.999))}, {"max_us", us(h.max())}};
}

void print_timing_table(std::ostream& out, const Executive& exec) {
  const auto& c = exec.config();
  char line[256];
  std::snprintf(line, sizeof line, "%-3s %-14s %7s %5s %8s %-8s %8s %8s %8s %8s %8s %8s %9s %6s %8s %6s %6s\n", "#",
                "TASK", "RATE", "PH", "BUDGET", "POLICY", "RUNS", "MIN", "AVG", "P99", "MAX", "CPU-P99", "MODEL-P99", "OVR",
                "MEAS-OVR", "SKIP", "SHARE");
  out << line;
  const auto tasks = exec.tasks();
  const auto stats = exec.task_stats();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const auto& t = tasks[i].spec;
    const auto& s = stats[i];
    char rate[16];
    std::snprintf(rate, sizeof rate, "%.1fHz", rate_hz(c, t));
    std::snprintf(line, sizeof line,
                  "%-3zu %-14s %7s %5d %8s %-8s %8llu %8s %8s %8s %8s %8s %9s %6llu %8llu %6llu %5.1f%%\n", i,
                  t.name.c_str(), rate, t.phase, fmt_us(t.budget).c_str(), std::string(to_string(t.policy)).c_str(),
                  static_cast<unsigned long long>(s.runs), fmt_us(s.wall.min()).c_str(), fmt_us(s.wall.mean()).c_str(),
                  fmt_us(s.wall.percentile(0.99)).c_str(), fmt_us(s.wall.max()).c_str(),
                  fmt_us(s.cpu.percentile(0.99)).c_str(), fmt_us(s.model.percentile(0.99)).c_str(),
                  static_cast<unsigned long long>(s.overruns), static_cast<unsigned long long>(s.measured_overruns),
                  static_cast<unsigned long long>(s.skipped), frame_share(c, t, s));
    out << line;
  }
  const auto& f = exec.frame_stats();
  std::snprintf(line, sizeof line,
                "frames %llu  period %s us  frame-overruns %llu  slips %llu  busy p99 %s us max %s us  "
                "wake-latency p99 %s us max %s us\n",
                static_cast<unsigned long long>(f.frames), fmt_us(c.period).c_str(),
                static_cast<unsigned long long>(f.frame_overruns), static_cast<unsigned long long>(f.slips),
                fmt_us(f.busy.percentile(0.99)).c_str(), fmt_us(f.busy.max()).c_str(),
                fmt_us(f.wake_latency.percentile(0.99)).c_str(), fmt_us(f.wake_latency.max()).c_str());
  out << line;
  out << "(times in us; wall time unless marked CPU or MODEL; budgets judged on " << judged_on_text(c)
      << "; MEAS-OVR: activations over budget on measured " << (c.overrun_on_cpu_time ? "CPU" : "wall") << " time)\n";
}

nlohmann::json timing_json(const Executive& exec) {
  const auto& c = exec.config();
  nlohmann::json tasks = nlohmann::json::array();
  const auto specs = exec.tasks();
  const auto stats = exec.task_stats();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const auto& t = specs[i].spec;
    const auto& s = stats[i];
    tasks.push_back({{"order", i},
                     {"name", t.name},
                     {"every", t.every},
                     {"rate_hz", rate_hz(c, t)},
                     {"phase", t.phase},
                     {"budget_us", us(t.budget)},
                     {"policy", std::string(to_string(t.policy))},
                     {"runs", s.runs},
                     {"overruns", s.overruns},
                     {"measured_overruns", s.measured_overruns},
                     {"overloads", s.overloads},
                     {"skipped", s.skipped},
                     {"degraded_runs", s.degraded_runs},
                     {"degrade_level", s.degrade_level},
                     {"share_percent", frame_share(c, t, s)},
                     {"wall", histogram_json(s.wall)},
                     {"cpu", histogram_json(s.cpu)},
                     {"model", histogram_json(s.model)}});
  }
  const auto& f = exec.frame_stats();
  return {{"period_us", us(c.period)},
          {"budgets_judged_on", judged_on_tag(c)},
          {"measured_on", c.overrun_on_cpu_time ? "cpu" : "wall"},
          {"tasks", tasks},
          {"frames",
           {{"executed", f.frames},
            {"frame_overruns", f.frame_overruns},
            {"slips", f.slips},
            {"busy", histogram_json(f.busy)},
            {"wake_latency", histogram_json(f.wake_latency)}}},
          {"failsafe", exec.failsafe_triggered()},
          {"failsafe_task", exec.failsafe_task() >= 0 ? nlohmann::json(specs[static_cast<std::size_t>(exec.failsafe_task())].spec.name)
                                                       : nlohmann::json(nullptr)}};
}

std::string describe(const Event& e, const Executive& exec) {
  const auto name = [&](std::size_t i) { return i < exec.tasks().size() ? exec.tasks()[i].spec.name : std::string("?"); };
  char buf[256];
  switch (e.kind) {
    case EventKind::kOverrun:
      std::snprintf(buf, sizeof buf, "overrun: task '%s' %s %.1f us > budget %.1f us in frame %llu (policy %s%s)%s",
                    name(e.task).c_str(), exec.config().judge_on_model ? "cost (modelled)" : "took", us(e.measured), us(e.limit), static_cast<unsigned long long>(e.frame),
                    std::string(to_string(exec.tasks()[e.task].spec.policy)).c_str(),
                    exec.tasks()[e.task].spec.policy == OverrunPolicy::kDegrade
                        ? (", level " + std::to_string(e.level)).c_str()
                        : "",
                    e.suppressed ? (" [" + std::to_string(e.suppressed) + " more not shown]").c_str() : "");
      break;
    case EventKind::kFrameOverrun:
      std::snprintf(buf, sizeof buf, "frame overrun: frame %llu ran %.1f us > period %.1f us; %llu frame(s) skipped",
                    static_cast<unsigned long long>(e.frame), us(e.measured), us(e.limit),
                    static_cast<unsigned long long>(e.suppressed));
      break;
    case EventKind::kFailsafe:
      std::snprintf(buf, sizeof buf, "FAILSAFE: task '%s' overran (%.1f us > %.1f us) in frame %llu; safe state commanded",
                    name(e.task).c_str(), us(e.measured), us(e.limit), static_cast<unsigned long long>(e.frame));
      break;
  }
  return buf;
}

}  // namespace ringlet::executive
