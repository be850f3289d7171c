#pragma once
// Little-endian bytes, written and read one field at a time whatever the host's byte order: the
// HAL log's only way to turn values into bytes and back (never a memcpy of a struct).
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ringlet::hal {

/// Appends fields to a byte vector (the writer thread's buffer).
class LeWriter {
 public:
  explicit LeWriter(std::vector<std::uint8_t>& out) noexcept : out_(out) {}
  void u8(std::uint8_t v) { out_.push_back(v); }
  void boolean(bool v) { out_.push_back(v ? 1 : 0); }
  void u16(std::uint16_t v) { put(v, 2); }
  void u32(std::uint32_t v) { put(v, 4); }
  void u64(std::uint64_t v) { put(v, 8); }
  void i64(std::int64_t v) { put(static_cast<std::uint64_t>(v), 8); }
  void f64(double v) { put(std::bit_cast<std::uint64_t>(v), 8); }
  void bytes(const std::uint8_t* p, std::size_t n) {
    if (n > 0) out_.insert(out_.end(), p, p + n);
  }

 private:
  void put(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  }
  std::vector<std::uint8_t>& out_;
};

/// Reads fields from a buffer the caller has checked is long enough (the reader checks a record's
/// size before it decodes it).
class LeReader {
 public:
  explicit LeReader(const std::uint8_t* p) noexcept : p_(p) {}
  std::uint8_t u8() noexcept { return *p_++; }
  std::uint16_t u16() noexcept { return static_cast<std::uint16_t>(get(2)); }
  std::uint32_t u32() noexcept { return static_cast<std::uint32_t>(get(4)); }
  std::uint64_t u64() noexcept { return get(8); }
  std::int64_t i64() noexcept { return static_cast<std::int64_t>(get(8)); }
  double f64() noexcept { return std::bit_cast<double>(get(8)); }
  float f32() noexcept { return std::bit_cast<float>(u32()); }
  [[nodiscard]] const std::uint8_t* position() const noexcept { return p_; }

 private:
  std::uint64_t get(int n) noexcept {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= std::uint64_t{p_[i]} << (8 * i);
    p_ += n;
    return v;
  }
  const std::uint8_t* p_;
};

}  // namespace ringlet::hal
