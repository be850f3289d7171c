#include "ringlet/hal/opencv_camera.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstring>
#include <iostream>
#include <mutex>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include "ringlet/hal/image_header.hpp"
#include "ringlet/hal/read_file.hpp"
#include "ringlet/hal/yuv.hpp"

namespace ringlet::hal {
namespace {

bool is_device(const std::string& source) {
  return source.rfind("/dev/video", 0) == 0 ||
         (!source.empty() && std::all_of(source.begin(), source.end(), [](char c) { return c >= '0' && c <= '9'; }));
}

std::vector<std::filesystem::path> image_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    auto ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png" || ext == ".jpg" || ext == ".jpeg") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// An image file as BGR (empty, with `why` naming the file, when it cannot be read or decoded):
/// bounded read, header check, then OpenCV, whose exceptions become `why` too.
cv::Mat decode_image_file(const std::filesystem::path& path, std::string& why) {
  const FileRead read = read_file(path, "image", kMaxBinaryFileBytes);
  if (!read.ok()) {
    why = read.error;
    return {};
  }
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size());
  const ImageProbe probe = probe_image(bytes);
  if (!probe.ok()) {
    why = path.filename().string() + ": cannot decode image: " + probe.error;
    return {};
  }
  // libjpeg decodes a JPEG cut short with grey rows and only a warning: refuse it here.
  if (const std::string cut = image_truncation(bytes, probe.header->format); !cut.empty()) {
    why = path.filename().string() + ": cannot decode image: " + cut;
    return {};
  }
  cv::Mat bgr;
  try {
    // imdecode only reads the buffer (the const_cast is its C-style API).
    bgr = cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data())),
                       cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    why = path.filename().string() + ": cannot decode image: the " + to_string(probe.header->format) +
          " decoder failed (" + e.err + ")";
    return {};
  }
  if (bgr.empty()) {
    why = path.filename().string() + ": cannot decode image: corrupt or truncated " + to_string(probe.header->format) +
          " data";
  }
  return bgr;
}

int bytes_per_pixel(PixelFormat f) { return f == PixelFormat::kBgr8 ? 3 : (f == PixelFormat::kYuyv ? 2 : 1); }

// Three buffers shared by one writer (the capture thread) and one reader (grab_latest): the
// writer fills its back buffer and swaps it with the published one; the reader swaps the
// published one with its front buffer when a fresh frame is there. One atomic word, no locks.
class TripleBuffer {
 public:
  static constexpr unsigned kFresh = 4;

  /// Writer: publishes the back buffer, returns the index of the new back buffer.
  unsigned publish(unsigned back) noexcept {
    return state_.exchange(back | kFresh, std::memory_order_acq_rel) & 3U;
  }
  /// Reader: swaps in the published buffer if it is fresh; returns the (possibly new) front.
  unsigned take(unsigned front, bool& fresh) noexcept {
    fresh = (state_.load(std::memory_order_acquire) & kFresh) != 0;
    if (!fresh) return front;
    return state_.exchange(front, std::memory_order_acq_rel) & 3U;
  }
  /// Writer (replays): has the reader taken the last published frame?
  [[nodiscard]] bool consumed() const noexcept { return (state_.load(std::memory_order_acquire) & kFresh) == 0; }

 private:
  std::atomic<unsigned> state_{1};  // published index 1, not fresh; writer starts on 0, reader on 2
};

}  // namespace

struct OpenCvCamera::Impl {
  OpenCvCameraConfig config;
  const Clock& clock;
  CameraWarningSink warn_sink;
  bool replay = false;
  cv::VideoCapture capture;                    // devices and video files
  std::vector<std::filesystem::path> images;   // image folders
  std::size_t stride = 0;
  std::array<std::vector<std::uint8_t>, 3> buffers;
  std::array<Nanos, 3> stamps{};
  std::array<std::uint64_t, 3> sequences{};
  TripleBuffer triple;
  unsigned front = 2;
  bool have_frame = false;
  std::atomic<bool> stop{false};
  std::atomic<bool> source_done{false};
  mutable std::mutex error_mutex;  // error text only; never taken by grab_latest
  std::string error;
  std::atomic<std::size_t> undecodable{0};
  std::string first_undecodable;  // capture thread only
  std::thread thread;

