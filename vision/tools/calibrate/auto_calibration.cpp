#include "auto_calibration.hpp"

#include <cstdio>
#include <memory>

#include <opencv2/core.hpp>

#include "class_drawing.hpp"
#include "ringlet/hal/camera_geometry.hpp"
#include "ringlet/hal/yuv.hpp"
#include "ringlet/vision/class_image.hpp"
#include "ringlet/vision/horizon.hpp"

namespace ringlet::vision::tools {

namespace {

std::string percent(double f) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f%%", 100.0 * f);
  return text;
}

}  // namespace

AutoCalibration auto_calibrate(const std::vector<std::string>& photos, const AutoOptions& o) {
  if (photos.empty()) throw ToolError("--auto: no photos given (ringlet-vision-calibrate --auto PHOTO.jpg... --out TABLE)");
  const hal::CameraIntrinsics k = o.camera.intrinsics();
  const hal::CameraPose pose = hal::CameraPose::from_head(o.camera.camera_mount(), o.camera.head());
  std::vector<int> first_row(static_cast<std::size_t>(k.width));
  const int horizon = horizon_rows(k, pose, 2, first_row);
  AutoCalibration out;
  std::vector<LabelledSample> samples;
  std::vector<cv::Mat> pictures;
  std::vector<ClassImage> classes;
  const auto adaptive = std::make_unique<AdaptiveClassifier>(o.adaptive);
  for (const std::string& photo : photos) {
    const cv::Mat bgr = load_bgr(photo, k.width, k.height);
    if (horizon >= k.height) {
      throw ToolError(photo + ": no ground below the horizon at this head pose (give --pitch/--yaw of the photo)");
    }
    // As the robot's camera delivers it: YUYV, pixel pairs sharing chroma.
    std::vector<std::uint8_t> yuyv(static_cast<std::size_t>(k.width) * static_cast<std::size_t>(k.height) * 2U);
    for (int y = 0; y < k.height; ++y) {
      hal::bgr_row_to_yuyv(bgr.ptr<std::uint8_t>(y), yuyv.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(k.width) * 2U,
                           k.width);
    }
    hal::FrameView view;
    view.format = hal::PixelFormat::kYuyv;
    view.width = k.width;
    view.height = k.height;
    view.stride = 2 * k.width;
    view.data = yuyv.data();
    AutoPhoto report;
    report.photo = photo;
    report.estimate = FieldColourEstimator::measure(view, first_row, o.adaptive);
    const FieldColourEstimate& e = report.estimate;
    if (!e.valid) {
      throw ToolError(photo + ": no dominant field colour below the horizon: the largest chroma cluster (Y " +
                      std::to_string(e.y) + " U " + std::to_string(e.u) + " V " + std::to_string(e.v) + ") holds " +
                      std::to_string(e.field_samples) + " of " + std::to_string(e.samples) +
                      " samples; a field needs a green-ish cluster (U <= " + std::to_string(o.adaptive.field_max_u) +
                      ", V <= " + std::to_string(o.adaptive.field_max_v) + ", (128 - U) + (128 - V) >= " +
                      std::to_string(o.adaptive.field_min_chroma) + ") with at least " +
                      percent(o.adaptive.min_field_fraction) + " of them (check the photo, --pitch and --yaw)");
    }
    adaptive->build(e, k.width, k.height);
    ClassImage& c = classes.emplace_back(k.width, k.height);
    (void)c.classify(view, *adaptive, horizon, 1);
    std::array<long, kColourClassCount> counts{};
    for (int y = 0; y < k.height; ++y) {
      for (int x = 0; x < k.width; ++x) {
        if (y < first_row[static_cast<std::size_t>(x)]) continue;
        const ColourClass cls = c.at(x, y);
        ++counts[static_cast<std::size_t>(cls)];
        ++report.classified;
        if (y % o.stride == 0 && (x + y / o.stride) % o.stride == 0) {
          const std::uint8_t* pair = yuyv.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(k.width) * 2U +
                                     static_cast<std::size_t>(x / 2) * 4U;
          samples.push_back({{pair[x % 2 == 0 ? 0 : 2], pair[1], pair[3]}, cls});
        }
      }
    }
    for (std::size_t i = 0; i < counts.size(); ++i) {
      report.fractions[i] = report.classified > 0 ? static_cast<double>(counts[i]) / report.classified : 0.0;
    }
    pictures.push_back(bgr);
    out.photos.push_back(report);
  }
  out.samples = samples.size();
  out.table = ColourTable::from_examples(samples, o.training, o.bin_bits);
  if (!o.classes_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.classes_dir, ec);
    for (std::size_t i = 0; i < out.photos.size(); ++i) {
      const auto file = o.classes_dir / (std::filesystem::path(out.photos[i].photo).stem().string() + "_classes.png");
      if (!write_class_image(file, pictures[i], classes[i], "ringlet-vision-calibrate")) {
        throw std::runtime_error(file.string() + ": cannot write the class picture");
      }
      out.photos[i].classes_image = file.string();
    }
  }
  return out;
}

std::string describe(const AutoPhoto& p) {
  const FieldColourEstimate& e = p.estimate;
  char text[512];
  std::snprintf(text, sizeof text,
                "%s: field Y %d U %d V %d (spread Y %d, UV %d), confidence %.2f; classes: field %.1f%%, line %.1f%%, "
                "ball %.1f%%, other %.1f%%",
                p.photo.c_str(), e.y, e.u, e.v, e.y_spread, e.uv_spread, e.confidence, 100.0 * p.fractions[1],
                100.0 * p.fractions[2], 100.0 * p.fractions[3], 100.0 * p.fractions[0]);
  return text;
}

nlohmann::json report_json(const AutoCalibration& c) {
  nlohmann::json photos = nlohmann::json::array();
  for (const AutoPhoto& p : c.photos) {
    const FieldColourEstimate& e = p.estimate;
    nlohmann::json j{{"photo", p.photo},
                     {"field", {{"y", e.y}, {"u", e.u}, {"v", e.v}, {"y_spread", e.y_spread}, {"uv_spread", e.uv_spread},
                                {"confidence", e.confidence}, {"samples", e.samples}, {"field_samples", e.field_samples}}},
                     {"classified_pixels", p.classified},
                     {"fractions", {{"other", p.fractions[0]}, {"field", p.fractions[1]}, {"line", p.fractions[2]},
                                    {"ball", p.fractions[3]}}}};
    if (!p.classes_image.empty()) j["classes_image"] = p.classes_image;
    photos.push_back(j);
  }
  return {{"photos", photos}, {"samples", c.samples}, {"bin_bits", c.table.bin_bits()}};
}

}  // namespace ringlet::vision::tools
