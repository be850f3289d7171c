#include "ringlet/firmware/mission_report.hpp"

#include <bit>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <string>

#include "ringlet/executive/report.hpp"
#include "ringlet/vision/stages.hpp"

namespace ringlet::firmware {

namespace {

// FNV-1a, fed byte by byte in little-endian order whatever the host, so that x86-64 and aarch64
// agree.
struct Fnv1a {
  std::uint64_t h = 1469598103934665603ULL;
  void bits(std::uint64_t v) noexcept {
    for (int i = 0; i < 8; ++i) {
      h ^= v & 0xffU;
      h *= 1099511628211ULL;
      v >>= 8;
    }
  }
  void real(double v) noexcept { bits(std::bit_cast<std::uint64_t>(v)); }
  void text(std::string_view t) noexcept {
    bits(t.size());
    for (const char c : t) bits(static_cast<unsigned char>(c));
  }
};

// Everything the controller decided that is not a pose: what the schedule ran, skipped and
// degraded, what vision found, where the machines ended, what the robot hit. Host measurements
// (wall and CPU times, measured overruns) stay out: they differ from run to run by nature. So do
// scores computed from ground truth with libm (see head tracking below).
std::uint64_t run_hash(const FirmwareStack& stack, const MissionSummary& s) noexcept {
  Fnv1a f;
  f.bits(s.trajectory_hash);
  const auto tasks = stack.executive().tasks();
  const auto stats = stack.executive().task_stats();
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    f.text(tasks[i].spec.name);
    f.bits(stats[i].runs);
    f.bits(stats[i].overruns);
    f.bits(stats[i].skipped);
    f.bits(stats[i].degraded_runs);
  }
  f.bits(stack.executive().next_frame());
  f.bits(s.failsafe ? 1U : 0U);
  for (const auto& m : s.machines) {
    f.text(m.name);
    f.text(m.state);
    f.bits(m.ringlets);
    f.bits(m.suspended ? 1U : 0U);
  }
  f.bits(s.goals_reached);
  f.bits(s.collisions);
  f.bits(s.fsm_status_seen);
  if (s.vision) {
    for (const std::uint64_t v : {s.vision->frames, s.vision->with_lines, s.vision->lines, s.vision->with_ball,
                                  s.vision->cut, s.vision->degraded, s.vision->bad_frames, s.vision->missed_frames}) {
      f.bits(v);
    }
  }
  // The head-tracking score counts, not its error sum: the error is computed for scoring with libm
  // (atan2), whose last bits differ between x86-64 and aarch64, and it decides nothing.
  if (s.truth) {
    f.bits(s.truth->head.frames);
    f.bits(s.truth->head.on_target);
  }
  return f.h;
}

std::string seed_text(const MissionSummary& s) { return s.seed ? std::to_string(*s.seed) : std::string("none"); }

}  // namespace

std::uint64_t trajectory_hash(std::span<const hal::Pose2> poses) noexcept {
  Fnv1a f;
  for (const auto& p : poses) {
    f.real(p.x);
    f.real(p.y);
    f.real(p.theta);
  }
  return f.h;
}

