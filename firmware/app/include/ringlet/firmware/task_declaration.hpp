#pragma once
// What a task declares about itself, as B-Human's modules and the generated machines do: its name
// in the task table, the whiteboard types it REQUIRES (reads) and PROVIDES (posts), and where the
// declaration is written, so that a start-up problem points at the task's own file.
//
//   static constexpr TaskDeclaration kDeclaration{
//       "sense", kNoTypes, kTypeNames<wb::Pose, wb::LaserSummary>, here()};
#include <array>
#include <span>
#include <string>
#include <string_view>

#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::firmware {

/// The names of whiteboard types, as a constexpr list a declaration can point at.
template <wb::Message... Ts>
inline constexpr std::array<std::string_view, sizeof...(Ts)> kTypeNames{Ts::kName...};
inline constexpr std::span<const std::string_view> kNoTypes{};

/// Where a declaration is written. std::source_location would do, but clang 14 with GCC 12's
/// library has none; the builtins behind it work in both compilers.
struct SourcePlace {
  const char* file;
  unsigned line;
};
/// The place of the call: `here()` as a declaration's last argument.
consteval SourcePlace here(const char* file = __builtin_FILE(), unsigned line = __builtin_LINE()) noexcept {
  return {file, line};
}

struct TaskDeclaration {
  std::string_view name;
  std::span<const std::string_view> requires_types;
  std::span<const std::string_view> provides_types;
  SourcePlace where;
  /// Types the task reads when some task or machine provides them, and does without otherwise
  /// (e.g. the planner marks the robots vision sees, on a robot that runs vision).
  std::span<const std::string_view> optional_types{};

  /// "file:line" of the declaration, for start-up messages. The compiler may have been handed the
  /// file relative to the build folder (ccache's base_dir does that): leading "../" go.
  [[nodiscard]] std::string location() const {
    std::string_view file = where.file;
    while (file.starts_with("../")) file.remove_prefix(3);
    return std::string(file) + ":" + std::to_string(where.line);
  }
};

}  // namespace ringlet::firmware
