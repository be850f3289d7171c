#pragma once
// The comparison on a ringlet-dataset folder: Ringlet's pipeline (on YUYV made from the PNG with
// hal::bgr_to_yuyv, what the robot's camera gives) against Canny + HoughLinesP (on the BGR
// picture, edges above the horizon masked), scored by the same rule (segment_match.hpp) on the
// same frames, each timed alone with std::chrono::steady_clock on one thread.
//
// Fairness: Hough's parameters are chosen (best F1 over HoughParams::candidates()) on a tuning
// set — another ringlet-dataset folder (`tune_set`), or the first `tune_frames` frames of the
// dataset — and BOTH detectors are reported only on the test set. Before anything is scored, the
// tuning set and every `disjoint_from` set (e.g. the frames Ringlet's own parameters were chosen
// on) are checked against the test set (frame_identity.hpp: same seed and index, or identical
// pixels); any shared frame is a ToolError, so a report can only come from unseen frames.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "circle_score.hpp"
#include "mark_score.hpp"
#include "hough_baseline.hpp"
#include "object_score.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "segment_match.hpp"

namespace ringlet::vision::evaluate {

struct EvalOptions {
  std::filesystem::path dataset;
  std::filesystem::path lut;   // empty: the default thresholds table
  std::filesystem::path tune_set;  // empty: tune on the first tune_frames frames of `dataset`
  /// Without tune_set: the first N frames of `dataset` tune Hough and are not reported (0: no
  /// tuning, OpenCV-style defaults HoughParams{}). With tune_set: its first N frames (0: all).
  int tune_frames = 40;
  std::vector<std::filesystem::path> disjoint_from;  // sets the test set must share no frame with
  int max_frames = 0;          // 0: all (of the test set)
  MatchParams match{};
  CircleMatchParams circle_match{};
  MarkMatchParams mark_match{};
  BallMatchParams ball_match{};
  RobotMatchParams robot_match{};
  // HOG/SVM models installed in the pipeline (empty: none; the black-and-white ball and the
  // robots are then reported unverified). A file that does not load, or a model for the other
  // target, is a ToolError naming the flag (--ball-model / --robot-model) and the file.
  std::filesystem::path ball_model;
  std::filesystem::path robot_model;
  VisionConfig vision{};       // intrinsics and mount are replaced by each frame's
  // The head pitch the pipeline is given: each frame's plus this (a camera mounted off, a wrong
  // joint reading), and with auto_pitch corrected from the lines first (pitch_check.hpp).
  double pitch_error_deg = 0.0;
  bool auto_pitch = false;
  /// (stage, done, total): "loading", "tuning", "evaluating".
  std::function<void(const char*, std::size_t, std::size_t)> progress;
};

struct DetectorReport {
  std::string name;
  MatchCounts counts{};
  std::size_t raw_detections = 0;   // every segment reported, scored or not
  // Of the scored false positives, the pieces of the centre circle, per test frame.
  std::vector<std::size_t> per_frame_arcs;
  std::vector<double> time_ms;      // per frame
  std::vector<MatchCounts> per_frame;  // line counts per test frame (which frames fail)
  std::vector<std::vector<Segment2>> segments;  // what was reported, per test frame
  [[nodiscard]] double median_ms() const;
  [[nodiscard]] double p99_ms() const;
  [[nodiscard]] double mean_ms() const;
  [[nodiscard]] std::size_t arc_false_positives() const;              // their sum
  [[nodiscard]] std::size_t frames_with_arc_false_positives() const;  // frames with any
};

struct TuningResult {
  HoughParams params{};
  MatchCounts counts{};
};

struct EvalReport {
  std::string dataset;
  std::string lut;
  std::uint64_t ransac_seed = 0;
  double pitch_error_deg = 0.0;       // EvalOptions'
  bool auto_pitch = false;
  std::size_t pitch_corrected = 0;     // frames whose pitch --auto-pitch corrected
  std::vector<double> pitch_abs_error_deg;  // per corrected frame: |pitch used − true pitch|
  std::vector<double> pitch_correction_deg; // per corrected frame: pitch used − pitch given (their median
                                            //   over a set is the camera's pitch as mounted)
  std::string test_set;                 // FrameSet::describe() of each
  std::string tuning_set;               // empty: no tuning
  std::vector<std::string> excluded_sets;
  std::vector<std::string> test_frames;  // file names of the reported frames, in order
  std::string disjointness;             // what was checked, in words
  std::size_t frames_total = 0;
  std::size_t tune_frames = 0;      // frames Hough was tuned on (none of them reported on)
  std::size_t report_frames = 0;    // frames reported on: the test set
  HoughParams hough{};
  std::vector<TuningResult> tuning;  // every candidate, in HoughParams::candidates() order
  std::size_t chosen = 0;            // index into tuning (when tuned)
  DetectorReport ringlet;
  DetectorReport baseline;
  CircleCounts circle{};             // Ringlet's centre circle (Hough reports none)
  CircleCounts marks{};              // Ringlet's penalty and centre marks (mark_score.hpp; no radius)
  std::size_t rings_visible = 0;     // test frames showing any of the ring
  std::size_t arc_frames_circle_missed = 0;  // Ringlet's frames with arc pieces taken for lines
                                             //   whose circle was expected and not found
  CircleMatchParams circle_match{};
  MarkMatchParams mark_match{};
  MatchParams match{};
  // Balls and robots (object_score.hpp), over the test frames that carry their truth (ringlet-dataset
  // generator version 3 and later).
  std::size_t object_frames = 0;
  std::string ball_mode;             // "bw" or "orange"
  std::string ball_model;            // file, or "none"
  std::string robot_model;
  ObjectCounts balls{};
  ObjectCounts ball_proposals{};     // every black-and-white ball candidate scored as a detection:
                                     // its recall is the share of expected balls proposed at all
  ObjectCounts robots{};
  ObjectCounts robot_proposals{};    // every robot candidate scored as a detection (the same for robots)
  struct RobotMatchInFrame {
    std::string frame;  // the test frame's JSON file name
    RobotMatch match;
  };
  std::vector<RobotMatchInFrame> robot_matches;  // every matched expected robot: where the errors come from
  BallMatchParams ball_match{};
  RobotMatchParams robot_match{};
  /// Per test frame, Ringlet's time as the cost model has it on this host (host_cost of the
  /// frame's work: modelled_cost before the board factor), beside ringlet.time_ms: how far the
  /// model is off.
  std::vector<double> model_host_ms;
  /// Per stage (pipeline Stage) and test frame: the time the stage took (wall, on the stage laps)
  /// and the model's rows for it (horizon: the per-frame row; classify: the colour estimate, the
  /// table rebuild and the classified pixels; scan: its pixels and candidates; ...).
  struct StageTimes {
    std::vector<double> measured_ms, modelled_ms;
  };
  std::array<StageTimes, kStageCount> stage_times{};
  /// Hough's median time / Ringlet's: > 1 means Ringlet is faster.
  [[nodiscard]] double speed_ratio() const;
  /// Percentile p of measured / modelled time over the test frames (0 without frames).
  [[nodiscard]] double measured_over_modelled(double p) const;
};

/// Runs the whole comparison. ToolError on bad input (folder, frame records, images, LUT, too few
/// frames for the tuning subset) and when the test set shares a frame with the tuning set or a
/// disjoint_from set.
[[nodiscard]] EvalReport run_evaluation(const EvalOptions& options);

/// Percentile (nearest rank, p in [0, 100]) of unsorted values; 0 for none.
[[nodiscard]] double percentile(std::vector<double> values, double p);

}  // namespace ringlet::vision::evaluate
