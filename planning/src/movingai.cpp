#include "ringlet/planning/movingai.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ringlet::planning {
namespace {

[[noreturn]] void fail(const std::filesystem::path& path, int line, const std::string& what) {
  throw MovingAiError(path.string() + ":" + std::to_string(line) + ": " + what);
}

std::ifstream open(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MovingAiError(path.string() + ": cannot open the file");
  return in;
}

/// Strips a trailing CR (files written on Windows).
void chomp(std::string& s) {
  if (!s.empty() && s.back() == '\r') s.pop_back();
}

int parse_int(const std::string& text, const std::filesystem::path& path, int line, const char* what) {
  int v = 0;
  const auto* end = text.data() + text.size();
  const auto [p, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc{} || p != end) fail(path, line, std::string("expected an integer ") + what + ", got \"" + text + "\"");
  return v;
}

/// "key value" header line of a .map.
int header_value(std::ifstream& in, const std::filesystem::path& path, int& line, const char* key) {
  std::string text;
  ++line;
  if (!std::getline(in, text)) fail(path, line, std::string("expected \"") + key + " <n>\", got the end of the file");
  chomp(text);
  std::istringstream words(text);
  std::string k, v, extra;
  words >> k >> v;
  if (k != key || v.empty() || (words >> extra)) fail(path, line, std::string("expected \"") + key + " <n>\", got \"" + text + "\"");
  return parse_int(v, path, line, key);
}

}  // namespace

MovingAiMap read_movingai_map(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  int line = 1;
  std::string text;
  if (!std::getline(in, text)) fail(path, line, "empty file: expected \"type octile\"");
  chomp(text);
  if (text != "type octile") fail(path, line, "expected \"type octile\", got \"" + text + "\"");
  MovingAiMap m;
  m.height = header_value(in, path, line, "height");
  m.width = header_value(in, path, line, "width");
  if (m.width <= 0 || m.height <= 0 || m.width > 8192 || m.height > 8192)
    fail(path, line, "width and height must be 1 to 8192, got " + std::to_string(m.width) + " × " + std::to_string(m.height));
  ++line;
  if (!std::getline(in, text) || (chomp(text), text != "map")) fail(path, line, "expected \"map\"");
  m.terrain.reserve(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
  for (int y = 0; y < m.height; ++y) {
    ++line;
    if (!std::getline(in, text)) fail(path, line, "expected " + std::to_string(m.height) + " rows, the file ends after " + std::to_string(y));
    chomp(text);
    if (static_cast<int>(text.size()) != m.width)
      fail(path, line, "row " + std::to_string(y) + " has " + std::to_string(text.size()) + " cells, expected " + std::to_string(m.width));
    for (std::size_t x = 0; x < text.size(); ++x) {
      const char c = text[x];
      if (!MovingAiMap::passable_char(c) && c != '@' && c != 'O' && c != 'T' && c != 'W')
        fail(path, line, "column " + std::to_string(x + 1) + ": unknown terrain '" + std::string(1, c) + "' (expected one of . G S @ O T W)");
    }
    m.terrain.insert(m.terrain.end(), text.begin(), text.end());
  }
  while (std::getline(in, text)) {
    ++line;
    chomp(text);
    if (!text.empty()) fail(path, line, "unexpected text after the map's last row");
  }
  return m;
}

void write_movingai_map(std::ostream& out, const MovingAiMap& m) {
  out << "type octile\nheight " << m.height << "\nwidth " << m.width << "\nmap\n";
  for (int y = 0; y < m.height; ++y) {
    out.write(m.terrain.data() + static_cast<std::ptrdiff_t>(y) * m.width, m.width);
    out << '\n';
  }
}

std::vector<MovingAiProblem> read_movingai_scen(const std::filesystem::path& path) {
  std::ifstream in = open(path);
  std::string text;
  int line = 1;
  if (!std::getline(in, text)) fail(path, line, "empty file: expected \"version 1\"");
  chomp(text);
  if (text != "version 1" && text != "version 1.0") fail(path, line, "expected \"version 1\", got \"" + text + "\"");
  std::vector<MovingAiProblem> out;
  while (std::getline(in, text)) {
    ++line;
    chomp(text);
    if (text.empty()) continue;
    // Tab-separated in the benchmark files; any whitespace is accepted.
    std::istringstream words(text);
    std::vector<std::string> f;
    for (std::string w; words >> w;) f.push_back(w);
    if (f.size() != 9) fail(path, line, "expected 9 fields (bucket map width height sx sy gx gy optimal), got " + std::to_string(f.size()));
    MovingAiProblem p;
    p.source = path.string();
    p.line = line;
    p.bucket = parse_int(f[0], path, line, "bucket");
    p.map = f[1];
    p.map_width = parse_int(f[2], path, line, "map width");
    p.map_height = parse_int(f[3], path, line, "map height");
    p.start_x = parse_int(f[4], path, line, "start x");
    p.start_y = parse_int(f[5], path, line, "start y");
    p.goal_x = parse_int(f[6], path, line, "goal x");
    p.goal_y = parse_int(f[7], path, line, "goal y");
    char* end = nullptr;
    p.optimal = std::strtod(f[8].c_str(), &end);
    if (end == f[8].c_str() || *end != '\0' || !std::isfinite(p.optimal) || p.optimal < 0.0)
      fail(path, line, "expected a non-negative optimal length, got \"" + f[8] + "\"");
    out.push_back(std::move(p));
  }
  return out;
}

std::string check_problem(const MovingAiProblem& p, const MovingAiMap& m) {
  if (p.map_width != m.width || p.map_height != m.height)
    return "the problem is for a " + std::to_string(p.map_width) + " × " + std::to_string(p.map_height) + " map, the map is " +
           std::to_string(m.width) + " × " + std::to_string(m.height);
  if (!m.passable(p.start_x, p.start_y)) return "the start (" + std::to_string(p.start_x) + ", " + std::to_string(p.start_y) + ") is not a passable cell";
  if (!m.passable(p.goal_x, p.goal_y)) return "the goal (" + std::to_string(p.goal_x) + ", " + std::to_string(p.goal_y) + ") is not a passable cell";
  return {};
}

MovingAiGraph::MovingAiGraph(const MovingAiMap& map, bool all_known)
    : map_(map), known_(map.terrain.size(), all_known ? 1 : 0) {}

bool MovingAiGraph::blocked(int x, int y) const noexcept {
  if (!inside(x, y)) return true;
  const auto i = static_cast<std::size_t>(vertex(x, y));
  return known_[i] != 0 && !MovingAiMap::passable_char(map_.terrain[i]);
}

bool MovingAiGraph::reveal(int v) noexcept {
  auto& k = known_[static_cast<std::size_t>(v)];
  if (k != 0) return false;
  k = 1;
  return !MovingAiMap::passable_char(map_.terrain[static_cast<std::size_t>(v)]);
}

Cost MovingAiGraph::step_cost(int v, int k) const noexcept {
  const int x = x_of(v), y = y_of(v);
  const GridStep s = kGridSteps[static_cast<std::size_t>(k)];
  if (blocked(x, y) || blocked(x + s.dx, y + s.dy)) return kInfiniteCost;
  if (!is_diagonal(k)) return kCellCost;
  if (blocked(x + s.dx, y) || blocked(x, y + s.dy)) return kInfiniteCost;  // no corner cutting
  return kDiagonalCost;
}

}  // namespace ringlet::planning
