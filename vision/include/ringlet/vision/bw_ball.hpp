#pragma once
// The SPL ball (black and white since 2016): candidates of the right size for their distance,
// verified by a HOG + linear SVM classifier (hog_svm.hpp).
//
// Candidates: vertical scan columns every `stride` px walk the class image below the horizon and
// collect runs of non-field samples (line, other or ball class: the ball's white shows as line, its
// black patches as other). The camera model gives, for the run's centre, the radius a ball there
// would have, r = fx·R / depth (the ray meets the plane z = R at the ball's centre); a run is a
// candidate when its length is 0.6–1.6 × 2r. A run that is too long (a ball in front of a robot's
// feet or on a line seen lengthwise) gives a candidate at its bottom. A ball cut by the image's
// left, right or bottom edge is centred a radius inside the part seen (from its top when the
// bottom edge cuts it; such a run needs only 0.3 × 2r). Each candidate is re-centred
// along its row and column, then refined on its outline: 16 rays from the centre walk the class
// image to the first two field samples; rays that end within `max_extent` × r give outline points
// (rays running on into a line, a robot or the image's border give none), and a circle of the
// expected radius is fitted to them (when ≥ `min_outline_points`). A blob within r of where an
// outline failed this frame gets none (its neighbouring columns' would fail too). Candidates closer than r to a
// better one are merged. They are ranked (BallCandidate::rank) by how well their extent matches
// 2r, how round their outline is and, most, by the contrast inside: the black patches on white
// that a robot's foot, a line crossing or a white blob lacks.
//
// Verification: the best `max_verified` candidates each get a window of `window_diameters` × 2r
// image px resampled to the model's window, a HOG descriptor and an SVM score; a candidate is a
// ball when score ≥ the model's threshold. Without a classifier (none loaded, or the degrade level
// drops it) the best-ranked candidate is reported unverified with a low confidence (≤ 0.3).
#include <array>
#include <cstddef>
#include <span>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/ball.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/deadline.hpp"
#include "ringlet/vision/hog_svm.hpp"
#include "ringlet/vision/resample.hpp"

namespace ringlet::vision {

inline constexpr std::size_t kMaxBalls = 4;          // reported per frame
inline constexpr std::size_t kMaxBallCandidates = 32;

struct BwBallParams {
  double radius_m = 0.05;
  double min_radius_px = 3.0;      // smaller expected balls (≈ 10 m on the NAO) are not looked for
  double min_extent = 0.6;         // run length / expected diameter, accepted range
  double max_extent = 1.6;
  double min_cut_extent = 0.3;     // a run cut by the image's bottom edge: shortest accepted (the ball's top)
  double window_diameters = 1.6;   // HOG window side / expected ball diameter
  double merge_radii = 1.0;        // candidates closer than this × r merge
  int min_outline_points = 6;      // of 16 rays, for the outline to re-centre a candidate
  double min_contrast = 0.3;       // less inside (no black on white): not re-centred, ranked low
};

/// Where viewing rays meet the plane of ball centres (z = R) for one camera pose: the image radius
/// a ball seen through a pixel would have, r = fx·R / depth, and the ground point under it. Built
/// once per frame: a pixel then costs a few products, a square root and a division instead of a
/// ray through the camera rotation (the detector takes one at every non-field run's end). With
/// n = ((u − cx)/fx, (v − cy)/fy, 1) the ray is A·n for the pose's rotation A, so |ray| = |n| and
/// depth = (R − z)·|n| / (A·n)_z: only the rotation's bottom row is needed for the radius.
class BallPlane {
 public:
  BallPlane(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, double radius_m) noexcept;

  /// 0 when the ray does not meet the plane (at or above its horizon, or a camera below it).
  [[nodiscard]] double radius_px(const hal::Pixel& px) const noexcept;
  /// The robot-frame ground point under the ball seen through `px`; false where radius_px is 0.
  [[nodiscard]] bool ground(const hal::Pixel& px, hal::RobotPoint& at) const noexcept;

 private:
  hal::Vec3 normalised(const hal::Pixel& px) const noexcept;  // n above

