#pragma once
// Balls and robots scored against ringlet-dataset's balls[] and robots[] truth (tools/README.md).
//
//   Ball. A detection MATCHES a truth ball (one in front of the camera and visible at all) when
//   its image centre is within max(centre_share × the ball's projected radius, min_centre_px) of
//   the ball's projected centre: inside half the radius, or 4 px for small far balls, whose centre
//   the detector cannot place better than a pixel or two. A ball is EXPECTED (counted for recall)
//   when it is at most max_distance_m away on the ground and at least min_visible of it shows
//   (in_image_fraction × visible_fraction: cut by the image's edge and hidden both count); any
//   other truth ball is "don't care": a detection of it is right, missing it is not wrong.
//
//   Robot. A detection MATCHES a truth robot (in front, visible) when its foot point is within
//   max(foot_share × the robot's projected box width, min_foot_px) of the truth foot point
//   projected into the image, or its box overlaps the truth box by IoU ≥ min_iou (a robot whose
//   feet are cut off by the image's bottom edge). Expected: at most max_distance_m away, its foot
//   point inside the image, and at least min_visible of its silhouette's in-image pixels shown.
//
//   Matching is one to one, nearest (image distance) first. Precision: matching detections /
//   detections; recall: expected objects matched / expected objects. The distance error is
//   relative, |detected − true| / true ground distance, over matched expected objects whose
//   detection has a ground point.
#include <cstddef>
#include <span>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"

namespace ringlet::vision::evaluate {

struct TruthBall {
  bool in_front = false;       // image_centre and image_radius valid
  bool visible = false;
  double u = 0.0, v = 0.0;     // projected centre, px
  double radius_px = 0.0;
  double distance_m = 0.0;
  double visible_fraction = 0.0;   // of its in-image pixels, the share not hidden
  double in_image_fraction = 0.0;  // of its projected disc, the share inside the image
};

struct TruthRobot {
  bool in_front = false;
  bool visible = false;
  bool has_box = false;
  double u0 = 0.0, v0 = 0.0, u1 = 0.0, v1 = 0.0;  // projected body, pixel edges
  bool foot_projects = false;
  double foot_u = 0.0, foot_v = 0.0;               // the foot point projected
  double distance_m = 0.0;
  double visible_fraction = 0.0;
};

struct FoundBall {
  double u = 0.0, v = 0.0;
  bool ground_valid = false;
  double distance_m = 0.0;
};

struct FoundRobot {
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;
  double foot_u = 0.0, foot_v = 0.0;
  double distance_m = 0.0;
};

struct BallMatchParams {
  double centre_share = 0.5;
  double min_centre_px = 4.0;
  double max_distance_m = 5.0;
  double min_visible = 0.5;
};

struct RobotMatchParams {
  double foot_share = 0.5;
  double min_foot_px = 4.0;
  double min_iou = 0.5;
  double max_distance_m = 3.0;
  double min_visible = 0.5;
};

struct ObjectCounts {
  std::size_t detections = 0;
  std::size_t true_positives = 0;  // detections matching a truth object
  std::size_t expected = 0;        // truth objects counted for recall
  std::size_t recalled = 0;
  std::size_t errors = 0;          // relative distance errors summed (matched expected objects)
  double error_sum = 0.0;
  double error_max = 0.0;

  ObjectCounts& operator+=(const ObjectCounts& o) noexcept;
  [[nodiscard]] double precision() const noexcept;  // 1 with no detections
  [[nodiscard]] double recall() const noexcept;     // 1 with nothing expected
  [[nodiscard]] double f1() const noexcept;
  [[nodiscard]] double mean_error() const noexcept;
};

/// A matched, expected robot: where its distance error comes from.
struct RobotMatch {
  double true_distance_m = 0.0;
  double found_distance_m = 0.0;
  double relative_error = 0.0;  // |found − true| / true, as the mean and max are taken
  double foot_offset_px = 0.0;  // found foot point to the true one (px; huge when the truth's does not project)
  bool by_foot = false;         // matched by its foot point (else by box overlap alone)
};

/// One frame's balls.
[[nodiscard]] ObjectCounts score_balls(std::span<const FoundBall> found, std::span<const TruthBall> truth,
                                       const BallMatchParams& params = {});
/// One frame's robots; the image is width × height (an expected robot's foot lies inside it).
/// `matches`, if given, receives one record per matched expected robot.
[[nodiscard]] ObjectCounts score_robots(std::span<const FoundRobot> found, std::span<const TruthRobot> truth,
                                        int width, int height, const RobotMatchParams& params = {},
                                        std::vector<RobotMatch>* matches = nullptr);

}  // namespace ringlet::vision::evaluate
