#pragma once
// Everything one run of ringlet-experiments measured, for the report. Host measurements (wall
// time) are not in it: the outputs are a function of the options and the seed only.
#include <optional>
#include <vector>

#include "data.hpp"
#include "fig2.hpp"
#include "fig3.hpp"
#include "incremental.hpp"
#include "options.hpp"
#include "tables.hpp"

namespace ringlet::experiments {

struct Results {
  Options options;
  TrainingData data;
  std::vector<LearnerRow> table1;   // baseline, kNN k = 2, 5, 15, 50, linear regression
  std::optional<LearnerRow> mlp;    // Table I's perceptron: builds with OpenCV's ml only
  std::vector<LearnerRow> table2;   // kNN k = 5 per n
  std::optional<Fig2Result> fig2;
  std::optional<Fig3Result> fig3;        // the planner given the woods' obstacles, as in the paper
  std::optional<Fig3Result> fig3_laser;  // the same trials, the obstacles found by the laser alone
  std::vector<IncrementalChain> incremental;
};

/// The CSV files, the training data and the SVG plots in options.out_dir (csv_outputs.cpp).
/// Throws std::runtime_error naming a file that cannot be written.
void write_csv_and_plots(const Results& r);
/// The Markdown report at options.markdown (report.cpp), linking the plots.
void write_report(const Results& r);

}  // namespace ringlet::experiments
