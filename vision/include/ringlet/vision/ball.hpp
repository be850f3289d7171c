#pragma once
// The ball: orange blobs in the class image. Seeds are found by a coarse scan below the horizon;
// each seed's connected component (4-neighbourhood on the class image's sampled grid) is grown
// with a fixed-capacity stack; the best-scoring blob wins.
//
// Ground position: the viewing ray through the blob's centre meets the plane z = ball radius
// (0.05 m) at the ball's centre. This is used rather than the bottom point because the bottom of
// the image blob is where the tangent ray grazes the ball, which lands on the ground beyond the
// contact point (biased far, more so when close), and the bottom is the first part hidden by feet;
// the apparent radius is only used for confidence (it is too few pixels far away).
#include <cstdint>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/class_image.hpp"

namespace ringlet::vision {

/// Which detector finds the ball: orange blobs (this file) or the SPL's black-and-white ball
/// (bw_ball.hpp: candidates by size + HOG/SVM verification).
enum class BallMode : std::uint8_t { kOrange, kBlackWhite };

struct BallParams {
  BallMode mode = BallMode::kOrange;
  int seed_stride = 4;          // px between seed rows and columns (rounded to the class step)
  int min_pixels = 6;           // smaller blobs (in image pixels) are noise
  int max_blobs = 8;            // blobs grown per frame at most
  double radius_m = 0.05;       // the ball
};

struct BallDetection {
  bool seen = false;
  hal::Pixel centre{};          // image, pixel-centre coordinates
  double radius_px = 0.0;       // half the larger bounding-box side (robust to a cut-off side)
  hal::RobotPoint ground{};     // ball centre, robot frame
  bool ground_valid = false;    // false when the centre ray does not reach the ball plane
  int pixels = 0;               // image pixels covered (samples × step²)
  double confidence = 0.0;      // [0, 1]: roundness × fill × size × radius consistency (orange);
                                // from the SVM margin (black and white, bw_ball.hpp)
  double distance_m = 0.0;      // of `ground` from the robot's origin, when ground_valid
  double bearing_rad = 0.0;     // atan2(y, x) of `ground`: positive to the left
  bool verified = false;        // black and white: accepted by the HOG/SVM classifier
  double score = 0.0;           // black and white: SVM decision value (0 when not classified)
};

class BallDetector {
 public:
  BallDetector(const BallParams& params, int width, int height);

  /// Detects the ball in `classes` (with `first_row` per column as from horizon_rows()).
  [[nodiscard]] BallDetection detect(const ClassImage& classes, const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                     int seed_stride_override = -1) noexcept;

 private:
  BallParams params_;
  int width_;
  int height_;
  std::vector<std::uint16_t> stamp_;  // per pixel: the frame stamp that visited it (no clearing)
  std::uint16_t current_ = 0;
  std::vector<std::int32_t> stack_;
};

}  // namespace ringlet::vision
