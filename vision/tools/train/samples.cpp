// Examples for ringlet-train-hog: dataset frames, synthetic frames, patch folders (samples.hpp).
#include "samples.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "ringlet/hal/read_file.hpp"
#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/colour.hpp"
#include "ringlet/vision/prng.hpp"
#include "ringlet/vision/robots.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::train {
namespace {

using tools::ToolError;

cv::Mat to_gray(const cv::Mat& bgr) {
  cv::Mat gray(bgr.rows, bgr.cols, CV_8UC1);
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* in = bgr.ptr<std::uint8_t>(y);
    auto* out = gray.ptr<std::uint8_t>(y);
    for (int x = 0; x < bgr.cols; ++x) out[x] = bgr_to_yuv(in[3 * x], in[3 * x + 1], in[3 * x + 2]).y;
  }
  return gray;
}

double number(const nlohmann::json& j, const std::string& where) {
  if (!j.is_number()) throw ToolError(where + ": expected a number, got " + std::string(j.type_name()));
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw ToolError(where + ": not a finite number");
  return v;
}

/// A box as [x, y, w, h], or (`edges`: ringlet-dataset generator version 3 and later, tools/README.md)
/// as [u0, v0, u1, v1] in pixel edges, where null means the object projects to nothing (behind
/// the camera): std::nullopt.
std::optional<Box> parse_box(const nlohmann::json& o, const std::string& where, bool edges) {
  const char* form = edges ? "[u0, v0, u1, v1]" : "[x, y, w, h]";
  if (!o.is_object() || !o.contains("box")) throw ToolError(where + ": missing \"box\": " + form);
  const auto& b = o["box"];
  if (edges && b.is_null()) return std::nullopt;
  if (!b.is_array() || b.size() != 4) throw ToolError(where + ".box: expected " + form);
  Box box{number(b[0], where + ".box[0]"), number(b[1], where + ".box[1]"), number(b[2], where + ".box[2]"),
          number(b[3], where + ".box[3]")};
  if (edges) {
    box.w -= box.x;
    box.h -= box.y;
  }
  if (box.w <= 0 || box.h <= 0) throw ToolError(where + ".box: width and height must be positive");
  return box;
}

/// The share of the object that shows: visible_fraction (of its in-image pixels, the share not
/// hidden) times, for a ball cut by the image's edge, in_image_fraction (ringlet-dataset's balls).
double visible_fraction(const nlohmann::json& o, const std::string& where) {
  double share = 1.0;
  if (o.contains("visible_fraction")) share = number(o["visible_fraction"], where + ".visible_fraction");
  if (o.contains("in_image_fraction")) share *= number(o["in_image_fraction"], where + ".in_image_fraction");
  return share;
}

// A pentagon (or hexagon) patch of the ball's pattern, projected onto the disc.
void ball_patch(cv::Mat& img, cv::Point2d c, double r, double angle, double dist, int value) {
  const cv::Point2d p = c + cv::Point2d(std::cos(angle), std::sin(angle)) * dist * r;
  const double size = 0.33 * r * (1.0 - 0.45 * dist);
  std::vector<cv::Point> poly;
  for (int k = 0; k < 5; ++k) {
    const double a = angle + k * 2.0 * std::numbers::pi / 5.0;
    // Foreshortened towards the rim.
    const double rx = size * (1.0 - 0.5 * dist * std::abs(std::cos(a - angle)));
    poly.emplace_back(static_cast<int>(std::lround((p.x + rx * std::cos(a)) * 16)),
                      static_cast<int>(std::lround((p.y + size * std::sin(a)) * 16)));
  }
  cv::fillConvexPoly(img, poly, cv::Scalar(value), cv::LINE_AA, 4);
}

void draw_ball(cv::Mat& img, cv::Point2d c, double r, SplitMix64& g) {
  const int white = 190 + static_cast<int>(g.below(55));
  const int dark = 20 + static_cast<int>(g.below(50));
  cv::circle(img, cv::Point(static_cast<int>(std::lround(c.x * 16)), static_cast<int>(std::lround(c.y * 16))),
             static_cast<int>(std::lround(r * 16)), cv::Scalar(white), cv::FILLED, cv::LINE_AA, 4);
  const double turn = static_cast<double>(g.below(6283)) / 1000.0;
  ball_patch(img, c, r, turn, 0.0, dark);
  for (int k = 0; k < 5; ++k) ball_patch(img, c, r, turn + k * 2.0 * std::numbers::pi / 5.0, 0.78, dark);
  // Shading: the lower half a little darker.
  cv::Mat shade = cv::Mat::zeros(img.size(), CV_8UC1);
  cv::ellipse(shade, cv::Point(static_cast<int>(c.x), static_cast<int>(c.y + 0.35 * r)),
              cv::Size(static_cast<int>(0.8 * r) + 1, static_cast<int>(0.55 * r) + 1), 0, 0, 360, cv::Scalar(25),
              cv::FILLED);
  cv::Mat mask = cv::Mat::zeros(img.size(), CV_8UC1);
  cv::circle(mask, cv::Point(static_cast<int>(c.x), static_cast<int>(c.y)), static_cast<int>(r), cv::Scalar(255),
             cv::FILLED);
  cv::Mat shaded;
  cv::subtract(img, shade, shaded);
  shaded.copyTo(img, mask);
}

