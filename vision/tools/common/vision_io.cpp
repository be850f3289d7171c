#include "vision_io.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/image_header.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/vision/horizon.hpp"
#include "ringlet/vision/stages.hpp"

namespace ringlet::vision::tools {

cv::Mat decode_image(std::span<const std::uint8_t> bytes, const std::string& source, int imread_flags,
                     std::size_t max_pixels) {
  // The header first: a decoder allocates what the header declares before it reads a pixel.
  const hal::ImageProbe probe = hal::probe_image(bytes, max_pixels);
  if (!probe.ok()) throw ToolError(source + ": not a readable image: " + probe.error);
  // A file cut short decodes "fine" (libjpeg fills the missing rows with grey and only warns).
  const std::string truncated = hal::image_truncation(bytes, probe.header->format);
  if (!truncated.empty()) throw ToolError(source + ": not a readable image: " + truncated);
  cv::Mat bgr;
  try {
    // imdecode wants a Mat; it only reads the buffer (the const_cast is its C-style API).
    const cv::Mat raw(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data()));
    bgr = cv::imdecode(raw, imread_flags);
  } catch (const cv::Exception& e) {
    throw ToolError(source + ": not a readable image: the " + std::string(hal::to_string(probe.header->format)) +
                    " decoder failed (" + e.err + ")");
  }
  if (bgr.empty() || (imread_flags == cv::IMREAD_COLOR && bgr.type() != CV_8UC3)) {
    throw ToolError(source + ": not a readable image: the " + std::string(hal::to_string(probe.header->format)) +
                    " data is corrupt or truncated");
  }
  return bgr;
}

cv::Mat decode_bgr(std::span<const std::uint8_t> bytes, const std::string& source, std::size_t max_pixels) {
  return decode_image(bytes, source, cv::IMREAD_COLOR, max_pixels);
}

cv::Mat load_image(const std::filesystem::path& file, int imread_flags) {
  const hal::FileRead read = hal::read_file(file, "image", hal::kMaxBinaryFileBytes);
  if (!read.ok()) throw ToolError(read.error);
  return decode_image({reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size()}, file.string(),
                      imread_flags);
}

namespace {

void check_size(const cv::Mat& bgr, const std::filesystem::path& file, int width, int height) {
  if (width > 0 && (bgr.cols != width || bgr.rows != height)) {
    throw ToolError(file.string() + ": image is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
                    ", the camera is " + std::to_string(width) + "x" + std::to_string(height) +
                    " (give --width/--height and the intrinsics of the camera that took it)");
  }
}

}  // namespace

cv::Mat load_bgr(const std::filesystem::path& file, int width, int height) {
  cv::Mat bgr = load_image(file, cv::IMREAD_COLOR);
  check_size(bgr, file, width, height);
  return bgr;
}

LoadedImage load_frame(const std::filesystem::path& file, int width, int height) {
  const hal::FileRead read = hal::read_file(file, "image", hal::kMaxBinaryFileBytes);
  if (!read.ok()) throw ToolError(read.error);
  const std::span<const std::uint8_t> bytes{reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size()};
  LoadedImage out;
  out.bgr = decode_image(bytes, file.string(), cv::IMREAD_COLOR);
  check_size(out.bgr, file, width, height);
  // What the decoder hid: it hands a grey picture out as three equal channels.
  const hal::ImageProbe probe = hal::probe_image(bytes);
  if (probe.ok() && probe.header->grayscale()) {
    out.warnings.emplace_back(
        "grayscale image: colour classification needs a colour picture (green field, white lines, the ball's "
        "colours), so it is processed as colourless and will find no field, lines or ball");
  }
  return out;
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

HogSvm load_hog_model(const std::filesystem::path& file, HogTarget target, const std::string& flag) {
  HogSvmLoad load = HogSvm::load(file);
  if (!load.model) throw ToolError(flag + " " + file.string() + ": " + load.error);
  if (load.model->target() != target) {
    throw ToolError(flag + " " + file.string() + ": a model for the " +
                    (target == HogTarget::kBall ? "robots, not the ball" : "ball, not the robots"));
  }
  return *std::move(load.model);
}

std::filesystem::path shipped_model(HogTarget target) {
  const char* name = target == HogTarget::kBall ? "ball.hog" : "robot.hog";
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = self.parent_path().parent_path() / RINGLET_INSTALL_MODELS_SUBDIR / name;
    if (std::filesystem::is_regular_file(installed, ec)) return installed;
  }
  const std::filesystem::path source = std::filesystem::path(RINGLET_SOURCE_MODELS_DIR) / name;
  if (std::filesystem::is_regular_file(source, ec)) return source;
  return {};
}

