#include "class_drawing.hpp"

#include <array>
#include <iostream>

#include <opencv2/imgcodecs.hpp>

namespace ringlet::vision::tools {

cv::Mat draw_classes(const cv::Mat& bgr, const ClassImage& classes) {
  cv::Mat out = bgr.clone();
  if (bgr.type() != CV_8UC3 || bgr.cols != classes.width() || bgr.rows != classes.height()) return out;
  // BGR paint per class; other is the picture darkened, so what is not field/line/ball stays visible.
  constexpr std::array<std::array<int, 3>, kColourClassCount> kPaint{{{0, 0, 0}, {40, 200, 40}, {255, 255, 255}, {0, 140, 255}}};
  const int step = classes.step();
  for (int y = 0; y < out.rows; ++y) {
    auto* row = out.ptr<std::uint8_t>(y);
    if (y < classes.first_row()) {
      for (int x = 0; x < out.cols * 3; ++x) row[x] = static_cast<std::uint8_t>(row[x] / 2);  // not classified
      continue;
    }
    const int sy = classes.first_row() + (y - classes.first_row()) / step * step;
    for (int x = 0; x < out.cols; ++x) {
      const ColourClass c = classes.at(x / step * step, sy);
      std::uint8_t* p = row + 3 * x;
      if (c == ColourClass::kOther) {
        for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(p[k] / 4);
        continue;
      }
      const auto& paint = kPaint[static_cast<std::size_t>(c)];
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((p[k] + 3 * paint[static_cast<std::size_t>(k)]) / 4);
    }
  }
  return out;
}

bool write_class_image(const std::filesystem::path& file, const cv::Mat& bgr, const ClassImage& classes, const char* tool) {
  bool written = false;
  try {
    written = cv::imwrite(file.string(), draw_classes(bgr, classes));
  } catch (const cv::Exception& e) {
    std::cerr << tool << ": " << file.string() << ": " << e.what() << "\n";
  }
  if (!written) {
    std::cerr << tool << ": " << file.string()
              << ": cannot write the class image (the extension picks the format: .png, .jpg)\n";
  }
  return written;
}

}  // namespace ringlet::vision::tools