MissionSummary summarize(const FirmwareStack& stack, const RunOutcome& outcome, bool safe_before_shutdown) {
  const auto& cfg = stack.config();
  MissionSummary s;
  const Telemetry& telemetry = stack.telemetry();
  s.backend = cfg.backend;
  s.world = cfg.backend_settings ? cfg.backend_settings->source_name() : std::string();
  if (cfg.seed_override || (cfg.backend_settings && cfg.backend_settings->seed())) s.seed = cfg.seed();
  s.goals_reached = telemetry.goals_reached();
  s.goal_count = cfg.mission.goals.size();
  s.complete = s.goal_count > 0 && s.goals_reached == s.goal_count;
  s.mission_seconds = outcome.schedule_seconds;
  s.wall_seconds = outcome.wall_seconds;
  s.distance_m = telemetry.odometry_path();
  s.collisions = telemetry.collisions();
  s.dropped_samples = telemetry.dropped_samples();
  s.failsafe = stack.executive().failsafe_triggered();
  s.watchdog = outcome.watchdog_fired;
  s.interrupted = outcome.interrupted;
  s.signal = outcome.signal;
  s.safe_state = safe_before_shutdown || outcome.interrupted;
  s.safe_at_end = outcome.safe_at_end;
  const auto because = [&s](const std::string& why) {
    s.safe_state_reason += (s.safe_state_reason.empty() ? "" : ", ") + why;
  };
  if (s.failsafe) because("failsafe policy");
  if (s.watchdog) because("watchdog");
  if (s.interrupted) because(s.signal != 0 ? signal_name(s.signal) : std::string("interrupted"));
  s.trajectory_hash = trajectory_hash(stack.telemetry().trajectory());
  const auto& schedule = stack.schedule();
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    const auto& m = schedule.machine(i);
    s.machines.push_back({std::string(m.name()), std::string(m.current_state_name()), m.ringlets(), m.suspended()});
  }
  s.fsm_status_seen = stack.fsm_status_seen();
  if (const hal::GroundTruth* truth = stack.truth()) {
    s.truth = TruthSummary{truth->distance_travelled(), truth->collisions(),
                           stack.truth_score() != nullptr ? stack.truth_score()->head_tracking() : HeadTracking{},
                           stack.truth_score() != nullptr ? stack.truth_score()->localization() : LocalizationScore{}};
  }
  if (const VisionStats* v = telemetry.vision()) s.vision = *v;
  s.run_hash = run_hash(stack, s);
  if (const hal::BoardHealth* board = stack.robot().board_health()) s.board = *board;
  if (const RemoteLink* r = stack.remote()) {
    const auto& b = r->bridge_config();
    s.remote = RemoteSummary{b.robot,        static_cast<int>(b.domain.id),   b.domain.partition,
                             r->totals(),    r->counts(wb::FsmStatus::kId), r->unacknowledged_frames(),
                             r->requests(),  std::chrono::duration<double, std::milli>(r->cpu_time()).count(),
                             r->pumps()};
  }
  return s;
}

