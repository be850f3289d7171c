#pragma once
// What the vision tools share: image files in (with the errors a person needs), a pipeline's
// result as JSON and drawn over the image, and the camera options every tool takes.
#include <filesystem>
#include <functional>
#include <span>
#include <string_view>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/image_header.hpp"
#include "ringlet/vision/colour_table.hpp"
#include "ringlet/vision/pipeline.hpp"

namespace ringlet::vision::tools {

class ToolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The bytes of a PNG or JPEG file as BGR, as every vision tool decodes images: the header is
/// checked first (hal::probe_image: PNG or JPEG, at most `max_pixels`), then OpenCV decodes it.
/// ToolError "<source>: not a readable image: <why>" for anything else (OpenCV's exceptions
/// included), and for a file cut short ("truncated JPEG (no end-of-image marker)",
/// hal::image_truncation: libjpeg would decode it with grey rows and only a warning).
[[nodiscard]] cv::Mat decode_bgr(std::span<const std::uint8_t> bytes, const std::string& source,
                                 std::size_t max_pixels = hal::kMaxImagePixels);
/// The same with other cv::imread flags (IMREAD_UNCHANGED for label images).
[[nodiscard]] cv::Mat decode_image(std::span<const std::uint8_t> bytes, const std::string& source, int imread_flags,
                                   std::size_t max_pixels = hal::kMaxImagePixels);
/// A PNG or JPEG file read with hal::read_file and decoded by decode_image.
[[nodiscard]] cv::Mat load_image(const std::filesystem::path& file, int imread_flags);

/// A PNG or JPEG file as BGR: read with hal::read_file (regular files, at most
/// hal::kMaxBinaryFileBytes), then decode_bgr. ToolError naming the file when it cannot be read
/// or decoded, or (when width > 0) is not width × height.
[[nodiscard]] cv::Mat load_bgr(const std::filesystem::path& file, int width = 0, int height = 0);

/// An image decoded for the pipeline, with what the person running the tool should be told.
struct LoadedImage {
  cv::Mat bgr;
  /// Things that make the results doubtful but not impossible, without the file name (the caller
  /// adds it): a grey picture, decoded as three equal channels, in which colour classification
  /// finds no field, no lines and no ball.
  std::vector<std::string> warnings;
};

/// load_bgr, and the warnings about the picture (see LoadedImage).
[[nodiscard]] LoadedImage load_frame(const std::filesystem::path& file, int width, int height);

/// A view of a BGR image for the pipeline (valid while the image lives).
[[nodiscard]] hal::FrameView frame_view(const cv::Mat& bgr, std::uint64_t sequence = 0);

/// The colour table from a file (ToolError with the loader's message), or, with an empty path,
/// the default thresholds.
[[nodiscard]] ColourTable load_table(const std::filesystem::path& file);

/// A HOG/SVM model for `target` from `file` (vision/models/*.hog): ToolError "<flag> <file>: <why>"
/// when it does not load or is a model for the other target.
[[nodiscard]] HogSvm load_hog_model(const std::filesystem::path& file, HogTarget target, const std::string& flag);

/// What a --ball-model / --robot-model flag says: "auto" (the default) is the shipped model
/// (shipped_model), "none" is no model (candidates reported unverified), anything else a file.
inline constexpr const char* kModelAuto = "auto";
inline constexpr const char* kModelNone = "none";

/// The model file shipped for `target` (ball.hog, robot.hog): where the package installs it beside
/// the running program (<prefix>/share/ringlet/vision/models, from <prefix>/bin), else the source
/// tree's vision/models this program was built from. Empty when neither exists.
[[nodiscard]] std::filesystem::path shipped_model(HogTarget target);

/// The file a flag's value names: empty for "none", and for "auto" when no model is shipped (then
/// `warning` says where the tool looked and which flag gives one).
struct ModelFile {
  std::filesystem::path file;
  std::string warning;
};
[[nodiscard]] ModelFile model_file(const std::string& flag_value, HogTarget target, const std::string& flag);

/// Both tools' --ball-model and --robot-model, resolved (model_file); each warning is printed to
/// stderr as "<tool>: warning: ..." and appended to `warnings` when given.
struct ModelFiles {
  ModelFile ball, robot;
};
[[nodiscard]] ModelFiles model_files(const std::string& ball_flag, const std::string& robot_flag, const char* tool,
                                     std::vector<std::string>* warnings = nullptr);

/// Camera and head options shared by the tools: image size, field of view (or fx/fy/cx/cy),
/// mount, head yaw and pitch, torso pitch and roll (degrees). Every number must be finite and in
/// its range (the --help text shows each range; yaw and pitch are the NAO's joint ranges,
/// hal::NaoHeadRange; the torso's are hal::BodyTiltRange), else the tool exits 2 naming the flag.
struct CameraOptions {
  int width = 640;
  int height = 480;
  double hfov_deg = 57.0;
  double vfov_deg = 44.0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;  // 0: from the field of view
  hal::CameraMount mount{};     // pitch from camera_pitch_deg (camera_mount())
  double camera_pitch_deg = 0.0;
  double yaw_deg = 0.0;
  double pitch_deg = 20.0;
  double body_pitch_deg = 0.0;  // the torso's tilt (hal::BodyTilt): forward positive
  double body_roll_deg = 0.0;   // leaning right positive

