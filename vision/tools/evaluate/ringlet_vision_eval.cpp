// ringlet-vision-eval: Ringlet's line detector against OpenCV's Canny + HoughLinesP on a folder
// written by ringlet-dataset (frame_NNNN.png + frame_NNNN.json). For every frame: the pipeline on
// the YUYV the robot's camera would give (hal::bgr_to_yuyv of the PNG) with the frame's camera and
// head, and Canny + HoughLinesP on the BGR picture with the same horizon mask; both scored against
// the visible straight line runs by the rule in segment_match.hpp, and timed.
//
// Hough's parameters are tuned (best F1 of HoughParams::candidates()) on a tuning set: another
// ringlet-dataset folder (--tune-set, e.g. another seed), or the first --tune frames of DATASET.
// Both detectors are reported on the test set only (DATASET, or the rest of it). Before anything
// is scored the test set is checked against the tuning set and every --disjoint-from folder (the
// frames anyone chose parameters on): a frame with the same generator, seed and index, or with
// identical pixels, in both is refused (exit 2). The output names all the sets.
//
// Balls and robots are scored too (object_score.hpp) on frames with balls[] and robots[] truth, with
// the ball detector of --ball-mode (default bw) and the HOG/SVM models of --ball-model and
// --robot-model installed.
//
// Exit codes: 0 done · 2 bad input (flags, folder, frame records, images, colour table, model
// files, too few frames, overlapping tuning and test sets) · 1 internal or output error (cannot
// write --json or --svg).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>
#include <unistd.h>

#include "evaluation.hpp"
#include "report.hpp"
#include "vision_io.hpp"

namespace {

using namespace ringlet::vision;

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text;
  if (!file) {
    std::cerr << "ringlet-vision-eval: " << path << ": cannot write\n";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  evaluate::EvalOptions o;
  std::string dataset, lut, json, svg, tune_set;
  std::vector<std::string> disjoint_from;
  bool quiet = false;
  CLI::App app{"ringlet-vision-eval: compare Ringlet's field-line detector with Canny + HoughLinesP on a "
               "ringlet-dataset folder (precision, recall, F1, errors, time per frame); score the centre circle, "
               "the balls and the robots. Exit codes: 0 done, "
               "2 bad input, 1 internal or output error."};
  app.add_option("dataset", dataset, "folder written by ringlet-dataset (png format)")->required();
  app.add_option("--lut", lut, "colour table for Ringlet (default: the built-in default thresholds)");
  app.add_option("--tune-set", tune_set, "tune Hough on this ringlet-dataset folder (all its frames, or its first "
                                        "--tune) and report on all of DATASET; the two must share no frame")
      ->check(CLI::ExistingDirectory);
  app.add_option("--tune", o.tune_frames, "without --tune-set: Hough is tuned on this many first frames of DATASET, "
                                          "which are then left out of the report (0: OpenCV-style defaults, report "
                                          "on all); with --tune-set: use its first N frames")
      ->capture_default_str()->check(CLI::Range(0, 1000000));
  app.add_option("--disjoint-from", disjoint_from, "ringlet-dataset folders the test set must share no frame with "
                                                   "(e.g. the frames Ringlet's parameters were chosen on); repeatable")
      ->check(CLI::ExistingDirectory);
  app.add_option("--max-frames", o.max_frames, "use only the first N frames (0: all)")->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  app.add_option("--max-angle", o.match.max_angle_deg, "matching: max angle (deg)")
      ->capture_default_str()->check(tools::finite_range(0.0, 90.0, "deg"));
  app.add_option("--max-distance", o.match.max_distance_px, "matching: endpoint distance (px) beyond the half width")
      ->capture_default_str()->check(tools::finite_range(0.0, 1000.0, "px"));
  app.add_option("--min-coverage", o.match.min_coverage, "matching: share of a true segment to cover for recall")
      ->capture_default_str()->check(tools::finite_range(0.0, 1.0, ""));
  std::string ball_mode = "bw", ball_model = tools::kModelAuto, robot_model = tools::kModelAuto;
  app.add_option("--ball-mode", ball_mode, "the ball's detector: bw (the SPL's black-and-white ball, HOG/SVM-verified "
                                           "with --ball-model) or orange")
      ->capture_default_str()->check(CLI::IsMember({"bw", "orange"}));
  app.add_option("--ball-model", ball_model, "HOG/SVM model verifying black-and-white ball candidates: a file "
                                             "(ringlet-train-hog), auto (the shipped vision/models/ball.hog) or none "
                                             "(candidates reported unverified); the report names the model used")
      ->capture_default_str();
  app.add_option("--robot-model", robot_model, "HOG/SVM model verifying robot candidates: a file, auto (the shipped "
                                               "vision/models/robot.hog) or none (candidates unverified)")
      ->capture_default_str();
  app.add_option("--seed", o.vision.ransac.seed, "RANSAC seed (each frame's stream is derived from it): the spread of "
                                                "the line figures over a few seeds shows how much of a difference is "
                                                "chance")
      ->capture_default_str();
  app.add_option("--pitch-error", o.pitch_error_deg, "give the pipeline each frame's head pitch plus this (deg): how "
                                                    "much a camera mounted off, or a wrong joint reading, costs")
      ->capture_default_str()->check(tools::finite_range(-20.0, 20.0, "deg"));
  app.add_flag("--auto-pitch", o.auto_pitch, "correct each frame's head pitch from its field lines first, as "
                                            "ringlet-vision --auto-pitch does; the report says how close it came");
  app.add_option("--json", json, "write the full report (per-frame times, tuning) as JSON");
  app.add_option("--svg", svg, "write a comparison chart (SVG)");
  app.add_flag("-q,--quiet", quiet, "no progress output");
  return tools::run_tool(app, argc, argv, "ringlet-vision-eval", [&] {
    o.dataset = dataset;
    o.lut = lut;
    o.tune_set = tune_set;
    if (!tune_set.empty() && app.count("--tune") == 0) o.tune_frames = 0;  // all of the tuning set
    o.vision.ball.mode = ball_mode == "orange" ? BallMode::kOrange : BallMode::kBlackWhite;
    const tools::ModelFiles models = tools::model_files(ball_model, robot_model, "ringlet-vision-eval");
    o.ball_model = models.ball.file;
    o.robot_model = models.robot.file;
    o.disjoint_from.assign(disjoint_from.begin(), disjoint_from.end());
    if (!quiet) {
      const bool tty = isatty(fileno(stderr)) != 0;
      o.progress = [tty](const char* stage, std::size_t done, std::size_t total) {
        if (tty) {
          std::fprintf(stderr, "\rringlet-vision-eval: %s %zu/%zu   ", stage, done, total);
          if (done == total) std::fputc('\n', stderr);
        } else if (done == total || (total >= 10 && done % (total / 10) == 0)) {
          std::fprintf(stderr, "ringlet-vision-eval: %s %zu/%zu\n", stage, done, total);
        }
      };
    }
    const evaluate::EvalReport report = evaluate::run_evaluation(o);
    evaluate::print_report(report, std::cout);
    if (!json.empty() && !write_file(json, evaluate::report_json(report).dump(2) + "\n")) return 1;
    if (!svg.empty() && !write_file(svg, evaluate::report_svg(report))) return 1;
    return 0;
  });
}