ModelFile model_file(const std::string& flag_value, HogTarget target, const std::string& flag) {
  if (flag_value == kModelNone) return {};
  if (flag_value != kModelAuto) return {flag_value, {}};
  ModelFile m{shipped_model(target), {}};
  if (m.file.empty()) {
    const std::string what = target == HogTarget::kBall ? "ball" : "robot";
    m.warning = "no " + what + " model shipped beside this program (<prefix>/" + RINGLET_INSTALL_MODELS_SUBDIR +
                ") or in " + RINGLET_SOURCE_MODELS_DIR + ": " + what + " candidates are reported unverified; give one with " +
                flag + " FILE";
  }
  return m;
}

ModelFiles model_files(const std::string& ball_flag, const std::string& robot_flag, const char* tool,
                       std::vector<std::string>* warnings) {
  ModelFiles m{model_file(ball_flag, HogTarget::kBall, "--ball-model"), model_file(robot_flag, HogTarget::kRobot, "--robot-model")};
  for (const ModelFile* f : {&m.ball, &m.robot}) {
    if (f->warning.empty()) continue;
    std::cerr << tool << ": warning: " << f->warning << "\n";
    if (warnings != nullptr) warnings->push_back(f->warning);
  }
  return m;
}

CLI::Validator finite_range(double lo, double hi, const std::string& unit) {
  return CLI::Validator(
      [lo, hi, unit](const std::string& text) -> std::string {
        double v = 0.0;
        std::size_t used = 0;
        try {
          v = std::stod(text, &used);
        } catch (const std::exception&) {
          return "not a number: " + text;
        }
        if (used != text.size()) return "not a number: " + text;
        if (!std::isfinite(v)) return "must be a finite number, got " + text;
        if (v < lo || v > hi) {
          return "must be within [" + fmt_number(lo) + ", " + fmt_number(hi) + "]" + (unit.empty() ? "" : " " + unit) +
                 ", got " + text;
        }
        return {};
      },
      "FINITE in [" + fmt_number(lo) + ", " + fmt_number(hi) + "]");
}

