#pragma once
// A domain file and a problem file read and parsed together (what LOAD_PDDL and the CLI do).
#include <string>

#include "ringlet/pddl/parser.hpp"

namespace ringlet::pddl {

struct LoadedFiles {
  Domain domain;
  Problem problem;
};

[[nodiscard]] Parsed<LoadedFiles> load_files(const std::string& domain_path, const std::string& problem_path);

}  // namespace ringlet::pddl