void print_summary(std::ostream& out, const MissionSummary& s) {
  char line[512];
  std::snprintf(line, sizeof line,
                "MISSION %s — %zu/%zu goals in %.2f s (simulated on %s, %.3f s of host time)\n"
                "  world %s, seed %s, distance %.2f m, collisions %llu, safe state forced: %s%s%s%s\n"
                "  trajectory hash %016llx  run hash %016llx\n",
                s.complete ? "COMPLETE" : (s.interrupted ? "INTERRUPTED" : "INCOMPLETE"), s.goals_reached,
                s.goal_count, s.mission_seconds, s.backend.c_str(), s.wall_seconds, s.world.c_str(),
                seed_text(s).c_str(), s.distance_m, static_cast<unsigned long long>(s.collisions),
                s.safe_state ? "yes" : "no", s.safe_state_reason.empty() ? "" : " (",
                s.safe_state_reason.c_str(), s.safe_state_reason.empty() ? "" : ")",
                static_cast<unsigned long long>(s.trajectory_hash), static_cast<unsigned long long>(s.run_hash));
  out << line;
  for (const auto& m : s.machines) {
    std::snprintf(line, sizeof line, "  machine %-12s final state %-12s ringlets %8llu%s\n", m.name.c_str(),
                  m.state.c_str(), static_cast<unsigned long long>(m.ringlets), m.suspended ? "  (suspended)" : "");
    out << line;
  }
  std::snprintf(line, sizeof line, "  FsmStatus messages delivered by whiteboard subscription: %llu\n",
                static_cast<unsigned long long>(s.fsm_status_seen));
  out << line;
  if (s.vision) {
    const VisionStats& v = *s.vision;
    const auto share = [&v](std::uint64_t n) { return v.frames == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(v.frames); };
    std::snprintf(line, sizeof line,
                  "  vision: %llu frames, lines in %.1f %% (%.1f per frame), ball in %.1f %%, robots %llu, "
                  "cut by the deadline %llu (the line search %llu), degraded %llu, frames missed %llu\n",
                  static_cast<unsigned long long>(v.frames), share(v.with_lines),
                  v.frames == 0 ? 0.0 : static_cast<double>(v.lines) / static_cast<double>(v.frames), share(v.with_ball),
                  static_cast<unsigned long long>(v.robots), static_cast<unsigned long long>(v.cut),
                  static_cast<unsigned long long>(v.lines_cut), static_cast<unsigned long long>(v.degraded),
                  static_cast<unsigned long long>(v.missed_frames));
    out << line;
    // Where the budget goes: each stage's modelled board time per frame (the cost model's rows).
    out << "  vision by stage, modelled on the board, p50/p99 us:";
    for (std::size_t i = 0; i < vision::kStageCount; ++i) {
      const executive::DurationHistogram& h = v.stage_model[i];
      std::snprintf(line, sizeof line, "%s %s %.0f/%.0f", i == 0 ? "" : ",",
                    std::string(vision::stage_name(static_cast<vision::Stage>(i))).c_str(),
                    static_cast<double>(h.percentile(0.50).count()) / 1e3, static_cast<double>(h.percentile(0.99).count()) / 1e3);
      out << line;
    }
    out << "\n";
  }
  if (s.remote) {
    const RemoteSummary& r = *s.remote;
    std::snprintf(line, sizeof line,
                  "  remote: robot %d on DDS domain %d, partition \"%s\": %llu samples sent (FsmStatus %llu), "
                  "%llu missed, %llu rate-limited, %llu failed\n",
                  r.robot, r.domain, r.partition.c_str(), static_cast<unsigned long long>(r.totals.sent),
                  static_cast<unsigned long long>(r.fsm_status.sent), static_cast<unsigned long long>(r.totals.missed),
                  static_cast<unsigned long long>(r.totals.rate_skipped), static_cast<unsigned long long>(r.totals.failed));
    out << line;
    const remote::RequestCounts& q = r.requests;
    if (q.accepted + q.unauthorized + q.malformed + q.dropped > 0) {
      std::snprintf(line, sizeof line, "  remote writes: %llu accepted, %llu not allowed, %llu malformed, %llu dropped\n",
                    static_cast<unsigned long long>(q.accepted), static_cast<unsigned long long>(q.unauthorized),
                    static_cast<unsigned long long>(q.malformed), static_cast<unsigned long long>(q.dropped));
      out << line;
    }
  }
  if (s.board) {
    const hal::BoardHealth& b = *s.board;
    std::snprintf(line, sizeof line,
                  "  board: %s, %llu frames in, %llu out, %llu malformed, %llu unknown, %llu stale readings, "
                  "%llu heartbeats lost, %llu bus-off, %llu dropped (queue full), %llu board faults\n",
                  b.board_alive ? "alive" : "LOST", static_cast<unsigned long long>(b.frames_received),
                  static_cast<unsigned long long>(b.frames_sent), static_cast<unsigned long long>(b.malformed),
                  static_cast<unsigned long long>(b.unknown_id), static_cast<unsigned long long>(b.stale_readings),
                  static_cast<unsigned long long>(b.heartbeat_losses), static_cast<unsigned long long>(b.bus_off),
                  static_cast<unsigned long long>(b.tx_full), static_cast<unsigned long long>(b.board_faults));
    out << line;
    const hal::RoundTrip& rt = b.round_trip;
    if (rt.samples > 0) {
      std::snprintf(line, sizeof line,
                    "  command -> board -> sensor round trip: p50 %.2f ms, p99 %.2f ms, max %.2f ms (%llu commands)\n",
                    rt.p50_us / 1e3, rt.p99_us / 1e3, rt.max_us / 1e3, static_cast<unsigned long long>(rt.samples));
      out << line;
    }
  }
  if (s.dropped_samples > 0) {
    std::snprintf(line, sizeof line, "  trajectory samples dropped (buffer full): %llu\n",
                  static_cast<unsigned long long>(s.dropped_samples));
    out << line;
  }
  if (s.truth) {
    std::snprintf(line, sizeof line, "  ground truth: distance %.2f m, collisions %llu\n", s.truth->distance_m,
                  static_cast<unsigned long long>(s.truth->collisions));
    out << line;
  }
  if (s.truth && s.truth->localization.frames > 0) {
    const LocalizationScore& l = s.truth->localization;
    std::snprintf(line, sizeof line,
                  "  localization vs truth: position mean %.3f m, p95 %.3f m, max %.3f m; heading mean %.2f deg, p95 %.1f "
                  "deg; Pose valid in %.1f %% of %llu frames\n",
                  l.mean_position(), l.p95_position(), l.max_position, l.mean_heading_deg(), l.p95_heading_deg(),
                  100.0 * static_cast<double>(l.valid_frames) / static_cast<double>(l.frames),
                  static_cast<unsigned long long>(l.frames));
    out << line;
  }
  if (s.truth && s.truth->head.frames > 0) {
    std::snprintf(line, sizeof line,
                  "  head on the ball (true ball, yaw within 5 deg): %.1f %% of %llu frames, mean error "
                  "%.2f deg, max %.1f deg\n",
                  100.0 * s.truth->head.on_target_share(), static_cast<unsigned long long>(s.truth->head.frames),
                  hal::rad_to_deg(s.truth->head.mean_error()), hal::rad_to_deg(s.truth->head.max_error));
    out << line;
  }
}