  /// Per-file warnings before the rest are only counted (and summed up at the end).
  static constexpr std::size_t kNamedWarnings = 10;

  Impl(const OpenCvCameraConfig& c, const Clock& k, CameraWarningSink w) : config(c), clock(k), warn_sink(std::move(w)) {}

  void fail(const std::string& what) {
    const std::lock_guard lock(error_mutex);
    if (error.empty()) error = config.source + ": " + what;
  }

  void warn(const std::string& what) const {
    const std::string line = config.source + ": " + what;
    if (warn_sink) {
      warn_sink(line);
    } else {
      std::cerr << "ringlet camera: warning: " + line + "\n" << std::flush;
    }
  }

  void skipped(const std::string& why) {
    const std::size_t n = undecodable.fetch_add(1, std::memory_order_relaxed) + 1;
    if (n == 1) first_undecodable = why;
    if (n <= kNamedWarnings) warn(why + "; skipped");
    if (n == kNamedWarnings) warn("further undecodable files are skipped and counted without a warning each");
  }

  void replay_summary() const {
    const std::size_t n = undecodable.load(std::memory_order_relaxed);
    if (n == 0) return;
    warn("replay ended: " + std::to_string(n) + " of " + std::to_string(images.size()) +
         " image files could not be decoded and were skipped (the first: " + first_undecodable + ")");
  }

  // Reads the next frame of the source as BGR; false at the end or on error. Image folders skip
  // files that cannot be decoded (counted and reported).
  bool next(cv::Mat& bgr, std::size_t& image_index) {
    if (!images.empty()) {
      while (image_index < images.size()) {
        std::string why;
        bgr = decode_image_file(images[image_index++], why);
        if (!bgr.empty()) return true;
        skipped(why);
        if (stop.load(std::memory_order_relaxed)) return false;
      }
      replay_summary();
      return false;
    }
    return capture.read(bgr) && !bgr.empty();
  }

  /// Start-up check of an image folder: some file must decode, and the first that does must
  /// have the configured size. The replay itself starts from the first file again.
  void check_folder() const {
    std::string first_why;
    for (const auto& path : images) {
      std::string why;
      const cv::Mat bgr = decode_image_file(path, why);
      if (bgr.empty()) {
        if (first_why.empty()) first_why = why;
        continue;
      }
      if (bgr.cols != config.width || bgr.rows != config.height) {
        throw CameraError(config.source + ": " + path.filename().string() + " is " + std::to_string(bgr.cols) + "x" +
                          std::to_string(bgr.rows) + ", expected " + std::to_string(config.width) + "x" +
                          std::to_string(config.height));
      }
      return;
    }
    throw CameraError(config.source + ": none of the " + std::to_string(images.size()) +
                      " image files can be decoded (the first: " + first_why + ")");
  }

  void store(const cv::Mat& bgr, unsigned slot) {
    auto* out = buffers[slot].data();
    for (int row = 0; row < config.height; ++row) {
      const auto* in = bgr.ptr<std::uint8_t>(row);
      auto* dst = out + static_cast<std::size_t>(row) * stride;
      if (config.format == PixelFormat::kYuyv) {
        bgr_row_to_yuyv(in, dst, config.width);
      } else {
        std::memcpy(dst, in, static_cast<std::size_t>(config.width) * 3);
      }
    }
  }

