#pragma once
// The vision step for one frame, inside a time budget:
//   horizon → classify (below the horizon) → ball → robots → scan lines → centre circle → RANSAC lines.
// The ball goes before the lines because it matters more and costs little; RANSAC is last
// because it is the part that degrades gracefully (its trials can be cut).
//
// Everything is allocated in the constructor; process() allocates nothing.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/sensors.hpp"
#include "ringlet/vision/ball.hpp"
#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/field_marks.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/colour_table.hpp"
#include "ringlet/vision/cost_model.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/field_colour.hpp"
#include "ringlet/vision/ransac.hpp"
#include "ringlet/vision/robots.hpp"
#include "ringlet/vision/scan_points.hpp"
#include "ringlet/vision/stages.hpp"

namespace ringlet::vision {

/// What one degrade level does.
struct DegradeProfile {
  int class_step = 1;     // classify every pixel (1) or every other row and column (2)
  int scan_stride = 2;    // px between scan lines
  int max_trials = -1;    // RANSAC trials per line (−1: ransac.max_trials)
  int max_lines = -1;     // RANSAC extraction rounds (−1: ransac.max_lines)
  int ball_stride = 4;    // px between ball seeds
  int ransac_skip = -1;   // RANSAC_SKIP (−1: ransac.skip): a sparser scan keeps more of its fewer candidates, so
                          // that lines keep enough points while trials × points still shrinks
  int circle_trials = -1; // centre circle hypotheses (−1: ransac.circle.max_trials)
  int ball_classify = 3;  // black-and-white ball candidates given to the HOG/SVM (0: classifier dropped)
  int robot_classify = 3; // robot candidates given to the HOG/SVM (0: classifier dropped)
};

inline constexpr int kDegradeLevels = 3;

struct VisionConfig {
  hal::CameraIntrinsics intrinsics = hal::CameraIntrinsics::nao();
  hal::CameraMount mount{};
  int horizon_margin_px = 2;             // rows below the horizon left out (too far to use)
  std::size_t max_candidates = 4096;
  ScanParams scan{};
  RansacParams ransac{};
  LineCheckParams line_check{};          // every piece RANSAC fits is checked against the picture
  FieldMarkParams marks{};               // the penalty and centre marks, from what the lines leave over
  // A reported piece lying inside a verified robot's box and within this slant of the image's
  // vertical (horizontal px per vertical px: about 20°) is the robot's leg, not paint, and is
  // dropped (drop_robot_legs); < 0: never.
  double robot_leg_max_slant = 0.35;
  // An upright piece (the same slant) whose bright band goes on for standing_reach_px above its
  // top end is a standing object (a goal post, a leg), not paint (drop_standing_objects); 0: never.
  int standing_reach_px = 18;
  BallParams ball{};                     // ball.mode picks the orange or the black-and-white detector
  BwBallParams bw_ball{};
  bool robots = true;                    // the robot stage (runs only with a robot model installed)
  RobotParams robot{};
  // Colour: adaptive (the field's colour estimated from each frame, the table as fallback when
  // none is found) or the static table always (field_colour.hpp).
  ColourMode colour_mode = ColourMode::kAdaptive;
  AdaptiveColourParams adaptive{};
  // Level 0 = full (the RansacParams: Mi-Pal's 30 trials, skip 10); 1 = every other pixel
  // classified, scan lines twice as far apart, half the trials; 2 = least. The HOG classifiers go
  // first: fewer candidates classified at level 1, none at level 2. Level 0's 5 robot windows
  // model about what its 3 did before the window was resampled with separable taps (5 × 67 µs
  // against 3 × 100 µs of host time).
  std::array<DegradeProfile, kDegradeLevels> degrade{{
      {1, 3, -1, -1, 4, -1, -1, 4, 5},
      {2, 4, 15, 6, 6, 5, 20, 2, 1},
      {2, 8, 8, 4, 8, 3, 10, 0, 0},
  }};
};


enum class VisionStatus : std::uint8_t {
  kOk,
  kBadFrame,  // size differs from the configured intrinsics, or no data: nothing was done
};

struct CutStats {
  bool deadline_hit = false;
  std::uint8_t stages_skipped = 0;   // bit (1 << Stage) per stage not run at all
  int trials_skipped = 0;            // RANSAC trials cut by the deadline
  bool lines_not_extracted = false;  // extraction stopped before the points ran out
  int points_left = 0;               // used candidate points never examined
  int classifications_cut = 0;       // ball and robot candidates not classified (deadline)

