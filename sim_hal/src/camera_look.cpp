// The words of the world file's `look` statement, for messages and ringlet-dataset's JSON.
#include "ringlet/sim_hal/camera_look.hpp"

namespace ringlet::sim_hal {

const char* look_style_name(LookStyle s) noexcept { return s == LookStyle::kSpl ? "spl" : "plain"; }

const char* ball_look_name(BallLook b) noexcept { return b == BallLook::kBlackWhite ? "bw" : "orange"; }

const char* light_kind_name(LightKind k) noexcept {
  switch (k) {
    case LightKind::kFluorescent: return "fluorescent";
    case LightKind::kDaylight: return "daylight";
    case LightKind::kBacklight: return "backlight";
  }
  return "fluorescent";
}

}  // namespace ringlet::sim_hal
