#include "world_lexer.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace ringlet::sim_hal::detail {
namespace {

constexpr bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

std::optional<std::string> split_tokens(std::string_view line, std::vector<Token>& tokens) {
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    const char c = line[i];
    if (is_space(c)) {
      ++i;
    } else if (c == '#') {
      break;
    } else if (c == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string_view::npos) return std::string("unterminated quoted string");
      tokens.push_back({line.substr(i + 1, close - i - 1), true});
      i = close + 1;
      // "abc"def would silently be two tokens; a quoted string must stand alone.
      if (i < line.size() && !is_space(line[i]) && line[i] != '#') {
        return std::string("unexpected text right after a quoted string");
      }
    } else {
      std::size_t end = i;
      while (end < line.size() && !is_space(line[end]) && line[end] != '#' && line[end] != '"') ++end;
      tokens.push_back({line.substr(i, end - i), false});
      i = end;
    }
  }
  return std::nullopt;
}

NumberResult parse_number(const Token& token) noexcept {
  if (token.quoted) return {};
  std::string_view text = token.text;
  // std::from_chars refuses a leading '+', but people write "+1.5"; "+-1" must stay refused.
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double value = 0.0;
  const char* const end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return {NumberResult::Status::kOutOfRange, 0.0};
  if (ec != std::errc{} || ptr != end) return {};
  if (!std::isfinite(value)) return {NumberResult::Status::kNotFinite, value};
  return {NumberResult::Status::kOk, value};
}

std::optional<int> parse_integer(const Token& token) noexcept {
  if (token.quoted) return std::nullopt;
  int value = 0;
  const char* const end = token.text.data() + token.text.size();
  const auto [ptr, ec] = std::from_chars(token.text.data(), end, value);
  if (ec != std::errc{} || ptr != end) return std::nullopt;
  return value;
}

}  // namespace ringlet::sim_hal::detail
