// ringlet-vision: runs Ringlet's vision pipeline on one image file (PNG or JPEG: a rendered frame
// or a photograph from a NAO's head camera) and prints the lines, centre circle and ball it found
// as JSON on stdout; --overlay draws them over the picture.
//
// The camera that took the picture is given by flags (image size, field of view or fx/fy/cx/cy,
// mount, head yaw and pitch): the pipeline needs them to find the horizon and put points on the
// ground. Defaults are the NAO's head camera at 20° pitch.
//
// Exit codes: 0 done · 2 bad input (flags, unreadable image, wrong image size, missing or corrupt
// colour table) · 1 internal or output error (e.g. the overlay cannot be written).
#include <CLI/CLI.hpp>
#include <opencv2/imgcodecs.hpp>

#include <iostream>
#include <string>

#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "class_drawing.hpp"
#include "vision_io.hpp"

namespace {

using namespace ringlet;
using namespace ringlet::vision;

struct Options {
  std::string image;
  std::string lut;
  std::string overlay;
  std::string classes;
  tools::CameraOptions camera;
  std::uint64_t seed = RansacParams{}.seed;
  int max_trials = RansacParams{}.max_trials;
  int skip = RansacParams{}.skip;
  bool compact = false;
};

int run(const Options& o) {
  VisionConfig config;
  config.intrinsics = o.camera.intrinsics();
  config.mount = o.camera.mount;
  config.ransac.seed = o.seed;
  config.ransac.max_trials = o.max_trials;
  config.ransac.skip = o.skip;
  // Both are checked before anything runs, so a bad table or image never gives partial output.
  ColourTable table = tools::load_table(o.lut);
  if (!o.lut.empty()) config.colour_mode = ColourMode::kTable;  // a calibrated table is used as it is
  const cv::Mat bgr = tools::load_bgr(o.image, config.intrinsics.width, config.intrinsics.height);

  VisionPipeline pipeline(config, std::move(table));
  const hal::HeadJoints head = o.camera.head();
  const VisionResult& result = pipeline.process(tools::frame_view(bgr), head);
  nlohmann::json out = tools::result_json(result);
  out["image"] = o.image;
  std::cout << out.dump(o.compact ? -1 : 2) << "\n";

  if (!o.classes.empty() && !tools::write_class_image(o.classes, bgr, pipeline.classes(), "ringlet-vision")) return 1;
  if (!o.overlay.empty()) {
    cv::Mat drawn = bgr.clone();
    tools::draw_result(drawn, result, config.intrinsics, hal::CameraPose::from_head(config.mount, head));
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
               "(flags, image, colour table), 1 internal or output error."};
  app.add_option("image", o.image, "the picture (PNG, JPEG, ...), as the camera delivered it")->required();
  app.add_option("--lut", o.lut, "colour table file (RLUT, from ringlet-vision-calibrate); default: the built-in "
                                 "default thresholds");
  app.add_option("--overlay", o.overlay, "also write the picture with the detections drawn over it (PNG or JPEG)");
  app.add_option("--classes", o.classes, "also write the picture with the colour classes drawn over it (field "
                                         "green, line white, ball orange, other dark; PNG or JPEG)");
  app.add_option("--seed", o.seed, "RANSAC seed (the frame's stream is derived from it)")->capture_default_str();
  app.add_option("--max-trials", o.max_trials, "RANSAC MAX_TRIALS: hypotheses per line")
      ->capture_default_str()->check(CLI::Range(1, 100000));
  app.add_option("--skip", o.skip, "RANSAC_SKIP: only every N-th candidate point is used")
      ->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_flag("--compact", o.compact, "one-line JSON");
  o.camera.add_to(app);
  return tools::run_tool(app, argc, argv, "ringlet-vision", [&] { return run(o); });
}