  /// The line search was cut, not only optional work: RANSAC stopped early, or it or a stage it
  /// needs (classification, the scan) never ran. The firmware's vision task is then overloaded.
  [[nodiscard]] bool lines_cut() const noexcept {
    constexpr unsigned kNeeded = (1U << static_cast<unsigned>(Stage::kClassify)) |
                                 (1U << static_cast<unsigned>(Stage::kScan)) | (1U << static_cast<unsigned>(Stage::kRansac));
    return lines_not_extracted || (stages_skipped & kNeeded) != 0U;
  }
};

struct VisionResult {
  VisionStatus status = VisionStatus::kOk;
  std::uint64_t sequence = 0;
  hal::Nanos capture_time{0};
  hal::CameraPosture posture{};  // the torso tilt and head joints the frame was processed with
  int degrade_level = 0;
  int horizon_row = 0;  // first ground row (minimum over columns), image height when none
  std::array<FieldLine, kMaxLines> lines{};
  std::size_t line_count = 0;
  int robot_legs_dropped = 0;   // pieces RANSAC reported that lay on verified robots (drop_robot_legs)
  int standing_dropped = 0;     // upright pieces whose band went on up: posts, legs (drop_standing_objects)
  CentreCircle circle{};
  FieldMarkList marks{};        // penalty and centre marks (crosses), found in the line stage
  BallDetection ball{};         // the best ball (balls.balls[0] when balls.count > 0)
  BallList balls{};             // black and white: up to kMaxBalls; orange: the one ball
  RobotList robots{};
  FieldColourEstimate field_colour{};  // the field colour the frame was classified with (source kTable: the table)
  int candidates = 0;           // scan points found
  int candidates_dropped = 0;   // beyond max_candidates
  ScanStats scan{};
  RansacStats ransac{};
  CircleStats circle_stats{};   // the centre circle stage
  CutStats cut{};
  WorkCount work{};             // what the stages did, for the cost model (cost_model.hpp)
  std::array<hal::Nanos, kStageCount> stage_time{};  // by Stage; measured on the deadline's stopwatch
  hal::Nanos total_time{0};
};

/// Drops from lines[0, count) every piece whose image ends both lie inside a verified robot's
/// box and which runs within `max_slant` (horizontal px per vertical px) of the image's vertical:
/// a NAO's white legs on the carpet are runs with green either side, lined up like a line running
/// away from the camera, and LineCheck sees paint there. Upright pieces only: a true line seen
/// between or behind the legs crosses the box. Keeps the order; returns the new count.
[[nodiscard]] std::size_t drop_robot_legs(std::span<FieldLine> lines, std::size_t count, const RobotList& robots,
                                          double max_slant) noexcept;

/// Drops from lines[0, count) every upright piece (within `max_slant` of the image's vertical)
/// whose bright band goes on above its top end: every sample, 6 px apart up to `reach_px` beyond
/// it, at most 25 luminance levels darker than the piece's middle. The pieces are cut to their
/// paint (LineCheck), so above a painted line's end lies carpet; above a goal post's or a leg's
/// base, where the scan's runs lined up like a line running away, the post or the leg goes on up.
/// Keeps the order; returns the new count.
[[nodiscard]] std::size_t drop_standing_objects(std::span<FieldLine> lines, std::size_t count, const hal::FrameView& frame,
                                                double max_slant, int reach_px) noexcept;

class VisionPipeline {
 public:
  VisionPipeline(const VisionConfig& config, ColourTable table);

  /// One frame. `degrade_level` is clamped to [0, kDegradeLevels). With a stopwatch in the
  /// deadline, stages are timed and the deadline is checked between stages and between RANSAC
  /// trials; a stage that would start after the deadline is skipped and reported.
  /// `posture` is the torso's tilt and the head joints at the frame's capture time: the camera
  /// pose, and so the horizon and every ground point, comes from the whole chain.
  const VisionResult& process(const hal::FrameView& frame, const hal::CameraPosture& posture,
                              const Deadline& deadline = {}, int degrade_level = 0) noexcept;
  /// An upright torso (no inertial data): process(frame, {{}, head}, ...).
  const VisionResult& process(const hal::FrameView& frame, const hal::HeadJoints& head, const Deadline& deadline = {},
                              int degrade_level = 0) noexcept {
    return process(frame, hal::CameraPosture{hal::BodyTilt{}, head}, deadline, degrade_level);
  }

  /// Installs a HOG/SVM model as the ball's or the robots' classifier (by its target), at start-up
  /// (allocates). Returns "" or why not (a model that fails validate()).
  [[nodiscard]] std::string set_classifier(HogSvm model);
  [[nodiscard]] bool has_classifier(HogTarget target) const noexcept {
    return target == HogTarget::kBall ? ball_svm_.has_value() : robot_svm_.has_value();
  }

  /// The next frame is an independent picture (a test set, a folder of photos): nothing of the
  /// frames before it (the smoothed and held field colour) may shape how it is classified.
  void forget_history() noexcept { field_colour_.forget(); }

  [[nodiscard]] const VisionResult& result() const noexcept { return result_; }
  [[nodiscard]] const ClassImage& classes() const noexcept { return classes_; }
  [[nodiscard]] const CandidateBuffer& candidates() const noexcept { return candidates_; }
  /// The black-and-white ball detector's candidates of the last frame its stage ran on, best ranked first (the
  /// evaluation measures how many true balls get one at all: the ceiling of the ball's recall).
  [[nodiscard]] std::span<const BallCandidate> ball_candidates() const noexcept { return bw_ball_.candidates(); }
  /// The robot detector's candidates of the last frame its stage ran on, nearest first.
  [[nodiscard]] std::span<const RobotCandidate> robot_candidates() const noexcept { return robots_.candidates(); }
  [[nodiscard]] int robot_candidate_step() const noexcept { return robots_.step(); }
  [[nodiscard]] const VisionConfig& config() const noexcept { return config_; }
  [[nodiscard]] const ColourTable& table() const noexcept { return table_; }
  [[nodiscard]] const AdaptiveClassifier& adaptive() const noexcept { return adaptive_; }

 private:
  VisionConfig config_;
  ColourTable table_;
  FieldColourEstimator field_colour_;
  AdaptiveClassifier adaptive_;
  ClassImage classes_;
  std::vector<int> first_row_;
  LineScanner scanner_;
  CandidateBuffer candidates_;
  RansacLineFinder ransac_;
  CentreCircleFinder circle_;
  FieldMarkFinder marks_;
  BallDetector ball_;
  BwBallDetector bw_ball_;
  RobotDetector robots_;
  std::optional<HogClassifier> ball_svm_;
  std::optional<HogClassifier> robot_svm_;
  VisionResult result_;
};

}  // namespace ringlet::vision
