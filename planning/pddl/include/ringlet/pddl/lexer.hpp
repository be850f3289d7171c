#pragma once
// PDDL's tokens: parentheses, names (lower-cased: PDDL names are case-insensitive), variables
// (?x), keywords (:requirements), the type dash and numbers; `;` starts a comment to the end of
// the line. Every token keeps its line and column for the errors.
#include <string>
#include <string_view>
#include <vector>

#include "ringlet/pddl/error.hpp"

namespace ringlet::pddl {

enum class TokenKind { kOpen, kClose, kName, kVariable, kKeyword, kDash, kNumber, kEnd };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string text;  ///< lower-cased; "?x" for a variable, ":typing" for a keyword
  int line = 0;
  int col = 0;
};

/// "(", "a name", "end of file"...: how an error message names what it found.
[[nodiscard]] std::string describe(const Token& t);

/// Splits `text` into tokens ending with one kEnd token, or returns false and sets `error` (a
/// character PDDL does not use, a lone "?").
[[nodiscard]] bool tokenize(std::string_view text, const std::string& file, std::vector<Token>& out, Error& error);

}  // namespace ringlet::pddl
