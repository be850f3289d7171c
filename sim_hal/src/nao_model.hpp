#pragma once
// A NAO V6 for the camera: 22 ellipsoids and boxes in the robot's own frame (x forward, y left,
// z up, metres at the real size: 0.574 m tall, 0.276 m across the arms), with the materials a
// picture shows: the white shell, dark grey joints, the face band, the soles and the team jersey.
// The renderer scales it to the obstacle's height and turns it to the robot's heading.
#include <span>

#include "render_math.hpp"

namespace ringlet::sim_hal::detail {

enum class NaoMaterial : std::uint8_t { kShell, kJoint, kFace, kSole, kJersey };

inline constexpr double kNaoHeight = 0.574;  // m, NAO V6
inline constexpr double kNaoReach = 0.155;   // m, every part lies within this of the body axis

struct NaoHit {
  double t = kNoHit3;
  Vec3 normal{};  // outward, robot frame, not normalised
  NaoMaterial material = NaoMaterial::kShell;
};

/// A world-frame point (`point`) or direction into the model frame of the NAO standing on circle
/// `c`, facing sin_h/cos_h (geometry.hpp: forward is (sin h, cos h)), scaled by 1/scale: t along
/// a ray is the same in both frames.
inline Vec3 to_robot_model(const Circle& c, double sin_h, double cos_h, double scale, const Vec3& v,
                           bool point) noexcept {
  const double x = point ? v.x - c.centre.x : v.x;
  const double y = point ? v.y - c.centre.y : v.y;
  const double inv = 1.0 / scale;
  return {(x * sin_h + y * cos_h) * inv, (y * sin_h - x * cos_h) * inv, v.z * inv};
}

/// First hit of the ray o + t·d (robot frame, metres at the real size) with the NAO, or
/// hit.t = +inf. Tests the bounding cylinder first, so rays that miss are cheap.
void ray_nao(const Vec3& o, const Vec3& d, NaoHit& hit) noexcept;

/// The corners of every part's bounding box (robot frame, real size), for projecting the robot's
/// image bounding box: 8 per part.
[[nodiscard]] std::span<const Vec3> nao_hull_points() noexcept;

}  // namespace ringlet::sim_hal::detail
