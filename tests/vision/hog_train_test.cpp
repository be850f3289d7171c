// ringlet-train-hog's training: a model trained with OpenCV's ml::SVM on our HOG features, saved
// and loaded again, scores held-out windows exactly as OpenCV's own decision function does
// (within 1e-4), separates them, and comes out bit-identical for the same seed. The dataset
// reader names the file and the field it misses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "ringlet/vision/hog_svm.hpp"
#include "run_command.hpp"
#include "samples.hpp"
#include "temp_dir.hpp"
#include "trainer.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::train {
namespace {

TrainConfig small_config(HogTarget t) {
  TrainConfig c;
  c.target = t;
  c.seed = 5;
  c.jitter = 2;
  c.negatives_per_frame = 6;
  c.hard_rounds = 1;
  c.hard_tries_per_frame = 20;
  c.hard_per_frame = 3;
  return c;
}

void round_trip(HogTarget target) {
  const auto frames = synthetic_frames(target, 5, 60);
  const TrainResult r = train_hog(frames, {}, small_config(target));
  ASSERT_TRUE(r.svm);
  const ringlet::test::TempDir tmp("ringlet_hog_train");
  const auto path = tmp / (std::string(to_string(target)) + ".hog");
  ASSERT_EQ(r.model.save(path), "");
  const HogSvmLoad loaded = HogSvm::load(path);
  ASSERT_TRUE(loaded.model.has_value()) << loaded.error;
  const HogSvm& model = *loaded.model;
  HogClassifier ours(model);

  // Held-out windows: other synthetic frames (another seed), true and random windows.
  const auto test_frames = synthetic_frames(target, 77, 20);
  std::vector<std::uint8_t> patch;
  HogExtractor hog(model.params());
  std::vector<float> f(hog.feature_length());
  int windows = 0, correct = 0;
  double worst = 0.0;
  for (const LabelledFrame& fr : test_frames) {
    std::vector<std::pair<WindowPlacement, bool>> windows_here;
    for (const Box& b : fr.objects) windows_here.emplace_back(truth_window(target, model.params(), b), true);
    for (int k = 0; k < 6; ++k) {
      const Box implied{40.0 * k, 30.0 + 20.0 * k, 30.0, 30.0 + 10.0 * k};
      bool clear = true;
      for (const Box& b : fr.objects) clear = clear && overlap(implied, b) < 0.1;
      if (clear) windows_here.emplace_back(truth_window(target, model.params(), implied), false);
    }
    for (const auto& [w, positive] : windows_here) {
      cut_patch(fr.gray, w, model.params(), patch);
      ASSERT_TRUE(hog.compute(patch, f));
      const double mine = ours.score_patch(patch);
      cv::Mat row(1, static_cast<int>(f.size()), CV_32F, f.data());
      const double theirs =
          r.opencv_sign * static_cast<double>(r.svm->predict(row, cv::noArray(), cv::ml::StatModel::RAW_OUTPUT));
      worst = std::max(worst, std::abs(mine - theirs));
      EXPECT_NEAR(mine, theirs, 1e-4);
      ++windows;
      correct += ((mine >= model.threshold()) == positive) ? 1 : 0;
    }
  }
  std::printf("%s: %d held-out windows, max |ours - OpenCV| %.2e, %d classified correctly\n", to_string(target), windows,
              worst, correct);
  EXPECT_GT(windows, 60);
  EXPECT_GE(correct, windows * 9 / 10);
}

TEST(HogTrain, BallModelRoundTripMatchesOpenCv) { round_trip(HogTarget::kBall); }
TEST(HogTrain, RobotModelRoundTripMatchesOpenCv) { round_trip(HogTarget::kRobot); }

TEST(HogTrain, SameSeedSameModel) {
  const auto frames = synthetic_frames(HogTarget::kBall, 3, 30);
  const TrainResult a = train_hog(frames, {}, small_config(HogTarget::kBall));
  const TrainResult b = train_hog(synthetic_frames(HogTarget::kBall, 3, 30), {}, small_config(HogTarget::kBall));
  EXPECT_EQ(a.model.serialise(), b.model.serialise());
  TrainConfig other = small_config(HogTarget::kBall);
  other.seed = 6;
  EXPECT_NE(train_hog(frames, {}, other).model.serialise(), a.model.serialise());
}

class DatasetDir : public ::testing::Test {
 protected:
  void write(const std::string& name, const std::string& text) { std::ofstream(dir_ / name) << text; }
  std::string error(HogTarget t) {
    try {
      (void)load_dataset(dir_, t, 0.5, 0);
    } catch (const tools::ToolError& e) {
      return e.what();
    }
    return "";
  }
  ringlet::test::TempDir tmp_{"ringlet_hog_dataset"};
  const std::filesystem::path& dir_ = tmp_.path();
};

TEST_F(DatasetDir, NamesTheFileAndTheMissingField) {
  EXPECT_NE(error(HogTarget::kBall).find("no frame_*.json files"), std::string::npos);
  write("frame_0000.json", R"({"image": "frame_0000.png"})");
  const std::string e = error(HogTarget::kRobot);
  EXPECT_NE(e.find("frame_0000.json: no \"robots\" array"), std::string::npos) << e;
  write("frame_0000.json", R"({"image": "frame_0000.png", "balls": [{"box": [1, 2, 3]}]})");
  EXPECT_NE(error(HogTarget::kBall).find("frame_0000.json: balls[0].box: expected [x, y, w, h]"), std::string::npos);
  write("frame_0000.json", R"({"image": "frame_0000.png", "balls": [{"box": [1, 2, 0, 4]}]})");
  EXPECT_NE(error(HogTarget::kBall).find("width and height must be positive"), std::string::npos);
  write("frame_0000.json", R"({"balls": []})");
  EXPECT_NE(error(HogTarget::kBall).find("missing \"image\""), std::string::npos);
  write("frame_0000.json", R"({"image": "frame_0000.png", "balls": []})");
  EXPECT_NE(error(HogTarget::kBall).find("frame_0000.png: cannot read image"), std::string::npos) << error(HogTarget::kBall);
  write("frame_0000.json", "{not json");
  EXPECT_NE(error(HogTarget::kBall).find("not valid JSON"), std::string::npos);
}

// ringlet-dataset (generator version 3) writes boxes as pixel edges [u0, v0, u1, v1] and null for an
// object behind the camera: read as such, not as [x, y, w, h]. A ball's share inside the image
// counts towards how visible it is.
TEST_F(DatasetDir, ReadsTheDatasetsEdgeBoxes) {
  cv::imwrite((dir_ / "frame_0000.png").string(), cv::Mat(48, 64, CV_8UC3, cv::Scalar(40, 120, 40)));
  write("frame_0000.json", R"({"image": "frame_0000.png", "generator_version": 3, "balls": [)"
                           R"({"box": [10, 20, 30, 60], "visible_fraction": 1}, {"box": null, "visible_fraction": 0},)"
                           R"({"box": [1, 2, 5, 9], "visible_fraction": 0.2}, {"box": [40, 2, 80, 42], "visible_fraction": 1, "in_image_fraction": 0.4}]})");
  const std::vector<LabelledFrame> frames = load_dataset(dir_, HogTarget::kBall, 0.5, 0);
  ASSERT_EQ(frames.size(), 1U);
  ASSERT_EQ(frames[0].objects.size(), 1U);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].x, 10.0);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].y, 20.0);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].w, 20.0);
  EXPECT_DOUBLE_EQ(frames[0].objects[0].h, 40.0);
  // Too hidden (20 %), and a ball mostly outside the image (40 % of its disc inside): not positives.
  ASSERT_EQ(frames[0].ignore.size(), 2U);
  EXPECT_DOUBLE_EQ(frames[0].ignore[0].w, 4.0);
  EXPECT_DOUBLE_EQ(frames[0].ignore[1].w, 40.0);
  write("frame_0000.json", R"({"image": "frame_0000.png", "generator_version": 3, "balls": [{"box": [10, 20, 5, 60]}]})");
  EXPECT_NE(error(HogTarget::kBall).find("width and height must be positive"), std::string::npos);
}

