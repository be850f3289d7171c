#include "hough_baseline.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace ringlet::vision::evaluate {

std::string HoughParams::describe() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "blur sigma %.1f, Canny %.0f/%.0f aperture %d, HoughLinesP rho %.0f px theta %.1f deg votes %d "
                "min length %.0f px max gap %.0f px",
                blur_sigma, canny_low, canny_high, canny_aperture, rho_px, theta_deg, votes, min_length_px, max_gap_px);
  return text;
}

std::vector<HoughParams> HoughParams::candidates() {
  std::vector<HoughParams> out;
  for (const double low : {50.0, 80.0}) {
    for (const int votes : {30, 50, 80}) {
      for (const double gap : {5.0, 15.0}) {
        HoughParams p;
        p.canny_low = low;
        p.canny_high = 3.0 * low;
        p.votes = votes;
        p.max_gap_px = gap;
        out.push_back(p);
      }
    }
  }
  return out;
}

std::vector<Segment2> detect_hough(const cv::Mat& bgr, const std::vector<int>& horizon_row, const HoughParams& p) {
  cv::Mat gray;
  cv::cvtColor(bgr, gray, cv::COLOR_BGR2GRAY);
  if (p.blur_sigma > 0.0) cv::GaussianBlur(gray, gray, cv::Size(0, 0), p.blur_sigma);
  cv::Mat edges;
  cv::Canny(gray, edges, p.canny_low, p.canny_high, p.canny_aperture);
  if (!horizon_row.empty()) {
    for (int x = 0; x < edges.cols && x < static_cast<int>(horizon_row.size()); ++x) {
      const int rows = std::min(std::max(horizon_row[static_cast<std::size_t>(x)], 0), edges.rows);
      for (int y = 0; y < rows; ++y) edges.at<std::uint8_t>(y, x) = 0;
    }
  }
  std::vector<cv::Vec4i> lines;
  cv::HoughLinesP(edges, lines, p.rho_px, p.theta_deg * std::numbers::pi / 180.0, p.votes, p.min_length_px,
                  p.max_gap_px);
  std::vector<Segment2> out;
  out.reserve(lines.size());
  for (const auto& l : lines) out.push_back({static_cast<double>(l[0]), static_cast<double>(l[1]), static_cast<double>(l[2]), static_cast<double>(l[3])});
  return out;
}

}  // namespace ringlet::vision::evaluate