namespace {
nlohmann::json counts_json(const remote::TypeCounts& c) {
  return {{"sent", c.sent}, {"missed", c.missed}, {"rate_skipped", c.rate_skipped}, {"failed", c.failed}};
}
nlohmann::json board_json(const MissionSummary& s) {
  if (!s.board) return nullptr;
  const hal::BoardHealth& b = *s.board;
  static constexpr const char* kBus[] = {"active", "error-passive", "bus-off"};
  return {{"alive", b.board_alive},          {"board_state", b.board_state},
          {"bus", kBus[static_cast<int>(b.bus)]}, {"frames_received", b.frames_received},
          {"frames_sent", b.frames_sent},    {"malformed", b.malformed},
          {"unknown_id", b.unknown_id},      {"stale_readings", b.stale_readings},
          {"heartbeat_losses", b.heartbeat_losses}, {"bus_off", b.bus_off},
          {"error_passive", b.error_passive}, {"tx_full", b.tx_full},
          {"socket_failures", b.socket_failures}, {"reconnects", b.reconnects},
          {"refused_commands", b.refused_commands}, {"board_faults", b.board_faults},
          {"last_fault", b.last_fault},      {"incomplete_scans", b.incomplete_scans},
          {"round_trip", {{"samples", b.round_trip.samples}, {"p50_us", b.round_trip.p50_us},
                          {"p99_us", b.round_trip.p99_us}, {"max_us", b.round_trip.max_us}}}};
}
nlohmann::json remote_json(const MissionSummary& s) {
  if (!s.remote) return nullptr;
  const RemoteSummary& r = *s.remote;
  return {{"robot", r.robot},
          {"domain", r.domain},
          {"partition", r.partition},
          {"totals", counts_json(r.totals)},
          {"fsm_status", counts_json(r.fsm_status)},
          {"unacknowledged_frames", r.unacknowledged_frames},
          {"cpu_ms", r.cpu_ms},
          {"cpu_us_per_pump", r.pumps == 0 ? 0.0 : 1e3 * r.cpu_ms / static_cast<double>(r.pumps)},
          {"pumps", r.pumps},
          {"requests",
           {{"accepted", r.requests.accepted},
            {"unauthorized", r.requests.unauthorized},
            {"malformed", r.requests.malformed},
            {"dropped", r.requests.dropped}}}};
}
}  // namespace