// A NAO-like silhouette standing with its feet at `foot` and `h` px tall: head, torso, arms,
// legs and feet in proportions of the real robot (0.574 m tall, ~0.31 m across the arms).
void draw_robot(cv::Mat& img, cv::Point2d foot, double h, SplitMix64& g) {
  const int white = 175 + static_cast<int>(g.below(70));
  const int grey = 80 + static_cast<int>(g.below(60));
  const double lean = (static_cast<double>(g.below(200)) / 1000.0 - 0.1) * h;  // a little side lean
  const auto pt = [&](double dx, double dy) {  // dy from the foot up, in robot heights; dx in heights
    const double t = dy;
    return cv::Point(static_cast<int>(std::lround((foot.x + dx * h + lean * t * 0.3) * 16)),
                     static_cast<int>(std::lround((foot.y - dy * h) * 16)));
  };
  const auto rect = [&](double x0, double y0, double x1, double y1, int v) {
    std::vector<cv::Point> p{pt(x0, y0), pt(x1, y0), pt(x1, y1), pt(x0, y1)};
    cv::fillConvexPoly(img, p, cv::Scalar(v), cv::LINE_AA, 4);
  };
  const double stance = 0.02 + static_cast<double>(g.below(60)) / 1000.0;
  rect(-0.14 - stance, 0.0, -0.02 - stance * 0.5, 0.05, grey);  // feet
  rect(0.02 + stance * 0.5, 0.0, 0.14 + stance, 0.05, grey);
  rect(-0.11 - stance * 0.6, 0.04, -0.015, 0.46, white);          // legs
  rect(0.015, 0.04, 0.11 + stance * 0.6, 0.46, white);
  rect(-0.10, 0.24, -0.02, 0.30, grey);                           // knees
  rect(0.02, 0.24, 0.10, 0.30, grey);
  rect(-0.15, 0.44, 0.15, 0.80, white);                           // torso
  rect(-0.05, 0.52, 0.05, 0.68, grey);                            // chest button area
  const double arm = static_cast<double>(g.below(80)) / 1000.0;
  rect(-0.27 - arm, 0.50, -0.16, 0.79, white);                    // arms
  rect(0.16, 0.50, 0.27 + arm, 0.79, white);
  cv::ellipse(img, pt(0.0, 0.89), cv::Size(static_cast<int>(0.115 * h * 16), static_cast<int>(0.11 * h * 16)), 0,
              0, 360, cv::Scalar(white), cv::FILLED, cv::LINE_AA, 4);  // head
  rect(-0.08, 0.86, 0.08, 0.92, grey);                            // eyes band
}

}  // namespace

Box window_box(const WindowPlacement& w, const HogParams& hog) {
  return {w.left, w.top, w.scale * hog.window_width, w.scale * hog.window_height};
}

double overlap(const Box& a, const Box& b) {
  const double ix = std::max(0.0, std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x));
  const double iy = std::max(0.0, std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y));
  const double smaller = std::min(a.w * a.h, b.w * b.h);
  return smaller > 0 ? ix * iy / smaller : 0.0;
}

WindowPlacement truth_window(HogTarget target, const HogParams& hog, const Box& b) {
  if (target == HogTarget::kBall) {
    return ball_window(BwBallParams{}, hog, {b.x + 0.5 * b.w, b.y + 0.5 * b.h}, 0.5 * std::max(b.w, b.h));
  }
  return robot_window(RobotParams{}, hog, {b.x + 0.5 * b.w, b.y + b.h}, b.h);
}

