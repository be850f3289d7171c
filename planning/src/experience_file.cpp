#include "ringlet/planning/experience_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>

namespace ringlet::planning {
namespace {

constexpr std::string_view kMagic = "ringlet-experiences";
constexpr std::array<std::string_view, 5> kRecordColumns{"frame", "time_ns", "duration_s", "commanded_speed",
                                                         "achieved_speed"};
constexpr std::size_t kColumnCount = kRecordColumns.size() + kFeatureCount;

std::string column_header() {
  std::string h;
  for (const auto c : kRecordColumns) (h += c) += ' ';
  for (const auto c : kFeatureNames) (h += c) += ' ';
  h.pop_back();
  return h;
}

class Reader {
 public:
  Reader(const std::filesystem::path& path, int line) : path_(path), line_(line) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw ExperienceFileError(path_.string() + ":" + std::to_string(line_) + ": " + what);
  }

  /// Splits a line at spaces into exactly kColumnCount fields.
  std::array<std::string_view, kColumnCount> fields(std::string_view text) const {
    std::array<std::string_view, kColumnCount> out{};
    std::size_t n = 0;
    while (!text.empty()) {
      const std::size_t start = text.find_first_not_of(' ');
      if (start == std::string_view::npos) break;
      text.remove_prefix(start);
      const std::size_t end = std::min(text.find(' '), text.size());
      if (n == kColumnCount) fail("expected " + std::to_string(kColumnCount) + " fields, got more");
      out[n++] = text.substr(0, end);
      text.remove_prefix(end);
    }
    if (n != kColumnCount) fail("expected " + std::to_string(kColumnCount) + " fields, got " + std::to_string(n));
    return out;
  }

  template <typename T>
  T number(std::string_view text, std::string_view column) const {
    T v{};
    const char* end = text.data() + text.size();
    const auto [p, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc{} || p != end)
      fail("column " + std::string(column) + ": expected a number, got \"" + std::string(text) + "\"");
    if constexpr (std::is_floating_point_v<T>) {
      if (!std::isfinite(v)) fail("column " + std::string(column) + ": " + std::string(text) + " is not finite");
    }
    return v;
  }

  double in_range(std::string_view text, std::string_view column, double lo, double hi) const {
    const double v = number<double>(text, column);
    if (v < lo || v > hi)
      fail("column " + std::string(column) + ": " + std::string(text) + " is outside [" + shortest(lo) + ", " +
           shortest(hi) + "]");
    return v;
  }

  static std::string shortest(double v) {
    std::array<char, 32> buf{};
    const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
    return {buf.data(), r.ptr};
  }

 private:
  const std::filesystem::path& path_;
  int line_;
};

void append_number(std::string& out, auto v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  out.append(buf.data(), r.ptr);
}

Experience parse(const Reader& r, std::string_view text) {
  const auto f = r.fields(text);
  Experience e;
  e.frame = r.number<std::uint64_t>(f[0], kRecordColumns[0]);
  e.time_ns = r.number<std::int64_t>(f[1], kRecordColumns[1]);
  e.duration_s = r.number<double>(f[2], kRecordColumns[2]);
  if (!(e.duration_s > 0.0)) r.fail("column duration_s: " + std::string(f[2]) + " is not a positive time");
  constexpr double kFastest = 1000.0;  // m/s: far beyond any robot, catches a unit mix-up
  e.commanded_speed = r.in_range(f[3], kRecordColumns[3], 0.0, kFastest);
  e.achieved_speed = r.in_range(f[4], kRecordColumns[4], 0.0, kFastest);
  for (std::size_t i = 0; i < kFeatureCount; ++i)
    e.features[i] = r.in_range(f[kRecordColumns.size() + i], kFeatureNames[i], 0.0, 1.0);
  if (e.features[kDiagonal] != 0.0 && e.features[kDiagonal] != 1.0)
    r.fail("column diagonal: " + std::string(f[kRecordColumns.size()]) + " is neither 0 nor 1");
  return e;
}

}  // namespace

void save_experiences(const std::filesystem::path& path, std::span<const Experience> experiences) {
  std::string text;
  text.reserve(64 + experiences.size() * 160);
  ((text += kMagic) += ' ') += std::to_string(kExperienceFileVersion) + "\n";
  (text += column_header()) += '\n';
  int line = 2;
  for (const Experience& e : experiences) {
    const std::size_t start = text.size();
    append_number(text, e.frame);
    text += ' ';
    append_number(text, e.time_ns);
    for (const double v : {e.duration_s, e.commanded_speed, e.achieved_speed}) {
      text += ' ';
      append_number(text, v);
    }
    for (const double v : e.features) {
      text += ' ';
      append_number(text, v);
    }
    // What is written must load: the line goes through the reader's own checks (one set of rules).
    ++line;
    try {
      (void)parse(Reader(path, line), std::string_view(text).substr(start));
    } catch (const ExperienceFileError& bad) {
      throw ExperienceFileError(std::string("refusing to write experience ") + std::to_string(line - 3) + ": " + bad.what());
    }
    text += '\n';
  }
  std::filesystem::path tmp = path;
  tmp += ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw ExperienceFileError(tmp.string() + ": cannot create the file");
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw ExperienceFileError(tmp.string() + ": cannot write the file");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw ExperienceFileError(path.string() + ": cannot replace the file: " + ec.message());
}

std::vector<Experience> load_experiences(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ExperienceFileError(path.string() + ": cannot open the file");
  std::string text;
  const std::string expected_magic = std::string(kMagic) + " " + std::to_string(kExperienceFileVersion);
  if (!std::getline(in, text)) Reader(path, 1).fail("empty file: expected \"" + expected_magic + "\"");
  if (!text.empty() && text.back() == '\r') text.pop_back();
  if (text != expected_magic) {
    if (text.starts_with(std::string(kMagic) + " "))
      Reader(path, 1).fail("format version " + text.substr(kMagic.size() + 1) + ", this program reads version " +
                           std::to_string(kExperienceFileVersion));
    Reader(path, 1).fail("not an experience file: expected \"" + expected_magic + "\"");
  }
  const std::string header = column_header();
  if (!std::getline(in, text) || (text.ends_with('\r') ? text.substr(0, text.size() - 1) : text) != header)
    Reader(path, 2).fail("the columns are not this version's: expected \"" + header + "\"");

  std::vector<Experience> out;
  int line = 2;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (text.empty()) continue;
    out.push_back(parse(Reader(path, line), text));
  }
  if (in.bad()) throw ExperienceFileError(path.string() + ": read error after line " + std::to_string(line));
  return out;
}

}  // namespace ringlet::planning
