#pragma once
// The lexical layer of the world format: splitting a line into tokens (whitespace separated,
// `#` to the end of the line is a comment, "double quoted" strings may contain spaces and `#`),
// and reading numbers strictly. Errors come back as messages; the parser adds "<source>:<line>: ".
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ringlet::sim_hal::detail {

struct Token {
  std::string_view text;  // without the quotes for a quoted token
  bool quoted = false;
};

/// Splits `line` into `tokens` (cleared first). Returns an error message, or nothing on success.
[[nodiscard]] std::optional<std::string> split_tokens(std::string_view line, std::vector<Token>& tokens);

/// The outcome of reading one number token.
struct NumberResult {
  enum class Status { kOk, kNotANumber, kOutOfRange, kNotFinite };
  Status status = Status::kNotANumber;
  double value = 0.0;
};

/// Reads a decimal floating-point number that must fill the whole token (so "1.5m" is refused).
/// A leading '+' is accepted; "inf" and "nan" parse but are reported as not finite.
[[nodiscard]] NumberResult parse_number(const Token& token) noexcept;

/// Reads a base-10 integer that fills the whole token.
[[nodiscard]] std::optional<int> parse_integer(const Token& token) noexcept;

}  // namespace ringlet::sim_hal::detail
