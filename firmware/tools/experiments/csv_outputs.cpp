// The CSV files and the plots of a run (results.hpp): one file per table or figure.
#include <cmath>
#include <exception>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "format.hpp"
#include "results.hpp"
#include "ringlet/planning/experience_file.hpp"
#include "svg_chart.hpp"

namespace ringlet::experiments {
namespace {

class Csv {
 public:
  explicit Csv(std::filesystem::path path) : path_(std::move(path)), out_(path_) {}
  ~Csv() noexcept(false) {
    out_.close();
    if (!out_ && std::uncaught_exceptions() == 0) throw std::runtime_error(path_.string() + ": cannot write");
  }
  Csv(const Csv&) = delete;
  Csv& operator=(const Csv&) = delete;
  std::ofstream& out() { return out_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
};

void learner_csv(const std::filesystem::path& path, const std::vector<LearnerRow>& rows) {
  Csv csv(path);
  csv.out() << "learner,n,relative_absolute_error_pct,correlation,mean_absolute_error,root_mean_squared_error,"
               "paper_relative_absolute_error_pct,paper_correlation\n";
  for (const LearnerRow& r : rows) {
    csv.out() << r.name << ',' << r.n << ',' << fixed(r.scores.relative_absolute_error_pct, 2) << ','
              << fixed(r.scores.correlation, 4) << ',' << fixed(r.scores.mean_absolute_error, 4) << ','
              << fixed(r.scores.root_mean_squared_error, 4) << ','
              << (r.paper_error_pct < 0 ? "" : fixed(r.paper_error_pct, 0)) << ','
              << (r.paper_correlation < -1.5 ? "" : fixed(r.paper_correlation, 2)) << '\n';
  }
}

void data_csv(const Options& o, const TrainingData& d) {
  Csv csv(o.out_dir / "training_missions.csv");
  csv.out() << "leg,goals,reached,mission_s,straight_line_m,driven_m,experiences,collisions\n";
  for (std::size_t i = 0; i < d.missions.size(); ++i) {
    const MissionRecord& m = d.missions[i];
    csv.out() << i + 1 << ',' << m.goals << ',' << m.reached << ',' << fixed(m.seconds, 2) << ','
              << fixed(m.straight_m, 2) << ',' << fixed(m.driven_m, 2) << ',' << m.experiences << ','
              << m.collisions << '\n';
  }
}

void fig2_outputs(const Options& o, const Fig2Result& f) {
  {
    Csv csv(o.out_dir / "fig2_goals.csv");
    csv.out() << "goal,x,y,timeout_s";
    for (const Fig2System& s : f.systems) csv.out() << ',' << (s.n == 0 ? std::string("baseline") : "n" + std::to_string(s.n)) << "_s";
    csv.out() << '\n';
    for (std::size_t g = 0; g < f.goals.size(); ++g) {
      csv.out() << g + 1 << ',' << fixed(f.goals[g].x, 2) << ',' << fixed(f.goals[g].y, 2) << ','
                << fixed(f.timeouts[g], 1);
      for (const Fig2System& s : f.systems)
        csv.out() << ',' << (s.goal_seconds[g] < 0 ? std::string("missed") : fixed(s.goal_seconds[g], 2));
      csv.out() << '\n';
    }
  }
  Csv csv(o.out_dir / "fig2.csv");
  csv.out() << "n,reached,goals,paired,baseline_mean_s,learned_mean_s,improvement_pct,t,p\n";
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    const Fig2Row& r = f.rows[i];
    csv.out() << r.n << ',' << f.systems[i + 1].reached << ',' << f.goals.size() << ',' << r.paired << ','
              << fixed(r.baseline_mean_s, 3) << ',' << fixed(r.learned_mean_s, 3) << ','
              << fixed(r.improvement_pct, 2) << ',' << fixed(r.t, 4) << ',' << p_value(r.p) << '\n';
  }
  Bars improvement{"(a) improvement over the baseline", "mission time per goal cut (%)", {}, {},
                   std::numeric_limits<double>::quiet_NaN(), ""};
  Bars significance{"(b) paired t-test p-value", "p", {}, {}, 0.05, "p = 0.05"};
  for (const Fig2Row& r : f.rows) {
    improvement.labels.push_back(std::to_string(r.n));
    improvement.values.push_back(r.improvement_pct);
    significance.labels.push_back(std::to_string(r.n));
    significance.values.push_back(r.p);
  }
  write_bar_panels(o.out_dir / "fig2.svg", {improvement, significance});
}

// fig3.csv holds both sets of trials (column map: prior or laser); fig3.svg is the prior map's
// figure trial, fig3_laser.svg the laser-only one.
void fig3_outputs(const Options& o, const std::vector<const Fig3Result*>& sets) {
  Csv csv(o.out_dir / "fig3.csv");
  csv.out() << "map,trial,sim_seed,system,complete,mission_s,first_plan_m,driven_m,collisions,cut_pct\n";
  for (const Fig3Result* f : sets) {
    const char* map = f->prior_map ? "prior" : "laser";
    for (std::size_t t = 0; t < f->trials.size(); ++t) {
      const Fig3Trial& trial = f->trials[t];
      const auto row = [&](const std::string& name, const MissionResult& m, double plan_m) {
        csv.out() << map << ',' << t + 1 << ',' << trial.sim_seed << ',' << name << ',' << (m.summary.complete ? 1 : 0)
                  << ',' << fixed(m.summary.mission_seconds, 2) << ',' << fixed(plan_m, 2) << ','
                  << fixed(m.summary.distance_m, 2) << ',' << m.summary.collisions << ',' << fixed(trial.cut_pct, 2) << '\n';
      };
      row("baseline", trial.baseline, trial.plan_length_baseline_m);
      row("learned n=" + std::to_string(f->n), trial.learned, trial.plan_length_learned_m);
    }
    write_fig3_svg(o.out_dir / (f->prior_map ? "fig3.svg" : "fig3_laser.svg"), o.config_dir / "pb_woods.toml", *f);
  }
}

void incremental_outputs(const Options& o, const std::vector<IncrementalChain>& chains) {
  {
    Csv csv(o.out_dir / "incremental.csv");
    csv.out() << "world,repeat,model_experiences,mission_s,complete,baseline_s,baseline_complete\n";
    for (const IncrementalChain& c : chains)
      for (std::size_t r = 0; r < c.seconds.size(); ++r)
        csv.out() << c.name << ',' << r + 1 << ',' << c.model_size[r] << ',' << fixed(c.seconds[r], 2) << ','
                  << (c.complete[r] ? 1 : 0) << ',' << fixed(c.baseline_s, 2) << ',' << (c.baseline_complete ? 1 : 0)
                  << '\n';
  }
  std::vector<Lines> panels;
  for (const IncrementalChain& c : chains) {
    Line learned{"learning online (kNN, from empty)", "#1f5fd1", c.seconds, false};
    Line base{"baseline (binary)", "#d62020", std::vector<double>(c.seconds.size(), c.baseline_s), true};
    panels.push_back(Lines{c.name + ": mission time over repeats", "repeat", "mission time (s)", {learned, base}});
  }
  write_line_panels(o.out_dir / "incremental.svg", panels);
}

}  // namespace

void write_csv_and_plots(const Results& r) {
  const Options& o = r.options;
  std::filesystem::create_directories(o.out_dir);
  planning::save_experiences(o.out_dir / "training.exp", r.data.experiences);
  data_csv(o, r.data);
  learner_csv(o.out_dir / "table1.csv", r.table1);
  if (r.mlp) learner_csv(o.out_dir / "table1_mlp.csv", {*r.mlp});
  learner_csv(o.out_dir / "table2.csv", r.table2);
  if (r.fig2) fig2_outputs(o, *r.fig2);
  std::vector<const Fig3Result*> woods;
  for (const auto* f : {&r.fig3, &r.fig3_laser})
    if (*f) woods.push_back(&**f);
  if (!woods.empty()) fig3_outputs(o, woods);
  if (!r.incremental.empty()) incremental_outputs(o, r.incremental);
}

}  // namespace ringlet::experiments
