// ringlet-dataset: N rendered head-camera frames of a world, each a picture and a JSON file with
// its ground truth, from random robot poses and head angles, with varied sun stripes and, for
// some frames, robots standing close to the camera. Deterministic for a seed. Unless --no-labels,
// also frame_NNNN_labels.png: per pixel the vision ColourClass of what the renderer drew there,
// the labelled examples ringlet-vision-calibrate builds and evaluates colour tables from.
//
// Exit codes: 0 done · 2 bad input (flags, world file) · 1 cannot write the output.
#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

#include "dataset_json.hpp"
#include "ringlet/sim/camera_renderer.hpp"
#include "ringlet/sim/collision.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/vision/colour.hpp"

namespace {

using namespace ringlet;
using namespace ringlet::sim;

/// Uniform in [lo, hi) from the raw engine output: std::uniform_real_distribution is not
/// specified bit-for-bit, so datasets would differ between standard libraries.
class Uniform {
 public:
  explicit Uniform(std::uint64_t seed) : engine_(seed) {}
  double operator()(double lo, double hi) {
    const double unit = static_cast<double>(engine_() >> 11) * (1.0 / 9007199254740992.0);
    return lo + (hi - lo) * unit;
  }

 private:
  std::mt19937_64 engine_;
};

struct Options {
  std::string world = RINGLET_DEFAULT_WORLD;
  int count = 100;
  std::uint64_t seed = 1;
  std::string out = "dataset";
  std::string format = "png";
  double occluded_share = 0.3;
  double max_yaw_deg = 60.0;
  double min_pitch_deg = 8.0;
  double max_pitch_deg = 32.0;
  bool quiet = false;
  bool labels = true;
};

/// The colour class a pixel of this label should be classified as: carpet is field, painted
/// markings are line, the ball is ball; everything else (background, floor beyond the carpet,
/// robots, posts, obstacles) is other, even where it is white, because a line detector must not
/// take it for a line.
vision::ColourClass colour_class(PixelLabel label) {
  switch (label) {
    case PixelLabel::kCarpet: return vision::ColourClass::kField;
    case PixelLabel::kMarking: return vision::ColourClass::kLine;
    case PixelLabel::kBall: return vision::ColourClass::kBall;
    case PixelLabel::kBackground:
    case PixelLabel::kFloor:
    case PixelLabel::kRobot:
    case PixelLabel::kPost:
    case PixelLabel::kObstacle: return vision::ColourClass::kOther;
  }
  return vision::ColourClass::kOther;
}

std::string labels_name(int index) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "frame_%04d_labels.png", index);
  return buffer;
}

/// A pose inside the bounds (0.3 m from the walls) where a robot of radius 0.25 stands free.
hal::Pose2 random_pose(const World& world, Uniform& rnd) {
  for (;;) {
    const hal::Pose2 p{rnd(world.min.x + 0.3, world.max.x - 0.3), rnd(world.min.y + 0.3, world.max.y - 0.3),
                       rnd(-std::numbers::pi, std::numbers::pi)};
    if (!disc_collides(world, Vec2{p.x, p.y}, 0.25)) return p;
  }
}

/// One or two robots 0.5–1.6 m in front of the camera, inside ±25° of where it looks.
std::vector<Circle> random_occluders(const hal::Pose2& pose, double head_yaw, Uniform& rnd) {
  std::vector<Circle> robots;
  const int n = rnd(0.0, 1.0) < 0.5 ? 1 : 2;
  for (int i = 0; i < n; ++i) {
    const double distance = rnd(0.5, 1.6);
    // Bearing in the world (geometry.hpp): the robot's heading minus the head's left yaw.
    const double bearing = pose.theta - head_yaw + hal::deg_to_rad(rnd(-25.0, 25.0));
    Circle c;
    c.centre = {pose.x + distance * std::sin(bearing), pose.y + distance * std::cos(bearing)};
    c.radius = 0.15;
    c.height = 0.58;
    c.kind = ObstacleKind::kRobot;
    robots.push_back(c);
  }
  return robots;
}

Lighting random_lighting(const Lighting& base, Uniform& rnd) {
  Lighting l = base;
  l.brightness = base.brightness * rnd(0.75, 1.25);
  l.texture = rnd(0.03, 0.12);
  l.sun_strength = rnd(0.0, 1.0) < 0.3 ? 0.0 : rnd(0.1, 0.45);
  l.sun_period = rnd(1.0, 3.0);
  l.sun_angle = rnd(0.0, std::numbers::pi);
  l.sun_phase = rnd(0.0, l.sun_period);
  return l;
}

std::string frame_name(int index, const char* extension) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "frame_%04d.%s", index, extension);
  return buffer;
}

void progress(const Options& o, int done) {
  if (o.quiet) return;
  static const bool tty = isatty(fileno(stderr)) != 0;
  if (tty) {
    std::fprintf(stderr, "\rringlet-dataset: %d/%d frames", done, o.count);
    if (done == o.count) std::fputc('\n', stderr);
  } else if (done == o.count || (o.count >= 10 && done % (o.count / 10) == 0)) {
    std::fprintf(stderr, "ringlet-dataset: %d/%d frames\n", done, o.count);
  }
}

