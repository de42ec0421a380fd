#pragma once
// Generic design sweeps: `--param` specs (ranges, lists, single values) expanded into a
// Cartesian grid of config overrides, and SVG heatmaps of one number per design.

#include <string>
#include <utility>
#include <vector>

namespace tactip {

/// Most values one `--param` may produce.
inline constexpr int kMaxSweepValues = 1000;
/// Most designs one grid may hold (guards against an accidental 1000^3 sweep).
inline constexpr long long kMaxSweepDesigns = 100000;

/// One swept config key and the values it takes, in sweep order (never empty or
/// repeated when made by ParseSweepParam).
struct SweepParam {
  std::string key;                  ///< dotted config key, e.g. "skin.thickness_mm"
  std::vector<std::string> values;  ///< override texts, as for `--set key=value`
};

/// Parses one `--param` spec:
///   "key=start:stop:step"  numeric range start, start+step, ... up to stop (stop is
///                          included when reached within 1e-9*step); values are computed
///                          as start + i*step and printed with 10 significant digits
///                          ("0.3", not "0.30000000000000004");
///   "key=v1,v2,v3"         explicit list of numbers or words, taken verbatim;
///   "key=value"            a single value.
/// Throws InputError "--param 'SPEC': problem" (one line) for a missing '=', an empty key
/// or value, a non-numeric range part, step <= 0, stop < start, more than
/// kMaxSweepValues values or a repeated value.
SweepParam ParseSweepParam(const std::string& spec);

/// One design of a sweep: (key, value) pairs in parameter order.
using SweepDesign = std::vector<std::pair<std::string, std::string>>;

/// Expands the full Cartesian grid; the first parameter varies slowest. No parameters
/// gives one design with no pairs. Throws InputError for a key swept twice, a parameter
/// with no values or a grid larger than kMaxSweepDesigns.
std::vector<SweepDesign> ExpandGrid(const std::vector<SweepParam>& params);

/// A self-contained SVG heatmap: one coloured cell (<rect class="cell">) per value,
/// coloured on a viridis scale between the smallest and largest finite value and labelled
/// with the value to 3 significant digits (NaN: grey, "n/a"; infinities: grey, "inf"),
/// tick labels from `x_values` (columns) and `y_values` (rows, first on top), axis
/// labels, a title and a colour bar with min, max and `unit`. `cells` is row-major:
/// cells[iy * x_values.size() + ix]. A single row (one empty y value, empty y label)
/// draws as a 1-D strip with no y axis. All text is XML-escaped. Throws
/// std::invalid_argument if either axis is empty or cells.size() != x * y.
std::string HeatmapSvg(const std::string& title, const std::string& x_label, const std::vector<std::string>& x_values,
                       const std::string& y_label, const std::vector<std::string>& y_values,
                       const std::vector<double>& cells, const std::string& unit);

/// Writes HeatmapSvg(...) to `path` atomically; throws as HeatmapSvg, or InputError
/// naming the path if it cannot be written.
void WriteHeatmapSvg(const std::string& path, const std::string& title, const std::string& x_label,
                     const std::vector<std::string>& x_values, const std::string& y_label,
                     const std::vector<std::string>& y_values, const std::vector<double>& cells,
                     const std::string& unit);

}  // namespace tactip
