// Fuzz target: the firmware's configuration parser (TOML text -> FirmwareConfig). Any input must
// either give a configuration that keeps the parser's promises, or a ConfigError naming the
// source; any other exception, crash or sanitizer report is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "ringlet/executive/task_table.hpp"
#include "ringlet/firmware/config.hpp"

namespace {

const std::string kSource = "fuzz.toml";

// What a caller may rely on once parse_config returned (firmware/README.md, config.hpp).
void check(const ringlet::firmware::FirmwareConfig& cfg) {
  if (cfg.source != kSource) __builtin_trap();
  if (cfg.tasks.empty()) __builtin_trap();
  if (!ringlet::executive::validate(cfg.executive, cfg.tasks).empty()) __builtin_trap();
  for (const auto& t : cfg.tasks) {
    if (t.name.empty() || t.every < 1 || t.phase < 0 || t.phase >= t.every) __builtin_trap();
  }
  // The chosen backend's section was read (the factory relies on it), and a mission has goals to
  // visit: at least one, at most what the whiteboard holds, all finite.
  if (cfg.backend_settings == nullptr) __builtin_trap();
  const auto& goals = cfg.mission.goals;
  if (goals.empty() || goals.size() > ringlet::firmware::MissionSettings::kMaxGoals) __builtin_trap();
  for (const auto& g : goals) {
    if (!std::isfinite(g.x) || !std::isfinite(g.y)) __builtin_trap();
  }
  if (!(cfg.mission.goal_tolerance > 0.0) || !(cfg.mission.timeout_s > 0.0)) __builtin_trap();
  if (cfg.safety.release_range <= cfg.safety.stop_range) __builtin_trap();
  if (cfg.follower.min_speed > cfg.follower.max_speed) __builtin_trap();
  if (cfg.camera.intrinsics.width % 2 != 0) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    check(ringlet::firmware::parse_config(text, kSource, "/fuzz/base"));
  } catch (const ringlet::firmware::ConfigError& e) {
    // Every message names where: "fuzz.toml:line:col: ...".
    if (std::string_view(e.what()).substr(0, kSource.size() + 1) != kSource + ":") __builtin_trap();
  }
  return 0;
}
