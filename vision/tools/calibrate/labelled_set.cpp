#include "labelled_set.hpp"

#include <algorithm>
#include <string>

#include <opencv2/imgcodecs.hpp>

#include "ringlet/hal/yuv.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::tools {

namespace fs = std::filesystem;

std::vector<LabelledImage> find_labelled_images(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw ToolError(dir.string() + ": not a directory");
  const std::string suffix = "_labels.png";
  std::vector<LabelledImage> out;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const std::string stem = name.substr(0, name.size() - suffix.size());
    LabelledImage image{{}, e.path()};
    for (const char* ext : {".png", ".jpg", ".jpeg", ".PNG", ".JPG"}) {
      if (fs::exists(dir / (stem + ext))) {
        image.picture = dir / (stem + ext);
        break;
      }
    }
    if (image.picture.empty()) throw ToolError(e.path().string() + ": no picture " + stem + ".png (or .jpg) next to it");
    out.push_back(std::move(image));
  }
  if (ec) throw ToolError(dir.string() + ": cannot list: " + ec.message());
  if (out.empty()) throw ToolError(dir.string() + ": no labelled images (*_labels.png next to their pictures)");
  std::sort(out.begin(), out.end(), [](const LabelledImage& a, const LabelledImage& b) { return a.labels < b.labels; });
  return out;
}

void sample_labelled_image(const LabelledImage& image, int stride, std::vector<LabelledSample>& out) {
  const cv::Mat bgr = load_bgr(image.picture);
  const cv::Mat labels = load_image(image.labels, cv::IMREAD_UNCHANGED);
  if (labels.type() != CV_8UC1) throw ToolError(image.labels.string() + ": not an 8-bit single-channel label image");
  if (labels.cols != bgr.cols || labels.rows != bgr.rows) {
    throw ToolError(image.labels.string() + ": " + std::to_string(labels.cols) + "x" + std::to_string(labels.rows) +
                    " labels for a " + std::to_string(bgr.cols) + "x" + std::to_string(bgr.rows) + " picture");
  }
  const int width = bgr.cols & ~1;  // YUYV needs pixel pairs; an odd last column is left out
  std::vector<std::uint8_t> yuyv(static_cast<std::size_t>(width) * 2U);
  for (int y = 0; y < bgr.rows; y += stride) {
    hal::bgr_row_to_yuyv(bgr.ptr<std::uint8_t>(y), yuyv.data(), width);
    const std::uint8_t* label = labels.ptr<std::uint8_t>(y);
    // Shift the start each sampled row so both pixels of a pair are sampled over the image.
    for (int x = (y / stride) % stride; x < width; x += stride) {
      const std::uint8_t c = label[x];
      if (c == kIgnoreLabel) continue;  // not labelled: neither trains nor scores
      if (c >= kColourClassCount) {
        throw ToolError(image.labels.string() + ": pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                        ") has label " + std::to_string(c) +
                        ", not a colour class (0 other, 1 field, 2 line, 3 ball) or 255 (not labelled)");
      }
      const auto pair = static_cast<std::size_t>(x / 2) * 4U;
      const std::uint8_t luma = yuyv[pair + (x % 2 == 0 ? 0U : 2U)];
      out.push_back({{luma, yuyv[pair + 1], yuyv[pair + 3]}, static_cast<ColourClass>(c)});
    }
  }
}

std::vector<LabelledSample> sample_labelled_set(const std::vector<LabelledImage>& images, int stride,
                                                const std::function<void(std::size_t, std::size_t)>& progress) {
  std::vector<LabelledSample> out;
  for (std::size_t i = 0; i < images.size(); ++i) {
    sample_labelled_image(images[i], stride, out);
    if (progress) progress(i + 1, images.size());
  }
  return out;
}

}  // namespace ringlet::vision::tools
