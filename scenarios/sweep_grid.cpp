#include "scenarios/sweep_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

#include "sim/config.h"
#include "sim/files.h"

namespace tactip {
namespace {

// ---------------------------------------------------------------- --param specs

/// The spec as it appears in messages: control characters shown as escapes so that the
/// message stays on one line.
std::string Printable(const std::string& text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  return out;
}

InputError SpecError(const std::string& spec, const std::string& problem) {
  return InputError("--param '" + Printable(spec) + "': " + problem);
}

/// One part of a range: a finite number, nothing else.
double RangeNumber(const std::string& spec, const std::string& text, const char* what) {
  double v = 0.0;
  const char* b = text.data();
  const char* e = b + text.size();
  const auto res = std::from_chars(b, e, v);
  if (text.empty() || res.ec != std::errc() || res.ptr != e || !std::isfinite(v)) {
    throw SpecError(spec, fmt::format("range {} '{}' is not a number", what, Printable(text)));
  }
  return v;
}

std::vector<std::string> Split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (true) {
    const size_t at = text.find(sep, start);
    parts.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return parts;
    start = at + 1;
  }
}

/// start, start+step, ..., stop (within 1e-9*step), each printed with 10 significant
/// digits. Values are start + i*step, never accumulated, and snapped to stop / to 0 when
/// within the tolerance so that rounding noise ("5.55e-17") never reaches the text.
std::vector<std::string> RangeValues(const std::string& spec, const std::string& range) {
  const std::vector<std::string> parts = Split(range, ':');
  if (parts.size() != 3) throw SpecError(spec, "a range is start:stop:step (three numbers)");
  const double start = RangeNumber(spec, parts[0], "start");
  const double stop = RangeNumber(spec, parts[1], "stop");
  const double step = RangeNumber(spec, parts[2], "step");
  if (step <= 0.0) throw SpecError(spec, "step <= 0");
  if (stop < start) throw SpecError(spec, "stop < start");
  const double tol = 1e-9 * step;
  const double steps = (stop - start) / step + 1e-9;  // inf if the span overflows
  if (!(steps < kMaxSweepValues)) {
    throw SpecError(spec, fmt::format("more than {} values", kMaxSweepValues));
  }
  const int n = static_cast<int>(std::floor(steps)) + 1;
  std::vector<std::string> values;
  values.reserve(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    double v = start + i * step;
    if (std::abs(v - stop) <= tol) v = stop;
    if (std::abs(v) <= tol) v = 0.0;
    values.push_back(fmt::format("{:.10g}", v));
  }
  if (std::set<std::string>(values.begin(), values.end()).size() != values.size()) {
    throw SpecError(spec, "duplicate values (step too small for 10 significant digits)");
  }
  return values;
}

std::vector<std::string> ListValues(const std::string& spec, const std::string& list) {
  std::vector<std::string> values = Split(list, ',');
  std::set<std::string> seen;
  for (const std::string& v : values) {
    if (v.empty()) throw SpecError(spec, "empty value in list");
    if (!seen.insert(v).second) throw SpecError(spec, "duplicate value '" + Printable(v) + "'");
  }
  if (values.size() > static_cast<size_t>(kMaxSweepValues)) {
    throw SpecError(spec, fmt::format("more than {} values", kMaxSweepValues));
  }
  return values;
}

// ---------------------------------------------------------------- SVG heatmap

/// Text safe inside XML elements and attributes. Control characters that XML 1.0
/// cannot carry become '?'.
std::string XmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : c;
    }
  }
  return out;
}

/// Rough rendered width (px) of `text` in a sans-serif font of size `font_px`.
double TextWidth(const std::string& text, double font_px) {
  size_t glyphs = 0;
  for (const char c : text) glyphs += (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // UTF-8 lead bytes
  return 0.56 * font_px * static_cast<double>(glyphs);
}

struct Rgb {
  double r, g, b;  // 0..255
};

/// Viridis at nine evenly spaced points (matplotlib's map; dark purple -> yellow).
constexpr std::array<Rgb, 9> kViridis{{{0x44, 0x01, 0x54},
                                       {0x47, 0x2d, 0x7b},
                                       {0x3b, 0x52, 0x8b},
                                       {0x2c, 0x72, 0x8e},
                                       {0x21, 0x90, 0x8c},
                                       {0x27, 0xad, 0x81},
                                       {0x5d, 0xc8, 0x63},
                                       {0xaa, 0xdc, 0x32},
                                       {0xfd, 0xe7, 0x25}}};

/// Viridis at t in [0, 1], linearly interpolated between the stops.
Rgb Viridis(double t) {
  t = std::clamp(t, 0.0, 1.0) * (kViridis.size() - 1);
  const size_t i = std::min(static_cast<size_t>(t), kViridis.size() - 2);
  const double f = t - static_cast<double>(i);
  const Rgb& a = kViridis[i];
  const Rgb& b = kViridis[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

std::string Hex(const Rgb& c) {
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 255.0))); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(c.r), byte(c.g), byte(c.b));
}