int run(const Options& o) {
  World world;
  try {
    world = load_world(o.world);
  } catch (const WorldError& e) {
    std::cerr << "ringlet-dataset: " << e.what() << "\n";
    return 2;
  }
  const std::filesystem::path out(o.out);
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    std::cerr << "ringlet-dataset: " << o.out << ": cannot create directory: " << ec.message() << "\n";
    return 1;
  }

  const CameraSpec spec{};  // the NAO's camera: 640×480, 57°×44°
  const hal::CameraIntrinsics& k = spec.intrinsics;
  Uniform rnd(o.seed);
  std::vector<std::uint8_t> yuyv(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 2U);
  cv::Mat classes(k.height, k.width, CV_8UC1);

  for (int i = 0; i < o.count; ++i) {
    const hal::Pose2 pose = random_pose(world, rnd);
    const hal::HeadJoints head{hal::deg_to_rad(rnd(-o.max_yaw_deg, o.max_yaw_deg)),
                               hal::deg_to_rad(rnd(o.min_pitch_deg, o.max_pitch_deg))};
    World scene = world;
    scene.lighting = random_lighting(world.lighting, rnd);
    dataset::FrameRecord record;
    record.index = i;
    record.seed = o.seed;
    record.format = o.format;
    if (rnd(0.0, 1.0) < o.occluded_share) record.occluders = random_occluders(pose, head.yaw, rnd);
    scene.circles.insert(scene.circles.end(), record.occluders.begin(), record.occluders.end());

    CameraRenderer renderer(std::move(scene), spec, o.seed + static_cast<std::uint64_t>(i));
    renderer.render(pose, head);

    const auto bgr = renderer.bgr();
    if (o.format == "png") {
      record.image = frame_name(i, "png");
      // OpenCV only reads the buffer; the const_cast is its C-style API, not a write.
      const cv::Mat mat(k.height, k.width, CV_8UC3, const_cast<std::uint8_t*>(bgr.data()));
      if (!cv::imwrite((out / record.image).string(), mat)) {
        std::cerr << "ringlet-dataset: " << (out / record.image).string() << ": cannot write PNG\n";
        return 1;
      }
    } else {
      record.image = frame_name(i, "yuyv");
      hal::bgr_to_yuyv(bgr, k.width, k.height, yuyv);
      std::ofstream file(out / record.image, std::ios::binary);
      file.write(reinterpret_cast<const char*>(yuyv.data()), static_cast<std::streamsize>(yuyv.size()));
      if (!file) {
        std::cerr << "ringlet-dataset: " << (out / record.image).string() << ": cannot write\n";
        return 1;
      }
    }
    if (o.labels) {
      const auto labels = renderer.labels();
      for (std::size_t p = 0; p < labels.size(); ++p) classes.data[p] = static_cast<std::uint8_t>(colour_class(labels[p]));
      const std::filesystem::path labels_path = out / labels_name(i);
      if (!cv::imwrite(labels_path.string(), classes)) {
        std::cerr << "ringlet-dataset: " << labels_path.string() << ": cannot write PNG\n";
        return 1;
      }
    }
    const std::filesystem::path json_path = out / frame_name(i, "json");
    std::ofstream json(json_path);
    json << dataset::frame_json(record, renderer).dump(2) << "\n";
    if (!json) {
      std::cerr << "ringlet-dataset: " << json_path.string() << ": cannot write\n";
      return 1;
    }
    progress(o, i + 1);
  }
  std::cout << "ringlet-dataset: wrote " << o.count << " frames (" << o.format << " + json" << (o.labels ? " + labels" : "")
            << ") to " << o.out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"ringlet-dataset: rendered head-camera frames (PNG or raw YUYV) with JSON ground truth "
               "(lines as image and ground segments, rings, the ball) from random poses, head angles, "
               "lighting and nearby robots. Exit codes: 0 done, 2 bad input, 1 cannot write."};
  app.add_option("-w,--world", o.world, "world file")->capture_default_str();
  app.add_option("-n,--count", o.count, "number of frames")->capture_default_str()->check(CLI::Range(1, 1000000));
  app.add_option("-s,--seed", o.seed, "seed: the same seed gives the same dataset")->capture_default_str();
  app.add_option("-o,--out", o.out, "output directory (created if missing)")->capture_default_str();
  app.add_option("-f,--format", o.format, "png (BGR picture) or yuyv (raw NAO-style bytes)")
      ->capture_default_str()
      ->check(CLI::IsMember({"png", "yuyv"}));
  app.add_option("--occluded", o.occluded_share, "share of frames with robots close to the camera")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--max-yaw", o.max_yaw_deg, "head yaw range ±deg")->capture_default_str()->check(CLI::Range(0.0, 119.0));
  app.add_option("--min-pitch", o.min_pitch_deg, "lowest head pitch, deg (down positive)")->capture_default_str();
  app.add_option("--max-pitch", o.max_pitch_deg, "highest head pitch, deg")->capture_default_str();
  app.add_flag("-q,--quiet", o.quiet, "no progress output");
  app.add_flag("!--no-labels", o.labels,
               "do not write frame_NNNN_labels.png (8-bit, per pixel the colour class: 0 other, 1 field, 2 line, 3 ball)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (!(o.min_pitch_deg <= o.max_pitch_deg)) {
    std::cerr << "ringlet-dataset: --min-pitch must be <= --max-pitch\n";
    return 2;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "ringlet-dataset: internal error: " << e.what() << "\n";
    return 1;
  }
}
