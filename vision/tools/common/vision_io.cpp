#include "vision_io.hpp"

#include <cmath>
#include <iostream>
#include <numbers>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace ringlet::vision::tools {

cv::Mat load_bgr(const std::filesystem::path& file, int width, int height) {
  if (!std::filesystem::exists(file)) throw ToolError(file.string() + ": no such file");
  cv::Mat bgr = cv::imread(file.string(), cv::IMREAD_COLOR);
  if (bgr.empty()) throw ToolError(file.string() + ": not a readable image (PNG, JPEG, ...)");
  if (width > 0 && (bgr.cols != width || bgr.rows != height)) {
    throw ToolError(file.string() + ": image is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
                    ", the camera is " + std::to_string(width) + "x" + std::to_string(height) +
                    " (give --width/--height and the intrinsics of the camera that took it)");
  }
  return bgr;
}

hal::FrameView frame_view(const cv::Mat& bgr, std::uint64_t sequence) {
  hal::FrameView v;
  v.sequence = sequence;
  v.format = hal::PixelFormat::kBgr8;
  v.width = bgr.cols;
  v.height = bgr.rows;
  v.stride = static_cast<int>(bgr.step[0]);
  v.data = bgr.data;
  return v;
}

ColourTable load_table(const std::filesystem::path& file) {
  if (file.empty()) return ColourTable::from_thresholds(ColourThresholds{});
  ColourTableLoad loaded = ColourTable::load(file);
  if (!loaded.table) throw ToolError(loaded.error);
  return std::move(*loaded.table);
}

void CameraOptions::add_to(CLI::App& app, bool with_head) {
  app.add_option("--width", width, "image width the camera delivers (px)")->capture_default_str()->check(CLI::Range(2, 8192));
  app.add_option("--height", height, "image height (px)")->capture_default_str()->check(CLI::Range(2, 8192));
  app.add_option("--hfov", hfov_deg, "horizontal field of view (deg), used when --fx is not given")
      ->capture_default_str()->check(CLI::Range(1.0, 179.0));
  app.add_option("--vfov", vfov_deg, "vertical field of view (deg)")->capture_default_str()->check(CLI::Range(1.0, 179.0));
  app.add_option("--fx", fx, "focal length x (px); with --fy, --cx, --cy instead of the fields of view")
      ->check(CLI::PositiveNumber);
  app.add_option("--fy", fy, "focal length y (px)")->check(CLI::PositiveNumber);
  app.add_option("--cx", cx, "principal point x (px)");
  app.add_option("--cy", cy, "principal point y (px)");
  app.add_option("--pivot-height", mount.pivot_height, "height of the head's pan-tilt pivot above the ground (m)")
      ->capture_default_str()->check(CLI::Range(0.01, 10.0));
  app.add_option("--camera-forward", mount.forward, "camera ahead of the pivot (m)")->capture_default_str();
  app.add_option("--camera-up", mount.up, "camera above the pivot (m)")->capture_default_str();
  if (with_head) {
    app.add_option("--yaw", yaw_deg, "head yaw when the image was taken (deg, left positive)")->capture_default_str();
    app.add_option("--pitch", pitch_deg, "head pitch (deg, down positive)")->capture_default_str();
  }
}

hal::CameraIntrinsics CameraOptions::intrinsics() const {
  hal::CameraIntrinsics k = hal::CameraIntrinsics::from_fov(width, height, hfov_deg, vfov_deg);
  if (fx > 0.0) {
    if (!(fy > 0.0)) throw ToolError("--fx needs --fy (and --cx, --cy)");
    k.fx = fx;
    k.fy = fy;
    k.cx = cx > 0.0 ? cx : width / 2.0;
    k.cy = cy > 0.0 ? cy : height / 2.0;
  }
  return k;
}

hal::HeadJoints CameraOptions::head() const { return {hal::deg_to_rad(yaw_deg), hal::deg_to_rad(pitch_deg)}; }

nlohmann::json result_json(const VisionResult& r) {
  nlohmann::json lines = nlohmann::json::array();
  for (std::size_t i = 0; i < r.line_count; ++i) {
    const FieldLine& l = r.lines[i];
    lines.push_back({{"image", {{l.image_start.u, l.image_start.v}, {l.image_end.u, l.image_end.v}}},
                     {"ground", {{l.ground_start.x, l.ground_start.y}, {l.ground_end.x, l.ground_end.y}}},
                     {"length_m", l.length_m},
                     {"inliers", l.inliers}});
  }
  nlohmann::json out{{"status", r.status == VisionStatus::kOk ? "ok" : "bad frame"},
                     {"lines", lines},
                     {"circle", {{"seen", r.circle.seen}}},
                     {"ball", {{"seen", r.ball.seen}}},
                     {"candidates", r.candidates},
                     {"horizon_row", r.horizon_row}};
  if (r.circle.seen) {
    out["circle"] = {{"seen", true},
                     {"centre", {r.circle.centre.x, r.circle.centre.y}},
                     {"radius_m", r.circle.radius_m},
                     {"inliers", r.circle.inliers}};
  }
  if (r.ball.seen) {
    out["ball"] = {{"seen", true},
                   {"image", {r.ball.centre.u, r.ball.centre.v}},
                   {"radius_px", r.ball.radius_px},
                   {"confidence", r.ball.confidence}};
    if (r.ball.ground_valid) out["ball"]["ground"] = {r.ball.ground.x, r.ball.ground.y};
  }
  return out;
}

void draw_result(cv::Mat& bgr, const VisionResult& r, const hal::CameraIntrinsics& k, const hal::CameraPose& pose) {
  const auto pt = [](const hal::Pixel& p) { return cv::Point(static_cast<int>(std::lround(p.u)), static_cast<int>(std::lround(p.v))); };
  cv::line(bgr, {0, r.horizon_row}, {bgr.cols - 1, r.horizon_row}, {255, 128, 0}, 1);
  for (std::size_t i = 0; i < r.line_count; ++i) {
    const FieldLine& l = r.lines[i];
    cv::line(bgr, pt(l.image_start), pt(l.image_end), {0, 0, 0}, 5);
    cv::line(bgr, pt(l.image_start), pt(l.image_end), {0, 255, 0}, 2);
    cv::putText(bgr, std::to_string(i), pt(l.image_start), cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 255, 0}, 1);
  }
  if (r.circle.seen) {
    for (int a = 0; a < 72; ++a) {
      const double t = a * std::numbers::pi / 36.0;
      const auto px = hal::project(k, pose, {r.circle.centre.x + r.circle.radius_m * std::cos(t),
                                             r.circle.centre.y + r.circle.radius_m * std::sin(t), 0.0});
      if (px) cv::circle(bgr, pt(*px), 2, {255, 0, 255}, cv::FILLED);
    }
  }
  if (r.ball.seen) {
    cv::circle(bgr, pt(r.ball.centre), static_cast<int>(std::lround(r.ball.radius_px)) + 2, {0, 140, 255}, 2);
  }
}

int run_tool(CLI::App& app, int argc, char** argv, std::string_view name, const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    return body();
  } catch (const ToolError& e) {
    std::cerr << name << ": " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << name << ": internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace ringlet::vision::tools
