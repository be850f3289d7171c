#include "bench_runs.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "ringlet/planning/astar.hpp"
#include "ringlet/planning/dstar_lite.hpp"

namespace ringlet::planning::bench {
namespace {

constexpr std::int64_t kUnsliced = std::int64_t{1} << 40;

double cells(Cost c) {
  return c == kInfiniteCost ? std::numeric_limits<double>::infinity() : MovingAiGraph::cells(c);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Makes every cell within `radius` of `v` known; appends the ones found blocked to `blocked`.
void sense(MovingAiGraph& graph, int v, int radius, std::vector<int>& blocked) {
  const int x0 = graph.x_of(v), y0 = graph.y_of(v);
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      if (dx * dx + dy * dy > radius * radius || !graph.inside(x0 + dx, y0 + dy)) continue;
      const int c = graph.vertex(x0 + dx, y0 + dy);
      if (graph.reveal(c)) blocked.push_back(c);
    }
}

}  // namespace

std::vector<CheckRow> check_scenarios(const MovingAiMap& map, const std::vector<MovingAiProblem>& problems) {
  const MovingAiGraph graph(map, true);
  DStarLite d;
  d.reserve(graph.vertex_count());
  AStar a;
  a.reserve(graph.vertex_count());
  std::vector<CheckRow> rows;
  for (const MovingAiProblem& p : problems) {
    if (const std::string why = check_problem(p, map); !why.empty())
      throw MovingAiError(p.where() + ": " + why);
    CheckRow r;
    r.line = p.line;
    r.optimal = p.optimal;
    const int s = graph.vertex(p.start_x, p.start_y), g = graph.vertex(p.goal_x, p.goal_y);
    d.begin(graph, s, g);
    d.step(kUnsliced);
    r.dstar = cells(d.plan_cost());
    r.dstar_expansions = d.counters().expansions;
    const std::int64_t before = a.expansions();
    r.astar = cells(a.search(graph, s, g));
    r.astar_expansions = a.expansions() - before;
    rows.push_back(r);
  }
  return rows;
}

ReplanRow replan(const MovingAiMap& map, const MovingAiProblem& problem, const ReplanOptions& options) {
  if (const std::string why = check_problem(problem, map); !why.empty())
    throw MovingAiError(problem.where() + ": " + why);
  MovingAiGraph graph(map, false);
  DStarLite d;
  d.reserve(graph.vertex_count());
  AStar a;
  a.reserve(graph.vertex_count());
  ReplanRow row;
  row.line = problem.line;
  const int goal = graph.vertex(problem.goal_x, problem.goal_y);
  int at = graph.vertex(problem.start_x, problem.start_y);
  std::vector<int> blocked;
  sense(graph, at, options.sensor_radius, blocked);

  const auto both_plan = [&](bool first) {
    auto t0 = std::chrono::steady_clock::now();
    if (first) {
      d.begin(graph, at, goal);
    } else {
      for (const int v : blocked) d.vertex_changed(v);
    }
    d.step(kUnsliced);
    row.dstar_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const Cost c = a.search(graph, at, goal);
    row.astar_seconds += seconds_since(t0);
    if (d.plan_cost() != c)
      throw std::runtime_error(problem.where() + ": D* Lite's plan costs " +
                               std::to_string(cells(d.plan_cost())) + " cells, A*'s " + std::to_string(cells(c)));
    blocked.clear();
  };
  both_plan(true);
  row.first_plan.resize(static_cast<std::size_t>(graph.vertex_count()));
  row.first_plan.resize(static_cast<std::size_t>(std::max(0, d.extract_path(row.first_plan))));
  row.trajectory.push_back(at);
  const int max_moves = 4 * graph.vertex_count();  // a bound, never reached: each move is on a best path
  while (at != goal && d.status() == SearchStatus::kReady && row.moves < max_moves) {
    const int next = d.next_vertex();
    row.travelled += octile_cells(graph.x_of(next) - graph.x_of(at), graph.y_of(next) - graph.y_of(at));
    at = next;
    ++row.moves;
    row.trajectory.push_back(at);
    d.move_start(at);
    sense(graph, at, options.sensor_radius, blocked);
    if (blocked.empty()) {
      d.step(kUnsliced);  // nothing new: the plan stands (this confirms it, with no expansion)
    } else {
      ++row.replans;
      both_plan(false);
    }
  }
  row.reached = at == goal;
  row.dstar_expansions = d.counters().expansions;
  row.astar_expansions = a.expansions();
  return row;
}

std::string replan_svg(const MovingAiMap& map, const ReplanRow& row, const ReplanOptions& options, const std::string& title) {
  constexpr int kScale = 4;
  const int w = map.width * kScale, h = map.height * kScale;
  // What the robot came to know: every cell within the radius of a cell it drove through.
  std::vector<std::uint8_t> known(map.terrain.size(), 0);
  const int r = options.sensor_radius;
  for (const int v : row.trajectory) {
    const int x0 = v % map.width, y0 = v / map.width;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int x = x0 + dx, y = y0 + dy;
        if (dx * dx + dy * dy <= r * r && x >= 0 && y >= 0 && x < map.width && y < map.height)
          known[static_cast<std::size_t>(y * map.width + x)] = 1;
      }
  }
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h + 24 << "\" viewBox=\"0 0 " << w << ' '
    << h + 24 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"4\" y=\"16\" font-family=\"sans-serif\" font-size=\"13\">" << title << "</text>\n<g transform=\"translate(0 24)\">\n";
  for (int y = 0; y < map.height; ++y)
    for (int x = 0; x < map.width; ++x) {
      const auto i = static_cast<std::size_t>(y * map.width + x);
      if (MovingAiMap::passable_char(map.terrain[i])) continue;
      s << "<rect x=\"" << x * kScale << "\" y=\"" << y * kScale << "\" width=\"" << kScale << "\" height=\"" << kScale
        << "\" fill=\"" << (known[i] != 0 ? "#333" : "#ddd") << "\"/>\n";
    }
  const auto polyline = [&](const std::vector<int>& cells, const char* style) {
    s << "<polyline fill=\"none\" " << style << " points=\"";
    for (const int v : cells) s << (v % map.width) * kScale + kScale / 2 << ',' << (v / map.width) * kScale + kScale / 2 << ' ';
    s << "\"/>\n";
  };
  polyline(row.first_plan, "stroke=\"#3a6fd8\" stroke-width=\"2\" stroke-dasharray=\"6 4\" opacity=\"0.7\"");
  polyline(row.trajectory, "stroke=\"#d8362a\" stroke-width=\"2\"");
  if (!row.trajectory.empty()) {
    const int a = row.trajectory.front(), b = row.trajectory.back();
    s << "<circle cx=\"" << (a % map.width) * kScale + 2 << "\" cy=\"" << (a / map.width) * kScale + 2 << "\" r=\"5\" fill=\"#2a9d3a\"/>\n";
    s << "<circle cx=\"" << (b % map.width) * kScale + 2 << "\" cy=\"" << (b / map.width) * kScale + 2 << "\" r=\"5\" fill=\"#d8362a\"/>\n";
  }
  s << "</g>\n</svg>\n";
  return s.str();
}

}  // namespace ringlet::planning::bench
