// ringlet-dataset: N rendered head-camera frames of a world, each a picture and a JSON file with
// its ground truth, from random robot poses and head angles. With --look spl (the default) every
// frame draws its own look (light, exposure, white balance, carpet, noise, motion blur, a JPEG
// round trip: sim_hal/look_randomizer.hpp) and its own black-and-white balls and NAO robots at
// 0.5-6 m, some partly hidden or cut by the image's edge; --look plain keeps the first renderer's
// look and only varies the sun stripes. Some frames get robots standing close to the camera. Unless --no-labels, also
// frame_NNNN_labels.png: per pixel the vision ColourClass of what the renderer drew there, the
// labelled examples ringlet-vision-calibrate builds and evaluates colour tables from.
//
// Each frame is a pure function of (seed, frame index) and the options: it draws from its own
// random stream, so `--first K -n N` writes frames K..K+N-1 exactly as a longer run would, and
// sets with different seeds, or the same seed and disjoint index ranges, share no frame. That is
// what makes honest tuning/test splits possible (ringlet-vision-eval checks them). The folder's
// manifest.json records the generator, the seed, the options and the index ranges written.
//
// Exit codes: 0 done · 2 bad input (flags, world file, a world with no free pose, a folder that
// holds a different dataset) · 1 cannot write the output.
#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <unistd.h>
#include <vector>

#include "dataset_json.hpp"
#include "ringlet/sim_hal/camera_renderer.hpp"
#include "ringlet/sim_hal/collision.hpp"
#include "ringlet/sim_hal/look_randomizer.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/vision/colour.hpp"

