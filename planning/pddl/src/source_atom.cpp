#include "ringlet/pddl/source_atom.hpp"

#include <array>
#include <cctype>
#include <cstddef>

namespace ringlet::pddl {
namespace {

bool same_name(std::string_view a, std::string_view b) noexcept {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

template <typename Names>
std::int32_t index_of(const Names& names, std::string_view n) noexcept {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (same_name(names[i], n)) return static_cast<std::int32_t>(i);
  }
  return -1;
}

constexpr std::size_t kMaxTokens = 9;  // a predicate and 8 arguments

}  // namespace

std::int32_t find_fact(const Task& task, std::string_view text) noexcept {
  std::array<std::string_view, kMaxTokens> tokens{};
  std::size_t count = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '\t' || c == '(' || c == ')') {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && text[j] != ' ' && text[j] != '\t' && text[j] != '(' && text[j] != ')') ++j;
    if (count == kMaxTokens) return -1;
    tokens[count++] = text.substr(i, j - i);
    i = j;
  }
  if (count == 0) return -1;
  const std::int32_t predicate = index_of(task.predicate_names, tokens[0]);
  if (predicate < 0) return -1;
  std::array<std::int32_t, kMaxTokens> args{};
  for (std::size_t k = 1; k < count; ++k) {
    args[k - 1] = index_of(task.object_names, tokens[k]);
    if (args[k - 1] < 0) return -1;
  }
  for (std::size_t f = 0; f < task.facts.size(); ++f) {
    const FactInfo& info = task.facts[f];
    if (info.predicate != predicate || info.args.count != count - 1) continue;
    const auto fa = task.list(info.args);
    bool same = true;
    for (std::size_t k = 0; k + 1 < count && same; ++k) same = fa[k] == args[k];
    if (same) return static_cast<std::int32_t>(f);
  }
  return -1;
}

void put_source(const Task& task, State state, std::int32_t fact) noexcept {
  const FactInfo& of = task.facts[static_cast<std::size_t>(fact)];
  const auto of_args = task.list(of.args);
  for (std::size_t f = 0; f < task.facts.size(); ++f) {
    const FactInfo& info = task.facts[f];
    if (info.predicate != of.predicate) continue;
    const auto a = task.list(info.args);
    if (of_args.empty() || (!a.empty() && a[0] == of_args[0])) clear(state, static_cast<std::int32_t>(f));
  }
  set(state, fact);
}

}  // namespace ringlet::pddl