nlohmann::json summary_json(const MissionSummary& s) {
  char hash[20];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(s.trajectory_hash));
  char run[20];
  std::snprintf(run, sizeof run, "%016llx", static_cast<unsigned long long>(s.run_hash));
  nlohmann::json machines = nlohmann::json::array();
  for (const auto& m : s.machines) {
    machines.push_back({{"name", m.name}, {"state", m.state}, {"ringlets", m.ringlets}, {"suspended", m.suspended}});
  }
  nlohmann::json vision = nullptr;
  if (s.vision) {
    vision = {{"frames", s.vision->frames},       {"with_lines", s.vision->with_lines}, {"lines", s.vision->lines},
              {"with_ball", s.vision->with_ball}, {"cut", s.vision->cut},               {"degraded", s.vision->degraded},
              {"bad_frames", s.vision->bad_frames}, {"missed_frames", s.vision->missed_frames},
              {"robots", s.vision->robots},
              {"lines_cut", s.vision->lines_cut}};
    nlohmann::json stages = nlohmann::json::object();
    for (std::size_t i = 0; i < vision::kStageCount; ++i) {
      stages[std::string(vision::stage_name(static_cast<vision::Stage>(i)))] = executive::histogram_json(s.vision->stage_model[i]);
    }
    vision["stage_model"] = std::move(stages);  // modelled board time per frame, by stage
  }
  return {{"backend", s.backend},
          {"world", s.world},
          {"seed", s.seed ? nlohmann::json(*s.seed) : nlohmann::json(nullptr)},
          {"goals_reached", s.goals_reached},
          {"goal_count", s.goal_count},
          {"complete", s.complete},
          {"mission_seconds", s.mission_seconds},
          {"host_seconds", s.wall_seconds},
          {"distance_m", s.distance_m},
          {"collisions", s.collisions},
          {"safe_state_forced", s.safe_state},
          {"safe_state_reason", s.safe_state_reason.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.safe_state_reason)},
          {"safe_state_at_end", s.safe_at_end},
          {"failsafe", s.failsafe},
          {"watchdog", s.watchdog},
          {"interrupted", s.interrupted},
          {"signal", s.signal != 0 ? nlohmann::json(signal_name(s.signal)) : nlohmann::json(nullptr)},
          {"trajectory_hash", hash},
          {"run_hash", run},
          {"machines", machines},
          {"fsm_status_seen", s.fsm_status_seen},
          {"vision", vision},
          {"remote", remote_json(s)},
          {"board", board_json(s)},
          {"trajectory_samples_dropped", s.dropped_samples},
          {"ground_truth", s.truth ? nlohmann::json{{"distance_m", s.truth->distance_m},
                                                    {"collisions", s.truth->collisions}}
                                   : nlohmann::json(nullptr)},
          {"localization", s.truth && s.truth->localization.frames > 0
                               ? nlohmann::json{{"frames", s.truth->localization.frames},
                                                {"valid_frames", s.truth->localization.valid_frames},
                                                {"position_mean_m", s.truth->localization.mean_position()},
                                                {"position_p95_m", s.truth->localization.p95_position()},
                                                {"position_max_m", s.truth->localization.max_position},
                                                {"heading_mean_deg", s.truth->localization.mean_heading_deg()},
                                                {"heading_p95_deg", s.truth->localization.p95_heading_deg()}}
                               : nlohmann::json(nullptr)},
          {"head_tracking", s.truth ? nlohmann::json{{"frames", s.truth->head.frames},
                                                     {"on_target_share", s.truth->head.on_target_share()},
                                                     {"mean_error_deg", hal::rad_to_deg(s.truth->head.mean_error())},
                                                     {"max_error_deg", hal::rad_to_deg(s.truth->head.max_error)}}
                                    : nlohmann::json(nullptr)}};
}

bool write_picture(std::ostream& out, const FirmwareStack& stack, const MissionSummary& s) {
  const hal::GroundTruth* truth = stack.truth();
  if (truth == nullptr) return false;
  std::vector<hal::WorldPoint> goals;
  for (const auto& g : stack.config().mission.goals) goals.push_back({g.x, g.y});
  char caption[256];
  std::snprintf(caption, sizeof caption, "%s: %zu/%zu goals in %.1f s, %.1f m, %llu collisions (seed %s)",
                s.world.c_str(), s.goals_reached, s.goal_count, s.mission_seconds, s.distance_m,
                static_cast<unsigned long long>(s.collisions), seed_text(s).c_str());
  hal::RunPicture run{stack.telemetry().trajectory(), stack.telemetry().collision_points(), goals, s.goals_reached, caption};
  run.plans = stack.telemetry().plan_picture();
  run.localization = stack.telemetry().localization_picture();
  truth->write_picture(out, run);
  return true;
}

int exit_code(const MissionSummary& s) noexcept {
  if (s.interrupted) return 128 + (s.signal != 0 ? s.signal : SIGINT);
  if (s.safe_state) return 4;
  if (!s.complete) return 3;
  return 0;
}

}  // namespace ringlet::firmware
