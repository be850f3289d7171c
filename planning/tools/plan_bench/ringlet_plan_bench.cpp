// ringlet-plan-bench: Ringlet's planners on MovingAI grid benchmarks (.map + .scen).
//
//   ringlet-plan-bench check MAP SCEN     D* Lite and A* on the fully known map must find the
//                                         .scen file's optimal lengths (octile, no corner cutting)
//   ringlet-plan-bench replan MAP SCEN    the robot knows nothing at first and sees obstacles
//                                         within --sensor-radius as it drives; D* Lite repairs its
//                                         plan, A* plans again from scratch, from the same cells
//                                         with the same heuristic and the same kind of expansion
//
// Exit codes: 0 done · 1 a planner disagreed with the file or with the other planner · 2 bad
// input (flags, unreadable or malformed files, a problem that does not fit its map).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "bench_runs.hpp"

namespace {

using namespace ringlet::planning;
using nlohmann::json;

struct Options {
  std::string map, scen, json_out, svg_out;
  double tolerance = 1e-6;
  int problems = 0;  // 0: all
  bench::ReplanOptions replan;
};

void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<MovingAiProblem> selected(const Options& o) {
  std::vector<MovingAiProblem> all = read_movingai_scen(o.scen);
  if (o.problems > 0 && static_cast<std::size_t>(o.problems) < all.size()) all.resize(static_cast<std::size_t>(o.problems));
  return all;
}

int run_check(const Options& o) {
  const MovingAiMap map = read_movingai_map(o.map);
  const auto rows = bench::check_scenarios(map, selected(o));
  double worst = 0.0;
  int wrong = 0;
  json out = {{"map", o.map}, {"scen", o.scen}, {"tolerance", o.tolerance}, {"problems", json::array()}};
  for (const auto& r : rows) {
    const double err = std::max(std::abs(r.dstar - r.optimal), std::abs(r.astar - r.optimal));
    const bool ok = err <= o.tolerance;  // an infinite cost (no path) is never within it
    worst = std::max(worst, err);
    if (!ok) {
      ++wrong;
      std::cerr << "ringlet-plan-bench: " << o.scen << ":" << r.line << ": optimal " << r.optimal << ", D* Lite " << r.dstar
                << ", A* " << r.astar << "\n";
    }
    out["problems"].push_back({{"line", r.line}, {"optimal", r.optimal}, {"dstar_lite", r.dstar}, {"astar", r.astar},
                               {"dstar_lite_expansions", r.dstar_expansions}, {"astar_expansions", r.astar_expansions}, {"ok", ok}});
  }
  out["mismatches"] = wrong;
  out["max_abs_error"] = worst;
  std::cout << std::setprecision(3) << o.map << ": " << rows.size() - static_cast<std::size_t>(wrong) << " of " << rows.size()
            << " problems at the optimal length (largest difference " << worst << ", tolerance " << o.tolerance << ")\n";
  if (!o.json_out.empty()) write_file(o.json_out, out.dump(2) + "\n");
  return wrong == 0 ? 0 : 1;
}

int run_replan(const Options& o) {
  const MovingAiMap map = read_movingai_map(o.map);
  const auto problems = selected(o);
  json out = {{"map", o.map}, {"scen", o.scen}, {"sensor_radius", o.replan.sensor_radius}, {"problems", json::array()}};
  std::int64_t d_exp = 0, a_exp = 0;
  double d_s = 0.0, a_s = 0.0;
  int replans = 0, reached = 0;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    const bench::ReplanRow r = bench::replan(map, problems[i], o.replan);
    std::cerr << "\r" << o.map << ": problem " << i + 1 << " of " << problems.size() << std::flush;  // progress
    d_exp += r.dstar_expansions;
    a_exp += r.astar_expansions;
    d_s += r.dstar_seconds;
    a_s += r.astar_seconds;
    replans += r.replans;
    reached += r.reached ? 1 : 0;
    out["problems"].push_back({{"line", r.line}, {"reached", r.reached}, {"moves", r.moves}, {"travelled", r.travelled},
                               {"replans", r.replans}, {"dstar_lite_expansions", r.dstar_expansions},
                               {"astar_expansions", r.astar_expansions}, {"dstar_lite_seconds", r.dstar_seconds},
                               {"astar_seconds", r.astar_seconds}});
    if (i == 0 && !o.svg_out.empty())
      write_file(o.svg_out, bench::replan_svg(map, r, o.replan,
                                              std::filesystem::path(o.scen).filename().string() + ":" + std::to_string(r.line) +
                                                  ": first plan dashed, path driven solid, obstacles seen dark"));
  }
  std::cerr << "\n";
  const double ratio = d_exp > 0 ? static_cast<double>(a_exp) / static_cast<double>(d_exp) : 0.0;
  const double time_ratio = d_s > 0.0 ? a_s / d_s : 0.0;
  out["totals"] = {{"problems", problems.size()}, {"reached", reached}, {"replans", replans},
                   {"dstar_lite_expansions", d_exp}, {"astar_expansions", a_exp}, {"expansion_ratio", ratio},
                   {"dstar_lite_seconds", d_s}, {"astar_seconds", a_s}, {"time_ratio", time_ratio}};
  std::cout << std::fixed << std::setprecision(1) << o.map << ": " << problems.size() << " problems, " << replans
            << " replans; expansions D* Lite " << d_exp << ", repeated A* " << a_exp << " (" << ratio << "x fewer); time "
            << std::setprecision(3) << d_s << " s vs " << a_s << " s (" << std::setprecision(1) << time_ratio << "x, host)\n";
  if (!o.json_out.empty()) write_file(o.json_out, out.dump(2) + "\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Ringlet's planners (D* Lite, A*) on MovingAI grid benchmarks (.map + .scen)."};
  app.require_subcommand(1);
  Options o;
  const auto files = [&](CLI::App* sub) {
    sub->add_option("map", o.map, "MovingAI .map file")->required()->check(CLI::ExistingFile);
    sub->add_option("scen", o.scen, "MovingAI .scen file (version 1) for that map")->required()->check(CLI::ExistingFile);
    sub->add_option("--problems", o.problems, "use only the first N problems (default: all)")->check(CLI::NonNegativeNumber);
    sub->add_option("--json", o.json_out, "write the per-problem results as JSON here");
  };
  CLI::App* check = app.add_subcommand("check", "D* Lite and A* on the known map against the .scen optimal lengths");
  files(check);
  check->add_option("--tolerance", o.tolerance, "largest accepted difference from an optimal length")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  CLI::App* replan = app.add_subcommand("replan", "discover obstacles while driving: D* Lite against repeated A*");
  files(replan);
  replan->add_option("--sensor-radius", o.replan.sensor_radius, "cells the robot sees around itself")
      ->capture_default_str()->check(CLI::Range(1, 100));
  replan->add_option("--svg", o.svg_out, "draw the first problem's run here");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    return check->parsed() ? run_check(o) : run_replan(o);
  } catch (const MovingAiError& e) {
    std::cerr << "ringlet-plan-bench: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ringlet-plan-bench: " << e.what() << "\n";
    return 1;
  }
}
