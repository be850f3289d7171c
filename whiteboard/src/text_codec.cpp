// Field-level text conversions and the error messages of the text and binary decoders.
#include <array>
#include <charconv>
#include <cmath>
#include <string>

#include "ringlet/whiteboard/binary.hpp"
#include "ringlet/whiteboard/field_codec.hpp"
#include "ringlet/whiteboard/text_format.hpp"

namespace ringlet::wb::detail {

std::string_view describe(TextError e) noexcept {
  switch (e) {
    case TextError::kNone: return "ok";
    case TextError::kNotANumber: return "not a number";
    case TextError::kOutOfRange: return "out of range";
    case TextError::kNotABool: return "not a bool (true/false/1/0)";
    case TextError::kTooLong: return "too long";
    case TextError::kBadEscape: return "bad escape";
    case TextError::kUnknownValue: return "unknown value";
  }
  return "?";
}

bool Tokens::next(std::string_view& token) noexcept {
  if (done_) return false;
  std::size_t i = 0;
  while (i < rest_.size() && rest_[i] != ',') {
    i += rest_[i] == '\\' ? std::size_t{2} : std::size_t{1};  // an escaped char (maybe ',') belongs to this token
  }
  if (i >= rest_.size()) {
    token = rest_;
    rest_ = {};
    done_ = true;
  } else {
    token = rest_.substr(0, i);
    rest_.remove_prefix(i + 1);
  }
  return true;
}

std::string_view trim(std::string_view s) noexcept {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

void append_text(std::string& out, bool v) { out.append(v ? "true" : "false"); }

void append_text(std::string& out, double v) {
  // Shortest form that reads back to the same bits (to_chars), independent of locale; inf and
  // nan come out as "inf", "-inf", "nan", "-nan", which from_chars reads back.
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), r.ptr);
}

void append_escaped(std::string& out, std::string_view s) {
  static constexpr char kHex[] = "0123456789abcdef";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    switch (c) {
      case '\\': out.append("\\\\"); break;
      case ',': out.append("\\,"); break;
      case '\n': out.append("\\n"); break;
      case '\t': out.append("\\t"); break;
      case '\r': out.append("\\r"); break;
      default:
        if (u < 0x20 || u == 0x7F) {
          out.append("\\x");
          out.push_back(kHex[u >> 4]);
          out.push_back(kHex[u & 0xF]);
        } else {
          out.push_back(c);
        }
    }
  }
}

TextError parse_token(std::string_view token, bool& v) noexcept {
  token = trim(token);
  if (token == "true" || token == "1") {
    v = true;
  } else if (token == "false" || token == "0") {
    v = false;
  } else {
    return TextError::kNotABool;
  }
  return TextError::kNone;
}

TextError parse_token(std::string_view token, double& v) noexcept {
  token = trim(token);
  const char* end = token.data() + token.size();
  // from_chars refuses a leading '+', which people do type.
  const char* begin = token.data();
  if (!token.empty() && token.front() == '+' && token.size() > 1 && token[1] != '-') ++begin;
  const auto r = std::from_chars(begin, end, v);
  if (r.ec == std::errc::result_out_of_range) return TextError::kOutOfRange;
  if (r.ec != std::errc{} || r.ptr != end || token.empty()) return TextError::kNotANumber;
  return TextError::kNone;
}

namespace {
int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

TextError unescape(std::string_view token, char* out, std::size_t cap, std::size_t& size) noexcept {
  size = 0;
  for (std::size_t i = 0; i < token.size(); ++i) {
    char c = token[i];
    if (c == '\\') {
      if (++i >= token.size()) return TextError::kBadEscape;
      switch (token[i]) {
        case '\\': c = '\\'; break;
        case ',': c = ','; break;
        case 'n': c = '\n'; break;
        case 't': c = '\t'; break;
        case 'r': c = '\r'; break;
        case 'x': {
          if (i + 2 >= token.size()) return TextError::kBadEscape;
          const int hi = hex_value(token[i + 1]);
          const int lo = hex_value(token[i + 2]);
          if (hi < 0 || lo < 0) return TextError::kBadEscape;
          c = static_cast<char>(hi * 16 + lo);
          i += 2;
          break;
        }
        default: return TextError::kBadEscape;
      }
    }
    if (size == cap) return TextError::kTooLong;
    out[size++] = c;
  }
  return TextError::kNone;
}

namespace {
std::string quoted(std::string_view token) {
  std::string q = "\"";
  q.append(token);
  q.push_back('"');
  return q;
}
std::string field_name(std::string_view type, std::string_view field, std::ptrdiff_t index) {
  std::string s{type};
  s.push_back('.');
  s.append(field);
  if (index >= 0) s += "[" + std::to_string(index) + "]";
  return s;
}
}  // namespace

Error field_error(std::string_view type, std::string_view field, std::ptrdiff_t index,
                  TextError reason, std::string_view token) {
  return Error{field_name(type, field, index) + ": " + std::string{describe(reason)} + ": " +
               quoted(token)};
}

Error missing_field(std::string_view type, std::string_view field, std::ptrdiff_t index) {
  return Error{field_name(type, field, index) + ": missing"};
}

Error extra_fields(std::string_view type, std::size_t expected) {
  return Error{std::string{type} + ": too many fields (expected " + std::to_string(expected) + ")"};
}

Error wire_error(std::string_view type, std::string_view what) {
  return Error{std::string{type} + ": " + std::string{what}};
}

Error wire_field_error(std::string_view type, std::string_view field) {
  return Error{std::string{type} + "." + std::string{field} + ": invalid bytes"};
}

Status check_header(std::span<const std::byte> in, TypeId id, std::string_view name,
                    std::uint16_t version, std::size_t payload) {
  if (in.size() < kWireHeaderSize) return wire_error(name, "buffer shorter than the header");
  const auto got_id = get_le<std::uint16_t>(in.data());
  const auto got_version = get_le<std::uint16_t>(in.data() + 2);
  const auto got_size = get_le<std::uint32_t>(in.data() + 4);
  if (got_id != to_underlying(id)) {
    return wire_error(name, "wrong type id " + std::to_string(got_id) + " (expected " +
                                std::to_string(to_underlying(id)) + ")");
  }
  if (got_version != version) {
    return wire_error(name, "schema version " + std::to_string(got_version) + " (expected " +
                                std::to_string(version) + ")");
  }
  if (got_size != payload) {
    return wire_error(name, "payload size " + std::to_string(got_size) + " (expected " +
                                std::to_string(payload) + ")");
  }
  if (in.size() < kWireHeaderSize + payload) return wire_error(name, "buffer shorter than the message");
  return {};
}

}  // namespace ringlet::wb::detail

namespace ringlet::wb {

Result<WireHeader> peek_header(std::span<const std::byte> in) {
  if (in.size() < kWireHeaderSize) return detail::wire_error("wire", "buffer shorter than the header");
  return WireHeader{TypeId{detail::get_le<std::uint16_t>(in.data())},
                    detail::get_le<std::uint16_t>(in.data() + 2),
                    detail::get_le<std::uint32_t>(in.data() + 4)};
}

}  // namespace ringlet::wb
