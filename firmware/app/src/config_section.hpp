#pragma once
// The TOML reading shared by the configuration's section readers and the backend factory: one
// table with the keys this firmware knows, every read checking type and range, unknown keys
// refused at the end so that typos surface. The fallback of every read is the setting's current
// value, so the defaults live in one place: the settings structs.
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ringlet/firmware/config.hpp"

namespace ringlet::firmware {

inline std::string where(const std::string& file, const toml::source_region& r) {
  std::ostringstream s;
  s << file << ':' << r.begin.line << ':' << r.begin.column;
  return s.str();
}

class Section {
 public:
  Section(const toml::table* table, std::string name, const std::string& file, const toml::source_region& fallback)
      : table_(table), name_(std::move(name)), file_(file), fallback_(fallback) {}

  [[nodiscard]] bool present() const { return table_ != nullptr; }

  double number(const std::string& key, double fallback, double lo, double hi) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    double v = 0.0;
    if (const auto* i = n->as_integer()) {
      v = static_cast<double>(i->get());
    } else if (const auto* f = n->as_floating_point()) {
      v = f->get();
    } else {
      fail(*n, key, "must be a number");
    }
    if (!std::isfinite(v) || v < lo || v > hi) {
      std::ostringstream s;
      s << "must be between " << lo << " and " << hi << ", got " << v;
      fail(*n, key, s.str());
    }
    return v;
  }

  int integer(const std::string& key, int fallback, int lo, int hi) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* i = n->as_integer();
    if (i == nullptr) fail(*n, key, "must be an integer");
    if (i->get() < lo || i->get() > hi) {
      fail(*n, key, "must be between " + std::to_string(lo) + " and " + std::to_string(hi) + ", got " +
                        std::to_string(i->get()));
    }
    return static_cast<int>(i->get());
  }

  std::uint64_t unsigned_integer(const std::string& key, std::uint64_t fallback) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* i = n->as_integer();
    if (i == nullptr || i->get() < 0) fail(*n, key, "must be a non-negative integer");
    return static_cast<std::uint64_t>(i->get());
  }

  bool boolean(const std::string& key, bool fallback) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* b = n->as_boolean();
    if (b == nullptr) fail(*n, key, "must be true or false");
    return b->get();
  }

  std::string text(const std::string& key, const std::string& fallback, const std::vector<std::string>& allowed = {}) {
    const toml::node* n = find(key);
    if (n == nullptr) return fallback;
    const auto* s = n->as_string();
    if (s == nullptr) fail(*n, key, "must be a string");
    if (!allowed.empty()) {
      bool ok = false;
      std::string list;
      for (const auto& a : allowed) {
        ok = ok || a == s->get();
        list += (list.empty() ? "\"" : ", \"") + a + "\"";
      }
      if (!ok) fail(*n, key, "must be one of " + list + ", got \"" + s->get() + "\"");
    }
    return s->get();
  }

  /// A file name, resolved against `base_dir` when relative; empty when the key is absent.
  std::filesystem::path path(const std::string& key, const std::filesystem::path& base_dir) {
    const std::string written = text(key, "");
    if (written.empty()) return {};
    return std::filesystem::path(written).is_absolute() ? std::filesystem::path(written) : base_dir / written;
  }

  const toml::node* find(const std::string& key) {
    used_.insert(key);
    return table_ == nullptr ? nullptr : table_->get(key);
  }

  [[noreturn]] void fail(const toml::node& n, const std::string& key, const std::string& message) const {
    throw ConfigError(where(file_, n.source()) + ": " + qualified(key) + ": " + message);
  }
  [[noreturn]] void fail_missing(const std::string& key, const std::string& message) const {
    const auto& region = table_ != nullptr ? table_->source() : fallback_;
    throw ConfigError(where(file_, region) + ": " + qualified(key) + ": " + message);
  }

  /// The inline table under `key` (e.g. sim.kidnap = { ... }) as a section of its own; a section
  /// without a table when absent (present() false). `example` shows the form in the error.
  Section sub(const std::string& key, const std::string& example) {
    const toml::node* n = find(key);
    if (n != nullptr && n->as_table() == nullptr) fail(*n, key, "must be a table, e.g. " + example);
    return Section(n != nullptr ? n->as_table() : nullptr, qualified(key), file_,
                   n != nullptr ? n->source() : fallback_);
  }

  void reject_unknown() const {
    if (table_ == nullptr) return;
    for (auto&& [k, v] : *table_) {
      if (!used_.contains(std::string(k.str()))) {
        throw ConfigError(where(file_, v.source()) + ": " + qualified(std::string(k.str())) + ": unknown key" +
                          (name_.empty() ? "" : " in [" + name_ + "]"));
      }
    }
  }

 private:
  [[nodiscard]] std::string qualified(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::table* table_;
  std::string name_;
  const std::string& file_;
  const toml::source_region& fallback_;
  std::set<std::string> used_;
};

inline Section section(const toml::table& root, Section& top, const std::string& name, const std::string& file) {
  const toml::node* n = top.find(name);
  if (n != nullptr && n->as_table() == nullptr) top.fail(*n, name, "must be a table, e.g. [" + name + "]");
  return Section(n != nullptr ? n->as_table() : nullptr, name, file, root.source());
}

}  // namespace ringlet::firmware
