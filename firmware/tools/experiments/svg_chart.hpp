#pragma once
// Small SVG charts for the experiments: bars (Fig. 2) and lines (incremental learning). Every
// number is printed with fixed decimals, so the same data give byte-identical files.
#include <filesystem>
#include <string>
#include <vector>

namespace ringlet::experiments {

struct Bars {
  std::string title, y_label;
  std::vector<std::string> labels;
  std::vector<double> values;
  double reference = 0;            // a dashed horizontal line (e.g. p = 0.05); NaN: none
  std::string reference_label;
};

struct Line {
  std::string name, colour;
  std::vector<double> y;           // at x = 1, 2, …; NaN: no point
  bool dashed = false;
};

struct Lines {
  std::string title, x_label, y_label;
  std::vector<Line> lines;
};

/// Panels side by side, each a bar chart, in one SVG file (throws naming the path on failure).
void write_bar_panels(const std::filesystem::path& path, const std::vector<Bars>& panels);
/// Panels side by side, each a line chart.
void write_line_panels(const std::filesystem::path& path, const std::vector<Lines>& panels);

}  // namespace ringlet::experiments
