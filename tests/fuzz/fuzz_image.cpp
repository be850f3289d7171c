// Fuzz target: image bytes as the vision tools take them. tools::decode_bgr checks the header
// (hal::probe_image: PNG or JPEG, a pixel limit) before OpenCV decodes; anything it refuses must
// be a ToolError "fuzz.png: not a readable image: <why>" — never an OpenCV exception, a crash or
// an allocation the header asked for. A picture that decodes to a usable size then goes through
// Ringlet's whole pipeline, once, as BGR or as the YUYV the robot's camera gives and at one of the
// degrade levels, with a camera of that size and a head posture from the input's last bytes; the
// result must be sane (status ok, at most kMaxLines finite lines, a finite ball).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "vision_io.hpp"

namespace {

using namespace ringlet;

constexpr std::string_view kPrefix = "fuzz.png: not a readable image: ";
// Far below the tools' limit so that one execution stays fast (a million of them must fit a
// campaign); the refusal path is the same code with another number.
constexpr std::size_t kMaxPixels = std::size_t{256} * 256;
// The pipeline runs on pictures from 8 × 8 up to 160 × 120: every stage and every size-dependent
// path (odd widths, a horizon inside or outside the picture) is there at a sixteenth of the NAO's
// 640 × 480; full-size frames go through the pipeline in the unit tests and the dataset runs.
constexpr int kMinSide = 8;
constexpr int kMaxWidth = 160, kMaxHeight = 120;

bool finite(const hal::Pixel& p) { return std::isfinite(p.u) && std::isfinite(p.v); }
bool finite(const hal::RobotPoint& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

void check(const vision::VisionResult& r, int width, int height) {
  if (r.status != vision::VisionStatus::kOk) __builtin_trap();
  if (r.line_count > vision::kMaxLines) __builtin_trap();
  if (r.horizon_row < 0 || r.horizon_row > height) __builtin_trap();
  for (std::size_t i = 0; i < r.line_count; ++i) {
    const vision::FieldLine& l = r.lines[i];
    if (!finite(l.ground_start) || !finite(l.ground_end) || !std::isfinite(l.length_m) || l.length_m < 0.0) __builtin_trap();
    if (!finite(l.image_start) || !finite(l.image_end)) __builtin_trap();
  }
  if (r.ball.seen) {
    if (!finite(r.ball.centre) || r.ball.centre.u < 0.0 || r.ball.centre.u > width || r.ball.centre.v < 0.0 ||
        r.ball.centre.v > height) {
      __builtin_trap();
    }
    if (!(r.ball.confidence >= 0.0 && r.ball.confidence <= 1.0)) __builtin_trap();
    if (r.ball.ground_valid && !finite(r.ball.ground)) __builtin_trap();
  }
  if (r.circle.seen && (!finite(r.circle.centre) || !std::isfinite(r.circle.radius_m))) __builtin_trap();
}

void run_pipeline(const cv::Mat& bgr, std::span<const std::uint8_t> input) {
  // Even width for YUYV: the odd last column is cut off, as the calibration tool does.
  const int width = bgr.cols & ~1;
  const int height = bgr.rows;
  const cv::Mat picture = bgr(cv::Rect(0, 0, width, height)).clone();
  // The table (256 KiB of bins) is built once; a pipeline is kept while pictures keep its size
  // (building either per execution made the target ten times slower).
  static const vision::ColourTable table = vision::ColourTable::from_thresholds({});
  static std::unique_ptr<vision::VisionPipeline> pipeline;
  if (!pipeline || pipeline->config().intrinsics.width != width || pipeline->config().intrinsics.height != height) {
    vision::VisionConfig config;
    config.intrinsics = hal::CameraIntrinsics::from_fov(width, height, 57.0, 44.0);
    pipeline = std::make_unique<vision::VisionPipeline>(config, table);
  }
  // The head inside the NAO's range, from the last two bytes.
  const double yaw_unit = input.size() >= 2 ? input[input.size() - 2] / 255.0 : 0.5;
  const double pitch_unit = input.empty() ? 0.8 : input.back() / 255.0;
  using R = hal::NaoHeadRange;
  const hal::HeadJoints head{hal::deg_to_rad((2.0 * yaw_unit - 1.0) * R::kMaxYawDeg),
                             hal::deg_to_rad(R::kMinPitchDeg + pitch_unit * (R::kMaxPitchDeg - R::kMinPitchDeg))};

  // One pipeline run per input (a million executions must fit a campaign): BGR or the robot's
  // YUYV and the degrade level, both from the input's third-last byte.
  const std::uint8_t choice = input.size() >= 3 ? input[input.size() - 3] : 0;
  const int level = choice % vision::kDegradeLevels;
  if ((choice & 0x80U) == 0) {
    check(pipeline->process(vision::tools::frame_view(picture, 1), head, {}, level), width, height);
    return;
  }

  std::vector<std::uint8_t> yuyv(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 2U);
  hal::bgr_to_yuyv({picture.data, picture.total() * 3U}, width, height, yuyv);
  hal::FrameView view;
  view.sequence = 2;
  view.format = hal::PixelFormat::kYuyv;
  view.width = width;
  view.height = height;
  view.stride = 2 * width;
  view.data = yuyv.data();
  check(pipeline->process(view, head, {}, level), width, height);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  cv::Mat bgr;
  try {
    bgr = vision::tools::decode_bgr(input, "fuzz.png", kMaxPixels);
  } catch (const vision::tools::ToolError& e) {
    const std::string_view what = e.what();
    if (what.size() <= kPrefix.size() || what.substr(0, kPrefix.size()) != kPrefix) __builtin_trap();
    return 0;
  }
  if (bgr.empty() || bgr.type() != CV_8UC3 || static_cast<std::size_t>(bgr.cols) * static_cast<std::size_t>(bgr.rows) > kMaxPixels) {
    __builtin_trap();
  }
  if (bgr.cols >= kMinSide && bgr.rows >= kMinSide && bgr.cols <= kMaxWidth && bgr.rows <= kMaxHeight) run_pipeline(bgr, input);
  return 0;
}
