// The OpenCV camera backend on replays (no camera devices exist on these machines): image folders
// are delivered frame by frame, in order, converted to YUYV or BGR exactly; bad sources fail with
// the source named.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <vector>
#include <thread>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "ringlet/hal/monotonic_clock.hpp"
#include "ringlet/hal/opencv_camera.hpp"
#include "ringlet/hal/yuv.hpp"
#include "temp_dir.hpp"

namespace ringlet::hal {
namespace {

namespace fs = std::filesystem;

using ringlet::test::TempDir;

// Frame i: a gradient whose blue channel encodes i, so frames and pixels are told apart.
cv::Mat frame(int i, int width = 64, int height = 48) {
  cv::Mat m(height, width, CV_8UC3);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      m.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<std::uint8_t>(40 * i + 10), static_cast<std::uint8_t>(3 * x),
                                        static_cast<std::uint8_t>(5 * y));
    }
  }
  return m;
}

void write_frames(const fs::path& dir, int count, int width = 64, int height = 48) {
  for (int i = 0; i < count; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    ASSERT_TRUE(cv::imwrite((dir / name).string(), frame(i, width, height)));
  }
}

// Grabs until a frame with a sequence other than `last` arrives (bounded wait).
bool grab_next(OpenCvCamera& camera, FrameView& view, std::uint64_t last, bool first) {
  for (int i = 0; i < 2000; ++i) {
    if (camera.grab_latest(view) && (first || view.sequence != last)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

TEST(OpenCvCamera, ImageFolderReplaysEveryFrameInOrderAsBgr) {
  TempDir dir;
  write_frames(dir.path(), 4);
  MonotonicClock clock;
  OpenCvCamera camera({dir.path().string(), 64, 48, 30.0, PixelFormat::kBgr8}, clock);
  FrameView view;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(grab_next(camera, view, view.sequence, i == 0)) << "frame " << i;
    EXPECT_EQ(view.sequence, static_cast<std::uint64_t>(i));
    EXPECT_EQ(view.format, PixelFormat::kBgr8);
    EXPECT_EQ(view.stride, 64 * 3);
    const cv::Mat expected = frame(i);
    EXPECT_EQ(std::memcmp(view.data, expected.data, 64 * 48 * 3), 0) << "frame " << i;
  }
  for (int i = 0; i < 1000 && !camera.finished(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(camera.finished());
  EXPECT_EQ(camera.error(), "");
}

TEST(OpenCvCamera, YuyvIsTheSharedBt601Conversion) {
  TempDir dir;
  write_frames(dir.path(), 1);
  MonotonicClock clock;
  OpenCvCamera camera({dir.path().string(), 64, 48, 30.0, PixelFormat::kYuyv}, clock);
  FrameView view;
  ASSERT_TRUE(grab_next(camera, view, 0, true));
  EXPECT_EQ(view.stride, 64 * 2);
  const cv::Mat bgr = frame(0);
  for (int y = 0; y < 48; y += 7) {
    std::vector<std::uint8_t> row(64 * 2);
    bgr_row_to_yuyv(bgr.ptr<std::uint8_t>(y), row.data(), 64);
    EXPECT_EQ(std::memcmp(view.data + y * view.stride, row.data(), row.size()), 0) << "row " << y;
  }
  // And the conversion itself: white, black and pure red under BT.601 full range.
  EXPECT_EQ(bgr_to_yuv(255, 255, 255).y, 255);
  EXPECT_EQ(bgr_to_yuv(255, 255, 255).u, 128);
  EXPECT_EQ(bgr_to_yuv(0, 0, 0).y, 0);
  EXPECT_EQ(bgr_to_yuv(0, 0, 255).y, 76);   // 0.299 * 255
  EXPECT_EQ(bgr_to_yuv(0, 0, 255).v, 255);  // 128 + 0.5 * 255, clamped
}

TEST(OpenCvCamera, BadSourcesAreRefusedByName) {
  MonotonicClock clock;
  TempDir empty;
  try {
    OpenCvCamera camera({empty.path().string()}, clock);
    FAIL() << "no error";
  } catch (const CameraError& e) {
    EXPECT_NE(std::string(e.what()).find(empty.path().string() + ": no .png, .jpg or .jpeg images"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(OpenCvCamera({"/nonexistent/video.mp4"}, clock), CameraError);
  EXPECT_THROW(OpenCvCamera({empty.path().string(), 63, 48}, clock), CameraError);  // odd width: no YUYV
}

// The first decodable image is checked at start-up: a folder of the wrong size is a start-up
// error. A later frame of another size stops the replay with an error.
TEST(OpenCvCamera, WrongSizeFramesAreErrors) {
  MonotonicClock clock;
  TempDir dir;
  write_frames(dir.path(), 1, 32, 24);  // smaller than configured
  try {
    OpenCvCamera camera({dir.path().string(), 64, 48}, clock);
    FAIL() << "no error";
  } catch (const CameraError& e) {
    EXPECT_NE(std::string(e.what()).find(dir.path().string() + ": frame_0000.png is 32x24, expected 64x48"),
              std::string::npos) << e.what();
  }
  TempDir mixed;
  write_frames(mixed.path(), 1);
  ASSERT_TRUE(cv::imwrite((mixed.path() / "frame_0001.png").string(), frame(1, 32, 24)));
  OpenCvCamera camera({mixed.path().string(), 64, 48}, clock);
  FrameView view;
  ASSERT_TRUE(grab_next(camera, view, 0, true));
  for (int i = 0; i < 1000 && camera.error().empty(); ++i) {
    (void)camera.grab_latest(view);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  EXPECT_NE(camera.error().find("frame 1 is 32x24, expected 64x48"), std::string::npos) << camera.error();
}

// A folder of garbage used to start, deliver nothing and say nothing (the firmware then ran
// without a single vision frame): now it is refused at start-up, naming the first file and why.
TEST(OpenCvCamera, FolderWithNoDecodableImageIsRefusedAtStartUp) {
  MonotonicClock clock;
  TempDir broken;
  std::ofstream(broken.path() / "frame_0000.png") << "not a png";
  std::ofstream(broken.path() / "frame_0001.jpg") << "\xFF\xD8\xFF\xD9";  // a JPEG that ends at once
  fs::create_directories(broken.path() / "frame_0002.png");           // a directory: not listed
  try {
    OpenCvCamera camera({broken.path().string(), 64, 48}, clock);
    FAIL() << "no error";
  } catch (const CameraError& e) {
    EXPECT_NE(std::string(e.what()).find(broken.path().string() +
                                         ": none of the 2 image files can be decoded (the first: frame_0000.png: "
                                         "cannot decode image: not a PNG or JPEG image)"),
              std::string::npos) << e.what();
  }
}

// Undecodable files among good ones are skipped, counted and reported (one warning each, then a
// summary naming the first); the good frames are all delivered, in order.
TEST(OpenCvCamera, UndecodableFilesAreSkippedCountedAndReported) {
  MonotonicClock clock;
  TempDir dir;
  write_frames(dir.path(), 3);
  std::ofstream(dir.path() / "frame_0000a.png") << "garbage";
  {
    // A PNG header claiming 40000 x 40000: refused before OpenCV would allocate for it.
    const unsigned char huge[] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                  0, 0, 0x9C, 0x40, 0, 0, 0x9C, 0x40, 8, 2, 0, 0, 0};
    std::ofstream(dir.path() / "frame_0001a.png", std::ios::binary).write(reinterpret_cast<const char*>(huge), sizeof huge);
  }
  {
    // A JPEG cut short: libjpeg would decode it with grey rows and a warning only.
    std::vector<std::uint8_t> jpeg;
    ASSERT_TRUE(cv::imencode(".jpg", frame(1), jpeg));
    std::ofstream(dir.path() / "frame_0001b.jpg", std::ios::binary)
        .write(reinterpret_cast<const char*>(jpeg.data()), static_cast<std::streamsize>(jpeg.size() * 3 / 5));
  }
  std::vector<std::string> warnings;
  std::mutex mutex;
  OpenCvCamera camera({dir.path().string(), 64, 48, 30.0, PixelFormat::kBgr8}, clock, [&](const std::string& w) {
    const std::lock_guard lock(mutex);
    warnings.push_back(w);
  });
  FrameView view;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(grab_next(camera, view, view.sequence, i == 0)) << "frame " << i;
    EXPECT_EQ(view.sequence, static_cast<std::uint64_t>(i));
    const cv::Mat expected = frame(i);
    EXPECT_EQ(std::memcmp(view.data, expected.data, 64 * 48 * 3), 0) << "frame " << i;
  }
  for (int i = 0; i < 1000 && !camera.finished(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(camera.finished());
  EXPECT_EQ(camera.error(), "");
  EXPECT_EQ(camera.undecodable_files(), 3U);
  const std::lock_guard lock(mutex);
  ASSERT_EQ(warnings.size(), 4U);
  const std::string folder = dir.path().string() + ": ";
  EXPECT_EQ(warnings[0], folder + "frame_0000a.png: cannot decode image: not a PNG or JPEG image; skipped");
  EXPECT_EQ(warnings[1], folder + "frame_0001a.png: cannot decode image: PNG image is 40000x40000 = 1600000000 "
                                  "pixels, more than the limit of 16777216; skipped");
  EXPECT_EQ(warnings[2], folder + "frame_0001b.jpg: cannot decode image: truncated JPEG (no end-of-image marker); skipped");
  EXPECT_EQ(warnings[3], folder + "replay ended: 3 of 6 image files could not be decoded and were skipped (the "
                                  "first: frame_0000a.png: cannot decode image: not a PNG or JPEG image)");
}

}  // namespace
}  // namespace ringlet::hal
