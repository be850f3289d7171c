#pragma once
// The MovingAI grid benchmark format (Sturtevant, "Benchmarks for Grid-Based Pathfinding", 2012):
// `.map` files (an octile grid of terrain characters) and `.scen` files (start, goal and optimal
// length per problem). Off the cycle path: these read files and allocate.
//
// Movement follows the benchmark's octile rule: straight steps cost 1, diagonal ones √2, and a
// diagonal step may not cut the corner of a blocked cell (both cells beside it must be passable).
// In Cost units a cell is kCellCost (2^32), so a 10 000-step path is exact to ~1e-6 cells.
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ringlet/planning/grid_graph.hpp"

namespace ringlet::planning {

/// A file that is not valid MovingAI: the message names the file and line.
class MovingAiError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct MovingAiMap {
  int width = 0, height = 0;
  std::vector<char> terrain;  // row-major, row 0 first as in the file

  /// '.', 'G' and 'S' are passable (ground, ground, swamp); '@', 'O', 'T', 'W' are not.
  [[nodiscard]] static bool passable_char(char c) noexcept { return c == '.' || c == 'G' || c == 'S'; }
  [[nodiscard]] bool passable(int x, int y) const noexcept {
    return x >= 0 && y >= 0 && x < width && y < height && passable_char(terrain[static_cast<std::size_t>(y * width + x)]);
  }
};

struct MovingAiProblem {
  int bucket = 0;
  std::string map;
  int map_width = 0, map_height = 0;
  int start_x = 0, start_y = 0, goal_x = 0, goal_y = 0;
  double optimal = 0.0;
  std::string source;  // the .scen file it came from
  int line = 0;        // and the line

  /// "file:line", for messages about this problem.
  [[nodiscard]] std::string where() const { return source + ":" + std::to_string(line); }
};

/// Reads a `.map`; throws MovingAiError naming the file and line of the first problem.
MovingAiMap read_movingai_map(const std::filesystem::path& path);
/// Writes `m` as a `.map` (terrain as given, rows in order), to `out`.
void write_movingai_map(std::ostream& out, const MovingAiMap& m);
/// Reads a `.scen` (version 1); throws MovingAiError naming the file and line of the first problem.
std::vector<MovingAiProblem> read_movingai_scen(const std::filesystem::path& path);
/// Checks a problem against its map (dimensions, passable ends); empty when fine, else why.
std::string check_problem(const MovingAiProblem& p, const MovingAiMap& m);

/// A map's cells as a GridGraph under the octile rule, with what is known to be blocked: a cell
/// is blocked when the map says so and it is `known` (the unknown is assumed free: the free-space
/// assumption of navigation in unknown terrain). All cells start known; reveal() flips them.
class MovingAiGraph final : public GridGraph {
 public:
  static constexpr Cost kCellCost = Cost{1} << 32;
  static constexpr Cost kDiagonalCost = 6074001000;  // round(√2 · 2^32)
  [[nodiscard]] static double cells(Cost c) noexcept { return static_cast<double>(c) / static_cast<double>(kCellCost); }

  /// `all_known`: the whole map is known (the optimal-length check); else nothing is.
  MovingAiGraph(const MovingAiMap& map, bool all_known);

  [[nodiscard]] int width() const noexcept override { return map_.width; }
  [[nodiscard]] int height() const noexcept override { return map_.height; }
  [[nodiscard]] Cost step_cost(int v, int k) const noexcept override;
  [[nodiscard]] Cost min_step_cost() const noexcept override { return kCellCost; }

  /// Cell `v` becomes known; true when that makes it blocked (the planner must hear of it).
  bool reveal(int v) noexcept;
  [[nodiscard]] bool blocked(int x, int y) const noexcept;

 private:
  const MovingAiMap& map_;
  std::vector<std::uint8_t> known_;
};

}  // namespace ringlet::planning
