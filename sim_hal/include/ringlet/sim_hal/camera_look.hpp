#pragma once
// How the simulated camera's pictures look: the plain look of the first renderer (flat colours,
// an orange ball, robots as jerseyed cylinders; the courtyard keeps it) or the look of a real SPL
// field seen by a NAO's camera (grass-like carpet, the black-and-white ball, NAO-shaped robots,
// fluorescent light, daylight patches or backlight, the camera's exposure, white balance, drift,
// sensor noise and motion blur). A world chooses it with its `look` statement
// (sim_hal/README.md); ringlet-dataset draws one per frame.
#include <cstdint>

namespace ringlet::sim_hal {

enum class LookStyle : std::uint8_t {
  kPlain,  // the first renderer's look, byte for byte
  kSpl,    // a real SPL field under a real camera
};

enum class BallLook : std::uint8_t {
  kOrange,      // the pre-2016 ball (the plain look's)
  kBlackWhite,  // the SPL ball: white with twelve black pentagons (an icosahedron's vertices)
};

enum class LightKind : std::uint8_t {
  kFluorescent,  // even, a slight green-blue cast
  kDaylight,     // window light: warm bright patches on the carpet (the world's sun_* parameters)
  kBacklight,    // bright windows behind the field: the camera exposes for them, the field is dark
};

/// The camera and the light, for LookStyle::kSpl (the plain look ignores everything but `ball`).
struct CameraLook {
  LookStyle style = LookStyle::kPlain;
  BallLook ball = BallLook::kOrange;
  LightKind light = LightKind::kFluorescent;
  double exposure = 1.0;       // the camera's gain on the scene (backlit scenes: about 0.7)
  double white_red = 1.0;      // white-balance gains of red and blue against green
  double white_blue = 1.0;
  double carpet_warmth = 0.0;  // [-1, 1]: bluish green .. yellowish green carpet (V about 108 .. 128)
  double noise = 2.5;          // sensor noise: amplitude in grey levels (triangular, per channel)
  double drift = 0.0;          // auto-exposure / white-balance drift: amplitude as a fraction
  double drift_frames = 90.0;  // frames between the drift's independent values (it blends between)
  int blur = 0;                // motion blur: box length in pixels (0 or 1 = none)
  bool blur_vertical = false;  // the blur's direction (a head pitching rather than turning)
};

/// "plain"/"spl", "orange"/"bw", "fluorescent"/"daylight"/"backlight": the world file's words.
[[nodiscard]] const char* look_style_name(LookStyle s) noexcept;
[[nodiscard]] const char* ball_look_name(BallLook b) noexcept;
[[nodiscard]] const char* light_kind_name(LightKind k) noexcept;

}  // namespace ringlet::sim_hal
