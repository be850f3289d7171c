#pragma once
// One frame of a ringlet-dataset folder: frame_NNNN.json (camera, head, ground truth) and its
// picture. The truth for line detectors is the JSON's visible straight-line runs as image segments
// with their painted width projected into the image; the balls' and robots' truth for the object
// scores (object_score.hpp).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "ringlet/hal/camera.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/sensors.hpp"
#include "circle_score.hpp"
#include "mark_score.hpp"
#include "object_score.hpp"
#include "segment_match.hpp"

namespace ringlet::vision::evaluate {

struct DatasetFrame {
  std::filesystem::path json;
  std::filesystem::path picture;  // empty when the frame is not a PNG/JPEG (e.g. raw yuyv)
  std::uint64_t index = 0;
  std::uint64_t seed = 0;
  int generator_version = 1;      // frames written before the field existed: 1
  hal::CameraIntrinsics intrinsics{};
  hal::CameraMount mount{};
  hal::HeadJoints head{};
  std::vector<TruthSegment> lines;
  std::vector<TruthRing> rings;   // the centre circle(s): "rings" (frames without the field: none)
  std::vector<TruthMark> marks;   // the penalty and centre marks in view (mark_score.hpp)
  // Generator version 3 and later: every ball ("balls") and robot ("robots"); older frames: none
  // (has_objects false, and they are not scored).
  bool has_objects = false;
  std::vector<TruthBall> balls;
  std::vector<TruthRobot> robots;
};

/// The frame_*.json files of a dataset folder, in index order (by name; frame_10000 after
/// frame_9999). ToolError when the folder is missing or holds none.
[[nodiscard]] std::vector<std::filesystem::path> list_dataset_frames(const std::filesystem::path& dir);

/// Reads one frame's JSON. ToolError naming the file on a read or parse error, a missing field, or
/// a picture format other than png.
[[nodiscard]] DatasetFrame load_dataset_frame(const std::filesystem::path& json);

/// A frame with its picture, as the evaluation gives it to the detectors: BGR as read (Hough,
/// drawings) and the YUYV the robot's camera would deliver (hal::bgr_to_yuyv; Ringlet's pipeline).
struct LoadedFrame {
  DatasetFrame meta;
  cv::Mat bgr;
  std::vector<std::uint8_t> yuyv;
};

/// load_dataset_frame and its picture. ToolError as there, or naming the picture when it cannot be
/// read, has another size than the frame's camera, or an odd width (YUYV needs pixel pairs).
[[nodiscard]] LoadedFrame load_frame(const std::filesystem::path& json);

/// The YUYV picture as a camera frame whose sequence number is the frame's index: the pipeline
/// derives RANSAC's random stream from it, so every tool that runs a dataset frame this way sees
/// exactly what the evaluation saw.
[[nodiscard]] hal::FrameView yuyv_view(const LoadedFrame& f);

/// Half the image width of a painted line `width_m` wide at ground point `at` on a line with unit
/// ground direction (dx, dy): the two points ±width/2 across it, projected. 0 when either does not
/// project.
[[nodiscard]] double projected_half_width(const hal::CameraIntrinsics& k, const hal::CameraPose& pose,
                                          const hal::RobotPoint& at, double dx, double dy, double width_m);

}  // namespace ringlet::vision::evaluate
