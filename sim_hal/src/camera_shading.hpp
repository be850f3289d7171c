#pragma once
// The SPL look's colours (CameraLook::style == kSpl): what each surface reflects (albedo, in the
// picture's 0..255 units at exposure 1), the light falling on it (fluorescent, daylight with warm
// window patches, backlight) and the camera's per-channel gains (exposure × white balance, with
// their drift). Everything is arithmetic on doubles and integer hashes: the same bytes on every
// target. Calibrated so that, in full-range BT.601, the nominal carpet has V ≈ 118 and the
// randomization of ringlet-dataset covers the real photos' ranges (tests/sim_hal/camera_look_test.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "nao_model.hpp"
#include "render_math.hpp"
#include "spl_ball.hpp"
#include "ringlet/sim_hal/camera_look.hpp"
#include "ringlet/sim_hal/world.hpp"

namespace ringlet::sim_hal::detail {

struct Rgb {
  double b = 0.0, g = 0.0, r = 0.0;
};

inline std::uint8_t to_byte(double v) noexcept {
  return static_cast<std::uint8_t>(v <= 0.0 ? 0 : (v >= 255.0 ? 255 : static_cast<int>(v + 0.5)));
}

/// Team jerseys (SPL colours): blue, red, yellow, black.
inline constexpr std::array<Rgb, 4> kJerseys{{{150.0, 70.0, 25.0}, {40.0, 40.0, 185.0}, {35.0, 190.0, 215.0},
                                               {40.0, 40.0, 42.0}}};
inline constexpr std::uint32_t kJerseyCount = static_cast<std::uint32_t>(kJerseys.size());

class SplShader {
 public:
  SplShader(const CameraLook& look, const Lighting& light, std::uint32_t seed, const std::array<double, 3>& gain) noexcept
      : look_(look), light_(light), seed_(seed), gain_(gain),
        sun_cos_(std::cos(light.sun_angle)), sun_sin_(std::sin(light.sun_angle)),
        base_light_(scaled(tint(look.light), light.brightness)) {}

  /// Carpet (grass-like fibres, blade hue, slow mottling) or paint at ground point (x, y).
  void ground(std::uint8_t* out, double x, double y, bool paint) const noexcept {
    const double tex = light_.texture;
    // One hash per 4 mm cell: its high bits are the fibre's brightness, its low byte the blade's hue.
    const std::uint32_t cell = hash2(fast_floor(x * 250.0), fast_floor(y * 250.0), seed_);
    const double fibre = 2.0 * unit(cell) - 1.0;
    const double coarse = 2.0 * value_noise(x * (1.0 / 1.5), y * (1.0 / 1.5), seed_ ^ 0x51ed270bU) - 1.0;
    const double bright = 1.0 + 0.75 * tex * coarse;
    if (paint) {
      emit(out, kPaint, illumination(x, y), bright * (1.0 + 0.3 * tex * fibre));
      return;
    }
    const double blade = static_cast<double>(cell & 0xffU) * (2.0 / 255.0) - 1.0;
    const double w = look_.carpet_warmth;
    const double hue = 0.6 * tex * blade;  // yellower or bluer blades
    const Rgb carpet{(58.0 - 8.0 * w) * (1.0 - hue), 122.0, (98.0 + 22.0 * w) * (1.0 + hue)};
    emit(out, carpet, illumination(x, y), bright * (1.0 + 1.2 * tex * fibre));
  }

  /// The hall floor beyond the carpet.
  void floor(std::uint8_t* out, double x, double y) const noexcept {
    const double n = unit(hash2(fast_floor(x * 20.0), fast_floor(y * 20.0), seed_));
    emit(out, Rgb{112.0, 116.0, 120.0}, illumination(x, y), 0.92 + 0.16 * n);
  }

  /// Above the horizon: the hall's walls and crowd, or with backlight bright windows.
  void background(std::uint8_t* out, const Vec3& d) const noexcept {
    const double inv = 1.0 / std::sqrt(dot(d, d));
    const double up = d.z * inv;  // 0 at the horizon, 1 straight up
    if (look_.light == LightKind::kBacklight) {
      const double h = unit(hash2(fast_floor(d.x * inv * 9.0), fast_floor(d.y * inv * 9.0) + 31 * fast_floor(up * 6.0),
                                  seed_ ^ 0x3a1dU));
      // The camera exposes for these: even at its backlit exposure they are nearly white.
      const double window = h < 0.7 ? 1.0 / std::max(0.2, look_.exposure) : 0.45;
      emit(out, Rgb{246.0, 250.0, 252.0}, Rgb{1.0, 1.0, 1.0}, window * light_.brightness);
      return;
    }
    const double h1 = unit(hash2(fast_floor(d.x * inv * 40.0), fast_floor(d.y * inv * 40.0), seed_ ^ 0x9e3779b9U));
    emit(out, Rgb{122.0, 120.0, 126.0}, tint(look_.light), light_.brightness * (0.7 + 0.45 * h1) * (1.0 - 0.35 * up));
  }