  void run() {
    using namespace std::chrono_literals;
    unsigned back = 0;
    std::size_t image_index = 0;
    std::uint64_t sequence = 0;
    cv::Mat bgr;
    while (!stop.load(std::memory_order_relaxed)) {
      if (!next(bgr, image_index)) {
        if (!replay) fail("the device stopped delivering frames");
        break;
      }
      if (bgr.cols != config.width || bgr.rows != config.height || bgr.type() != CV_8UC3) {
        fail("frame " + std::to_string(sequence) + " is " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) +
             ", expected " + std::to_string(config.width) + "x" + std::to_string(config.height) + " colour");
        break;
      }
      store(bgr, back);
      stamps[back] = clock.now();
      sequences[back] = sequence++;
      // A replay hands out every frame: wait until the reader took the previous one.
      while (replay && !triple.consumed() && !stop.load(std::memory_order_relaxed)) std::this_thread::sleep_for(1ms);
      back = triple.publish(back);
    }
    source_done.store(true, std::memory_order_release);
  }
};

OpenCvCamera::OpenCvCamera(const OpenCvCameraConfig& config, const Clock& clock, CameraWarningSink warn)
    : impl_(std::make_unique<Impl>(config, clock, std::move(warn))) {
  auto& d = *impl_;
  if (config.width <= 0 || config.height <= 0 || config.width % 2 != 0) {
    throw CameraError(config.source + ": frame size must be positive with an even width, got " +
                      std::to_string(config.width) + "x" + std::to_string(config.height));
  }
  if (config.format != PixelFormat::kYuyv && config.format != PixelFormat::kBgr8) {
    throw CameraError(config.source + ": the OpenCV camera delivers YUYV or BGR8");
  }
  if (is_device(config.source)) {
    const bool numeric = config.source.rfind("/dev/", 0) != 0;
    if (numeric ? !d.capture.open(std::stoi(config.source), cv::CAP_V4L2) : !d.capture.open(config.source, cv::CAP_V4L2)) {
      throw CameraError(config.source + ": cannot open the V4L2 device");
    }
    d.capture.set(cv::CAP_PROP_FOURCC, cv::VideoWriter::fourcc('Y', 'U', 'Y', 'V'));
    d.capture.set(cv::CAP_PROP_FRAME_WIDTH, config.width);
    d.capture.set(cv::CAP_PROP_FRAME_HEIGHT, config.height);
    d.capture.set(cv::CAP_PROP_FPS, config.fps);
  } else if (std::filesystem::is_directory(config.source)) {
    d.replay = true;
    d.images = image_files(config.source);
    if (d.images.empty()) throw CameraError(config.source + ": no .png, .jpg or .jpeg images in the folder");
    d.check_folder();
  } else {
    d.replay = true;
    if (!std::filesystem::exists(config.source)) throw CameraError(config.source + ": no such file or folder");
    if (!d.capture.open(config.source)) throw CameraError(config.source + ": cannot open as a video");
  }
  d.stride = static_cast<std::size_t>(config.width * bytes_per_pixel(config.format));
  for (auto& b : d.buffers) b.assign(d.stride * static_cast<std::size_t>(config.height), 0);
  d.thread = std::thread([&d] { d.run(); });
}

OpenCvCamera::~OpenCvCamera() {
  impl_->stop.store(true);
  if (impl_->thread.joinable()) impl_->thread.join();
}

bool OpenCvCamera::grab_latest(FrameView& out) noexcept {
  auto& d = *impl_;
  bool fresh = false;
  d.front = d.triple.take(d.front, fresh);
  d.have_frame = d.have_frame || fresh;
  if (!d.have_frame) return false;
  out.capture_time = d.stamps[d.front];
  out.sequence = d.sequences[d.front];
  out.format = d.config.format;
  out.width = d.config.width;
  out.height = d.config.height;
  out.stride = static_cast<int>(d.stride);
  out.data = d.buffers[d.front].data();
  return true;
}

bool OpenCvCamera::finished() const noexcept {
  return impl_->replay && impl_->source_done.load(std::memory_order_acquire) && impl_->triple.consumed();
}

std::string OpenCvCamera::error() const {
  const std::lock_guard lock(impl_->error_mutex);
  return impl_->error;
}

std::size_t OpenCvCamera::undecodable_files() const noexcept {
  return impl_->undecodable.load(std::memory_order_relaxed);
}

}  // namespace ringlet::hal
