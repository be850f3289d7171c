// ringlet-vision: runs Ringlet's vision pipeline on one image file (PNG or JPEG: a rendered frame
// or a photograph from a NAO's head camera) and prints the lines, centre circle and ball it found
// as JSON on stdout, with the time each stage took; --overlay draws them over the picture;
// --repeat N processes the frame N times and adds timing statistics.
//
// The camera that took the picture is given by flags (image size, field of view or fx/fy/cx/cy,
// mount, head yaw and pitch, the torso's pitch and roll from the inertial unit): the pipeline
// needs them to find the horizon and put points on the ground. Defaults are the NAO's head camera
// at 20° pitch on an upright torso. --dataset-frame takes a ringlet-dataset frame instead, with its
// camera, and runs it exactly as ringlet-vision-eval does (its YUYV, its index as the frame's
// sequence): where the evaluation missed a line, this shows why.
//
// Exit codes: 0 done (warnings, e.g. a grey picture, go to stderr and the JSON's "warnings") ·
// 2 bad input (flags, unreadable or truncated image, wrong image size, missing or corrupt colour
// table) · 1 internal or output error (e.g. the overlay cannot be written).
#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include <iomanip>
#include <iostream>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/vision/pitch_check.hpp"
#include "ringlet/vision/stages.hpp"
#include "class_drawing.hpp"
#include "dataset_frame.hpp"
#include "vision_io.hpp"

namespace {

using namespace ringlet;
using namespace ringlet::vision;

struct Options {
  std::string image;
  std::string dataset_frame;
  std::string lut;
  std::string overlay;
  std::string classes;
  bool draw_candidates = false;
  tools::CameraOptions camera;
  std::uint64_t seed = RansacParams{}.seed;
  int max_trials = RansacParams{}.max_trials;
  int skip = RansacParams{}.skip;
  int repeat = 1;
  bool compact = false;
  bool auto_pitch = false;
  std::string ball_mode = "bw";
  std::string ball_model = tools::kModelAuto;
  std::string robot_model = tools::kModelAuto;
};

/// The picture and the camera that took it: from the image file and the camera flags, or from a
/// dataset frame (its picture converted to YUYV, as the evaluation runs it).
struct Input {
  std::string name;                              // what the JSON and the messages call it
  tools::LoadedImage image;                      // an image file ...
  std::optional<evaluate::LoadedFrame> dataset;  // ... or a dataset frame
  hal::CameraIntrinsics intrinsics{};
  hal::CameraMount mount{};
  hal::CameraPosture posture{};
  nlohmann::json posture_deg;  // as given: the flags' degrees, or the frame's angles in degrees

