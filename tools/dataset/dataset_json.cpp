// Ground truth as JSON: every length in metres, angles in radians, pixels as doubles with (0, 0)
// the top-left corner of the top-left pixel (hal/camera_geometry.hpp's convention).
#include "dataset_json.hpp"

#include <cmath>

namespace ringlet::sim_hal::dataset {
namespace {

using Json = nlohmann::ordered_json;

Json pair(double a, double b) { return Json::array({a, b}); }
Json vec3(const hal::Vec3& v) { return Json::array({v.x, v.y, v.z}); }
/// [u0, v0, u1, v1] in pixel edges, or null for an empty box.
Json box(const ImageBox& b) { return b.empty() ? Json(nullptr) : Json::array({b.u0, b.v0, b.u1, b.v1}); }

Json ball_json(const BallTruth& b, double radius) {
  Json j{{"visible", b.visible},
         {"position", pair(b.position.x, b.position.y)},
         {"radius", radius},
         {"in_front", b.in_front},
         {"image_centre", pair(b.image_centre.u, b.image_centre.v)},
         {"image_radius", b.image_radius},
         {"visible_fraction", b.visible_fraction}};
  j["distance"] = b.distance;
  j["bearing"] = b.bearing;
  j["in_image_fraction"] = b.in_image_fraction;
  j["box"] = b.in_front ? box(ImageBox{b.image_centre.u - b.image_radius, b.image_centre.v - b.image_radius,
                                       b.image_centre.u + b.image_radius, b.image_centre.v + b.image_radius})
                        : Json(nullptr);
  j["pixels"] = box(b.pixels);
  j["visible_pixels"] = box(b.visible_pixels);
  return j;
}

}  // namespace

Json frame_json(const FrameRecord& record, const CameraRenderer& renderer) {
  const FrameTruth& truth = renderer.truth();
  const CameraSpec& spec = renderer.spec();
  const World& world = renderer.world();
  const hal::CameraIntrinsics& k = spec.intrinsics;
  const hal::CameraPose camera = hal::CameraPose::from_head(spec.mount, truth.head);

  Json j;
  j["frame"] = record.index;
  j["image"] = record.image;
  j["format"] = record.format;
  j["seed"] = record.seed;
  j["generator_version"] = record.generator_version;
  j["world"] = world.name;
  j["pose"] = {{"x", truth.pose.x}, {"y", truth.pose.y}, {"theta", truth.pose.theta}};
  j["head"] = {{"yaw", truth.head.yaw}, {"pitch", truth.head.pitch}};
  j["intrinsics"] = {{"width", k.width}, {"height", k.height}, {"fx", k.fx}, {"fy", k.fy}, {"cx", k.cx}, {"cy", k.cy}};
  j["mount"] = {{"pivot_height", spec.mount.pivot_height}, {"forward", spec.mount.forward}, {"up", spec.mount.up}};
  j["camera_in_robot"] = {{"position", vec3(camera.position)},
                          {"axes", Json::array({vec3(camera.axes[0]), vec3(camera.axes[1]), vec3(camera.axes[2])})}};
  const Lighting& l = world.lighting;
  const CameraLook& look = world.look;
  j["look"] = {{"style", look_style_name(look.style)}, {"ball", ball_look_name(look.ball)},
               {"light", light_kind_name(look.light)}, {"exposure", look.exposure},
               {"white_red", look.white_red},   {"white_blue", look.white_blue},
               {"carpet_warmth", look.carpet_warmth}, {"noise", look.noise},
               {"blur", look.blur},             {"blur_vertical", look.blur_vertical},
               {"jpeg_quality", record.jpeg_quality}};
  j["lighting"] = {{"brightness", l.brightness}, {"texture", l.texture},   {"sun_strength", l.sun_strength},
                   {"sun_period", l.sun_period}, {"sun_angle", l.sun_angle}, {"sun_phase", l.sun_phase}};

  Json lines = Json::array();
  for (const LineRunTruth& run : truth.lines) {
    const Marking& m = world.markings[run.marking];
    lines.push_back({{"marking", run.marking},
                     {"world", Json::array({pair(m.a.x, m.a.y), pair(m.b.x, m.b.y)})},
                     {"width", m.width},
                     {"image", Json::array({pair(run.image_a.u, run.image_a.v), pair(run.image_b.u, run.image_b.v)})},
                     {"ground", Json::array({pair(run.ground_a.x, run.ground_a.y), pair(run.ground_b.x, run.ground_b.y)})}});
  }
  j["lines"] = std::move(lines);
  j["lines_truncated"] = truth.lines_truncated;

  Json rings = Json::array();
  for (const RingTruth& r : truth.rings) {
    const Ring& ring = world.rings[r.ring];
    const hal::RobotPoint c = hal::to_robot_frame(truth.pose, ring.centre.x, ring.centre.y);
    rings.push_back({{"ring", r.ring},
                     {"centre", pair(c.x, c.y)},
                     {"radius", ring.radius},
                     {"visible", r.visible},
                     {"visible_fraction", r.visible_fraction}});
  }
  j["rings"] = std::move(rings);

  // The centre circle (the first ring): where its centre is on the ground and in the picture.
  if (!truth.rings.empty()) {
    const Ring& ring = world.rings[truth.rings.front().ring];
    const hal::RobotPoint c = hal::to_robot_frame(truth.pose, ring.centre.x, ring.centre.y);
    const auto px = hal::project(k, camera, hal::Vec3{c.x, c.y, 0.0});
    j["centre_circle"] = {{"centre", pair(c.x, c.y)},
                          {"distance", std::hypot(c.x, c.y)},
                          {"bearing", std::atan2(c.y, c.x)},
                          {"radius", ring.radius},
                          {"width", ring.width},
                          {"visible", truth.rings.front().visible},
                          {"visible_fraction", truth.rings.front().visible_fraction},
                          {"image_centre", px ? pair(px->u, px->v) : Json(nullptr)}};
  } else {
    j["centre_circle"] = nullptr;
  }

  const BallTruth& b = truth.ball;
  j["ball"] = b.present ? ball_json(b, world.ball->radius) : Json(nullptr);
  Json balls = Json::array();
  for (std::size_t i = 0; i < truth.balls.size(); ++i) {
    const double radius = (world.ball && i == 0) ? world.ball->radius
                                                 : world.extra_balls[i - (world.ball ? 1U : 0U)].radius;
    balls.push_back(ball_json(truth.balls[i], radius));
  }
  j["balls"] = std::move(balls);

  Json robots = Json::array();
  for (const RobotTruth& r : truth.robots) {
    const Circle& c = world.circles[r.circle];
    robots.push_back({{"circle", r.circle},
                      {"world", pair(c.centre.x, c.centre.y)},
                      {"foot", pair(r.foot.x, r.foot.y)},
                      {"distance", r.distance},
                      {"bearing", r.bearing},
                      {"heading", r.heading},
                      {"team", r.team},
                      {"height", c.height},
                      {"in_front", r.in_front},
                      {"box", box(r.box)},
                      {"pixels", box(r.pixels)},
                      {"visible_pixels", box(r.visible_pixels)},
                      {"visible", r.visible},
                      {"visible_fraction", r.visible_fraction}});
  }
  j["robots"] = std::move(robots);

  Json occluders = Json::array();
  for (const Circle& c : record.occluders) {
    const hal::RobotPoint p = hal::to_robot_frame(truth.pose, c.centre.x, c.centre.y);
    occluders.push_back({{"world", pair(c.centre.x, c.centre.y)}, {"robot", pair(p.x, p.y)},
                         {"radius", c.radius}, {"height", c.height}});
  }
  j["occluders"] = std::move(occluders);
  return j;
}

}  // namespace ringlet::sim_hal::dataset
