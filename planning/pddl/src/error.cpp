#include "ringlet/pddl/error.hpp"

namespace ringlet::pddl {

std::string Error::to_string() const {
  if (where.file.empty() && where.line == 0) return message;
  return where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.col) + ": " + message;
}

}  // namespace ringlet::pddl
