#include "fig3.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "format.hpp"
#include "goals.hpp"
#include "data.hpp"
#include "pool.hpp"
#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/planning/movingai.hpp"
#include "ringlet/sim_hal/world_svg.hpp"

namespace ringlet::experiments {
namespace {

double path_length(const std::vector<hal::WorldPoint>& p) {
  double sum = 0.0;
  for (std::size_t i = 1; i < p.size(); ++i) sum += std::hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y);
  return sum;
}

// Removes the attribute `name="…"` from the first tag of `text`.
void drop_attribute(std::string& text, const std::string& name) {
  const std::size_t tag_end = text.find('>');
  const std::size_t at = text.find(" " + name + "=\"");
  if (at == std::string::npos || at > tag_end) return;
  const std::size_t end = text.find('"', at + name.size() + 3);
  text.erase(at, end + 1 - at);
}

// One panel: the world with either the plan or the trajectory drawn, as an SVG element without
// the XML declaration and without its own width and height, so that the figure places and
// scales it (its viewBox keeps the proportions).
std::string panel(const sim_hal::World& world, const MissionResult& r, bool plan, const std::string& caption) {
  hal::RunPicture pic;
  std::vector<std::uint32_t> ends{static_cast<std::uint32_t>(r.first_plan.size())};
  if (plan) {
    pic.plans.plan_points = r.first_plan;
    pic.plans.plan_ends = ends;
  } else {
    pic.trajectory = r.trajectory;
  }
  pic.goals = r.goals;
  pic.goals_reached = plan ? 0 : r.summary.goals_reached;
  pic.caption = caption;
  std::ostringstream s;
  sim_hal::write_world_svg(s, world, pic);
  std::string text = s.str();
  if (text.rfind("<?xml", 0) == 0) text.erase(0, text.find('\n') + 1);
  drop_attribute(text, "width");
  drop_attribute(text, "height");
  return text;
}

}  // namespace

std::filesystem::path write_prior_map(const std::filesystem::path& config, const std::filesystem::path& dir) {
  const auto path = dir / (config.stem().string() + ".map");
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  planning::write_movingai_map(out, firmware::sim_world_map(firmware::load_config(config)));
  if (!out.flush()) throw std::runtime_error(path.string() + ": cannot write the prior map");
  return path;
}

Fig3Result run_fig3(const Fig3Plan& plan, Progress& progress) {
  const std::uint64_t shipped = firmware::load_config(plan.config).seed();
  const auto trials = static_cast<std::size_t>(plan.trials);
  const std::filesystem::path prior = plan.prior_map ? write_prior_map(plan.config, plan.work_dir) : std::filesystem::path();
  progress.begin(plan.prior_map ? "Fig. 3 (pb_woods, prior map)" : "Fig. 3 (pb_woods, laser only)", 2 * trials);
  auto runs = run_indexed<MissionResult>(2 * trials, plan.threads, [&](std::size_t j) {
    const std::size_t trial = j / 2;
    MissionSpec spec;
    spec.config = plan.config;
    spec.seed = trial == 0 ? shipped : derive_seed(plan.seed, 5000 + trial);
    spec.timeout_cap_s = plan.timeout_cap_s;
    spec.learned = j % 2 == 1;
    spec.prior_map = prior;
    if (spec.learned) spec.experiences = plan.experiences;
    MissionResult r = run_mission(spec);
    progress.step(std::string(spec.learned ? "learned" : "baseline") + ", seed " + std::to_string(spec.seed) +
                  (r.summary.complete ? ": reached" : ": missed"));
    return r;
  });
  progress.end();
  Fig3Result f;
  f.n = plan.n;
  f.prior_map = plan.prior_map;
  double sum = 0.0;
  for (std::size_t t = 0; t < trials; ++t) {
    Fig3Trial trial{runs[2 * t].summary.seed.value_or(0), std::move(runs[2 * t]), std::move(runs[2 * t + 1]),
                    std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0};
    const auto& b = trial.baseline.summary;
    const auto& l = trial.learned.summary;
    if (b.complete && l.complete) {
      trial.cut_pct = 100.0 * (b.mission_seconds - l.mission_seconds) / b.mission_seconds;
      sum += trial.cut_pct;
      ++f.both_complete;
    }
    trial.plan_length_baseline_m = path_length(trial.baseline.first_plan);
    trial.plan_length_learned_m = path_length(trial.learned.first_plan);
    f.trials.push_back(std::move(trial));
  }
  f.mean_cut_pct = f.both_complete > 0 ? sum / static_cast<double>(f.both_complete) : std::numeric_limits<double>::quiet_NaN();
  return f;
}

void write_fig3_svg(const std::filesystem::path& path, const std::filesystem::path& config, const Fig3Result& f) {
  const Fig3Trial& r = f.trials.front();
  const sim_hal::World world = world_of(config);
  const auto secs = [](const MissionResult& m) {
    return fixed(m.summary.mission_seconds, 1) + " s" + (m.summary.complete ? "" : " (goal not reached)");
  };
  const std::string panels[4] = {
      panel(world, r.baseline, true, "(a) baseline: first plan, " + fixed(r.plan_length_baseline_m, 1) + " m"),
      panel(world, r.baseline, false, "(b) baseline: trajectory, " + secs(r.baseline)),
      panel(world, r.learned, true, "(c) learned (n = " + std::to_string(f.n) + "): first plan, " +
                                        fixed(r.plan_length_learned_m, 1) + " m"),
      panel(world, r.learned, false, "(d) learned: trajectory, " + secs(r.learned))};
  constexpr int kW = 480, kH = 560;
  std::ofstream out(path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 2 * kW
      << "\" height=\"" << 2 * kH + 30 << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"10\" y=\"20\" font-family=\"sans-serif\" font-size=\"16\">Fig. 3: the path in the woods"
      << (f.prior_map ? " (prior map)" : " (laser only)") << ", baseline against learned, simulator seed " << r.sim_seed
      << ": mission time cut "
      << (std::isnan(r.cut_pct) ? std::string("n/a (a goal was not reached)") : fixed(r.cut_pct, 1) + " %") << "</text>\n";
  for (int i = 0; i < 4; ++i) {
    std::ostringstream place;
    place << "<svg x=\"" << (i / 2) * kW << "\" y=\"" << 30 + (i % 2) * kH << "\" width=\"" << kW << "\" height=\"" << kH
          << "\"";
    out << place.str() << panels[i].substr(4);  // the panel's own <svg tag, placed
  }
  out << "</svg>\n";
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace ringlet::experiments
