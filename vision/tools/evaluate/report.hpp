#pragma once
// The evaluation's outputs: a table for the terminal, JSON, and an SVG chart (hand-written, no
// plotting library): P/R/F1 bars side by side, and per-frame time distributions.
#include <ostream>

#include <nlohmann/json.hpp>

#include "evaluation.hpp"

namespace ringlet::vision::evaluate {

void print_report(const EvalReport& report, std::ostream& os);
[[nodiscard]] nlohmann::json report_json(const EvalReport& report);
[[nodiscard]] std::string report_svg(const EvalReport& report);

}  // namespace ringlet::vision::evaluate
