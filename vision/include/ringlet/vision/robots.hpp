#pragma once
// NAO robots (Mi-Pal's shape recognition by HOG + linear SVM): obstacles, reported at the point
// where their feet touch the ground.
//
// Candidates: vertical scan columns every `stride` px collect runs of non-field samples (a NAO is
// white and grey) that end on the field below (the foot point: the run's lowest row, the ray
// through it meets the ground). At that foot point the camera model gives the image height of a
// standing NAO (0.574 m: the projection of the point that far above the foot); a run counts when
// it is at least `min_height_share` of that tall or reaches the top of the classified area (the
// robot continues above the horizon margin). Field gaps up to `max_gap_share` of that height inside
// a run are bridged (shaded grey parts pass for carpet) when what follows the gap is longer than
// twice the gap (the legs below); longer gaps, or a short piece after one, end it there (a ball
// before the feet must not become the foot). Neighbouring columns whose foot rows agree (within
// `foot_tolerance_share` of that height, column to column) form one candidate; columns up to
// `join_share` of a NAO's width apart still join it. Columns beside it whose runs end higher up are
// held apart (a shadow): the field between its legs when the candidate goes on after them, else
// something farther away, a candidate of its own once the near one has ended (a robot half hidden
// behind another). Something nearer standing before a robot (a ball, a line seen between its
// legs) cuts its columns into pieces: pieces that are each narrower than `min_width_share` of a
// NAO's width, whose foot rows agree and that together are at most `merge_width_share` of it wide
// are put together (ranked after the whole candidates). A candidate still narrower than
// `min_width_share` of a NAO's width is a line or a post.
//
// Ranking: whole candidates before pieces put together, then nearest first (lowest foot row, then the wider): the nearest obstacles matter most and
// fill their windows best. On the 200 tuning frames val_s101 this alone took recall at 3 windows
// from 0.21 (widest first) to 0.54, close to the 0.55 of classifying every candidate.
//
// Position: the lowest non-field row is the near edge of the feet (and their shadow); the robot
// stands `foot_depth_m` farther along the ray (its ground point is moved by that much).
//
// Verification: the best `max_verified` candidates (nearest first) get a window `window_height`
// robot heights tall (the robot's foot at row `foot_row` of the model's window, centred on the
// candidate), resampled to the model's window (32 × 64), HOG and the SVM score; score ≥ the
// model's threshold is a robot. Without a classifier the candidates are reported unverified
// (confidence ≤ 0.3): still obstacles, just not known to be robots.
#include <array>
#include <cstddef>
#include <span>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision {

inline constexpr std::size_t kMaxRobots = 6;
inline constexpr std::size_t kMaxRobotCandidates = 16;
inline constexpr std::size_t kMaxRawRobotCandidates = 64;
inline constexpr std::size_t kMaxRobotColumns = 1024;  // scan columns remembered (a 4K frame at step 4)

struct RobotParams {
  double height_m = 0.574;         // a standing NAO
  double width_m = 0.31;           // its shoulders (arms down)
  double min_height_px = 16.0;     // robots smaller in the image (≈ 9 m away) are not looked for
  double min_height_share = 0.4;   // run length / expected height
  double max_gap_share = 0.2;      // field gaps inside a run up to this × expected height are bridged
  double foot_tolerance_share = 0.1;  // neighbouring columns' foot rows agree within this × expected height
  double join_share = 0.4;         // columns up to this × expected width apart join one candidate
                                   //   (the field seen between a robot's legs)
  double min_width_share = 0.15;   // candidate width / expected width (a NAO seen side on) ...
  double max_width_share = 3.0;    // ... at most this (two robots side by side; the floor beyond
                                   //   the carpet is a "non-field run on the field" too, but wide)
  double merge_width_share = 1.0;  // pieces of one robot (cut by something before it) are joined
                                   //   when together at most this × expected width
  double split_width_share = 1.5;  // a candidate wider than this × expected width is searched for
                                   //   robots standing before the field's edge (below)
  double protrusion_share = 0.04;  // feet this × expected height below the edge stand before it
  double window_height = 64.0 / 56.0;  // window height / expected robot height (margin above and below)
  double foot_row = 60.0 / 64.0;   // where the foot lies in the window, as a share of its height
  double foot_depth_m = 0.1;       // the lowest non-field row is the feet's near edge (and shadow);
                                   //   the robot stands this much farther along the ray
};

