#include "svg_chart.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "format.hpp"

namespace ringlet::experiments {
namespace {

constexpr double kPanelW = 460, kPanelH = 340;
constexpr double kLeft = 60, kRight = 15, kTop = 40, kBottom = 60;

std::string esc(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

struct Frame {  // a panel's plotting area and its y range
  double x0, y0, w, h, lo, hi;
  [[nodiscard]] double y(double v) const { return y0 + h - (v - lo) / (hi - lo) * h; }
};

// A "nice" range covering [lo, hi] and 0, with ticks.
Frame frame(double ox, double lo, double hi) {
  lo = std::min(lo, 0.0);
  hi = std::max(hi, 0.0);
  if (hi - lo < 1e-9) hi = lo + 1.0;
  const double span = (hi - lo) * 1.1;
  const double step = std::pow(10.0, std::floor(std::log10(span / 5.0)));
  lo = std::floor(lo / step) * step;
  hi = std::ceil(hi * 1.05 / step) * step;
  return Frame{ox + kLeft, kTop, kPanelW - kLeft - kRight, kPanelH - kTop - kBottom, lo, hi};
}

void axes(std::ostringstream& s, const Frame& f, const std::string& title, const std::string& y_label) {
  s << "<text x=\"" << fixed(f.x0 + f.w / 2, 1) << "\" y=\"22\" text-anchor=\"middle\" font-size=\"13\">" << esc(title)
    << "</text>\n";
  const double range = f.hi - f.lo;
  const double step = std::pow(10.0, std::floor(std::log10(range / 4.0)));
  const double tick = range / step > 8 ? 2 * step : step;
  for (double v = std::ceil(f.lo / tick) * tick; v <= f.hi + 1e-9; v += tick) {
    s << "<line x1=\"" << fixed(f.x0, 1) << "\" x2=\"" << fixed(f.x0 + f.w, 1) << "\" y1=\"" << fixed(f.y(v), 1)
      << "\" y2=\"" << fixed(f.y(v), 1) << "\" stroke=\"#ddd\"/>\n"
      << "<text x=\"" << fixed(f.x0 - 4, 1) << "\" y=\"" << fixed(f.y(v) + 4, 1)
      << "\" text-anchor=\"end\" font-size=\"10\">" << fixed(v, step < 1 ? 2 : 0) << "</text>\n";
  }
  s << "<line x1=\"" << fixed(f.x0, 1) << "\" x2=\"" << fixed(f.x0 + f.w, 1) << "\" y1=\"" << fixed(f.y(0), 1)
    << "\" y2=\"" << fixed(f.y(0), 1) << "\" stroke=\"black\"/>\n"
    << "<text transform=\"translate(" << fixed(f.x0 - 45, 1) << " " << fixed(f.y0 + f.h / 2, 1)
    << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"11\">" << esc(y_label) << "</text>\n";
}

void write(const std::filesystem::path& path, double width, const std::string& body) {
  std::ofstream out(path);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\""
      << fixed(width, 0) << "\" height=\"" << fixed(kPanelH, 0) << "\" font-family=\"sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n" << body << "</svg>\n";
  if (!out) throw std::runtime_error(path.string() + ": cannot write");
}

}  // namespace

void write_bar_panels(const std::filesystem::path& path, const std::vector<Bars>& panels) {
  std::ostringstream s;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Bars& b = panels[p];
    double lo = 0, hi = 0;
    for (const double v : b.values)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (!std::isnan(b.reference)) hi = std::max(hi, b.reference);
    const Frame f = frame(static_cast<double>(p) * kPanelW, lo, hi);
    axes(s, f, b.title, b.y_label);
    const double slot = f.w / static_cast<double>(std::max<std::size_t>(b.values.size(), 1));
    for (std::size_t i = 0; i < b.values.size(); ++i) {
      const double x = f.x0 + slot * static_cast<double>(i);
      const double v = std::isfinite(b.values[i]) ? b.values[i] : 0.0;
      const double top = std::min(f.y(v), f.y(0)), height = std::abs(f.y(v) - f.y(0));
      s << "<rect x=\"" << fixed(x + slot * 0.15, 1) << "\" y=\"" << fixed(top, 1) << "\" width=\""
        << fixed(slot * 0.7, 1) << "\" height=\"" << fixed(height, 1) << "\" fill=\"#1f5fd1\"/>\n"
        << "<text x=\"" << fixed(x + slot / 2, 1) << "\" y=\"" << fixed(top - 3, 1)
        << "\" text-anchor=\"middle\" font-size=\"9\">" << (std::isfinite(b.values[i]) ? fixed(b.values[i], 3) : "n/a")
        << "</text>\n<text x=\"" << fixed(x + slot / 2, 1) << "\" y=\"" << fixed(f.y0 + f.h + 16, 1)
        << "\" text-anchor=\"middle\" font-size=\"10\">" << esc(b.labels[i]) << "</text>\n";
    }
    if (!std::isnan(b.reference)) {
      s << "<line x1=\"" << fixed(f.x0, 1) << "\" x2=\"" << fixed(f.x0 + f.w, 1) << "\" y1=\"" << fixed(f.y(b.reference), 1)
        << "\" y2=\"" << fixed(f.y(b.reference), 1) << "\" stroke=\"#d62020\" stroke-dasharray=\"5 3\"/>\n"
        << "<text x=\"" << fixed(f.x0 + f.w, 1) << "\" y=\"" << fixed(f.y(b.reference) - 3, 1)
        << "\" text-anchor=\"end\" font-size=\"10\" fill=\"#d62020\">" << esc(b.reference_label) << "</text>\n";
    }
    s << "<text x=\"" << fixed(f.x0 + f.w / 2, 1) << "\" y=\"" << fixed(f.y0 + f.h + 40, 1)
      << "\" text-anchor=\"middle\" font-size=\"11\">training examples n</text>\n";
  }
  write(path, kPanelW * static_cast<double>(panels.size()), s.str());
}

void write_line_panels(const std::filesystem::path& path, const std::vector<Lines>& panels) {
  std::ostringstream s;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Lines& l = panels[p];
    double hi = 0;
    std::size_t count = 1;
    for (const Line& line : l.lines) {
      count = std::max(count, line.y.size());
      for (const double v : line.y)
        if (std::isfinite(v)) hi = std::max(hi, v);
    }
    const Frame f = frame(static_cast<double>(p) * kPanelW, 0, hi);
    axes(s, f, l.title, l.y_label);
    const auto x = [&](std::size_t i) {
      return f.x0 + (count == 1 ? f.w / 2 : f.w * static_cast<double>(i) / static_cast<double>(count - 1));
    };
    for (std::size_t i = 0; i < count; ++i)
      s << "<text x=\"" << fixed(x(i), 1) << "\" y=\"" << fixed(f.y0 + f.h + 16, 1)
        << "\" text-anchor=\"middle\" font-size=\"10\">" << i + 1 << "</text>\n";
    s << "<text x=\"" << fixed(f.x0 + f.w / 2, 1) << "\" y=\"" << fixed(f.y0 + f.h + 34, 1)
      << "\" text-anchor=\"middle\" font-size=\"11\">" << esc(l.x_label) << "</text>\n";
    for (std::size_t k = 0; k < l.lines.size(); ++k) {
      const Line& line = l.lines[k];
      std::string points;
      for (std::size_t i = 0; i < line.y.size(); ++i) {
        if (!std::isfinite(line.y[i])) continue;
        points += fixed(x(i), 1) + "," + fixed(f.y(line.y[i]), 1) + " ";
        if (!line.dashed)
          s << "<circle cx=\"" << fixed(x(i), 1) << "\" cy=\"" << fixed(f.y(line.y[i]), 1) << "\" r=\"3\" fill=\""
            << line.colour << "\"/>\n";
      }
      s << "<polyline fill=\"none\" stroke=\"" << line.colour << "\" stroke-width=\"2\"" 
        << (line.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"" << points << "\"/>\n"
        << "<text x=\"" << fixed(f.x0 + 8, 1) << "\" y=\"" << fixed(f.y0 + 14 + 14 * static_cast<double>(k), 1)
        << "\" font-size=\"11\" fill=\"" << line.colour << "\">" << esc(line.name) << "</text>\n";
    }
  }
  write(path, kPanelW * static_cast<double>(panels.size()), s.str());
}

}  // namespace ringlet::experiments
