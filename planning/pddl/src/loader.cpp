#include "ringlet/pddl/loader.hpp"

namespace ringlet::pddl {

Parsed<LoadedFiles> load_files(const std::string& domain_path, const std::string& problem_path) {
  auto domain_text = read_text_file(domain_path);
  if (auto* e = std::get_if<Error>(&domain_text)) return *e;
  auto domain = parse_domain(std::get<std::string>(domain_text), domain_path);
  if (auto* e = std::get_if<Error>(&domain)) return *e;
  auto problem_text = read_text_file(problem_path);
  if (auto* e = std::get_if<Error>(&problem_text)) return *e;
  auto problem = parse_problem(std::get<std::string>(problem_text), problem_path, std::get<Domain>(domain));
  if (auto* e = std::get_if<Error>(&problem)) return *e;
  return LoadedFiles{std::move(std::get<Domain>(domain)), std::move(std::get<Problem>(problem))};
}

}  // namespace ringlet::pddl