// The trainer sees the detector's own proposals: load_dataset fills them for ringlet-dataset
// frames (which carry their camera), clutter included, and the visible balls are among them.
TEST(HogTrainProposals, DatasetFramesCarryTheDetectorsProposals) {
  const ringlet::test::TempDir tmp("ringlet_proposals");
  const auto run = ringlet::test::run_command(std::string(RINGLET_DATASET_BIN) + " --seed 7 -n 6 -q --no-labels -o " +
                                              tmp.path().string() + " 2>&1");
  ASSERT_EQ(run.rc, 0) << run.out;
  const std::vector<LabelledFrame> frames = load_dataset(tmp.path(), HogTarget::kBall, 0.5, 0);
  ASSERT_EQ(frames.size(), 6U);
  std::size_t proposals = 0, balls = 0, proposed = 0;
  for (const LabelledFrame& f : frames) {
    proposals += f.proposals.size();
    balls += f.objects.size();
    for (const Box& o : f.objects) {
      const double r = 0.25 * (o.w + o.h);
      for (const Proposal& p : f.proposals) {
        if (std::hypot(p.at.u - (o.x + 0.5 * o.w), p.at.v - (o.y + 0.5 * o.h)) <= std::max(0.5 * r, 4.0)) {
          ++proposed;
          break;
        }
      }
    }
  }
  ASSERT_GT(balls, 0U);
  EXPECT_GT(proposals, balls) << "clutter is proposed too: the negatives the classifier must learn";
  EXPECT_GE(2 * proposed, balls) << "most visible balls are proposed";
  std::size_t robot_proposals = 0;
  for (const LabelledFrame& f : load_dataset(tmp.path(), HogTarget::kRobot, 0.5, 0)) robot_proposals += f.proposals.size();
  EXPECT_GT(robot_proposals, 0U) << "the robot detector proposes too";
}

}  // namespace
}  // namespace ringlet::vision::train