namespace {

using namespace ringlet;
using namespace ringlet::sim_hal;

/// Bumped whenever the frames a (seed, index) gives change: frames of different generator
/// versions are different frames. 1: one stream for the whole run (a run was a prefix of any
/// longer one). 2: one stream per frame. 3: the SPL look, balls and robots per frame. 4: the
/// occluding robots stand on the carpet.
constexpr int kGeneratorVersion = 4;

/// Random poses tried before a world is declared to have no free pose.
constexpr int kMaxPoseTries = 100000;

class DatasetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// SplitMix64's finaliser: a bijection on 64 bits that spreads every input bit.
std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// The seed of frame `index`'s own random stream, and of its renderer (texture noise): distinct
/// for every (seed, index), unlike seed + index, where seed 1 frame 1 was seed 2 frame 0.
std::uint64_t frame_stream(std::uint64_t seed, std::uint64_t index) { return mix64(mix64(seed) ^ mix64(index ^ 0x5EED5EEDULL)); }
std::uint64_t render_seed(std::uint64_t seed, std::uint64_t index) { return mix64(frame_stream(seed, index) ^ 0xC0FFEEULL); }

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
  int first = 0;
  std::uint64_t seed = 1;
  std::string out = "dataset";
  std::string format = "png";
  double occluded_share = 0.3;
  double max_yaw_deg = 60.0;
  double min_pitch_deg = 8.0;
  double max_pitch_deg = 29.5;  // the NAO's HeadPitch limit (hal::NaoHeadRange)
  bool quiet = false;
  bool labels = true;
  std::string look = "spl";  // spl: the realistic look, drawn per frame; plain: the first renderer's
  std::string ball = "bw";   // bw or orange
  int max_balls = 4;         // balls per frame: 1..max_balls
  int max_robots = 4;        // NAO robots added per frame: 0..max_robots (besides the world's)
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
/// DatasetError naming the world when none is found in kMaxPoseTries draws.
hal::Pose2 random_pose(const World& world, const std::string& world_file, Uniform& rnd) {
  for (int i = 0; i < kMaxPoseTries; ++i) {
    const hal::Pose2 p{rnd(world.min.x + 0.3, world.max.x - 0.3), rnd(world.min.y + 0.3, world.max.y - 0.3),
                       rnd(-std::numbers::pi, std::numbers::pi)};
    if (!disc_collides(world, Vec2{p.x, p.y}, 0.25)) return p;
  }
  throw DatasetError(world_file + ": no free pose for the camera robot (a 0.25 m disc, 0.3 m inside the bounds) in " +
                     std::to_string(kMaxPoseTries) + " random tries: world \"" + world.name +
                     "\" is too small or full of obstacles");
}

/// Where things may stand: on the carpet, 0.2 m inside the bounds, off every obstacle by `clear`.
bool free_spot(const World& world, Vec2 p, double clear) {
  return p.x > world.min.x + 0.2 && p.x < world.max.x - 0.2 && p.y > world.min.y + 0.2 && p.y < world.max.y - 0.2 &&
         !disc_collides(world, p, clear);
}

/// Where a robot may stand: a free spot (off every obstacle by a robot's 0.15 m and a little) and
/// not on a ball (one standing on it would hide it inside its feet).
bool robot_spot(const World& scene, Vec2 p) {
  const auto on_ball = [&](const Ball& b) { return std::hypot(b.position.x - p.x, b.position.y - p.y) <= 0.25; };
  return free_spot(scene, p, 0.16) && !(scene.ball && on_ball(*scene.ball)) &&
         std::none_of(scene.extra_balls.begin(), scene.extra_balls.end(), on_ball);
}

/// A point `distance` m from the camera robot, at `spread_deg` around where the head looks (the
/// camera's field of view is ±28.5°, so a spread past it puts some things at or beyond the edge).
Vec2 around_view(const hal::Pose2& pose, double head_yaw, double distance, double spread_deg, Uniform& rnd) {
  const double bearing = pose.theta - head_yaw + hal::deg_to_rad(rnd(-spread_deg, spread_deg));
  return {pose.x + distance * std::sin(bearing), pose.y + distance * std::cos(bearing)};
}

/// Up to `n` NAO robots (`height` m tall) `near`–`far` m from the camera robot, within ±`spread_deg`
/// of where the head looks, each on a robot_spot and off the ones placed before it; a draw that
/// finds no spot in 50 tries places fewer.
std::vector<Circle> place_robots(const World& scene, const hal::Pose2& pose, double head_yaw, int n, double near,
                                 double far, double spread_deg, double height, Uniform& rnd) {
  std::vector<Circle> robots;
  World probe = scene;
  for (int i = 0, tries = 0; i < n && tries < 50; ++tries) {
    const Vec2 p = around_view(pose, head_yaw, rnd(near, far), spread_deg, rnd);
    const double dx = p.x - pose.x, dy = p.y - pose.y;
    if (!robot_spot(probe, p) || dx * dx + dy * dy < 0.45 * 0.45) continue;  // never on the camera robot
    const Circle c{p, 0.15, height, ObstacleKind::kRobot};
    probe.circles.push_back(c);
    robots.push_back(c);
    ++i;
  }
  return robots;
}

/// One or two robots 0.5–1.6 m in front of the camera, inside ±25° of where it looks, standing on
/// the carpet like every other robot (version 3 put them anywhere: past the carpet's edge, on the
/// floor, where no robot of a game stands).
std::vector<Circle> random_occluders(const World& scene, const hal::Pose2& pose, double head_yaw, Uniform& rnd) {
  const int n = rnd(0.0, 1.0) < 0.5 ? 1 : 2;
  return place_robots(scene, pose, head_yaw, n, 0.5, 1.6, 25.0, 0.58, rnd);
}

/// 1..max balls (SPL size, 0.05 m radius) 0.5-6 m away, most in view; each off the robots.
std::vector<Ball> random_balls(const World& scene, const hal::Pose2& pose, double head_yaw, int max, Uniform& rnd) {
  std::vector<Ball> balls;
  const int n = 1 + static_cast<int>(rnd(0.0, static_cast<double>(max)));
  for (int i = 0, tries = 0; i < n && tries < 50; ++tries) {
    const Vec2 p = around_view(pose, head_yaw, rnd(0.5, 6.0), 36.0, rnd);
    const double dx = p.x - pose.x, dy = p.y - pose.y;
    if (!free_spot(scene, p, 0.06) || dx * dx + dy * dy < 0.3 * 0.3) continue;
    bool apart = true;
    for (const Ball& b : balls) apart = apart && std::hypot(b.position.x - p.x, b.position.y - p.y) > 0.12;
    if (!apart) continue;
    balls.push_back(Ball{p, 0.05});
    ++i;
  }
  return balls;
}

/// 0..max NAO robots 0.5-6 m away, some at the image's edges; never on the camera robot.
std::vector<Circle> random_robots(const World& scene, const hal::Pose2& pose, double head_yaw, int max, Uniform& rnd) {
  const int n = static_cast<int>(rnd(0.0, static_cast<double>(max) + 1.0));
  return place_robots(scene, pose, head_yaw, n, 0.5, 6.0, 38.0, 0.574, rnd);
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

/// What decides the frames besides their index: equal generations give equal frames.
nlohmann::ordered_json generation(const Options& o, const World& world) {
  return {{"generator", "ringlet-dataset"}, {"generator_version", kGeneratorVersion},
          {"world_file", o.world},         {"world", world.name},
          {"seed", o.seed},                {"format", o.format},
          {"occluded", o.occluded_share},  {"max_yaw_deg", o.max_yaw_deg},
          {"min_pitch_deg", o.min_pitch_deg}, {"max_pitch_deg", o.max_pitch_deg},
          {"look", o.look},                {"ball", o.ball},
          {"max_balls", o.max_balls},      {"max_robots", o.max_robots}};
}

/// The index ranges [a, b) already in the folder's manifest (none without one). DatasetError when
/// the folder holds frames of another generation (or frames without a manifest): mixing them
/// would make the folder's identity a lie.
std::vector<std::pair<std::int64_t, std::int64_t>> existing_ranges(const std::filesystem::path& out,
                                                                    const nlohmann::ordered_json& gen) {
  std::vector<std::pair<std::int64_t, std::int64_t>> ranges;
  const std::filesystem::path manifest = out / "manifest.json";
  std::error_code ec;
  if (!std::filesystem::exists(manifest, ec)) {
    for (const auto& e : std::filesystem::directory_iterator(out, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".json") {
        throw DatasetError(out.string() + ": holds frames without a manifest.json (an older ringlet-dataset); write "
                           "to another folder");
      }
    }
    return ranges;
  }
  const hal::FileRead read = hal::read_file(manifest, "dataset manifest");
  if (!read.ok()) throw DatasetError(read.error);
  try {
    const auto j = nlohmann::ordered_json::parse(read.bytes);
    if (j.at("generation") != gen) {
      throw DatasetError(manifest.string() + ": the folder holds a different dataset (" + j.at("generation").dump() +
                         "); write to another folder");
    }
    for (const auto& r : j.at("ranges")) ranges.emplace_back(r.at(0).get<std::int64_t>(), r.at(1).get<std::int64_t>());
  } catch (const nlohmann::json::exception& e) {
    throw DatasetError(manifest.string() + ": not a ringlet-dataset manifest: " + e.what());
  }
  return ranges;
}

/// Sorted, overlapping or touching ranges joined.
std::vector<std::pair<std::int64_t, std::int64_t>> merge_ranges(std::vector<std::pair<std::int64_t, std::int64_t>> r) {
  std::sort(r.begin(), r.end());
  std::vector<std::pair<std::int64_t, std::int64_t>> out;
  for (const auto& x : r) {
    if (!out.empty() && x.first <= out.back().second) {
      out.back().second = std::max(out.back().second, x.second);
    } else {
      out.push_back(x);
    }
  }
  return out;
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
  {
    // A world without a free pose is refused before the output folder is created.
    Uniform probe(frame_stream(o.seed, static_cast<std::uint64_t>(o.first)));
    (void)random_pose(world, o.world, probe);
  }
  const std::filesystem::path out(o.out);
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    std::cerr << "ringlet-dataset: " << o.out << ": cannot create directory: " << ec.message() << "\n";
    return 1;
  }
  const nlohmann::ordered_json gen = generation(o, world);
  auto ranges = existing_ranges(out, gen);

  const CameraSpec spec{};  // the NAO's camera: 640×480, 57°×44°
  const hal::CameraIntrinsics& k = spec.intrinsics;
  std::vector<std::uint8_t> yuyv(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 2U);
  cv::Mat classes(k.height, k.width, CV_8UC1);
  std::vector<std::uint8_t> jpeg_frame(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 3U);

  for (int n = 0; n < o.count; ++n) {
    const int i = o.first + n;
    Uniform rnd(frame_stream(o.seed, static_cast<std::uint64_t>(i)));
    const hal::Pose2 pose = random_pose(world, o.world, rnd);
    const hal::HeadJoints head{hal::deg_to_rad(rnd(-o.max_yaw_deg, o.max_yaw_deg)),
                               hal::deg_to_rad(rnd(o.min_pitch_deg, o.max_pitch_deg))};
    World scene = world;
    dataset::FrameRecord record;
    record.index = i;
    record.seed = o.seed;
    record.generator_version = kGeneratorVersion;
    record.format = o.format;
    if (o.look == "spl") {
      const BallLook ball = o.ball == "bw" ? BallLook::kBlackWhite : BallLook::kOrange;
      const LookDraw draw = draw_spl_look(world.lighting, ball, mix64(frame_stream(o.seed, static_cast<std::uint64_t>(i)) ^ 0x100CULL));
      scene.look = draw.look;
      scene.lighting = draw.lighting;
      record.jpeg_quality = draw.jpeg_quality;
      const std::vector<Ball> balls = random_balls(scene, pose, head.yaw, o.max_balls, rnd);
      scene.ball.reset();
      if (!balls.empty()) {
        scene.ball = balls.front();
        scene.extra_balls.assign(balls.begin() + 1, balls.end());
      }
      record.added_robots = random_robots(scene, pose, head.yaw, o.max_robots, rnd);
      scene.circles.insert(scene.circles.end(), record.added_robots.begin(), record.added_robots.end());
    } else {
      scene.lighting = random_lighting(world.lighting, rnd);
      scene.look.ball = o.ball == "bw" ? BallLook::kBlackWhite : BallLook::kOrange;
    }
    if (rnd(0.0, 1.0) < o.occluded_share) record.occluders = random_occluders(scene, pose, head.yaw, rnd);
    scene.circles.insert(scene.circles.end(), record.occluders.begin(), record.occluders.end());

    CameraRenderer renderer(std::move(scene), spec, render_seed(o.seed, static_cast<std::uint64_t>(i)));
    renderer.render(pose, head);

    std::span<const std::uint8_t> bgr = renderer.bgr();
    if (record.jpeg_quality > 0) {
      // JPEG artefacts: the frame goes through the codec and back, as a compressed stream would.
      const cv::Mat mat(k.height, k.width, CV_8UC3, const_cast<std::uint8_t*>(bgr.data()));
      std::vector<std::uint8_t> encoded;
      if (!cv::imencode(".jpg", mat, encoded, {cv::IMWRITE_JPEG_QUALITY, record.jpeg_quality})) {
        std::cerr << "ringlet-dataset: frame " << i << ": cannot encode JPEG\n";
        return 1;
      }
      const cv::Mat decoded = cv::imdecode(encoded, cv::IMREAD_COLOR);
      if (decoded.rows != k.height || decoded.cols != k.width || !decoded.isContinuous()) {
        std::cerr << "ringlet-dataset: frame " << i << ": cannot decode its own JPEG\n";
        return 1;
      }
      std::copy(decoded.data, decoded.data + jpeg_frame.size(), jpeg_frame.begin());
      bgr = jpeg_frame;
    }
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
    progress(o, n + 1);
  }
  ranges.emplace_back(o.first, static_cast<std::int64_t>(o.first) + o.count);
  ranges = merge_ranges(std::move(ranges));
  nlohmann::ordered_json manifest{{"generation", gen}, {"ranges", nlohmann::ordered_json::array()}};
  for (const auto& [a, b] : ranges) manifest["ranges"].push_back({a, b});
  manifest["note"] = "frame i is a pure function of the generation and i; ranges are [first, end) of the frames written";
  const std::filesystem::path manifest_path = out / "manifest.json";
  std::ofstream manifest_file(manifest_path);
  manifest_file << manifest.dump(2) << "\n";
  if (!manifest_file) {
    std::cerr << "ringlet-dataset: " << manifest_path.string() << ": cannot write\n";
    return 1;
  }
  std::cout << "ringlet-dataset: wrote frames " << o.first << ".." << o.first + o.count - 1 << " (seed " << o.seed
            << ", " << o.format << " + json" << (o.labels ? " + labels" : "") << ") to " << o.out << "\n";
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
  app.add_option("--first", o.first, "index of the first frame: frames first..first+count-1 are written, each exactly "
                                     "as any other run with this seed writes it")
      ->capture_default_str()->check(CLI::Range(0, 1000000));
  app.add_option("-s,--seed", o.seed, "seed: frame i of a seed is always the same frame; other seeds share no frame")
      ->capture_default_str();
  app.add_option("-o,--out", o.out, "output directory (created if missing)")->capture_default_str();
  app.add_option("-f,--format", o.format, "png (BGR picture) or yuyv (raw NAO-style bytes)")
      ->capture_default_str()
      ->check(CLI::IsMember({"png", "yuyv"}));
  app.add_option("--occluded", o.occluded_share, "share of frames with robots close to the camera")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  using Head = hal::NaoHeadRange;
  app.add_option("--max-yaw", o.max_yaw_deg, "head yaw range ±deg (within the NAO's)")
      ->capture_default_str()->check(CLI::Range(0.0, Head::kMaxYawDeg));
  app.add_option("--min-pitch", o.min_pitch_deg, "lowest head pitch, deg (down positive; within the NAO's range)")
      ->capture_default_str()->check(CLI::Range(Head::kMinPitchDeg, Head::kMaxPitchDeg));
  app.add_option("--max-pitch", o.max_pitch_deg, "highest head pitch, deg")
      ->capture_default_str()->check(CLI::Range(Head::kMinPitchDeg, Head::kMaxPitchDeg));
  app.add_option("--look", o.look, "spl: a real field's look, drawn per frame (light, exposure, white balance, carpet, "
                                   "noise, blur, JPEG), with balls and NAO robots placed per frame; plain: the first "
                                   "renderer's look, only the sun stripes vary")
      ->capture_default_str()->check(CLI::IsMember({"spl", "plain"}));
  app.add_option("--ball", o.ball, "the ball: bw (the SPL ball) or orange")
      ->capture_default_str()->check(CLI::IsMember({"bw", "orange"}));
  app.add_option("--max-balls", o.max_balls, "--look spl: balls per frame, 1..N")
      ->capture_default_str()->check(CLI::Range(1, 12));
  app.add_option("--max-robots", o.max_robots, "--look spl: NAO robots added per frame, 0..N")
      ->capture_default_str()->check(CLI::Range(0, 12));
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
  if (static_cast<std::int64_t>(o.first) + o.count > 10000000) {
    std::cerr << "ringlet-dataset: --first + --count must stay below 10000000\n";
    return 2;
  }
  try {
    return run(o);
  } catch (const DatasetError& e) {
    std::cerr << "ringlet-dataset: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ringlet-dataset: internal error: " << e.what() << "\n";
    return 1;
  }
}