std::string fmt_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<CLI::Option*> CameraOptions::add_to(CLI::App& app, bool with_head) {
  const std::size_t before = app.get_options().size();
  app.add_option("--width", width, "image width the camera delivers (px)")->capture_default_str()->check(CLI::Range(2, 4096));
  app.add_option("--height", height, "image height (px)")->capture_default_str()->check(CLI::Range(2, 4096));
  app.add_option("--hfov", hfov_deg, "horizontal field of view (deg), used when --fx is not given")
      ->capture_default_str()->check(finite_range(1.0, 179.0, "deg"));
  app.add_option("--vfov", vfov_deg, "vertical field of view (deg)")->capture_default_str()->check(finite_range(1.0, 179.0, "deg"));
  app.add_option("--fx", fx, "focal length x (px); with --fy, --cx, --cy instead of the fields of view")
      ->check(finite_range(1.0, 1e5, "px"));
  app.add_option("--fy", fy, "focal length y (px)")->check(finite_range(1.0, 1e5, "px"));
  app.add_option("--cx", cx, "principal point x (px), inside the image")->check(finite_range(0.0, 4096.0, "px"));
  app.add_option("--cy", cy, "principal point y (px), inside the image")->check(finite_range(0.0, 4096.0, "px"));
  app.add_option("--pivot-height", mount.pivot_height, "height of the head's pan-tilt pivot above the ground (m)")
      ->capture_default_str()->check(finite_range(0.01, 10.0, "m"));
  app.add_option("--camera-forward", mount.forward, "camera ahead of the pivot (m)")
      ->capture_default_str()->check(finite_range(-1.0, 1.0, "m"));
  app.add_option("--camera-up", mount.up, "camera above the pivot (m)")
      ->capture_default_str()->check(finite_range(-1.0, 1.0, "m"));
  app.add_option("--camera-pitch", camera_pitch_deg,
                 "the camera's own pitch in the head as mounted (deg, down positive; ringlet-vision --auto-pitch's "
                 "correction_deg, the median over a few photos, measures it)")
      ->capture_default_str()->check(finite_range(-15.0, 15.0, "deg"));
  if (with_head) {
    using B = hal::BodyTiltRange;
    app.add_option("--body-pitch", body_pitch_deg,
                   "torso pitch from the inertial unit when the image was taken (deg, leaning forward positive)")
        ->capture_default_str()
        ->check(finite_range(-B::kMaxPitchDeg, B::kMaxPitchDeg, "deg (a standing or walking NAO; beyond, it is falling)"));
    app.add_option("--body-roll", body_roll_deg, "torso roll (deg, leaning to the robot's right positive)")
        ->capture_default_str()
        ->check(finite_range(-B::kMaxRollDeg, B::kMaxRollDeg, "deg (a standing or walking NAO; beyond, it is falling)"));
    using R = hal::NaoHeadRange;
    app.add_option("--yaw", yaw_deg, "head yaw when the image was taken (deg, left positive; the NAO's range)")
        ->capture_default_str()->check(finite_range(-R::kMaxYawDeg, R::kMaxYawDeg, "deg (the NAO's HeadYaw range)"));
    app.add_option("--pitch", pitch_deg, "head pitch (deg, down positive; the NAO's range)")
        ->capture_default_str()->check(finite_range(R::kMinPitchDeg, R::kMaxPitchDeg, "deg (the NAO's HeadPitch range)"));
  }
  std::vector<CLI::Option*> all = app.get_options();  // in the order they were added
  return {all.begin() + static_cast<std::ptrdiff_t>(before), all.end()};
}

hal::CameraIntrinsics CameraOptions::intrinsics() const {
  hal::CameraIntrinsics k = hal::CameraIntrinsics::from_fov(width, height, hfov_deg, vfov_deg);
  if (fx > 0.0) {
    if (!(fy > 0.0)) throw ToolError("--fx needs --fy (and --cx, --cy)");
    k.fx = fx;
    k.fy = fy;
    k.cx = cx > 0.0 ? cx : width / 2.0;
    k.cy = cy > 0.0 ? cy : height / 2.0;
  } else if (fy > 0.0) {
    throw ToolError("--fy needs --fx (and --cx, --cy)");
  }
  if (k.cx > width || k.cy > height) {
    throw ToolError("--cx/--cy (" + fmt_number(k.cx) + ", " + fmt_number(k.cy) + ") lies outside the " +
                    std::to_string(width) + "x" + std::to_string(height) + " image");
  }
  return k;
}

hal::HeadJoints CameraOptions::head() const { return {hal::deg_to_rad(yaw_deg), hal::deg_to_rad(pitch_deg)}; }

