#pragma once
// Shared by the firmware tests: the shipped configuration with a few keys changed, as text, so
// that every test builds the stack exactly the way the binary does.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "ringlet/firmware/config.hpp"
#include "ringlet/firmware/mission_runner.hpp"
#include "ringlet/firmware/stack.hpp"

namespace ringlet::firmware::test {

inline const std::filesystem::path kShippedConfig = RINGLET_SHIPPED_CONFIG;
/// The main job's configuration: the SPL field with the camera and vision (next to the other).
inline const std::filesystem::path kSplConfig = kShippedConfig.parent_path() / "spl_field.toml";

/// How much slower than the host's native speed this build runs (qemu-aarch64, sanitizers): CPU
/// time measured here says nothing about the robot then, and budgets are scaled by it or not
/// judged. 1 for native builds (set by tests/firmware/CMakeLists.txt).
inline constexpr double kCpuSlowdown = RINGLET_CPU_SLOWDOWN;
inline constexpr bool kNativeSpeed = kCpuSlowdown == 1.0;

inline std::string shipped_config_text(const std::filesystem::path& file = kShippedConfig) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The shipped configuration with the first line that starts with `key` replaced by `line`
/// (or `line` appended to the text when no line starts with `key`).
inline std::string with_line(std::string text, const std::string& key, const std::string& line) {
  std::istringstream in(text);
  std::ostringstream out;
  std::string l;
  bool replaced = false;
  while (std::getline(in, l)) {
    if (!replaced && l.rfind(key, 0) == 0) {
      out << line << '\n';
      replaced = true;
    } else {
      out << l << '\n';
    }
  }
  if (!replaced) out << line << '\n';
  return out.str();
}

/// Parses config text as if it were the shipped file (relative paths resolve the same way).
inline FirmwareConfig parse_as_shipped(const std::string& text) {
  return parse_config(text, kShippedConfig.string(), kShippedConfig.parent_path());
}

/// The ConfigError parse_as_shipped(text) throws, or "(no error)".
inline std::string error_of(const std::string& text) {
  try {
    (void)parse_as_shipped(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

/// Runs `stack`'s mission as the binary does, for cfg.mission.timeout_s at most, its log dropped.
inline RunOutcome run_to_end(FirmwareStack& stack, const FirmwareConfig& cfg) {
  std::atomic<bool> interrupt{false};
  std::ostringstream log;
  return run_mission(stack, cfg.mission.timeout_s, interrupt, log);
}

}  // namespace ringlet::firmware::test
