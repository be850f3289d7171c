// The ball detector's proposals in a dataset frame (proposals.hpp).
#include "proposals.hpp"

#include "dataset_frame.hpp"
#include "ringlet/vision/bw_ball.hpp"
#include "ringlet/vision/pipeline.hpp"

namespace ringlet::vision::train {

std::vector<Proposal> ball_proposals(const std::filesystem::path& frame_json, const cv::Mat& bgr) {
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
  BwBallDetector detector(config.bw_ball);
  BallList list;
  detector.detect(pipeline.classes(), view, meta.intrinsics, pose, config.degrade[0].ball_stride, nullptr, 0, {}, list);
  const HogParams hog = HogParams::ball();
  for (const BallCandidate& c : detector.candidates()) {
    out.push_back({ball_window(config.bw_ball, hog, c.centre, c.radius), c.centre, c.radius});
  }
  return out;
}

}  // namespace ringlet::vision::train