hal::BodyTilt CameraOptions::body() const { return {hal::deg_to_rad(body_pitch_deg), hal::deg_to_rad(body_roll_deg)}; }

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
                     {"field_colour", {{"source", to_string(r.field_colour.source)}, {"valid", r.field_colour.valid},
                                       {"y", r.field_colour.y}, {"u", r.field_colour.u}, {"v", r.field_colour.v},
                                       {"y_spread", r.field_colour.y_spread}, {"uv_spread", r.field_colour.uv_spread},
                                       {"confidence", r.field_colour.confidence}}},
                     {"horizon_row", r.horizon_row}};
  // The local field luminance per image cell (rows of the 8 x 8 grid); null where the cell held
  // too little field to measure: lines are never classified there.
  nlohmann::json cells = nlohmann::json::array();
  for (int row = 0; row < kColourCellsY; ++row) {
    nlohmann::json cells_row = nlohmann::json::array();
    for (int col = 0; col < kColourCellsX; ++col) {
      const int c = row * kColourCellsX + col;
      if (r.field_colour.valid && ((r.field_colour.field_cells >> c) & 1U) != 0) {
        cells_row.push_back(r.field_colour.cell_y[static_cast<std::size_t>(c)]);
      } else {
        cells_row.push_back(nullptr);
      }
    }
    cells.push_back(cells_row);
  }
  out["field_colour"]["cell_y"] = cells;
  // What became of the candidates: why pieces were not reported as lines.
  const RansacStats& rs = r.ransac;
  out["line_stats"] = {{"rounds_with_a_line", rs.lines_extracted}, {"too_sparse", rs.sparse_rejected},
                       {"not_paint", rs.check_rejected},         {"arcs", rs.arcs_rejected},
                       {"circle_points", rs.circle_points},      {"splits", rs.splits},
                       {"merges", rs.merges},                    {"beyond_max_lines", rs.segments_dropped},
                       {"cut_short_at_the_edge", rs.cut_short},  {"beyond_the_field", rs.beyond_field},
                       {"stopped_by_deadline", rs.stopped_early},
                       {"on_robots", r.robot_legs_dropped},      {"standing", r.standing_dropped}};
  if (r.circle.seen) {
    out["circle"] = {{"seen", true},
                     {"centre", {r.circle.centre.x, r.circle.centre.y}},
                     {"radius_m", r.circle.radius_m},
                     {"inliers", r.circle.inliers},
                     {"confidence", r.circle.confidence},
                     {"coverage_deg", r.circle.coverage_deg},
                     {"rms_m", r.circle.rms_m}};
  }
  out["marks"] = nlohmann::json::array();
  for (std::size_t i = 0; i < r.marks.count; ++i) {
    const FieldMark& m = r.marks.marks[i];
    out["marks"].push_back({{"centre", {m.centre.x, m.centre.y}},
                            {"distance_m", m.distance_m},
                            {"bearing_rad", m.bearing_rad},
                            {"orientation_rad", m.orientation_rad},
                            {"confidence", m.confidence},
                            {"points", m.points}});
  }
  if (r.ball.seen) {
    out["ball"] = {{"seen", true},
                   {"image", {r.ball.centre.u, r.ball.centre.v}},
                   {"radius_px", r.ball.radius_px},
                   {"confidence", r.ball.confidence}};
    if (r.ball.ground_valid) out["ball"]["ground"] = {r.ball.ground.x, r.ball.ground.y};
    out["ball"]["verified"] = r.ball.verified;  // black-and-white mode: accepted by the HOG/SVM
  }
  nlohmann::json robots = nlohmann::json::array();  // foot points on the ground (robots.hpp)
  for (std::size_t i = 0; i < r.robots.count; ++i) {
    const RobotDetection& d = r.robots.robots[i];
    robots.push_back({{"foot", {d.foot.u, d.foot.v}}, {"box", {d.left, d.top, d.width, d.height}},
                      {"ground", {d.ground.x, d.ground.y}}, {"distance_m", d.distance_m}, {"bearing_rad", d.bearing_rad},
                      {"verified", d.verified}, {"confidence", d.confidence}});
  }
  out["robots"] = std::move(robots);
  return out;
}

namespace {
double to_ms(hal::Nanos t) { return static_cast<double>(t.count()) / 1e6; }
}  // namespace

nlohmann::json stage_times_json(const VisionResult& r) {
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t i = 0; i < kStageCount; ++i) out[std::string(stage_name(static_cast<Stage>(i)))] = to_ms(r.stage_time[i]);
  out["total"] = to_ms(r.total_time);
  return out;
}