  /// With the head: --yaw, --pitch, --body-pitch and --body-roll too. Returns the options added.
  std::vector<CLI::Option*> add_to(CLI::App& app, bool with_head = true);
  [[nodiscard]] hal::CameraIntrinsics intrinsics() const;
  [[nodiscard]] hal::HeadJoints head() const;
  [[nodiscard]] hal::BodyTilt body() const;
  [[nodiscard]] hal::CameraPosture posture() const { return {body(), head()}; }
  [[nodiscard]] hal::CameraMount camera_mount() const {
    hal::CameraMount m = mount;
    m.pitch = hal::deg_to_rad(camera_pitch_deg);
    return m;
  }
};

/// A CLI11 check: a finite number in [lo, hi] (`unit` follows the range in the message).
/// CLI11's Range lets NaN through (every comparison with NaN is false), and a NaN pitch or focal
/// length would make the pipeline's geometry NaN.
[[nodiscard]] CLI::Validator finite_range(double lo, double hi, const std::string& unit);

/// A number as text ("29.5", "100000").
[[nodiscard]] std::string fmt_number(double v);

[[nodiscard]] nlohmann::json result_json(const VisionResult& result);

/// A frame's time per stage and in total, in ms ({"horizon": 0.01, ..., "total": 1.2}).
[[nodiscard]] nlohmann::json stage_times_json(const VisionResult& result);

/// min, median, p99 (nearest rank) and max of some durations, in ms.
struct TimeStats {
  double min_ms = 0.0;
  double median_ms = 0.0;
  double p99_ms = 0.0;
  double max_ms = 0.0;
};
/// Statistics of `samples` (sorted in place); all zero when empty.
[[nodiscard]] TimeStats time_stats(std::vector<hal::Nanos>& samples);
[[nodiscard]] nlohmann::json to_json(const TimeStats& s);

/// Every vision tool's main: parses the command line, then runs `body`, turning failures into the
/// tools' exit codes — 0 for --help, 2 for bad flags or bad input (ToolError, printed as
/// "<name>: <message>"), 1 for anything else (printed as an internal error).
[[nodiscard]] int run_tool(CLI::App& app, int argc, char** argv, std::string_view name,
                           const std::function<int()>& body);

/// Draws the scan lines' candidate points (vertical scans magenta, horizontal cyan) over `bgr`.
void draw_candidates(cv::Mat& bgr, std::span<const CandidatePoint> points);

/// Draws lines (green, numbered), the centre circle's points and the ball (orange) over `bgr`.
void draw_result(cv::Mat& bgr, const VisionResult& result, const hal::CameraIntrinsics& k, const hal::CameraPose& pose);

}  // namespace ringlet::vision::tools
