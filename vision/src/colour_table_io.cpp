// The colour table's file: whole or nothing. Every check names the file and what is wrong, and a
// table is only returned once every byte has been read and verified.
#include <array>
#include <cstring>
#include <fstream>

#include "ringlet/hal/read_file.hpp"

#include "ringlet/vision/colour_table.hpp"

namespace ringlet::vision {
namespace {

constexpr std::array<char, 4> kMagic{'R', 'L', 'U', 'T'};
constexpr std::size_t kHeaderSize = 16;

constexpr std::array<std::uint32_t, 256> make_crc_table() noexcept {
  std::array<std::uint32_t, 256> t{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    t[i] = c;
  }
  return t;
}
constexpr auto kCrcTable = make_crc_table();

void put_u16(std::array<std::uint8_t, kHeaderSize>& h, std::size_t at, std::uint16_t v) noexcept {
  h[at] = static_cast<std::uint8_t>(v & 0xFFU);
  h[at + 1] = static_cast<std::uint8_t>(v >> 8);
}
void put_u32(std::array<std::uint8_t, kHeaderSize>& h, std::size_t at, std::uint32_t v) noexcept {
  for (std::size_t k = 0; k < 4; ++k) h[at + k] = static_cast<std::uint8_t>((v >> (8 * k)) & 0xFFU);
}
std::uint32_t get_u32(std::span<const std::uint8_t> b, std::size_t at) noexcept {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k) v |= static_cast<std::uint32_t>(b[at + k]) << (8 * k);
  return v;
}

}  // namespace

std::uint32_t crc32(std::span<const std::uint8_t> bytes) noexcept {
  std::uint32_t c = 0xFFFFFFFFU;
  for (const std::uint8_t b : bytes) c = kCrcTable[(c ^ b) & 0xFFU] ^ (c >> 8);
  return c ^ 0xFFFFFFFFU;
}

std::vector<std::uint8_t> ColourTable::serialise() const {
  std::array<std::uint8_t, kHeaderSize> h{};
  for (std::size_t k = 0; k < 4; ++k) h[k] = static_cast<std::uint8_t>(kMagic[k]);
  put_u16(h, 4, kFileVersion);
  h[6] = static_cast<std::uint8_t>(bits_);
  h[7] = static_cast<std::uint8_t>(kColourClassCount);
  put_u32(h, 8, static_cast<std::uint32_t>(bins_.size()));
  put_u32(h, 12, crc32(bins_));
  std::vector<std::uint8_t> bytes(kHeaderSize + bins_.size());
  std::memcpy(bytes.data(), h.data(), kHeaderSize);
  std::memcpy(bytes.data() + kHeaderSize, bins_.data(), bins_.size());
  return bytes;
}

std::string ColourTable::save(const std::filesystem::path& file) const {
  const std::vector<std::uint8_t> bytes = serialise();
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) return "colour table " + file.string() + ": cannot open for writing";
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) return "colour table " + file.string() + ": write failed";
  return {};
}

ColourTableLoad ColourTable::load(const std::filesystem::path& file) {
  const hal::FileRead read = hal::read_file(file, "colour table", hal::kMaxBinaryFileBytes);
  if (!read.ok()) {
    // read_file says "<file>: cannot read colour table: <why>"; every colour-table error reads
    // "colour table <file>: <what>", so keep the why.
    const std::string prefix = file.string() + ": cannot read colour table: ";
    const bool ours = read.error.rfind(prefix, 0) == 0;
    return {std::nullopt, "colour table " + file.string() + ": " + (ours ? read.error.substr(prefix.size()) : read.error)};
  }
  return parse({reinterpret_cast<const std::uint8_t*>(read.bytes.data()), read.bytes.size()}, file.string());
}

ColourTableLoad ColourTable::parse(std::span<const std::uint8_t> bytes, std::string_view source) {
  const auto fail = [&](const std::string& what) {
    return ColourTableLoad{std::nullopt, "colour table " + std::string(source) + ": " + what};
  };
  if (bytes.size() < kHeaderSize) {
    return fail("truncated header: " + std::to_string(bytes.size()) + " bytes, need " + std::to_string(kHeaderSize));
  }
  for (std::size_t k = 0; k < 4; ++k) {
    if (bytes[k] != static_cast<std::uint8_t>(kMagic[k])) return fail("not a colour table (bad magic, expected \"RLUT\")");
  }
  const auto version = static_cast<std::uint16_t>(bytes[4] | (bytes[5] << 8));
  if (version != kFileVersion) {
    return fail("unsupported version " + std::to_string(version) + " (this build reads version " +
                          std::to_string(kFileVersion) + ")");
  }
  const int bits = bytes[6];
  if (bits < kMinBinBits || bits > kMaxBinBits) {
    return fail("bin bits " + std::to_string(bits) + " out of range [" + std::to_string(kMinBinBits) + ", " +
                          std::to_string(kMaxBinBits) + "]");
  }
  if (bytes[7] != kColourClassCount) {
    return fail("class count " + std::to_string(bytes[7]) + ", expected " + std::to_string(kColourClassCount));
  }
  const std::uint32_t entries = get_u32(bytes, 8);
  const std::size_t expected = std::size_t{1} << (3 * bits);
  if (entries != expected) {
    return fail("entry count " + std::to_string(entries) + " does not match " + std::to_string(bits) +
                          " bin bits (" + std::to_string(expected) + ")");
  }
  if (bytes.size() != kHeaderSize + expected) {
    return fail("size " + std::to_string(bytes.size()) + " bytes, expected " +
                          std::to_string(kHeaderSize + expected) + (bytes.size() < kHeaderSize + expected ? " (truncated)" : " (trailing bytes)"));
  }
  const std::span<const std::uint8_t> payload(bytes.data() + kHeaderSize, expected);
  if (crc32(payload) != get_u32(bytes, 12)) return fail("CRC mismatch (corrupt entries)");
  for (std::size_t i = 0; i < payload.size(); ++i) {
    if (payload[i] >= kColourClassCount) {
      return fail("entry " + std::to_string(i) + " has class " + std::to_string(payload[i]) + " >= class count");
    }
  }
  ColourTable table(bits);
  std::copy(payload.begin(), payload.end(), table.bins_.begin());
  return {std::move(table), {}};
}

}  // namespace ringlet::vision