TimeStats time_stats(std::vector<hal::Nanos>& samples) {
  if (samples.empty()) return {};
  std::sort(samples.begin(), samples.end());
  const std::size_t n = samples.size();
  // Nearest rank: the smallest sample with at least p of them at or below it.
  const auto rank = [n](double p) { return std::min(n - 1, static_cast<std::size_t>(std::ceil(p * static_cast<double>(n))) - 1); };
  return {to_ms(samples.front()), to_ms(samples[rank(0.5)]), to_ms(samples[rank(0.99)]), to_ms(samples.back())};
}

nlohmann::json to_json(const TimeStats& s) {
  return {{"min", s.min_ms}, {"median", s.median_ms}, {"p99", s.p99_ms}, {"max", s.max_ms}};
}

void draw_candidates(cv::Mat& bgr, std::span<const CandidatePoint> points) {
  for (const CandidatePoint& c : points) {
    const cv::Scalar colour = c.direction == ScanDirection::kVertical ? cv::Scalar{255, 0, 255} : cv::Scalar{255, 255, 0};
    cv::circle(bgr, {static_cast<int>(c.pixel.u), static_cast<int>(c.pixel.v)}, 1, colour, cv::FILLED);
  }
}

void draw_result(cv::Mat& bgr, const VisionResult& r, const hal::CameraIntrinsics& k, const hal::CameraPose& pose) {
  const auto pt = [](const hal::Pixel& p) { return cv::Point(static_cast<int>(std::lround(p.u)), static_cast<int>(std::lround(p.v))); };
  // The horizon of the whole chain: slanted when the torso is rolled.
  const double h0 = horizon_v(k, pose, 0.0);
  const double h1 = horizon_v(k, pose, static_cast<double>(bgr.cols));
  if (std::isfinite(h0) && std::isfinite(h1) && std::abs(h0) < 1e5 && std::abs(h1) < 1e5) {
    cv::line(bgr, {0, static_cast<int>(std::lround(h0))}, {bgr.cols - 1, static_cast<int>(std::lround(h1))},
             {255, 128, 0}, 1);
  }
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
  // The crosses (penalty and centre marks): their two bars, yellow.
  for (std::size_t i = 0; i < r.marks.count; ++i) {
    for (const auto& bar : FieldMarkFinder::bars(r.marks.marks[i])) {
      const auto a = hal::project(k, pose, {bar[0].x, bar[0].y, 0.0});
      const auto b = hal::project(k, pose, {bar[1].x, bar[1].y, 0.0});
      if (a && b) cv::line(bgr, pt(*a), pt(*b), {0, 255, 255}, 2);
    }
  }
  // Every ball (orange: one); an unverified candidate thinner.
  for (std::size_t i = 0; i < r.balls.count; ++i) {
    const BallDetection& b = r.balls.balls[i];
    cv::circle(bgr, pt(b.centre), static_cast<int>(std::lround(b.radius_px)) + 2, {0, 140, 255}, b.verified ? 2 : 1);
  }
  if (r.balls.count == 0 && r.ball.seen) {
    cv::circle(bgr, pt(r.ball.centre), static_cast<int>(std::lround(r.ball.radius_px)) + 2, {0, 140, 255}, 2);
  }
  // Robots: the expected box (cyan; thin when unverified) and the foot point.
  for (std::size_t i = 0; i < r.robots.count; ++i) {
    const RobotDetection& d = r.robots.robots[i];
    const cv::Rect box(static_cast<int>(std::lround(d.left)), static_cast<int>(std::lround(d.top)),
                       static_cast<int>(std::lround(d.width)), static_cast<int>(std::lround(d.height)));
    cv::rectangle(bgr, box, {255, 255, 0}, d.verified ? 2 : 1);
    cv::circle(bgr, pt(d.foot), 4, {255, 255, 0}, cv::FILLED);
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
