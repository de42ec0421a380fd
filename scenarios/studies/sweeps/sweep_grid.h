#pragma once
// Generic design sweeps: `--param` specs (ranges, lists, single values) expanded into a
// Cartesian grid of config overrides.

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

}  // namespace tactip
