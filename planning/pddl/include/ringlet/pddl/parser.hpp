#pragma once
// The STRIPS subset of PDDL with :typing, :negative-preconditions, :equality and
// :conditional-effects. Any malformed or inconsistent input is an Error located at
// file:line:col saying what was expected and what was found; nothing else is thrown.
#include <string>
#include <string_view>
#include <variant>

#include "ringlet/pddl/ast.hpp"

namespace ringlet::pddl {

template <typename T>
using Parsed = std::variant<T, Error>;

[[nodiscard]] Parsed<Domain> parse_domain(std::string_view text, const std::string& file);
/// A problem for `domain` (its :domain must name it).
[[nodiscard]] Parsed<Problem> parse_problem(std::string_view text, const std::string& file, const Domain& domain);

/// Reads a whole file; an Error naming the file when it cannot be read.
[[nodiscard]] Parsed<std::string> read_text_file(const std::string& path);

}  // namespace ringlet::pddl
