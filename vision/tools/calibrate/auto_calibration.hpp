#pragma once
// ringlet-vision-calibrate --auto: a colour table from a handful of unlabelled photos. Each photo
// is labelled by the adaptive classifier (vision/field_colour.hpp: field = the dominant chroma
// cluster below the horizon, line = bright unsaturated pixels relative to it, ball = the orange
// box, everything else other); the labelled pixels of all photos then train the table as
// labelled examples do. A photo without a dominant field colour is refused, naming it.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "ringlet/vision/colour_table.hpp"
#include "ringlet/vision/field_colour.hpp"
#include "vision_io.hpp"

namespace ringlet::vision::tools {

struct AutoPhoto {
  std::string photo;
  FieldColourEstimate estimate;
  std::array<double, kColourClassCount> fractions{};  // of the classified pixels below the horizon
  int classified = 0;                                 // pixels classified (below the horizon)
  std::string classes_image;                          // written picture of the classes, if any
};

struct AutoCalibration {
  ColourTable table;
  std::vector<AutoPhoto> photos;
  std::size_t samples = 0;
};

struct AutoOptions {
  CameraOptions camera;
  AdaptiveColourParams adaptive;
  int stride = 4;
  int bin_bits = ColourTable::kDefaultBinBits;
  ExampleTrainingOptions training;
  std::filesystem::path classes_dir;  // empty: no class pictures
};

/// ToolError (exit 2) naming the photo: unreadable, wrong size, no ground below the horizon, or
/// no dominant field colour; none of the photos: "no photos". Class pictures are written only
/// after every photo passed.
[[nodiscard]] AutoCalibration auto_calibrate(const std::vector<std::string>& photos, const AutoOptions& options);

[[nodiscard]] std::string describe(const AutoPhoto& photo);
[[nodiscard]] nlohmann::json report_json(const AutoCalibration& calibration);

}  // namespace ringlet::vision::tools
