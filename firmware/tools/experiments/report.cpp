// The Markdown report of a run: each table and figure next to the paper's numbers, the issue's
// goals judged as measured, and the command that produced it all.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "format.hpp"
#include "results.hpp"

namespace ringlet::experiments {
namespace {

std::string met(bool ok) { return ok ? "**met**" : "**missed**"; }

const LearnerRow* find(const std::vector<LearnerRow>& rows, const std::string& name) {
  for (const LearnerRow& r : rows)
    if (r.name == name) return &r;
  return nullptr;
}

void learner_table(std::ostringstream& md, const std::vector<LearnerRow>& rows) {
  md << "| learner | n | relative absolute error | paper | correlation | paper |\n|---|---|---|---|---|---|\n";
  for (const LearnerRow& r : rows) {
    md << "| " << r.name << " | " << r.n << " | " << fixed(r.scores.relative_absolute_error_pct, 1) << " % | "
       << (r.paper_error_pct < 0 ? std::string("–") : fixed(r.paper_error_pct, 0) + " %") << " | "
       << fixed(r.scores.correlation, 3) << " | "
       << (r.paper_correlation < -1.5 ? std::string("–") : fixed(r.paper_correlation, 2)) << " |\n";
  }
}

void data_section(std::ostringstream& md, const Results& r) {
  std::size_t goals = 0, reached = 0;
  std::uint64_t collisions = 0;
  double seconds = 0, straight = 0, driven = 0;
  for (const MissionRecord& m : r.data.missions) {
    goals += m.goals;
    reached += m.reached;
    seconds += m.seconds;
    straight += m.straight_m;
    driven += m.driven_m;
    collisions += m.collisions;
  }
  md << "## Data (§IV-A)\n\n" << r.data.experiences.size() << " experiences from " << r.data.missions.size()
     << " legs of a chain of seeded random goals in `pb_training` (Fig. 1 (a)), each leg a mission from the previous "
        "goal, with the baseline (binary) planner and the reactive layer: "
     << reached << " of " << goals << " goals reached, " << fixed(straight, 0) << " m of straight-line legs, "
     << fixed(driven, 0) << " m driven in " << fixed(seconds, 0) << " s, " << collisions
     << " collisions (per leg: `experiments/training_missions.csv`; the experiences: `experiments/training.exp`, "
        "the planner's file format). Only these are used to train; Fig. 2 runs in `pb_test`, Fig. 3 in `pb_woods`.\n\n";
}

void tables_section(std::ostringstream& md, const Results& r) {
  const Options& o = r.options;
  md << "## Table I: " << o.folds << "-fold cross-validation, n = " << r.data.experiences.size() << "\n\n";
  std::vector<LearnerRow> rows = r.table1;
  if (r.mlp) rows.push_back(*r.mlp);
  learner_table(md, rows);
  if (!r.mlp) md << "| multilayer perceptron | – | not in this build (OpenCV's ml module: host builds only) | – | – | – |\n";
  md << "\nWeka's measures: relative absolute error against each fold's training mean (ZeroR), Pearson correlation "
        "(`experiments/table1.csv`"
     << (r.mlp ? ", `experiments/table1_mlp.csv`" : "") << "). The paper gives no figures for linear regression and the perceptron.\n\n";
  md << "## Table II: kNN (k = 5) against the number of examples\n\n";
  learner_table(md, r.table2);
  md << "\nEach n is a seeded subset of the training data (nested: n = 100 lies inside n = 250), cross-validated on its "
        "own (`experiments/table2.csv`).";
  if (r.table2.size() >= 2) {
    const LearnerRow& a = r.table2.front();
    const LearnerRow& b = r.table2.back();
    md << " From n = " << a.n << " to n = " << b.n << " the error went from "
       << fixed(a.scores.relative_absolute_error_pct, 1) << " % to " << fixed(b.scores.relative_absolute_error_pct, 1)
       << " % and the correlation from " << fixed(a.scores.correlation, 3) << " to " << fixed(b.scores.correlation, 3)
       << "; the paper's fell from 112 % to 64 % and rose from 0.33 to 0.65. Here the curve is nearly flat: a small "
          "sample already predicts about as well as the whole set. The likely reason is the features: eleven compact "
          "ones in the robot's frame, where the paper encoded a local map, so a hundred transitions already cover the "
          "common situations. This is not measured here, since the paper's features are not reproduced.";
  }
  md << "\n\n";
}

void fig2_section(std::ostringstream& md, const Fig2Result& f, double cap_s) {
  md << "## Fig. 2: the planner with the learned model in the test world\n\n"
     << "`pb_test` (Fig. 1 (b)): " << f.goals.size() << " seeded random goals, " << fixed(f.straight_m, 0)
     << " m of straight-line legs in all. Each leg is a mission of its own, from the previous goal (the world's start "
        "for the first) heading as the robot arrived there, with the same simulator seed for every system and a time "
        "limit of 30 s + 4 s per straight-line metre"
     << (cap_s < 86400.0 ? " (capped at " + fixed(cap_s, 0) + " s by --mission-timeout)" : std::string())
     << "; a goal's time is its leg's mission time. The mean and the "
        "two-sided paired t-test are over the goals both systems reached; a missed goal counts only in \"goals "
        "reached\". Why a goal was missed: *no way*, the planner found no way through the cells the laser had "
        "marked (Navigate ended in Unreachable); *boxed in*, the robot moved less than 1 m (net) over the last "
        "quarter of its leg, stuck among obstacles (the simulated car cannot reverse and the reactive layer has no "
        "back-up behaviour); *out of time*, still under way at the time limit.\n\n"
     << "| model | goals reached | missed: no way / boxed in / out of time | mean time per goal (s) | baseline (s) | "
        "improvement | p (paired t) |\n|---|---|---|---|---|---|---|\n";
  const auto missed = [](const Fig2System& s) {
    return std::to_string(s.unreachable) + " / " + std::to_string(s.boxed_in) + " / " + std::to_string(s.out_of_time);
  };
  md << "| baseline | " << f.systems[0].reached << " / " << f.goals.size() << " | " << missed(f.systems[0])
     << " | – | – | – | – |\n";
  for (std::size_t i = 0; i < f.rows.size(); ++i) {
    const Fig2Row& row = f.rows[i];
    md << "| kNN n = " << row.n << " | " << f.systems[i + 1].reached << " / " << f.goals.size() << " | "
       << missed(f.systems[i + 1]) << " | " << fixed(row.learned_mean_s, 2) << " | " << fixed(row.baseline_mean_s, 2)
       << " | " << fixed(row.improvement_pct, 1) << " % | " << p_value(row.p) << " |\n";
  }
  md << "\n![Fig. 2](experiments/fig2.svg)\n\n(Per goal: `experiments/fig2_goals.csv`; per n: `experiments/fig2.csv`.)\n\n";
}

// Where `m` ended and why it missed its goal; true when it was boxed in.
bool describe_miss(std::ostringstream& md, const MissionResult& m) {
  const MissReport why = why_missed(m);
  md << "ended " << fixed(why.to_goal_m, 1) << " m from goal " << why.goal + 1 << " after "
     << fixed(m.summary.mission_seconds, 0) << " s, having moved " << fixed(why.moved_m, 1)
     << " m (net) over the last quarter of its run: " << describe(why.kind);
  return why.kind == Miss::kBoxedIn;
}

// Why the figure's trial cut what it cut: route length against mean speed; and why a mission
// missed its goal.
void why_fig3(std::ostringstream& md, const Fig3Result& f) {
  const Fig3Trial& first = f.trials.front();
  const auto& b = first.baseline.summary;
  const auto& l = first.learned.summary;
  if (b.complete && l.complete && b.mission_seconds > 0 && l.mission_seconds > 0) {
    const double vb = b.distance_m / b.mission_seconds, vl = l.distance_m / l.mission_seconds;
    md << "Why this cut: in the figure's trial the baseline drove " << fixed(b.distance_m, 1) << " m at a mean "
       << fixed(vb, 2) << " m/s, the learned model " << fixed(l.distance_m, 1) << " m at " << fixed(vl, 2)
       << " m/s. Its route was " << fixed(100.0 * std::abs(l.distance_m / b.distance_m - 1.0), 1) << " % "
       << (l.distance_m >= b.distance_m ? "longer" : "shorter") << " and its mean speed "
       << fixed(100.0 * (vl / vb - 1.0), 1) << " % higher, so its time was " << fixed(l.distance_m / b.distance_m, 3)
       << " (route) × " << fixed(vb / vl, 3) << " (speed) = " << fixed(l.mission_seconds / b.mission_seconds, 3)
       << " of the baseline's; a 25 % cut needs 0.75 or less. The time saved is what the reactive layer loses "
          "slowing for the trees along the baseline's route.\n\n";
  }
  bool any = false, boxed = false;
  for (std::size_t t = 0; t < f.trials.size(); ++t) {
    for (const auto* m : {&f.trials[t].baseline, &f.trials[t].learned}) {
      if (m->summary.complete) continue;
      md << (any ? "; " : "Missed goals: ") << "trial " << t + 1 << ", " << (m == &f.trials[t].baseline ? "baseline" : "learned")
         << ", ";
      boxed = describe_miss(md, *m) || boxed;
      any = true;
    }
  }
  if (any) md << ".";
  if (boxed)
    md << " The simulated car cannot reverse, and the reactive layer has no back-up behaviour: when a plan "
          "switches between the two sides of a tree, it can end nose-in among trunks with every forward arc blocked, "
          "and the mission times out there.";
  if (any) md << "\n\n";
}

void fig3_section(std::ostringstream& md, const Fig3Result& f) {
  if (f.prior_map)
    md << "## Fig. 3: the path in the woods\n\n`pb_woods` (Fig. 1 (c)), its shipped mission, baseline against kNN "
          "(k = 5) trained on n = "
       << f.n << " experiences of `pb_training`. As in the paper, the planner knows the woods' obstacles before it "
          "drives (`[planner] prior_map`, the world's map as `ringlet-world-map` writes it); the laser adds what it "
          "sees. Trial 1 uses the shipped configuration's simulator seed and is the figure; the others use derived "
          "seeds, to show how much one trial says.\n\n";
  else
    md << "### The same trials with the laser alone\n\nNo prior map: the planner starts from an empty grid and "
          "learns the trees from the laser as it drives, so both systems first plan straight through the wood "
          "(`experiments/fig3_laser.svg`).\n\n";
  md
     << "| trial | seed | system | goal reached | mission time (s) | first plan (m) | driven (m) | collisions | cut |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t t = 0; t < f.trials.size(); ++t) {
    const Fig3Trial& trial = f.trials[t];
    const auto line = [&](const char* name, const MissionResult& m, double plan, bool cut) {
      md << "| " << t + 1 << " | " << trial.sim_seed << " | " << name << " | " << (m.summary.complete ? "yes" : "**no**")
         << " | " << fixed(m.summary.mission_seconds, 1) << " | " << fixed(plan, 1) << " | "
         << fixed(m.summary.distance_m, 1) << " | " << m.summary.collisions << " | "
         << (cut ? (std::isnan(trial.cut_pct) ? std::string("n/a") : fixed(trial.cut_pct, 1) + " %") : std::string()) << " |\n";
    };
    line("baseline", trial.baseline, trial.plan_length_baseline_m, false);
    line("learned", trial.learned, trial.plan_length_learned_m, true);
  }
  const Fig3Trial& first = f.trials.front();
  md << "\nMission time cut in the figure's trial: **"
     << (std::isnan(first.cut_pct) ? std::string("n/a (a goal was not reached)") : fixed(first.cut_pct, 1) + " %")
     << "** (paper: 25 %); mean over the " << f.both_complete << " of " << f.trials.size()
     << " trials both systems completed: " << fixed(f.mean_cut_pct, 1)
     << " %.\n\n";
  why_fig3(md, f);
  if (f.prior_map) md << "![Fig. 3](experiments/fig3.svg)\n\n";
}

void incremental_section(std::ostringstream& md, const std::vector<IncrementalChain>& chains) {
  md << "## Incremental learning\n\nEach world's shipped mission repeated with `learn_online = true`, the model "
        "starting empty; repeat r loads every experience of the repeats before it and learns online during the "
        "mission (`publish_every = 20`).\n\n| world | baseline (s) |";
  const std::size_t repeats = chains.empty() ? 0 : chains[0].seconds.size();
  for (std::size_t i = 0; i < repeats; ++i) md << " " << i + 1 << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < repeats; ++i) md << "---|";
  md << "\n";
  for (const IncrementalChain& c : chains) {
    md << "| " << c.name << " | " << fixed(c.baseline_s, 1) << (c.baseline_complete ? "" : " (incomplete)") << " |";
    for (std::size_t i = 0; i < c.seconds.size(); ++i)
      md << " " << fixed(c.seconds[i], 1) << (c.complete[i] ? "" : " (incomplete)") << " |";
    md << "\n";
  }
  md << "\nExperiences in the model at each repeat's start: ";
  for (const IncrementalChain& c : chains) {
    md << c.name << ":";
    for (const std::size_t n : c.model_size) md << " " << n;
    md << "; ";
  }
  md << "(`experiments/incremental.csv`).\n\n![incremental learning](experiments/incremental.svg)\n\n";
}

