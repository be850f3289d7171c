// ringlet-wb-log: reads the whiteboard logs `ringlet --wb-log FILE` writes (message_log.hpp).
//
//   ringlet-wb-log show FILE [--type NAME]... [--from FRAME] [--to FRAME]
//       one line per message: type, generation, frame and every field, doubles to the last bit
//   ringlet-wb-log diff EXPECTED ACTUAL [--type NAME]...
//       the first message where the two runs part, or that they are the same; ExecutiveTiming
//       (the host's measured task times, different in any two runs) is left out unless --type
//       names it
//
// Why: a lockstep run is a pure function of seed and configuration, so two runs that should agree
// (a replay and its recording, the same configuration on x86-64 and aarch64) give byte-identical
// logs, and where they do not, the first differing message names what parted first.
//
// Exit codes: 0 shown / the logs are the same, 1 the logs differ, 2 bad flags or an unreadable log.
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ringlet/whiteboard/message_log.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace {

namespace wb = ringlet::wb;

constexpr int kExitSame = 0;
constexpr int kExitDiffer = 1;
constexpr int kExitUsage = 2;

struct Filter {
  std::vector<wb::TypeId> types;  // empty: every type
  std::uint64_t from = 0;
  std::uint64_t to = UINT64_MAX;

  [[nodiscard]] bool keeps(const wb::LoggedMessage& m) const {
    if (m.frame < from || m.frame > to) return false;
    if (types.empty()) return true;
    for (const wb::TypeId t : types) {
      if (t == m.type) return true;
    }
    return false;
  }
};

/// The type names the user gave, or an error naming the unknown one.
std::optional<std::string> resolve_types(const std::vector<std::string>& names, Filter& filter) {
  for (const std::string& name : names) {
    const auto info = wb::find_type(name);
    if (!info) return "--type: no whiteboard type named '" + name + "'";
    filter.types.push_back(info->id);
  }
  return std::nullopt;
}

/// The log at `path` with only the messages `filter` keeps, or nullopt after printing why not.
std::optional<wb::MessageLog> load(const std::string& path, const Filter& filter) {
  auto log = wb::read_message_log(path);
  if (!log) {
    std::fprintf(stderr, "ringlet-wb-log: %s\n", log.error().c_str());
    return std::nullopt;
  }
  wb::MessageLog kept = *log;
  std::erase_if(kept.messages, [&](const wb::LoggedMessage& m) { return !filter.keeps(m); });
  return kept;
}

int show(const std::string& path, const Filter& filter) {
  const auto log = load(path, filter);
  if (!log) return kExitUsage;
  for (const wb::LoggedMessage& m : log->messages) std::printf("%s\n", m.describe().c_str());
  std::printf("%zu messages%s%s\n", log->messages.size(), log->complete ? "" : ", no end record (the run was cut off)",
              log->dropped > 0 ? (", " + std::to_string(log->dropped) + " dropped by the logger").c_str() : "");
  return kExitSame;
}

int diff(const std::string& expected_path, const std::string& actual_path, const Filter& filter) {
  auto expected = load(expected_path, filter);
  if (!expected) return kExitUsage;
  auto actual = load(actual_path, filter);
  if (!actual) return kExitUsage;
  if (filter.types.empty()) {
    wb::drop_host_measurements(*expected);
    wb::drop_host_measurements(*actual);
  }
  if (const auto difference = wb::first_difference(*expected, *actual)) {
    std::printf("the logs differ: %s\n", difference->c_str());
    return kExitDiffer;
  }
  const std::uint64_t frames = expected->messages.empty() ? 0 : expected->messages.back().frame + 1;
  std::printf("the logs are the same: %zu messages over %llu frames\n", expected->messages.size(),
              static_cast<unsigned long long>(frames));
  return kExitSame;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Reads whiteboard logs (ringlet --wb-log FILE): shows one, or finds where two runs part."};
  app.require_subcommand(1);
  std::vector<std::string> type_names;
  Filter filter;

  std::string show_path;
  auto* show_cmd = app.add_subcommand("show", "every message of a log, one per line, doubles to the last bit");
  show_cmd->add_option("file", show_path, "the whiteboard log")->required();
  show_cmd->add_option("--type", type_names, "only this type (repeat for more), e.g. Localization");
  show_cmd->add_option("--from", filter.from, "only from this frame on");
  show_cmd->add_option("--to", filter.to, "only up to this frame");

  std::string expected_path;
  std::string actual_path;
  auto* diff_cmd = app.add_subcommand("diff", "the first message where two logs differ (exit 1), or that they are the same (host times left out)");
  diff_cmd->add_option("expected", expected_path, "the reference log")->required();
  diff_cmd->add_option("actual", actual_path, "the log to compare with it")->required();
  diff_cmd->add_option("--type", type_names, "compare only this type (repeat for more)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitSame : kExitUsage;
  }
  if (const auto bad = resolve_types(type_names, filter)) {
    std::fprintf(stderr, "ringlet-wb-log: %s\n", bad->c_str());
    return kExitUsage;
  }
  if (filter.from > filter.to) {
    std::fprintf(stderr, "ringlet-wb-log: --from %llu is after --to %llu\n", static_cast<unsigned long long>(filter.from),
                 static_cast<unsigned long long>(filter.to));
    return kExitUsage;
  }
  if (*show_cmd) return show(show_path, filter);
  return diff(expected_path, actual_path, filter);
}