/// Black text on light colours, white on dark ones.
const char* TextColourOn(const Rgb& c) { return 0.299 * c.r + 0.587 * c.g + 0.114 * c.b > 140 ? "#000" : "#fff"; }

constexpr double kTickFont = 12, kCellFont = 12, kLabelFont = 13, kTitleFont = 15;
constexpr double kCellHeight = 30, kMinCellWidth = 48, kMaxCellWidth = 120;
constexpr double kBarWidth = 14, kMinBarHeight = 60, kMargin = 10;
constexpr double kRotatedTickDeg = 40;  // long x tick labels are drawn slanted
const Rgb kMissing{0xbb, 0xbb, 0xbb};

}  // namespace

SweepParam ParseSweepParam(const std::string& spec) {
  const size_t eq = spec.find('=');
  if (eq == std::string::npos) {
    throw SpecError(spec, "expected key=start:stop:step, key=v1,v2,... or key=value");
  }
  SweepParam p;
  p.key = spec.substr(0, eq);
  const std::string value = spec.substr(eq + 1);
  if (p.key.empty()) throw SpecError(spec, "empty key");
  if (value.empty()) throw SpecError(spec, "empty value");
  if (value.find(':') != std::string::npos) {
    p.values = RangeValues(spec, value);
  } else {
    p.values = ListValues(spec, value);  // one item for a single value
  }
  return p;
}

std::vector<SweepDesign> ExpandGrid(const std::vector<SweepParam>& params) {
  std::set<std::string> keys;
  long long total = 1;
  for (const SweepParam& p : params) {
    if (!keys.insert(p.key).second) throw InputError("--param: key '" + Printable(p.key) + "' is swept twice");
    if (p.values.empty()) throw InputError("--param '" + Printable(p.key) + "': no values");
    const auto n = static_cast<long long>(p.values.size());
    if (n > kMaxSweepDesigns / total) {
      throw InputError(fmt::format("--param: the grid has more than {} designs", kMaxSweepDesigns));
    }
    total *= n;
  }
  std::vector<SweepDesign> designs;
  designs.reserve(static_cast<size_t>(total));
  std::vector<size_t> at(params.size(), 0);  // odometer; the last parameter turns fastest
  for (long long d = 0; d < total; ++d) {
    SweepDesign design;
    design.reserve(params.size());
    for (size_t i = 0; i < params.size(); ++i) design.emplace_back(params[i].key, params[i].values[at[i]]);
    designs.push_back(std::move(design));
    for (size_t i = params.size(); i-- > 0;) {
      if (++at[i] < params[i].values.size()) break;
      at[i] = 0;
    }
  }
  return designs;
}