void goals_section(std::ostringstream& md, const Results& r) {
  md << "## The issue's goals, as measured\n\n";
  if (const LearnerRow* k5 = find(r.table1, "kNN k = 5")) {
    const bool ok = k5->scores.relative_absolute_error_pct < 64.0 && k5->scores.correlation > 0.65;
    md << "- kNN (k = 5, n = " << k5->n << "): relative absolute error " << fixed(k5->scores.relative_absolute_error_pct, 1)
       << " % (goal < 64 %, " << fixed(k5->scores.relative_absolute_error_pct - 64.0, 1)
       << " points from it), correlation " << fixed(k5->scores.correlation, 3) << " (goal > 0.65, "
       << fixed(k5->scores.correlation - 0.65, 3) << "): " << met(ok) << ".\n";
  }
  if (r.fig2) {
    bool ok = true;
    std::string which;
    for (const Fig2Row& row : r.fig2->rows) {
      if (row.n < 500) continue;
      const bool good = row.p < 0.05 && row.improvement_pct > 0;
      ok = ok && good;
      which += " n = " + std::to_string(row.n) + ": " + fixed(row.improvement_pct, 1) + " %, p = " + p_value(row.p) + ";";
    }
    if (which.empty())
      md << "- Fig. 2, improvement significant (p < 0.05) from n = 500: not measured (no n ≥ 500 in this run).\n";
    else
      md << "- Fig. 2, improvement significant (p < 0.05) from n = 500:" << which << " " << met(ok) << ".\n";
  }
  if (r.fig3) {
    const double cut = r.fig3->trials.front().cut_pct;
    md << "- Fig. 3, a woods mission-time cut of at least 25 %: the figure's trial "
       << (std::isnan(cut) ? std::string("n/a (a goal was not reached)")
                           : fixed(cut, 1) + " % (" + fixed(cut - 25.0, 1) + " points from it)")
       << ", the mean over the trials both completed " << fixed(r.fig3->mean_cut_pct, 1) << " %: "
       << met(!std::isnan(cut) && cut >= 25.0) << ".\n";
  }
  md << "\n";
}

}  // namespace