void cut_patch(const cv::Mat& gray, const WindowPlacement& w, const HogParams& hog, std::vector<std::uint8_t>& patch) {
  hal::FrameView f{};
  f.format = hal::PixelFormat::kGray8;
  f.width = gray.cols;
  f.height = gray.rows;
  f.stride = static_cast<int>(gray.step[0]);
  f.data = gray.data;
  patch.resize(static_cast<std::size_t>(hog.window_width) * static_cast<std::size_t>(hog.window_height));
  resample_luma(f, w.left, w.top, w.scale, hog.window_width, hog.window_height, patch);
}

std::vector<LabelledFrame> load_dataset(const std::filesystem::path& dir, HogTarget target, double min_visible,
                                        int max_frames) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw ToolError(dir.string() + ": not a directory");
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".json") files.push_back(e.path());
  }
  if (ec) throw ToolError(dir.string() + ": cannot list: " + ec.message());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw ToolError(dir.string() + ": no frame_*.json files (not a ringlet-dataset folder)");
  if (max_frames > 0 && files.size() > static_cast<std::size_t>(max_frames)) files.resize(static_cast<std::size_t>(max_frames));
  const std::string key = target == HogTarget::kBall ? "balls" : "robots";
  std::vector<LabelledFrame> frames;
  for (const auto& file : files) {
    const std::string src = file.string();
    const hal::FileRead read = hal::read_file(file, "dataset frame JSON");
    if (!read.ok()) throw ToolError(read.error);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(read.bytes);
    } catch (const nlohmann::json::exception& e) {
      throw ToolError(src + ": not valid JSON: " + e.what());
    }
    if (!j.is_object() || !j.contains("image") || !j["image"].is_string()) {
      throw ToolError(src + ": missing \"image\" (the frame's file name)");
    }
    LabelledFrame f;
    f.source = src;
    // ringlet-dataset writes boxes as pixel edges since generator version 3 (tools/README.md).
    const bool edges = j.contains("generator_version") && j["generator_version"].is_number_integer() &&
                       j["generator_version"].get<int>() >= 3;
    const auto add = [&](const Box& b, double visible) { (visible >= min_visible ? f.objects : f.ignore).push_back(b); };
    if (j.contains(key)) {
      if (!j[key].is_array()) throw ToolError(src + ": \"" + key + "\" must be an array of {\"box\": [x, y, w, h]}");
      for (std::size_t i = 0; i < j[key].size(); ++i) {
        const std::string where = src + ": " + key + "[" + std::to_string(i) + "]";
        if (const std::optional<Box> b = parse_box(j[key][i], where, edges)) add(*b, visible_fraction(j[key][i], where));
      }
    } else if (target == HogTarget::kBall && j.contains("ball")) {
      // A dataset of before issue 10: one ball with its image centre and radius.
      const auto& b = j["ball"];
      if (b.is_object() && b.value("visible", false)) {
        if (!b.contains("image_centre") || !b["image_centre"].is_array() || b["image_centre"].size() != 2 ||
            !b.contains("image_radius")) {
          throw ToolError(src + ": ball: missing \"image_centre\": [u, v] or \"image_radius\"");
        }
        const double u = number(b["image_centre"][0], src + ": ball.image_centre[0]");
        const double v = number(b["image_centre"][1], src + ": ball.image_centre[1]");
        const double r = number(b["image_radius"], src + ": ball.image_radius");
        if (r > 0) add({u - r, v - r, 2 * r, 2 * r}, visible_fraction(b, src + ": ball"));
      }
    } else {
      throw ToolError(src + ": no \"" + key + "\" array of {\"box\": [x, y, w, h]} (a dataset written before " +
                      key + " truth existed? regenerate it with this ringlet-dataset)");
    }
    const cv::Mat bgr = tools::load_bgr(file.parent_path() / j["image"].get<std::string>());
    f.gray = to_gray(bgr);
    // Frames that carry their camera (ringlet-dataset) also yield the detector's proposals.
    if (j.contains("intrinsics")) f.proposals = detector_proposals(target, file, bgr);
    frames.push_back(std::move(f));
  }
  return frames;
}

