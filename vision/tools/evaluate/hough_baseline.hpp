#pragma once
// The baseline the RANSAC pipeline is compared with: OpenCV's Canny edge detector followed by the
// probabilistic Hough transform (cv::HoughLinesP), the approach Mi-Pal replaced. It gets the same
// knowledge of the horizon as the pipeline (edges above it are masked out), and its parameters are
// chosen by the evaluation on a tuning subset of the frames (HoughParams::candidates()).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "segment_match.hpp"

namespace ringlet::vision::evaluate {

struct HoughParams {
  double canny_low = 50.0;
  double canny_high = 150.0;
  int canny_aperture = 3;
  double blur_sigma = 1.0;    // Gaussian blur before Canny (0: none)
  double rho_px = 1.0;
  double theta_deg = 1.0;
  int votes = 40;             // accumulator threshold
  double min_length_px = 30.0;
  double max_gap_px = 10.0;

  [[nodiscard]] std::string describe() const;
  /// The parameter sets tried when tuning: around OpenCV's documented defaults, a few edge
  /// thresholds, vote counts and gap lengths.
  [[nodiscard]] static std::vector<HoughParams> candidates();
};

/// Segments found in a BGR image; rows above `horizon_row` (per column, may be empty: no mask)
/// are ignored.
[[nodiscard]] std::vector<Segment2> detect_hough(const cv::Mat& bgr, const std::vector<int>& horizon_row,
                                                 const HoughParams& params);

}  // namespace ringlet::vision::evaluate
