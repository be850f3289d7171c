// The NAO's parts. Proportions from the NAO V6 data sheet (height 574 mm, shoulders about
// 275 mm across, feet about 160 mm long); the shapes are the few ellipsoids a 640×480 camera
// can tell apart, not the CAD model.
#include "nao_model.hpp"

#include <array>
#include <cmath>

namespace ringlet::sim_hal::detail {
namespace {

struct Part {
  Vec3 centre;
  Vec3 radii;  // ellipsoid semi-axes, or a box's half sizes
  NaoMaterial material;
  bool box;
};

constexpr double kArmY = 0.112;  // shoulder axis to arm centre, sideways

constexpr std::array<Part, 22> kParts{{
    {{0.0, 0.0, 0.500}, {0.068, 0.066, 0.074}, NaoMaterial::kShell, false},   // head
    {{0.0, 0.0, 0.440}, {0.028, 0.028, 0.030}, NaoMaterial::kJoint, false},   // neck
    {{0.0, 0.0, 0.365}, {0.058, 0.083, 0.085}, NaoMaterial::kJersey, false},  // chest (jersey below the collar)
    {{0.0, 0.0, 0.275}, {0.050, 0.072, 0.032}, NaoMaterial::kJoint, false},   // pelvis
    {{0.0, 0.098, 0.425}, {0.038, 0.040, 0.035}, NaoMaterial::kShell, false},  // shoulders
    {{0.0, -0.098, 0.425}, {0.038, 0.040, 0.035}, NaoMaterial::kShell, false},
    {{0.0, kArmY, 0.355}, {0.030, 0.026, 0.060}, NaoMaterial::kShell, false},  // upper arms
    {{0.0, -kArmY, 0.355}, {0.030, 0.026, 0.060}, NaoMaterial::kShell, false},
    {{0.005, kArmY, 0.290}, {0.024, 0.022, 0.022}, NaoMaterial::kJoint, false},  // elbows
    {{0.005, -kArmY, 0.290}, {0.024, 0.022, 0.022}, NaoMaterial::kJoint, false},
    {{0.025, kArmY, 0.235}, {0.034, 0.026, 0.048}, NaoMaterial::kShell, false},  // forearms
    {{0.025, -kArmY, 0.235}, {0.034, 0.026, 0.048}, NaoMaterial::kShell, false},
    {{0.045, 0.110, 0.178}, {0.026, 0.020, 0.026}, NaoMaterial::kJoint, false},  // hands
    {{0.045, -0.110, 0.178}, {0.026, 0.020, 0.026}, NaoMaterial::kJoint, false},
    {{0.005, 0.050, 0.205}, {0.046, 0.040, 0.062}, NaoMaterial::kShell, false},  // thighs
    {{0.005, -0.050, 0.205}, {0.046, 0.040, 0.062}, NaoMaterial::kShell, false},
    {{0.020, 0.050, 0.140}, {0.036, 0.033, 0.026}, NaoMaterial::kJoint, false},  // knees
    {{0.020, -0.050, 0.140}, {0.036, 0.033, 0.026}, NaoMaterial::kJoint, false},
    {{0.008, 0.050, 0.080}, {0.042, 0.036, 0.058}, NaoMaterial::kShell, false},  // shins
    {{0.008, -0.050, 0.080}, {0.042, 0.036, 0.058}, NaoMaterial::kShell, false},
    {{0.0275, 0.052, 0.016}, {0.0775, 0.036, 0.016}, NaoMaterial::kShell, true},  // feet, 155 mm long
    {{0.0275, -0.052, 0.016}, {0.0775, 0.036, 0.016}, NaoMaterial::kShell, true},
}};

constexpr std::array<Vec3, kParts.size()> make_inverse_radii() noexcept {
  std::array<Vec3, kParts.size()> out{};
  for (std::size_t i = 0; i < kParts.size(); ++i) {
    out[i] = {1.0 / kParts[i].radii.x, 1.0 / kParts[i].radii.y, 1.0 / kParts[i].radii.z};
  }
  return out;
}

constexpr std::array<Vec3, kParts.size()> kInverseRadii = make_inverse_radii();

/// The material a point of a part shows: the chest's collar is shell, the head has a dark band
/// across the eyes and dark ears, the feet have dark soles.
NaoMaterial material_at(const Part& part, std::size_t index, const Vec3& p) noexcept {
  if (index == 0) {
    if (p.z > 0.478 && p.z < 0.522 && (p.x > 0.035 || p.y > 0.052 || p.y < -0.052)) return NaoMaterial::kFace;
    return NaoMaterial::kShell;
  }
  if (index == 2) return p.z > 0.43 ? NaoMaterial::kShell : NaoMaterial::kJersey;
  if (part.box && p.z < 0.009) return NaoMaterial::kSole;
  return part.material;
}

std::array<Vec3, kParts.size() * 8> make_hull() noexcept {
  std::array<Vec3, kParts.size() * 8> out{};
  for (std::size_t i = 0; i < kParts.size(); ++i) {
    const Part& p = kParts[i];
    for (int k = 0; k < 8; ++k) {
      out[i * 8 + static_cast<std::size_t>(k)] = {p.centre.x + ((k & 1) != 0 ? p.radii.x : -p.radii.x),
                                                  p.centre.y + ((k & 2) != 0 ? p.radii.y : -p.radii.y),
                                                  p.centre.z + ((k & 4) != 0 ? p.radii.z : -p.radii.z)};
    }
  }
  return out;
}

const std::array<Vec3, kParts.size() * 8> kHull = make_hull();

}  // namespace

void ray_nao(const Vec3& o, const Vec3& d, NaoHit& hit) noexcept {
  hit.t = kNoHit3;
  // Where the ray runs inside the bounding cylinder, and the heights it spans there: only parts
  // reaching into that height band can be hit (a near-level ray tests a few parts, not 22).
  double z_lo = 0.0;
  double z_hi = kNaoHeight;
  const double a = d.x * d.x + d.y * d.y;
  if (a > 0.0) {
    const double b = o.x * d.x + o.y * d.y;
    const double c = o.x * o.x + o.y * o.y - kNaoReach * kNaoReach;
    const double disc = b * b - a * c;
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    const double t0 = (-b - root) / a;
    const double t1 = (-b + root) / a;
    if (!(t1 > 0.0)) return;
    const double za = o.z + (t0 > 0.0 ? t0 : 0.0) * d.z;
    const double zb = o.z + t1 * d.z;
    z_lo = za < zb ? za : zb;
    z_hi = za < zb ? zb : za;
    if (z_hi < 0.0 || z_lo > kNaoHeight) return;
  } else if (o.x * o.x + o.y * o.y > kNaoReach * kNaoReach) {
    return;  // a vertical ray beside the robot
  }
  for (std::size_t i = 0; i < kParts.size(); ++i) {
    const Part& part = kParts[i];
    if (part.centre.z + part.radii.z < z_lo || part.centre.z - part.radii.z > z_hi) continue;
    Vec3 normal{};
    double t = kNoHit3;
    if (part.box) {
      int axis = 0;
      double side = 0.0;
      t = ray_box(o, d, sub(part.centre, part.radii), add(part.centre, part.radii), axis, side);
      normal = {axis == 0 ? side : 0.0, axis == 1 ? side : 0.0, axis == 2 ? side : 0.0};
    } else {
      t = ray_ellipsoid(o, d, part.centre, kInverseRadii[i], normal);
    }
    if (t < hit.t) {
      hit.t = t;
      hit.normal = normal;
      hit.material = material_at(part, i, add(o, scale(t, d)));
    }
  }
}

std::span<const Vec3> nao_hull_points() noexcept { return kHull; }

}  // namespace ringlet::sim_hal::detail