  [[nodiscard]] const cv::Mat& bgr() const { return dataset ? dataset->bgr : image.bgr; }
  /// What the pipeline takes: the image file's BGR, or the dataset frame as the evaluation gives it.
  [[nodiscard]] hal::FrameView view() const { return dataset ? evaluate::yuyv_view(*dataset) : tools::frame_view(image.bgr); }
};

Input read_input(const Options& o) {
  Input in;
  if (o.dataset_frame.empty()) {
    in.name = o.image;
    in.intrinsics = o.camera.intrinsics();
    in.mount = o.camera.camera_mount();
    in.posture = o.camera.posture();
    in.posture_deg = {{"head_yaw", o.camera.yaw_deg},
                      {"head_pitch", o.camera.pitch_deg},
                      {"body_pitch", o.camera.body_pitch_deg},
                      {"body_roll", o.camera.body_roll_deg}};
    in.image = tools::load_frame(o.image, in.intrinsics.width, in.intrinsics.height);
    return in;
  }
  in.name = o.dataset_frame;
  const evaluate::LoadedFrame& f = in.dataset.emplace(evaluate::load_frame(o.dataset_frame));
  in.intrinsics = f.meta.intrinsics;
  in.mount = f.meta.mount;
  in.posture = {hal::BodyTilt{}, f.meta.head};  // what ringlet-vision-eval gives the pipeline
  constexpr double kDeg = 180.0 / std::numbers::pi;
  in.posture_deg = {{"head_yaw", f.meta.head.yaw * kDeg}, {"head_pitch", f.meta.head.pitch * kDeg},
                    {"body_pitch", 0.0}, {"body_roll", 0.0}};
  return in;
}

/// --auto-pitch (pitch_check.hpp): `posture` becomes the corrected one; returns what was found.
nlohmann::json correct_pitch(VisionPipeline& pipeline, const hal::FrameView& view, hal::CameraPosture& posture,
                             std::vector<std::string>& warnings) {
  const double given_deg = hal::rad_to_deg(posture.head.pitch);
  const PitchCorrection c = correct_head_pitch(pipeline, view, posture);
  nlohmann::json rounds = nlohmann::json::array();
  for (int i = 0; i < c.round_count; ++i) {
    const PitchCheck& r = c.rounds[static_cast<std::size_t>(i)];
    rounds.push_back({{"valid", r.valid}, {"offset_deg", r.offset_deg}, {"residual_deg", r.residual_deg},
                      {"residual_at_given_deg", r.residual_at_given_deg}, {"segments", r.segments}, {"pairs", r.pairs}});
  }
  if (!c.corrected()) {
    warnings.emplace_back("--auto-pitch: too few field lines, or lines no pitch squares (pitch_check.rounds says "
                          "which); the given pitch is kept");
    std::cerr << "ringlet-vision: warning: " << warnings.back() << "\n";
  }
  posture = c.posture;
  const double used_deg = hal::rad_to_deg(posture.head.pitch);
  std::cerr << std::fixed << std::setprecision(2) << "ringlet-vision: --auto-pitch: head pitch " << given_deg << " -> "
            << used_deg << " deg\n";
  return {{"given_head_pitch_deg", given_deg}, {"head_pitch_deg", used_deg}, {"correction_deg", used_deg - given_deg},
          {"rounds", rounds}};
}

int run(const Options& o) {
  VisionConfig config;
  // Both are checked before anything runs, so a bad table or image never gives partial output.
  ColourTable table = tools::load_table(o.lut);
  const Input input = read_input(o);
  config.intrinsics = input.intrinsics;
  config.mount = input.mount;
  config.ransac.seed = o.seed;
  config.ransac.max_trials = o.max_trials;
  config.ransac.skip = o.skip;
  if (!o.lut.empty()) config.colour_mode = ColourMode::kTable;  // a calibrated table is used as it is
  for (const std::string& w : input.image.warnings) std::cerr << "ringlet-vision: warning: " << input.name << ": " << w << "\n";
  const cv::Mat& bgr = input.bgr();

  config.ball.mode = o.ball_mode == "orange" ? BallMode::kOrange : BallMode::kBlackWhite;
  // Both models are loaded (and a bad file refused) before anything runs.
  std::vector<std::string> warnings = input.image.warnings;
  const auto [ball, robot] = tools::model_files(o.ball_model, o.robot_model, "ringlet-vision", &warnings);
  std::vector<HogSvm> models;
  if (!ball.file.empty()) models.push_back(tools::load_hog_model(ball.file, HogTarget::kBall, "--ball-model"));
  if (!robot.file.empty()) models.push_back(tools::load_hog_model(robot.file, HogTarget::kRobot, "--robot-model"));

  VisionPipeline pipeline(config, std::move(table));
  for (HogSvm& m : models) {
    if (const std::string why = pipeline.set_classifier(std::move(m)); !why.empty()) throw tools::ToolError(why);
  }
  hal::CameraPosture posture = input.posture;
  const hal::FrameView view = input.view();
  nlohmann::json pitch_json;
  if (o.auto_pitch) pitch_json = correct_pitch(pipeline, view, posture, warnings);
  // Stages are timed on this thread's CPU clock (what the robot's budget is judged on; other
  // processes on the host do not inflate it), the whole frame on the wall clock too. The deadline
  // never expires: a desktop run does all the work.
  hal::ThreadStopwatch watch;
  const Deadline timed{&watch, hal::Nanos::max(), true};
  pipeline.forget_history();  // as a fresh run at the posture used
  std::vector<hal::Nanos> cpu, wall;
  std::vector<std::vector<hal::Nanos>> stages(kStageCount);
  cpu.reserve(static_cast<std::size_t>(o.repeat));
  wall.reserve(static_cast<std::size_t>(o.repeat));
  for (int i = 0; i < o.repeat; ++i) {
    const hal::Nanos start = watch.wall_now();
    const VisionResult& r = pipeline.process(view, posture, timed);
    wall.push_back(watch.wall_now() - start);
    cpu.push_back(r.total_time);
    for (std::size_t s = 0; s < kStageCount; ++s) stages[s].push_back(r.stage_time[s]);
  }
  const VisionResult& result = pipeline.result();  // the same every time: the frame's seed is fixed
  nlohmann::json out = tools::result_json(result);
  out["image"] = input.name;
  if (input.dataset) out["sequence"] = view.sequence;
  out["posture_deg"] = input.posture_deg;
  if (o.auto_pitch) {
    out["posture_deg"]["head_pitch"] = hal::rad_to_deg(posture.head.pitch);
    out["pitch_check"] = pitch_json;
  }
  out["time_ms"] = tools::stage_times_json(result);
  out["time_ms"]["wall"] = static_cast<double>(wall.back().count()) / 1e6;
  out["time_clock"] = "stages and total: this thread's CPU time; wall: the monotonic clock";
  const auto used = [](const tools::ModelFile& m) { return m.file.empty() ? std::string(tools::kModelNone) : m.file.string(); };
  out["models"] = {{"ball", used(ball)}, {"robot", used(robot)}};
  if (!warnings.empty()) out["warnings"] = warnings;
  if (o.draw_candidates) {
    nlohmann::json points = nlohmann::json::array();
    for (const CandidatePoint& c : pipeline.candidates().points()) points.push_back({c.pixel.u, c.pixel.v});
    out["candidate_points"] = points;
  }
  if (o.repeat > 1) {
    const tools::TimeStats total = tools::time_stats(cpu);
    const tools::TimeStats wall_stats = tools::time_stats(wall);
    nlohmann::json per_stage = nlohmann::json::object();
    for (std::size_t s = 0; s < kStageCount; ++s) per_stage[std::string(stage_name(static_cast<Stage>(s)))] = tools::to_json(tools::time_stats(stages[s]));
    out["timing"] = {{"repeat", o.repeat}, {"total_ms", tools::to_json(total)}, {"wall_ms", tools::to_json(wall_stats)},
                     {"stages_ms", per_stage}};
    std::cerr << std::fixed << std::setprecision(3) << "ringlet-vision: " << o.repeat
              << " runs, thread CPU ms per frame: min " << total.min_ms << " median "
              << total.median_ms << " p99 " << total.p99_ms << " max " << total.max_ms << " (wall median "
              << wall_stats.median_ms << ")\n";
  }
  std::cout << out.dump(o.compact ? -1 : 2) << "\n";

  if (!o.classes.empty() && !tools::write_class_image(o.classes, bgr, pipeline.classes(), "ringlet-vision")) return 1;
  if (!o.overlay.empty()) {
    cv::Mat drawn = bgr.clone();
    tools::draw_result(drawn, result, config.intrinsics, hal::CameraPose::from_posture(config.mount, posture));
    if (o.draw_candidates) tools::draw_candidates(drawn, pipeline.candidates().points());
    bool written = false;
    try {
      written = cv::imwrite(o.overlay, drawn);
    } catch (const cv::Exception& e) {
      std::cerr << "ringlet-vision: " << o.overlay << ": " << e.what() << "\n";
    }
    if (!written) {
      std::cerr << "ringlet-vision: " << o.overlay << ": cannot write the overlay image (the extension picks the format: .png, .jpg)\n";
      return 1;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"ringlet-vision: detect field lines, the centre circle and the ball in one image (PNG or JPEG) "
               "with Ringlet's pipeline; prints JSON on stdout. Exit codes: 0 done, 2 bad input "
               "(flags, image, colour table, model files), 1 internal or output error."};
  CLI::Option* image = app.add_option("image", o.image, "the picture (PNG, JPEG, ...), as the camera delivered it");
  CLI::Option* dataset_frame =
      app.add_option("--dataset-frame", o.dataset_frame,
                     "instead of an image: a ringlet-dataset frame (frame_NNNN.json), run with its own camera, "
                     "converted to YUYV and with its index as the frame's sequence, exactly as ringlet-vision-eval "
                     "runs it (the camera flags do not go with it)");
  image->excludes(dataset_frame);
  dataset_frame->excludes(image);
  app.add_option("--lut", o.lut, "colour table file (RLUT, from ringlet-vision-calibrate); default: the built-in "
                                 "default thresholds");
  app.add_option("--overlay", o.overlay, "also write the picture with the detections drawn over it (PNG or JPEG)");
  app.add_flag("--candidates", o.draw_candidates,
               "list the line candidates the scan lines found in the JSON (candidate_points, pixels) and, with "
               "--overlay, draw them (vertical scans magenta, horizontal cyan): where lines are missed, this shows "
               "whether the colour and scan or RANSAC lost them");
  app.add_option("--classes", o.classes, "also write the picture with the colour classes drawn over it (field "
                                         "green, line white, ball orange, other dark; PNG or JPEG)");
  app.add_option("--seed", o.seed, "RANSAC seed (the frame's stream is derived from it)")->capture_default_str();
  app.add_option("--max-trials", o.max_trials, "RANSAC MAX_TRIALS: hypotheses per line")
      ->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--skip", o.skip, "RANSAC_SKIP: only every N-th candidate point is used")
      ->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_option("--repeat", o.repeat, "process the frame N times and add timing statistics (min, median, p99, max "
                                       "in ms) to the JSON and stderr")
      ->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--ball-mode", o.ball_mode, "the ball's detector: bw (the SPL's black-and-white ball, verified by "
                                             "--ball-model) or orange")
      ->capture_default_str()->check(CLI::IsMember({"bw", "orange"}));
  app.add_option("--ball-model", o.ball_model, "HOG/SVM model verifying black-and-white ball candidates: a file "
                                               "(ringlet-train-hog), auto (the shipped vision/models/ball.hog) or none "
                                               "(candidates reported unverified); the JSON's models.ball says which")
      ->capture_default_str();
  app.add_option("--robot-model", o.robot_model, "HOG/SVM model verifying robot candidates: a file, auto (the shipped "
                                                 "vision/models/robot.hog) or none (candidates unverified)")
      ->capture_default_str();
  app.add_flag("--auto-pitch", o.auto_pitch,
               "correct the head pitch from the field lines themselves (any two SPL lines are parallel or square "
               "on the ground; a pitch that is off bends them): run, estimate the offset within ±8°, run again at "
               "the corrected pitch; the JSON's pitch_check says what was found and posture_deg the pitch used");
  app.add_flag("--compact", o.compact, "one-line JSON");
  for (CLI::Option* flag : o.camera.add_to(app)) dataset_frame->excludes(flag);  // the frame says which camera took it
  app.callback([&] {
    if (o.image.empty() && o.dataset_frame.empty()) throw CLI::RequiredError("image (or --dataset-frame)");
  });
  return tools::run_tool(app, argc, argv, "ringlet-vision", [&] { return run(o); });
}