  /// A ball point p with unit normal n; `axes` turns the pattern. Black-and-white or orange.
  void ball(std::uint8_t* out, const Vec3& p, const Vec3& n, const std::array<Vec3, 3>& axes, bool black_white,
            bool spl) const noexcept {
    Rgb albedo{20.0, 115.0, 245.0};
    if (black_white) {
      const Vec3 local{dot(n, axes[0]), dot(n, axes[1]), dot(n, axes[2])};
      albedo = pattern_.black(local) ? Rgb{30.0, 30.0, 32.0} : Rgb{232.0, 234.0, 234.0};
    }
    if (!spl) {  // the plain look's shading: lit from above, no camera
      const double s = light_.brightness * (0.55 + 0.45 * n.z);
      out[0] = to_byte(albedo.b * s);
      out[1] = to_byte(albedo.g * s);
      out[2] = to_byte(albedo.r * s);
      return;
    }
    emit(out, albedo, illumination(p.x, p.y), lambert(n));
  }

  /// A NAO point p with its (unnormalised) world normal and material.
  void nao(std::uint8_t* out, const Vec3& p, const Vec3& normal, NaoMaterial m, std::uint8_t team) const noexcept {
    Rgb albedo{222.0, 225.0, 226.0};
    switch (m) {
      case NaoMaterial::kShell: break;
      case NaoMaterial::kJoint: albedo = {64.0, 64.0, 68.0}; break;
      case NaoMaterial::kFace: albedo = {40.0, 40.0, 44.0}; break;
      case NaoMaterial::kSole: albedo = {50.0, 50.0, 52.0}; break;
      case NaoMaterial::kJersey: albedo = kJerseys[team % kJerseyCount]; break;
    }
    const double len = std::sqrt(dot(normal, normal));
    emit(out, albedo, illumination(p.x, p.y), lambert(len > 0.0 ? scale(1.0 / len, normal) : Vec3{0.0, 0.0, 1.0}));
  }

  /// Posts (white) and other obstacles (dark grey): cylinders lit from one side.
  void cylinder(std::uint8_t* out, const Vec3& p, const Circle& c) const noexcept {
    const double nx = (p.x - c.centre.x) / c.radius;
    const double ny = (p.y - c.centre.y) / c.radius;
    const bool cap = p.z >= c.height - 1e-9;
    const double shade = cap ? 1.0 : 0.85 + 0.15 * (0.6 * nx + 0.8 * ny);
    const Rgb albedo = c.kind == ObstacleKind::kPost ? Rgb{236.0, 238.0, 238.0} : Rgb{70.0, 70.0, 76.0};
    emit(out, albedo, illumination(p.x, p.y), shade);
  }

 private:
  static constexpr Rgb kPaint{226.0, 232.0, 230.0};

  static Rgb scaled(const Rgb& c, double s) noexcept { return {c.b * s, c.g * s, c.r * s}; }

  /// The light's colour before any window patch: fluorescent tubes are a little green-blue.
  [[nodiscard]] static Rgb tint(LightKind kind) noexcept {
    switch (kind) {
      case LightKind::kFluorescent: return {1.05, 1.02, 0.95};
      case LightKind::kDaylight: return {0.88, 0.88, 0.88};  // the hall is dimmer than the patches
      case LightKind::kBacklight: return {1.0, 1.0, 1.0};
    }
    return {1.0, 1.0, 1.0};
  }

  /// Light falling on ground point (x, y): the tint (the lamps' unevenness is the carpet's slow
  /// mottling), and with daylight the warm patches of the windows (rectangles from two soft square
  /// waves across each other).
  [[nodiscard]] Rgb illumination(double x, double y) const noexcept {
    Rgb out = base_light_;
    if (look_.light == LightKind::kDaylight && light_.sun_strength > 0.0) {
      const double across = (x * sun_cos_ - y * sun_sin_ - light_.sun_phase) / light_.sun_period;
      const double along = (x * sun_sin_ + y * sun_cos_) / (1.7 * light_.sun_period);
      const double patch = square_wave(across, 0.5) * square_wave(along, 0.6);
      const double s = 1.6 * light_.sun_strength * patch * light_.brightness;
      out = {out.b + 1.0 * s, out.g + 1.3 * s, out.r + 1.5 * s};  // sunlight is warm
    }
    return out;
  }

  /// 1 inside the first `duty` of each period, 0 outside, edges softened over 5 % of a period.
  static double square_wave(double s, double duty) noexcept {
    const double f = s - static_cast<double>(fast_floor(s));
    const double inside = f < duty ? std::min(f, duty - f) : -std::min(f - duty, 1.0 - f);
    return std::clamp(0.5 + inside / 0.05, 0.0, 1.0);
  }

  /// Diffuse shading of a unit normal: the lamps are high up, a little to one side.
  static double lambert(const Vec3& n) noexcept {
    const double l = n.x * 0.30 + n.y * 0.20 + n.z * 0.9327;
    return 0.62 + 0.4 * (l > 0.0 ? l : 0.0);
  }

  void emit(std::uint8_t* out, const Rgb& albedo, const Rgb& light, double shade) const noexcept {
    out[0] = to_byte(albedo.b * light.b * shade * gain_[0]);
    out[1] = to_byte(albedo.g * light.g * shade * gain_[1]);
    out[2] = to_byte(albedo.r * light.r * shade * gain_[2]);
  }

  const CameraLook& look_;
  const Lighting& light_;
  std::uint32_t seed_;
  std::array<double, 3> gain_;
  double sun_cos_;
  double sun_sin_;
  Rgb base_light_;  // tint × brightness
  BallPattern pattern_;
};

}  // namespace ringlet::sim_hal::detail
