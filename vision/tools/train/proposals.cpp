// The detectors' proposals in a dataset frame (proposals.hpp).
#include "proposals.hpp"

#include "dataset_frame.hpp"
#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/pipeline.hpp"
#include "ringlet/vision/robots.hpp"

namespace ringlet::vision::train {

std::vector<Proposal> detector_proposals(HogTarget target, const std::filesystem::path& frame_json, const cv::Mat& bgr) {
  const evaluate::DatasetFrame meta = evaluate::load_dataset_frame(frame_json);
  VisionConfig config;
  config.intrinsics = meta.intrinsics;
  config.mount = meta.mount;
  std::vector<Proposal> out;
  if (bgr.cols != meta.intrinsics.width || bgr.rows != meta.intrinsics.height || bgr.type() != CV_8UC3) return out;
  VisionPipeline pipeline(config, ColourTable::from_thresholds({}));
  hal::FrameView view;
  view.format = hal::PixelFormat::kBgr8;
  view.width = bgr.cols;
  view.height = bgr.rows;
  view.stride = static_cast<int>(bgr.step[0]);
  view.data = bgr.data;
  (void)pipeline.process(view, meta.head);
  const hal::CameraPose pose = hal::CameraPose::from_head(meta.mount, meta.head);
  const DegradeProfile& level = config.degrade[0];
  if (target == HogTarget::kBall) {
    BwBallDetector detector(config.bw_ball);
    BallList list;
    detector.detect(pipeline.classes(), view, meta.intrinsics, pose, level.ball_stride, nullptr, 0, {}, list);
    for (const BallCandidate& c : detector.candidates()) {
      out.push_back({ball_window(config.bw_ball, HogParams::ball(), c.centre, c.radius), c.centre, c.radius});
    }
  } else {
    // Unverified, the detector reports every candidate (up to kMaxRobots, nearest first), at the
    // pipeline's robot stride.
    RobotDetector detector(config.robot);
    RobotList list;
    detector.detect(pipeline.classes(), view, meta.intrinsics, pose, 2 * level.ball_stride, nullptr, 0, {}, list);
    for (std::size_t i = 0; i < list.count; ++i) {
      const RobotDetection& r = list.robots[i];
      out.push_back({robot_window(config.robot, HogParams::robot(), r.foot, r.height), r.foot, r.height});
    }
  }
  return out;
}

}  // namespace ringlet::vision::train
