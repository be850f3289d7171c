#include "frame_identity.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include "vision_io.hpp"

namespace ringlet::vision::evaluate {

namespace {

/// "0-39, 45, 50-59" from sorted, distinct indices.
std::string ranges_text(const std::vector<std::uint64_t>& sorted) {
  std::string out;
  for (std::size_t i = 0; i < sorted.size();) {
    std::size_t j = i;
    while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
    if (!out.empty()) out += ", ";
    out += std::to_string(sorted[i]);
    if (j > i) out += "-" + std::to_string(sorted[j]);
    i = j + 1;
  }
  return out;
}

std::string name_of(const FrameId& f) { return f.json.filename().string(); }

}  // namespace

std::string FrameSet::describe() const {
  std::map<std::pair<int, std::uint64_t>, std::vector<std::uint64_t>> by_seed;
  for (const FrameId& f : frames) by_seed[{f.generator_version, f.seed}].push_back(f.index);
  std::string out = folder + ": " + std::to_string(frames.size()) + " frames";
  for (auto& [key, indices] : by_seed) {
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    out += ", seed " + std::to_string(key.second) + " (generator v" + std::to_string(key.first) + ") frames " +
           ranges_text(indices);
  }
  return out;
}

std::uint64_t pixel_hash(const cv::Mat& bgr) {
  std::uint64_t h = 14695981039346656037ULL;
  const auto add = [&h](std::uint8_t byte) {
    h ^= byte;
    h *= 1099511628211ULL;
  };
  for (const int v : {bgr.cols, bgr.rows, bgr.type()}) {
    for (int k = 0; k < 4; ++k) add(static_cast<std::uint8_t>(static_cast<unsigned>(v) >> (8 * k)));
  }
  const std::size_t row_bytes = static_cast<std::size_t>(bgr.cols) * bgr.elemSize();
  for (int y = 0; y < bgr.rows; ++y) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(y);
    for (std::size_t x = 0; x < row_bytes; ++x) add(row[x]);
  }
  return h;
}

FrameId frame_id(const DatasetFrame& frame, const cv::Mat& bgr) {
  return {frame.json, frame.generator_version, frame.seed, frame.index, pixel_hash(bgr)};
}

Overlap find_overlap(const FrameSet& a, const FrameSet& b) {
  std::map<std::tuple<int, std::uint64_t, std::uint64_t>, const FrameId*> draws;
  std::unordered_map<std::uint64_t, const FrameId*> pixels;
  for (const FrameId& f : a.frames) {
    draws.emplace(std::tuple{f.generator_version, f.seed, f.index}, &f);
    pixels.emplace(f.pixels, &f);
  }
  Overlap o;
  for (const FrameId& f : b.frames) {
    const auto d = draws.find({f.generator_version, f.seed, f.index});
    const auto p = pixels.find(f.pixels);
    if (d != draws.end()) ++o.same_draws;
    if (p != pixels.end()) ++o.same_pixels;
    if (o.example.empty() && d != draws.end()) {
      o.example = a.role + " " + name_of(*d->second) + " and " + b.role + " " + name_of(f) + " are both seed " +
                  std::to_string(f.seed) + " frame " + std::to_string(f.index);
    } else if (o.example.empty() && p != pixels.end()) {
      o.example = a.role + " " + name_of(*p->second) + " and " + b.role + " " + name_of(f) + " have identical pixels";
    }
  }
  return o;
}

void require_disjoint(const FrameSet& a, const FrameSet& b) {
  const Overlap o = find_overlap(a, b);
  if (!o.any()) return;
  throw tools::ToolError("the " + a.role + " and the " + b.role + " overlap: " + std::to_string(o.same_draws) +
                         " frames of the " + b.role + " have the seed and index of a " + a.role + " frame, " +
                         std::to_string(o.same_pixels) + " have identical pixels (e.g. " + o.example +
                         "); a result on frames that were tuned on is not a test. " + a.role + ": " + a.describe() +
                         "; " + b.role + ": " + b.describe());
}

}  // namespace ringlet::vision::evaluate
