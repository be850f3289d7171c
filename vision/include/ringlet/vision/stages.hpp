#pragma once
// The pipeline's stages: their names, and a frame's modelled time split by the stage that did the
// work (where the vision budget goes). One grouping of the cost model's rows serves the evaluation
// tool (modelled beside measured, per stage) and the firmware's mission report (per stage over a
// run), so the two cannot disagree about which row belongs to which stage. Light on purpose: the
// firmware's telemetry includes it, not the pipeline.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ringlet/vision/cost_model.hpp"

namespace ringlet::vision {

// In enum order, not run order (horizon, classify, ball, robots, scan, circle, RANSAC): the later
// stages were appended so that the older stages keep their bits in CutStats::stages_skipped.
enum class Stage : std::uint8_t { kHorizon, kClassify, kBall, kScan, kRansac, kCircle, kRobots, kCount };
inline constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::kCount);

/// "horizon", "classify", "ball", "scan", "ransac", "circle", "robots" (the tools' JSON keys).
[[nodiscard]] std::string_view stage_name(Stage stage) noexcept;

/// A frame's modelled host time (before the board factor) by stage: horizon the per-frame row;
/// classify the colour estimate, the table rebuild and the classified pixels; ball its samples
/// and HOG windows; scan its pixels and the candidates it offers; ransac the lines' and the marks'
/// point tests; circle its tests; robots the candidate scan and the HOG windows. The rows sum to
/// `cost.total()` (up to rounding: another order of addition).
[[nodiscard]] std::array<double, kStageCount> host_cost_by_stage(const HostCost& cost) noexcept;

}  // namespace ringlet::vision
