#include "scenarios/studies/sweeps/sweep_grid.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "sim/base/number_text.h"
#include "sim/config.h"

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
  if (!ParseWhole(text, v) || !std::isfinite(v)) {
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

}  // namespace tactip
