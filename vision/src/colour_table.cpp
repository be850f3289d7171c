// Building and querying the colour table (thresholds, examples, confusion).
#include <algorithm>
#include <deque>

#include "ringlet/vision/colour_table.hpp"

namespace ringlet::vision {

ColourTable::ColourTable(int bin_bits)
    : bits_(std::clamp(bin_bits, kMinBinBits, kMaxBinBits)),
      shift_(8 - bits_),
      bins_(std::size_t{1} << (3 * bits_), static_cast<std::uint8_t>(ColourClass::kOther)) {}

Yuv ColourTable::bin_centre(std::size_t i) const noexcept {
  const std::size_t mask = (std::size_t{1} << bits_) - 1;
  const auto half = static_cast<std::size_t>(1U << shift_) / 2;
  const auto centre = [&](std::size_t b) { return static_cast<std::uint8_t>((b << shift_) + half); };
  return {centre((i >> (2 * bits_)) & mask), centre((i >> bits_) & mask), centre(i & mask)};
}

ColourTable ColourTable::from_thresholds(const ColourThresholds& t, int bin_bits) {
  ColourTable table(bin_bits);
  for (std::size_t i = 0; i < table.size(); ++i) {
    const Yuv c = table.bin_centre(i);
    if (t.ball.contains(c)) {
      table.set_bin(i, ColourClass::kBall);
    } else if (t.line.contains(c)) {
      table.set_bin(i, ColourClass::kLine);
    } else if (t.field.contains(c)) {
      table.set_bin(i, ColourClass::kField);
    }
  }
  return table;
}

ColourTable ColourTable::from_examples(std::span<const LabelledSample> samples, const ExampleTrainingOptions& options,
                                       int bin_bits) {
  ColourTable table(bin_bits);
  std::vector<std::array<std::uint32_t, kColourClassCount>> votes(table.size());
  for (const LabelledSample& s : samples) {
    ++votes[table.index(s.yuv.y, s.yuv.u, s.yuv.v)][static_cast<std::size_t>(s.label)];
  }
  // distance: 0 for a labelled bin, -1 for a bin not reached yet.
  std::vector<int> distance(table.size(), -1);
  std::deque<std::size_t> frontier;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& v = votes[i];
    const auto best = std::max_element(v.begin(), v.end());  // first maximum: ties → lower id
    if (*best == 0) continue;
    table.bins_[i] = static_cast<std::uint8_t>(best - v.begin());
    distance[i] = 0;
    frontier.push_back(i);
  }
  if (options.fill != EmptyBinFill::kNearest) return table;

  // Multi-source breadth-first flood over the 6-neighbourhood: each empty bin takes the class of
  // the labelled bin that reaches it first, i.e. the nearest in city-block distance.
  const int n = 1 << table.bits_;
  const auto coord = [&](std::size_t i, int axis) {
    return static_cast<int>((i >> (static_cast<std::size_t>(2 - axis) * static_cast<std::size_t>(table.bits_))) &
                            static_cast<std::size_t>(n - 1));
  };
  while (!frontier.empty()) {
    const std::size_t i = frontier.front();
    frontier.pop_front();
    if (distance[i] >= options.max_fill_distance) continue;
    for (int axis = 0; axis < 3; ++axis) {
      const std::size_t step = std::size_t{1} << (static_cast<std::size_t>(2 - axis) * static_cast<std::size_t>(table.bits_));
      const int c = coord(i, axis);
      for (const int d : {-1, 1}) {
        if (c + d < 0 || c + d >= n) continue;
        const std::size_t j = d < 0 ? i - step : i + step;
        if (distance[j] >= 0) continue;
        distance[j] = distance[i] + 1;
        table.bins_[j] = table.bins_[i];
        frontier.push_back(j);
      }
    }
  }
  return table;
}

Confusion ColourTable::confusion(std::span<const LabelledSample> samples) const noexcept {
  Confusion c;
  for (const LabelledSample& s : samples) {
    ++c.counts[static_cast<std::size_t>(s.label)][static_cast<std::size_t>(lookup(s.yuv))];
  }
  return c;
}

double Confusion::precision(ColourClass c) const noexcept {
  const auto k = static_cast<std::size_t>(c);
  std::uint64_t predicted = 0;
  for (const auto& row : counts) predicted += row[k];
  return predicted == 0 ? 1.0 : static_cast<double>(counts[k][k]) / static_cast<double>(predicted);
}

double Confusion::recall(ColourClass c) const noexcept {
  const auto k = static_cast<std::size_t>(c);
  std::uint64_t labelled = 0;
  for (const std::uint64_t n : counts[k]) labelled += n;
  return labelled == 0 ? 1.0 : static_cast<double>(counts[k][k]) / static_cast<double>(labelled);
}

std::uint64_t Confusion::total() const noexcept {
  std::uint64_t t = 0;
  for (const auto& row : counts)
    for (const std::uint64_t n : row) t += n;
  return t;
}

}  // namespace ringlet::vision
