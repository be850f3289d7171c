#pragma once
// The JSON record written next to each dataset image: what was rendered and its ground truth.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "ringlet/sim_hal/camera_renderer.hpp"

namespace ringlet::sim_hal::dataset {

struct FrameRecord {
  int index = 0;
  std::string image;      // file name of the picture, next to the JSON file
  std::string format;     // "png" (BGR) or "yuyv" (raw YUYV bytes)
  std::uint64_t seed = 0;
  int generator_version = 0;      // ringlet-dataset's: the same (version, seed, index) is the same frame
  std::vector<Circle> occluders;  // robots added close to the camera for this frame only
  std::vector<Circle> added_robots;  // NAO robots placed 0.5-6 m away for this frame only
  int jpeg_quality = 0;           // the picture went through JPEG at this quality (0: it did not)
};

[[nodiscard]] nlohmann::ordered_json frame_json(const FrameRecord& record, const CameraRenderer& renderer);

}  // namespace ringlet::sim_hal::dataset