  hal::CameraPose pose_;
  double cx_, cy_, inv_fx_, inv_fy_;
  double height_;      // R − z: negative while the camera is above the plane
  double scale_;       // fx·R / (R − z)
  double max_radius_;  // fx·R / 1 µm: the depth is never taken as less
  bool above_ = false; // the camera is above the plane
};

/// Up to kMaxBalls balls, best first, and what the detector did.
struct BallList {
  std::array<BallDetection, kMaxBalls> balls{};
  std::size_t count = 0;
  int candidates = 0;      // after merging
  int classified = 0;      // candidates given to the SVM
  int classifications_cut = 0;  // candidates not classified because the deadline passed
  int refine_samples = 0;  // class-image and luminance samples the outlines, extents and contrasts read, and
                           // the expected radii taken, in sample equivalents (cost model)
};

/// A ball candidate before verification.
struct BallCandidate {
  hal::Pixel centre{};
  double radius = 0.0;    // expected, px (camera model)
  double extent = 0.0;    // how well the blob's extent matches the expected diameter (0..1]
  double roundness = 0.0; // share of the rays ending on an outline, × how well it fits the circle
  double contrast = 0.0;  // (bright − dark) / bright inside: the black patches on white
  // Extent and roundness are read from the class image, which breaks where the ball's shaded white
  // passes for carpet; contrast, from the luminance, weighs most.
  [[nodiscard]] double rank() const noexcept { return (1.0 + extent) * (0.5 + roundness) * contrast * contrast; }
};

class BwBallDetector {
 public:
  explicit BwBallDetector(const BwBallParams& params) : params_(params) {}

  /// propose() then, with a classifier, verify(). `classifier` may be null; `max_verified` ≤ 0
  /// also skips it. The deadline is checked before every classification.
  void detect(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
              const hal::CameraPose& pose, int stride, HogClassifier* classifier, int max_verified,
              const Deadline& deadline, BallList& out) noexcept;

  /// The candidates (seeds every `stride` px), ranked; `out` is cleared and gets their count and
  /// the samples read. Unless they are to be verified, the best is reported unverified
  /// (confidence ≤ 0.3).
  void propose(const ClassImage& classes, const hal::FrameView& frame, const hal::CameraIntrinsics& k,
               const hal::CameraPose& pose, int stride, bool to_be_verified, BallList& out) noexcept;

  /// The last propose()'s candidates classified in rank order: at most `max_verified` windows,
  /// none once `deadline` has passed or `windows_allowed` have been (the pipeline's share of a
  /// modelled budget); those left out count in `classifications_cut`. The verified balls go into
  /// `out` by score.
  void verify(const hal::FrameView& frame, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
              HogClassifier& classifier, int max_verified, int windows_allowed, const Deadline& deadline,
              BallList& out) noexcept;

  /// The image radius (px) of a ball whose centre is seen through pixel `px`; 0 when the ray does
  /// not meet the ball plane (at or above the horizon of the plane z = R). BallPlane's, for one pixel.
  [[nodiscard]] double expected_radius_px(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                          const hal::Pixel& px, hal::RobotPoint* ground = nullptr) const noexcept;

  /// The last frame's candidates, best ranked first.
  [[nodiscard]] std::span<const BallCandidate> candidates() const noexcept { return {cands_.data(), count_}; }

 private:
  using Candidate = BallCandidate;
  void add(const Candidate& c) noexcept;
  /// A detection at candidate `c`, on the ground where it projects.
  [[nodiscard]] static BallDetection detection(const Candidate& c, const BallPlane& plane) noexcept;
  struct Outline {
    hal::Pixel centre{};     // of the circle of the given radius best fitting the outline
    double roundness = 0.0;  // 0 when too few rays end on the field (centre unchanged)
  };
  [[nodiscard]] Outline fit_outline(const ClassImage& classes, const hal::Pixel& centre, double radius) noexcept;

  BwBallParams params_;
  std::array<Candidate, kMaxBallCandidates> cands_{};
  std::size_t count_ = 0;
  std::array<hal::RobotPoint, 16> outline_{};
  std::array<hal::Pixel, kMaxBallCandidates> failed_outlines_{};  // where this frame's outlines failed
  std::size_t failed_count_ = 0;
  long refine_samples_ = 0;
};

/// The HOG window for a ball of image radius `radius_px` centred at `centre` (the detector and
/// the trainer both crop with this, so they see the same patches).
[[nodiscard]] WindowPlacement ball_window(const BwBallParams& p, const HogParams& hog, const hal::Pixel& centre,
                                          double radius_px) noexcept;

/// (0, 1): ½ at the threshold, rising with the margin (a rational sigmoid: basic arithmetic only).
[[nodiscard]] inline double svm_confidence(double score, double threshold) noexcept {
  const double z = score - threshold;
  return 0.5 + 0.5 * z / (1.0 + (z < 0 ? -z : z));
}

}  // namespace ringlet::vision
