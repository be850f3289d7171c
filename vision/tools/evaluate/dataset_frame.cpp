#include "dataset_frame.hpp"

#include <algorithm>
#include <cmath>

#include "ringlet/hal/read_file.hpp"
#include "ringlet/hal/yuv.hpp"

#include <nlohmann/json.hpp>

#include "vision_io.hpp"

namespace ringlet::vision::evaluate {

namespace fs = std::filesystem;
using tools::ToolError;

std::vector<fs::path> list_dataset_frames(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw ToolError(dir.string() + ": not a directory");
  std::vector<fs::path> out;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && e.path().extension() == ".json") out.push_back(e.path());
  }
  if (ec) throw ToolError(dir.string() + ": cannot list: " + ec.message());
  if (out.empty()) throw ToolError(dir.string() + ": no frame_*.json files (a folder written by ringlet-dataset)");
  std::sort(out.begin(), out.end(), [](const fs::path& a, const fs::path& b) {
    const std::string x = a.filename().string(), y = b.filename().string();
    return x.size() != y.size() ? x.size() < y.size() : x < y;
  });
  return out;
}

LoadedFrame load_frame(const fs::path& json) {
  LoadedFrame f;
  f.meta = load_dataset_frame(json);
  const hal::CameraIntrinsics& k = f.meta.intrinsics;
  if (k.width % 2 != 0) throw ToolError(json.string() + ": odd image width, YUYV needs pixel pairs");
  f.bgr = tools::load_bgr(f.meta.picture, k.width, k.height);
  if (!f.bgr.isContinuous()) f.bgr = f.bgr.clone();
  f.yuyv.resize(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 2U);
  hal::bgr_to_yuyv({f.bgr.data, f.bgr.total() * 3U}, k.width, k.height, f.yuyv);
  return f;
}

hal::FrameView yuyv_view(const LoadedFrame& f) {
  hal::FrameView v;
  v.sequence = f.meta.index;
  v.format = hal::PixelFormat::kYuyv;
  v.width = f.meta.intrinsics.width;
  v.height = f.meta.intrinsics.height;
  v.stride = 2 * v.width;
  v.data = f.yuyv.data();
  return v;
}

double projected_half_width(const hal::CameraIntrinsics& k, const hal::CameraPose& pose, const hal::RobotPoint& at,
                            double dx, double dy, double width_m) {
  const double h = width_m / 2.0;
  const auto a = hal::project(k, pose, {at.x - dy * h, at.y + dx * h, 0.0});
  const auto b = hal::project(k, pose, {at.x + dy * h, at.y - dx * h, 0.0});
  if (!a || !b) return 0.0;
  return std::hypot(a->u - b->u, a->v - b->v) / 2.0;
}

