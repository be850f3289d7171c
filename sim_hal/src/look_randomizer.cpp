// The ranges of the randomized look, chosen so rendered frames cover what real NAO photos of SPL
// fields show (issue 10, measured in full-range BT.601): carpet V medians 112..128, line U down
// to 95..103 under warm light, line Y 157..168 when backlit. tests/sim_hal/camera_look_test.cpp
// measures it.
#include "ringlet/sim_hal/look_randomizer.hpp"

#include <numbers>

namespace ringlet::sim_hal {

LookDraw draw_spl_look(const Lighting& base, BallLook ball, std::uint64_t seed) noexcept {
  SplitMix rnd(seed ^ 0x4c4f4f4b2d535044ULL);
  LookDraw d;
  CameraLook& l = d.look;
  l.style = LookStyle::kSpl;
  l.ball = ball;
  const double kind = rnd.uniform(0.0, 1.0);
  l.light = kind < 0.45 ? LightKind::kFluorescent : (kind < 0.8 ? LightKind::kDaylight : LightKind::kBacklight);
  // Backlight: the camera exposes for the windows, the field comes out dark.
  l.exposure = l.light == LightKind::kBacklight ? rnd.uniform(0.6, 0.8) : rnd.uniform(0.85, 1.15);
  l.white_red = rnd.uniform(0.9, 1.1);
  // Auto white balance is often left warm under daylight and old tubes: blue down to 0.72.
  l.white_blue = rnd.uniform(0.0, 1.0) < 0.3 ? rnd.uniform(0.72, 0.85) : rnd.uniform(0.9, 1.1);
  l.carpet_warmth = rnd.uniform(-0.7, 0.8);
  l.noise = rnd.uniform(1.0, 5.0);
  l.drift = 0.0;  // a single frame has no drift; the firmware's camera sets it per world
  l.blur = rnd.uniform(0.0, 1.0) < 0.5 ? 0 : static_cast<int>(rnd.uniform(2.0, 8.0));
  l.blur_vertical = rnd.uniform(0.0, 1.0) < 0.3;
  d.lighting = base;
  d.lighting.brightness = base.brightness * rnd.uniform(0.92, 1.08);
  d.lighting.texture = rnd.uniform(0.04, 0.12);
  d.lighting.sun_strength = l.light == LightKind::kDaylight ? rnd.uniform(0.15, 0.6) : 0.0;
  d.lighting.sun_period = rnd.uniform(1.5, 4.0);
  d.lighting.sun_angle = rnd.uniform(0.0, std::numbers::pi);
  d.lighting.sun_phase = rnd.uniform(0.0, d.lighting.sun_period);
  d.jpeg_quality = rnd.uniform(0.0, 1.0) < 0.6 ? static_cast<int>(rnd.uniform(35.0, 96.0)) : 0;
  return d;
}

}  // namespace ringlet::sim_hal