struct RobotDetection {
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;  // image box of the expected robot (px)
  hal::Pixel foot{};               // foot point (bottom centre of the candidate)
  hal::RobotPoint ground{};        // where the feet touch the ground, robot frame
  double distance_m = 0.0;
  double bearing_rad = 0.0;        // atan2(y, x): positive to the left
  bool verified = false;           // accepted by the classifier
  double score = 0.0;              // SVM decision value (0 when not classified)
  double confidence = 0.0;         // [0, 1]
};

/// A robot candidate before verification: the columns it spans and its foot row.
struct RobotCandidate {
  int x_min = 0, x_max = 0;  // columns (inclusive)
  int foot_row = 0;          // lowest non-field row + step (the first field row below)
  int columns = 0;
  double height_px = 0.0;    // a standing NAO's image height at the foot point
  bool pieces = false;       // put together from pieces too narrow alone (ranked after whole ones)
};

/// The image box of a standing NAO on candidate `c` (foot at the bottom centre of its columns;
/// `step`: the class grid's column step), as the detector reports it and the evaluation scores
/// its proposals.
struct RobotBox {
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;
  hal::Pixel foot{};
};
[[nodiscard]] RobotBox robot_box(const RobotCandidate& c, int step, const RobotParams& params) noexcept;

struct RobotList {
  std::array<RobotDetection, kMaxRobots> robots{};
  std::size_t count = 0;
  int candidates = 0;
  int classified = 0;
  int classifications_cut = 0;
};

/// The HOG window for a robot whose feet are at `foot` and who is `height_px` tall in the image
/// (the detector and the trainer both crop with this).
[[nodiscard]] WindowPlacement robot_window(const RobotParams& p, const HogParams& hog, const hal::Pixel& foot,
                                           double height_px) noexcept;

class RobotDetector {
 public:
  explicit RobotDetector(const RobotParams& params) : params_(params) {}

  /// propose() then report(): the candidates, verified by `classifier` when there is one.
  void detect(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
              const hal::CameraPose& pose, int stride, HogClassifier* classifier, int max_verified,
              const Deadline& deadline, RobotList& out) noexcept;

  /// The candidate scan alone (columns every `stride` px): `out` is cleared and gets the
  /// candidate count; the candidates wait, nearest first, for report().
  void propose(const ClassImage& classes, const hal::CameraIntrinsics& k, const hal::CameraPose& pose, int stride,
               RobotList& out) noexcept;

  /// The last propose()'s candidates into `out.robots`, nearest first. With a classifier, at most
  /// `max_verified` windows are classified, none once `deadline` has passed or `windows_allowed`
  /// have been (the pipeline's share of a modelled budget); those left out count in
  /// `classifications_cut`. Without one, the candidates are reported unverified.
  void report(const hal::FrameView& frame, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
              HogClassifier* classifier, int max_verified, int windows_allowed, const Deadline& deadline,
              RobotList& out) noexcept;

  /// The image height (px) of a standing robot whose feet are at ground point `g`; 0 when it
  /// cannot be projected.
  [[nodiscard]] double expected_height_px(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                          const hal::RobotPoint& g) const noexcept;

  /// The candidates of the last frame, nearest first (the evaluation measures how many true robots
  /// get one at all: the ceiling of the robots' recall).
  [[nodiscard]] std::span<const RobotCandidate> candidates() const noexcept { return {cands_.data(), count_}; }
  /// The column step the last frame's candidates were found with (their right edge is x_max + step).
  [[nodiscard]] int step() const noexcept { return step_; }

 private:
  using Candidate = RobotCandidate;
  RobotParams params_;
  int step_ = 1;
  std::array<Candidate, kMaxRobotCandidates> cands_{};
  std::size_t count_ = 0;
  std::array<Candidate, kMaxRawRobotCandidates> raw_{};  // before the pieces are joined and judged
  std::size_t raw_count_ = 0;
  std::array<int, kMaxRobotColumns> column_foot_{};  // each scan column's foot row (-1: none), last frame

};

}  // namespace ringlet::vision