void write_report(const Results& r) {
  std::ostringstream md;
  md << "# Powers & Balch §IV reproduced: Tables I and II, Fig. 2, Fig. 3, incremental learning\n\n"
     << "Every number and plot here was produced by one command, in lockstep (deterministic for the seed):\n\n"
     << "    " << r.options.command << "\n\n"
     << (r.options.quick ? "**This is a `--quick` run: small n and few goals, not the paper's sizes.**\n\n" : "");
  goals_section(md, r);
  data_section(md, r);
  tables_section(md, r);
  if (r.fig2) fig2_section(md, *r.fig2, r.options.timeout_cap_s);
  if (r.fig3) fig3_section(md, *r.fig3);
  if (r.fig3_laser) fig3_section(md, *r.fig3_laser);
  if (!r.incremental.empty()) incremental_section(md, r.incremental);
  const std::filesystem::path md_dir = r.options.markdown.parent_path().empty() ? "." : r.options.markdown.parent_path();
  std::filesystem::create_directories(md_dir);
  // The text names the outputs as experiments/…: the out directory as seen from the report's.
  const std::string dir = std::filesystem::absolute(r.options.out_dir).lexically_relative(std::filesystem::absolute(md_dir)).generic_string();
  std::string text = md.str();
  for (const std::string from : {"](experiments/", "`experiments/"}) {
    const std::string to = from.substr(0, from.size() - 12) + dir + "/";
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  std::ofstream out(r.options.markdown);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(r.options.markdown.string() + ": cannot write");
}

}  // namespace ringlet::experiments
