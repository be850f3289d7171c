#include "ringlet/pddl/lexer.hpp"

#include <cctype>

namespace ringlet::pddl {
namespace {

// Characters of a PDDL name (letters, digits, '-', '_') plus a few that real domain files use
// in names ('.', '@', '+', '*', '/', '<', '>', '=' after the first character).
bool name_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) != 0 || c == '-' || c == '_' || c == '.' || c == '@' || c == '+' || c == '*' ||
         c == '/' || c == '<' || c == '>' || c == '=';
}

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

}  // namespace

std::string describe(const Token& t) {
  switch (t.kind) {
    case TokenKind::kOpen: return "\"(\"";
    case TokenKind::kClose: return "\")\"";
    case TokenKind::kEnd: return "end of file";
    case TokenKind::kDash: return "\"-\"";
    default: return "\"" + t.text + "\"";
  }
}

bool tokenize(std::string_view text, const std::string& file, std::vector<Token>& out, Error& error) {
  int line = 1;
  int col = 1;
  std::size_t i = 0;
  auto advance = [&](std::size_t n) {
    for (std::size_t k = 0; k < n; ++k, ++i) {
      if (text[i] == '\n') {
        ++line;
        col = 1;
      } else {
        ++col;
      }
    }
  };
  while (i < text.size()) {
    const char c = text[i];
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      advance(1);
      continue;
    }
    if (c == ';') {
      while (i < text.size() && text[i] != '\n') advance(1);
      continue;
    }
    Token t;
    t.line = line;
    t.col = col;
    if (c == '(' || c == ')') {
      t.kind = c == '(' ? TokenKind::kOpen : TokenKind::kClose;
      t.text = std::string(1, c);
      advance(1);
      out.push_back(std::move(t));
      continue;
    }
    std::size_t start = i;
    std::size_t j = i;
    if (c == '?' || c == ':') ++j;
    while (j < text.size() && name_char(text[j])) ++j;
    if (j == start || ((c == '?' || c == ':') && j == start + 1)) {
      error = {{file, line, col},
               (c == '?' || c == ':') ? std::string("expected a name after \"") + c + "\""
                                      : "unexpected character '" + std::string(1, c) + "'"};
      return false;
    }
    for (std::size_t k = start; k < j; ++k) t.text.push_back(lower(text[k]));
    if (c == '?') {
      t.kind = TokenKind::kVariable;
    } else if (c == ':') {
      t.kind = TokenKind::kKeyword;
    } else if (t.text == "-") {
      t.kind = TokenKind::kDash;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      t.kind = TokenKind::kNumber;
    } else {
      t.kind = TokenKind::kName;
    }
    advance(j - start);
    out.push_back(std::move(t));
  }
  out.push_back(Token{TokenKind::kEnd, "", line, col});
  return true;
}

}  // namespace ringlet::pddl