std::string HeatmapSvg(const std::string& title, const std::string& x_label, const std::vector<std::string>& x_values,
                       const std::string& y_label, const std::vector<std::string>& y_values,
                       const std::vector<double>& cells, const std::string& unit) {
  const size_t nx = x_values.size(), ny = y_values.size();
  if (nx == 0 || ny == 0) throw std::invalid_argument("HeatmapSvg: needs at least one x and one y value");
  if (cells.size() != nx * ny) {
    throw std::invalid_argument(
        fmt::format("HeatmapSvg: {} cells for {} x values and {} y values", cells.size(), nx, ny));
  }

  // Colour scale over the finite values.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const double v : cells) {
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  const bool any_finite = lo <= hi;
  auto cell_text = [](double v) { return std::isnan(v) ? std::string("n/a") : fmt::format("{:.3g}", v); };
  auto colour = [&](double v) {
    if (!std::isfinite(v)) return kMissing;
    return Viridis(hi > lo ? (v - lo) / (hi - lo) : 0.5);
  };

  // Layout: title on top; y ticks (and label) left of the grid; x ticks and label below;
  // the colour bar right of the grid.
  double x_tick_w = 0, y_tick_w = 0, cell_text_w = 0;
  for (const auto& s : x_values) x_tick_w = std::max(x_tick_w, TextWidth(s, kTickFont));
  for (const auto& s : y_values) y_tick_w = std::max(y_tick_w, TextWidth(s, kTickFont));
  for (const double v : cells) cell_text_w = std::max(cell_text_w, TextWidth(cell_text(v), kCellFont));
  const bool slanted = x_tick_w + 8 > kMaxCellWidth;
  const double cell_w = std::max({kMinCellWidth, cell_text_w + 12, slanted ? 0.0 : x_tick_w + 8});
  const double grid_w = cell_w * static_cast<double>(nx), grid_h = kCellHeight * static_cast<double>(ny);
  const double y_label_w = TextWidth(y_label, kLabelFont);
  const bool y_label_horizontal = !y_label.empty() && y_label_w > grid_h;  // too long to run along the axis
  const double sin_a = std::sin(kRotatedTickDeg * std::numbers::pi / 180),
               cos_a = std::cos(kRotatedTickDeg * std::numbers::pi / 180);

  double left = kMargin + (y_tick_w > 0 ? y_tick_w + 8 : 0);
  if (!y_label.empty()) left += (y_label_horizontal ? y_label_w : kLabelFont) + 10;
  if (slanted) left = std::max(left, kMargin + cos_a * x_tick_w - cell_w / 2);
  const double x_label_w = TextWidth(x_label, kLabelFont);
  left = std::max(left, kMargin + x_label_w / 2 - grid_w / 2);
  const double top = kMargin + (title.empty() ? 14 : kTitleFont + 22);
  const double x_ticks_h = slanted ? sin_a * x_tick_w + kTickFont + 6 : kTickFont + 8;
  const double below = x_ticks_h + (x_label.empty() ? 0 : kLabelFont + 10);
  const double bar_x = left + grid_w + 20, bar_h = std::max(grid_h, kMinBarHeight);
  const std::string hi_text = any_finite ? fmt::format("{:.3g}", hi) : "n/a";
  const std::string lo_text = any_finite ? fmt::format("{:.3g}", lo) : "n/a";
  const double bar_text_w =
      std::max({TextWidth(hi_text, kTickFont), TextWidth(lo_text, kTickFont), TextWidth(unit, kTickFont) - kBarWidth});
  const double width =
      std::ceil(std::max({bar_x + kBarWidth + 6 + bar_text_w + kMargin, TextWidth(title, kTitleFont) + 2 * kMargin,
                          left + grid_w / 2 + x_label_w / 2 + kMargin}));
  const double height = std::ceil(std::max(top + grid_h + below, top + bar_h) + kMargin);

  std::string svg;
  const auto out = std::back_inserter(svg);
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  fmt::format_to(out,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
                 "font-family=\"sans-serif\">\n",
                 width, height);
  fmt::format_to(out, "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#fff\"/>\n", width, height);
  if (!title.empty()) {
    fmt::format_to(
        out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" font-weight=\"bold\" text-anchor=\"middle\">{}</text>\n",
        width / 2, kMargin + kTitleFont, kTitleFont, XmlEscape(title));
  }

  // Cells, each with a tooltip naming its coordinates.
  for (size_t iy = 0; iy < ny; ++iy) {
    for (size_t ix = 0; ix < nx; ++ix) {
      const double v = cells[iy * nx + ix];
      const Rgb c = colour(v);
      const double x = left + cell_w * static_cast<double>(ix), y = top + kCellHeight * static_cast<double>(iy);
      std::string tip = (x_label.empty() ? "" : x_label + " = ") + x_values[ix];
      if (ny > 1 || !y_values[iy].empty()) tip += ", " + (y_label.empty() ? "" : y_label + " = ") + y_values[iy];
      tip += ": " + (std::isnan(v) ? std::string("n/a") : fmt::format("{:.6g}", v)) +
             (unit.empty() || std::isnan(v) ? "" : " " + unit);
      fmt::format_to(out,
                     "<rect class=\"cell\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\" "
                     "stroke=\"#fff\" stroke-width=\"1\"><title>{}</title></rect>\n",
                     x, y, cell_w, kCellHeight, Hex(c), XmlEscape(tip));
      fmt::format_to(
          out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" text-anchor=\"middle\" fill=\"{}\">{}</text>\n",
          x + cell_w / 2, y + kCellHeight / 2 + kCellFont * 0.35, kCellFont, TextColourOn(c), XmlEscape(cell_text(v)));
    }
  }

  // Axes: tick labels, then axis labels.
  for (size_t iy = 0; iy < ny; ++iy) {
    if (y_values[iy].empty()) continue;
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" text-anchor=\"end\">{}</text>\n", left - 6,
                   top + kCellHeight * (static_cast<double>(iy) + 0.5) + kTickFont * 0.35, kTickFont,
                   XmlEscape(y_values[iy]));
  }
  const double tick_y = top + grid_h + kTickFont + 4;
  for (size_t ix = 0; ix < nx; ++ix) {
    const double cx = left + cell_w * (static_cast<double>(ix) + 0.5);
    if (slanted) {
      fmt::format_to(out,
                     "<text x=\"{0:.1f}\" y=\"{1:.1f}\" font-size=\"{2}\" text-anchor=\"end\" "
                     "transform=\"rotate(-{3} {0:.1f} {1:.1f})\">{4}</text>\n",
                     cx, tick_y, kTickFont, kRotatedTickDeg, XmlEscape(x_values[ix]));
    } else {
      fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" text-anchor=\"middle\">{}</text>\n", cx,
                     tick_y, kTickFont, XmlEscape(x_values[ix]));
    }
  }
  if (!x_label.empty()) {
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" text-anchor=\"middle\">{}</text>\n",
                   left + grid_w / 2, top + grid_h + x_ticks_h + kLabelFont + 2, kLabelFont, XmlEscape(x_label));
  }
  if (!y_label.empty()) {
    const double cy = top + grid_h / 2;
    // Right of the label: its tick labels (ending 6 px left of the grid), then a gap.
    const double label_right = left - (y_tick_w > 0 ? y_tick_w + 6 : 0) - 10;
    if (y_label_horizontal) {
      fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\" text-anchor=\"end\">{}</text>\n",
                     label_right, cy + kLabelFont * 0.35, kLabelFont, XmlEscape(y_label));
    } else {
      fmt::format_to(out,
                     "<text x=\"{0:.1f}\" y=\"{1:.1f}\" font-size=\"{2}\" text-anchor=\"middle\" "
                     "transform=\"rotate(-90 {0:.1f} {1:.1f})\">{3}</text>\n",
                     label_right, cy, kLabelFont, XmlEscape(y_label));
    }
  }

  // Colour bar: max on top, min at the bottom, unit above.
  if (any_finite) {
    svg += "<defs><linearGradient id=\"colour-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
    for (size_t i = 0; i < kViridis.size(); ++i) {
      fmt::format_to(out, "<stop offset=\"{:.3f}\" stop-color=\"{}\"/>", static_cast<double>(i) / (kViridis.size() - 1),
                     Hex(kViridis[i]));
    }
    svg += "</linearGradient></defs>\n";
  }
  fmt::format_to(out,
                 "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{}\" height=\"{:.1f}\" fill=\"{}\" stroke=\"#444\" "
                 "stroke-width=\"0.5\"/>\n",
                 bar_x, top, kBarWidth, bar_h, any_finite ? std::string("url(#colour-bar)") : Hex(kMissing));
  fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\">{}</text>\n", bar_x + kBarWidth + 6,
                 top + kTickFont * 0.8, kTickFont, XmlEscape(hi_text));
  fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\">{}</text>\n", bar_x + kBarWidth + 6,
                 top + bar_h, kTickFont, XmlEscape(lo_text));
  if (!unit.empty()) {
    fmt::format_to(out, "<text x=\"{:.1f}\" y=\"{:.1f}\" font-size=\"{}\">{}</text>\n", bar_x, top - 6, kTickFont,
                   XmlEscape(unit));
  }
  svg += "</svg>\n";
  return svg;
}

void WriteHeatmapSvg(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::vector<std::string>& x_values, const std::string& y_label,
                     const std::vector<std::string>& y_values, const std::vector<double>& cells,
                     const std::string& unit) {
  WriteFileAtomic(path, HeatmapSvg(title, x_label, x_values, y_label, y_values, cells, unit));
}

}  // namespace tactip
