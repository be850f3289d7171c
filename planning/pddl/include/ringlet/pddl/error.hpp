#pragma once
// Where something went wrong in a PDDL or plan file, and what: every error of the parser, the
// grounder and the validator is one of these, printed as "file:line:col: message" like a compiler.
#include <string>

namespace ringlet::pddl {

/// A position in a source file; line and column count from 1 (column in bytes).
struct Location {
  std::string file;
  int line = 0;
  int col = 0;
};

struct Error {
  Location where;
  std::string message;

  /// "file:line:col: message" (just the message when there is no file).
  [[nodiscard]] std::string to_string() const;
};

}  // namespace ringlet::pddl