DatasetFrame load_dataset_frame(const fs::path& json_path) {
  const hal::FileRead file = hal::read_file(json_path, "dataset frame record");
  if (!file.ok()) throw ToolError(file.error);
  DatasetFrame f;
  f.json = json_path;
  try {
    const nlohmann::json j = nlohmann::json::parse(file.bytes);
    const std::string format = j.at("format").get<std::string>();
    if (format != "png") {
      throw ToolError(json_path.string() + ": frame format is '" + format + "'; the evaluation needs png frames "
                      "(ringlet-dataset --format png)");
    }
    f.picture = json_path.parent_path() / j.at("image").get<std::string>();
    f.index = j.at("frame").get<std::uint64_t>();
    f.seed = j.at("seed").get<std::uint64_t>();
    f.generator_version = j.value("generator_version", 1);
    const auto& k = j.at("intrinsics");
    f.intrinsics.width = k.at("width").get<int>();
    f.intrinsics.height = k.at("height").get<int>();
    f.intrinsics.fx = k.at("fx").get<double>();
    f.intrinsics.fy = k.at("fy").get<double>();
    f.intrinsics.cx = k.at("cx").get<double>();
    f.intrinsics.cy = k.at("cy").get<double>();
    const auto& m = j.at("mount");
    f.mount = {m.at("pivot_height").get<double>(), m.at("forward").get<double>(), m.at("up").get<double>()};
    f.head = {j.at("head").at("yaw").get<double>(), j.at("head").at("pitch").get<double>()};
    const hal::CameraPose pose = hal::CameraPose::from_head(f.mount, f.head);
    // The crosses' bars: short markings, grouped by their world centre, placed with the frame's pose
    // (the simulator's convention, hal::to_robot_frame).
    std::vector<hal::RobotPoint> mark_world;
    const auto& robot = j.value("pose", nlohmann::json::object());
    const double rx = robot.value("x", 0.0), ry = robot.value("y", 0.0), rt = robot.value("theta", 0.0);
    for (const auto& line : j.at("lines")) {
      const auto& img = line.at("image");
      const auto& ground = line.at("ground");
      TruthSegment t;
      t.marking = line.value("marking", -1);
      t.line = {img.at(0).at(0).get<double>(), img.at(0).at(1).get<double>(), img.at(1).at(0).get<double>(),
                img.at(1).at(1).get<double>()};
      const hal::RobotPoint a{ground.at(0).at(0).get<double>(), ground.at(0).at(1).get<double>()};
      const hal::RobotPoint b{ground.at(1).at(0).get<double>(), ground.at(1).at(1).get<double>()};
      const double length = std::hypot(b.x - a.x, b.y - a.y);
      if (length > 0.0) {
        const double dx = (b.x - a.x) / length;
        const double dy = (b.y - a.y) / length;
        const double width = line.at("width").get<double>();
        t.half_width_px = std::max(projected_half_width(f.intrinsics, pose, a, dx, dy, width),
                                   projected_half_width(f.intrinsics, pose, b, dx, dy, width));
      }
      f.lines.push_back(t);
      if (line.contains("world")) {
        const auto& w = line.at("world");
        const hal::RobotPoint wa{w.at(0).at(0).get<double>(), w.at(0).at(1).get<double>()};
        const hal::RobotPoint wb{w.at(1).at(0).get<double>(), w.at(1).at(1).get<double>()};
        if (std::hypot(wb.x - wa.x, wb.y - wa.y) <= kCrossBarMaxM) {
          const hal::RobotPoint wc{(wa.x + wb.x) / 2.0, (wa.y + wb.y) / 2.0};
          const double bar_px = std::hypot(t.line.x1 - t.line.x0, t.line.y1 - t.line.y0);
          std::size_t cross = 0;
          while (cross < mark_world.size() && std::hypot(mark_world[cross].x - wc.x, mark_world[cross].y - wc.y) > 1e-6) ++cross;
          if (cross == mark_world.size()) {
            mark_world.push_back(wc);
            f.marks.push_back({hal::to_robot_frame({rx, ry, rt}, wc.x, wc.y), 0.0});
          }
          f.marks[cross].longest_bar_px = std::max(f.marks[cross].longest_bar_px, bar_px);
        }
      }
    }
    // The rings' truth as ringlet-dataset writes it (centre already in the robot frame).
    for (const auto& ring : j.value("rings", nlohmann::json::array())) {
      TruthRing t;
      t.centre = {ring.at("centre").at(0).get<double>(), ring.at("centre").at(1).get<double>()};
      t.radius = ring.at("radius").get<double>();
      t.width = ring.value("width", 0.05);
      t.visible = ring.at("visible").get<bool>();
      t.visible_fraction = ring.at("visible_fraction").get<double>();
      f.rings.push_back(t);
    }
    // Balls and robots (tools/README.md "The frame's JSON"): boxes are [u0, v0, u1, v1] or null.
    if (j.contains("balls") && j.contains("robots")) {
      f.has_objects = true;
      for (const auto& b : j.at("balls")) {
        TruthBall t;
        t.in_front = b.at("in_front").get<bool>();
        t.visible = b.at("visible").get<bool>();
        t.u = b.at("image_centre").at(0).get<double>();
        t.v = b.at("image_centre").at(1).get<double>();
        t.radius_px = b.at("image_radius").get<double>();
        t.distance_m = b.at("distance").get<double>();
        t.visible_fraction = b.at("visible_fraction").get<double>();
        t.in_image_fraction = b.at("in_image_fraction").get<double>();
        f.balls.push_back(t);
      }
      for (const auto& r : j.at("robots")) {
        TruthRobot t;
        t.in_front = r.at("in_front").get<bool>();
        t.visible = r.at("visible").get<bool>();
        const auto& box = r.at("box");
        if (!box.is_null()) {
          t.has_box = true;
          t.u0 = box.at(0).get<double>();
          t.v0 = box.at(1).get<double>();
          t.u1 = box.at(2).get<double>();
          t.v1 = box.at(3).get<double>();
        }
        const hal::RobotPoint foot{r.at("foot").at(0).get<double>(), r.at("foot").at(1).get<double>()};
        if (const auto px = hal::project(f.intrinsics, pose, {foot.x, foot.y, 0.0})) {
          t.foot_projects = true;
          t.foot_u = px->u;
          t.foot_v = px->v;
        }
        t.distance_m = r.at("distance").get<double>();
        t.visible_fraction = r.at("visible_fraction").get<double>();
        f.robots.push_back(t);
      }
    }
  } catch (const nlohmann::json::exception& e) {
    throw ToolError(json_path.string() + ": not a ringlet-dataset frame record: " + e.what());
  }
  if (f.intrinsics.width < 2 || f.intrinsics.height < 2 || !(f.intrinsics.fx > 0.0) || !(f.intrinsics.fy > 0.0)) {
    throw ToolError(json_path.string() + ": bad intrinsics");
  }
  return f;
}

}  // namespace ringlet::vision::evaluate