std::vector<LabelledFrame> synthetic_frames(HogTarget target, std::uint64_t seed, int count) {
  std::vector<LabelledFrame> frames;
  for (int i = 0; i < count; ++i) {
    SplitMix64 g = SplitMix64::for_frame(seed, static_cast<std::uint64_t>(i));
    const auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * static_cast<double>(g.below(1000001)) / 1e6; };
    LabelledFrame f;
    f.source = "synthetic frame " + std::to_string(i);
    const int carpet = 60 + static_cast<int>(g.below(80));
    f.gray = cv::Mat(240, 320, CV_8UC1, cv::Scalar(carpet));
    // Carpet texture: blotches, then fine noise after the objects.
    for (int k = 0; k < 40; ++k) {
      cv::circle(f.gray, cv::Point(static_cast<int>(g.below(320)), static_cast<int>(g.below(240))),
                 2 + static_cast<int>(g.below(12)), cv::Scalar(carpet + static_cast<int>(g.below(21)) - 10), cv::FILLED);
    }
    // Field lines (and sometimes a curved piece).
    const int lines = static_cast<int>(g.below(4));
    for (int k = 0; k < lines; ++k) {
      const cv::Point a(static_cast<int>(g.below(320)), static_cast<int>(g.below(240)));
      const cv::Point b(static_cast<int>(g.below(320)), static_cast<int>(g.below(240)));
      cv::line(f.gray, a, b, cv::Scalar(190 + static_cast<int>(g.below(60))), 2 + static_cast<int>(g.below(8)), cv::LINE_AA);
    }
    if (g.below(3) == 0) {
      cv::ellipse(f.gray, cv::Point(static_cast<int>(g.below(320)), static_cast<int>(g.below(240))),
                  cv::Size(40 + static_cast<int>(g.below(120)), 15 + static_cast<int>(g.below(50))), 0, 0, 360,
                  cv::Scalar(200), 2 + static_cast<int>(g.below(5)), cv::LINE_AA);
    }
    // Clutter of the other kind, then the target's objects.
    const auto place_robot = [&](bool truth) {
      const double h = uniform(40, 200);
      const cv::Point2d foot(uniform(20, 300), uniform(std::min(h, 230.0), 235));
      draw_robot(f.gray, foot, h, g);
      if (truth) f.objects.push_back({foot.x - 0.5 * h * 0.54, foot.y - h, h * 0.54, h});
    };
    const auto place_ball = [&](bool truth) {
      const double r = uniform(5, 30);
      const cv::Point2d c(uniform(r, 320 - r), uniform(r, 240 - r));
      draw_ball(f.gray, c, r, g);
      if (truth) f.objects.push_back({c.x - r, c.y - r, 2 * r, 2 * r});
    };
    const bool ball = target == HogTarget::kBall;
    if (g.below(2) == 0) {
      if (ball) {
        place_robot(false);
      } else {
        place_ball(false);
      }
    }
    const int n = static_cast<int>(g.below(3));
    for (int k = 0; k < n; ++k) {
      if (ball) {
        place_ball(true);
      } else {
        place_robot(true);
      }
    }
    // Blur and sensor noise.
    cv::GaussianBlur(f.gray, f.gray, cv::Size(3, 3), uniform(0.3, 1.2));
    for (int y = 0; y < f.gray.rows; ++y) {
      auto* row = f.gray.ptr<std::uint8_t>(y);
      for (int x = 0; x < f.gray.cols; ++x) {
        row[x] = static_cast<std::uint8_t>(std::clamp(static_cast<int>(row[x]) + static_cast<int>(g.below(13)) - 6, 0, 255));
      }
    }
    frames.push_back(std::move(f));
  }
  return frames;
}

PatchSet load_patches(const std::filesystem::path& dir, const HogParams& hog) {
  PatchSet set;
  for (const bool positive : {true, false}) {
    const std::filesystem::path sub = dir / (positive ? "pos" : "neg");
    std::error_code ec;
    if (!std::filesystem::is_directory(sub, ec)) throw ToolError(sub.string() + ": not a directory (expected pos/ and neg/)");
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(sub, ec)) {
      if (e.path().extension() == ".png") files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    if (files.empty()) throw ToolError(sub.string() + ": no *.png patches");
    for (const auto& file : files) {
      const cv::Mat gray = to_gray(tools::load_bgr(file));
      const double want = static_cast<double>(hog.window_width) / hog.window_height;
      const double have = static_cast<double>(gray.cols) / gray.rows;
      if (std::abs(have / want - 1.0) > 0.05) {
        throw ToolError(file.string() + ": patch is " + std::to_string(gray.cols) + "x" + std::to_string(gray.rows) +
                        ", the window's aspect ratio is " + std::to_string(hog.window_width) + ":" +
                        std::to_string(hog.window_height));
      }
      std::vector<std::uint8_t> patch;
      cut_patch(gray, {0.0, 0.0, static_cast<double>(gray.cols) / hog.window_width}, hog, patch);
      (positive ? set.positives : set.negatives).push_back(std::move(patch));
    }
  }
  return set;
}

}  // namespace ringlet::vision::train
