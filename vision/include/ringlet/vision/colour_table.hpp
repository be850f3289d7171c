#pragma once
// The colour lookup table: YUV → colour class with one load per pixel.
//
// Bins are the top `bin_bits` bits of Y, U and V (default 6: 64×64×64 = 256 KiB, which stays in
// the L2 cache while a frame is classified; 7 bits would be 2 MiB and miss it for little gain,
// since camera noise is several codes wide anyway). Index = (Y>>s)<<2b | (U>>s)<<b | V>>s with
// s = 8 − b. Storage is allocated once, when the table is built or loaded.
//
// File format (little-endian), see vision/README.md:
//   "RLUT" | u16 version (1) | u8 bin_bits (4..7) | u8 class_count (4) | u32 entry_count (2^(3b))
//   | u32 CRC-32 (IEEE) of the entries | entry_count bytes, each < class_count
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/vision/colour.hpp"

namespace ringlet::vision {

/// An inclusive box in YUV space.
struct YuvRange {
  std::uint8_t y_min = 0, y_max = 255;
  std::uint8_t u_min = 0, u_max = 255;
  std::uint8_t v_min = 0, v_max = 255;
  [[nodiscard]] constexpr bool contains(const Yuv& p) const noexcept {
    return p.y >= y_min && p.y <= y_max && p.u >= u_min && p.u <= u_max && p.v >= v_min && p.v <= v_max;
  }
};

/// Per-class boxes; the first that contains a bin's centre wins, in the order ball, line, field
/// (the ball's saturated orange is the most specific, green the broadest). Everything else: other.
/// Defaults: green carpet, white lines, orange ball under dim to bright indoor light (full-range
/// YUV, e.g. carpet RGB (40,140,40) → (99,95,86), line (235,235,235) → (235,128,128), ball
/// (255,120,0) → (147,45,205)).
struct ColourThresholds {
  YuvRange ball{40, 235, 0, 118, 158, 255};
  YuvRange line{165, 255, 106, 150, 106, 150};
  YuvRange field{25, 200, 0, 122, 0, 122};
};

/// One labelled colour sample (training and evaluation).
struct LabelledSample {
  Yuv yuv{};
  ColourClass label = ColourClass::kOther;
};

/// What to do with bins no example fell into.
enum class EmptyBinFill : std::uint8_t {
  kOther,    // leave them 'other' (conservative: unknown colours are not field or line)
  kNearest,  // the class of the nearest labelled bin (city-block distance in bin units, up to
             // max_fill_distance); ties go to the bin reached first by a breadth-first flood
             // seeded in index order, so the result is deterministic
};

struct ExampleTrainingOptions {
  EmptyBinFill fill = EmptyBinFill::kNearest;
  int max_fill_distance = 3;  // bins; farther than this stays 'other'
};

/// Counts[truth][predicted] over a labelled set, with per-class precision and recall.
struct Confusion {
  std::array<std::array<std::uint64_t, kColourClassCount>, kColourClassCount> counts{};
  /// Of the samples classified as c, the fraction that are c (1 when none were).
  [[nodiscard]] double precision(ColourClass c) const noexcept;
  /// Of the samples labelled c, the fraction classified as c (1 when there are none).
  [[nodiscard]] double recall(ColourClass c) const noexcept;
  [[nodiscard]] std::uint64_t total() const noexcept;
};

struct ColourTableLoad;

class ColourTable {
 public:
  static constexpr std::uint16_t kFileVersion = 1;
  static constexpr int kDefaultBinBits = 6;
  static constexpr int kMinBinBits = 4;
  static constexpr int kMaxBinBits = 7;

  /// All bins 'other'. bin_bits is clamped to [kMinBinBits, kMaxBinBits].
  explicit ColourTable(int bin_bits = kDefaultBinBits);

  [[nodiscard]] static ColourTable from_thresholds(const ColourThresholds& t, int bin_bits = kDefaultBinBits);
  /// Majority class per bin (ties: the lower class id), then empty bins filled per `options`.
  [[nodiscard]] static ColourTable from_examples(std::span<const LabelledSample> samples,
                                                 const ExampleTrainingOptions& options = {},
                                                 int bin_bits = kDefaultBinBits);

  /// Reads the file (hal::read_file: regular files only, at most hal::kMaxBinaryFileBytes) and
  /// parses it. Errors: "colour table <file>: <what>", e.g. "not a regular file (a directory)".
  [[nodiscard]] static ColourTableLoad load(const std::filesystem::path& file);
  /// A table from the bytes of a colour-table file; `source` names them in the error
  /// ("colour table <source>: <what>"). Every field and entry is checked before a table is built.
  [[nodiscard]] static ColourTableLoad parse(std::span<const std::uint8_t> bytes, std::string_view source);
  /// The bytes of the file `save` writes.
  [[nodiscard]] std::vector<std::uint8_t> serialise() const;
  /// Writes the file (whole or, on error, an error text naming it; "" on success).
  [[nodiscard]] std::string save(const std::filesystem::path& file) const;

  [[nodiscard]] int bin_bits() const noexcept { return bits_; }
  [[nodiscard]] std::size_t size() const noexcept { return bins_.size(); }
  [[nodiscard]] const std::uint8_t* data() const noexcept { return bins_.data(); }

  [[nodiscard]] std::size_t index(std::uint8_t y, std::uint8_t u, std::uint8_t v) const noexcept {
    return (static_cast<std::size_t>(y >> shift_) << (2 * bits_)) | (static_cast<std::size_t>(u >> shift_) << bits_) |
           static_cast<std::size_t>(v >> shift_);
  }
  [[nodiscard]] ColourClass lookup(std::uint8_t y, std::uint8_t u, std::uint8_t v) const noexcept {
    return static_cast<ColourClass>(bins_[index(y, u, v)]);
  }
  [[nodiscard]] ColourClass lookup(const Yuv& p) const noexcept { return lookup(p.y, p.u, p.v); }
  void set_bin(std::size_t i, ColourClass c) noexcept { bins_[i] = static_cast<std::uint8_t>(c); }
  /// The YUV value at the centre of bin i.
  [[nodiscard]] Yuv bin_centre(std::size_t i) const noexcept;

  [[nodiscard]] Confusion confusion(std::span<const LabelledSample> samples) const noexcept;

  friend bool operator==(const ColourTable&, const ColourTable&) = default;

 private:
  int bits_;
  int shift_;
  std::vector<std::uint8_t> bins_;
};

/// A load either gives a whole table or an error naming the file and the problem, never a
/// partly filled table.
struct ColourTableLoad {
  std::optional<ColourTable> table;
  std::string error;
};

/// CRC-32 (IEEE 802.3, reflected, as zlib) of a byte range.
[[nodiscard]] std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept;

}  // namespace ringlet::vision
