#pragma once
// Typed configuration with units, documentation and bounds on every field.
//
// A config struct lists its fields once, in a `Visit` member template:
//
//   template <class V> void Visit(V& v) {
//     v("mass_kg", mass_kg, "kg", "Mass of the slider and stimulus.", Bounds::Positive());
//   }
//
// and nested structs with `v.Section("object", object)`. Generic visitors then load
// YAML, apply `--set key=value` overrides, check bounds, list the documentation and
// write the fully resolved config back as YAML. Unknown keys are errors.

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sim/base/errors.h"

namespace tactip {

/// Allowed interval of a numeric config field; open or closed at either end.
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();  ///< lower limit
  double hi = std::numeric_limits<double>::infinity();   ///< upper limit
  bool lo_open = false;                                   ///< true: value must be > lo
  bool hi_open = false;                                   ///< true: value must be < hi

  /// Any finite value.
  static Bounds Any() { return {}; }
  /// value > 0.
  static Bounds Positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  /// value >= 0.
  static Bounds NonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  /// lo <= value <= hi.
  static Bounds Closed(double lo, double hi) { return {lo, hi, false, false}; }
  /// lo < value <= hi.
  static Bounds LeftOpen(double lo, double hi) { return {lo, hi, true, false}; }
  /// lo <= value < hi.
  static Bounds RightOpen(double lo, double hi) { return {lo, hi, false, true}; }

  /// Empty when `v` is allowed, else the rule it breaks ("must be > 0").
  std::string Check(double v) const;
  /// Human-readable interval, e.g. "(0, inf)".
  std::string Describe() const;
};

/// Allowed values of a string-valued config field.
using Choices = std::vector<std::string>;

/// One documented config field, as listed by `tactip config`.
struct FieldDoc {
  std::string key;      ///< dotted key, e.g. "rail.retract_speed_mm_s"
  std::string type;     ///< "real", "int", "bool" or "string"
  std::string unit;     ///< unit symbol, empty for dimensionless
  std::string value;    ///< current value as text
  std::string allowed;  ///< interval or list of choices
  std::string doc;      ///< what the field means and why the default is what it is
};

namespace config_detail {

/// Formats a double so that parsing it back yields the same bits.
std::string FormatReal(double v);
/// `limit` to three significant digits, rounded down (FormatAtMost) or up (FormatAtLeast) so
/// that the printed value, parsed back, still satisfies "<= limit" or ">= limit": the safe
/// value a refusal suggests is accepted when entered as printed.
std::string FormatAtMost(double limit);
std::string FormatAtLeast(double limit);
/// `text` with control characters escaped (a line break as \n, others as \xNN), so that
/// a message quoting user input stays on one line.
std::string Escaped(std::string_view text);
/// Parses text into a field value; throws InputError naming `key`.
double ParseReal(const std::string& key, const std::string& text);
long long ParseInt(const std::string& key, const std::string& text);
bool ParseBool(const std::string& key, const std::string& text);

/// Prefix-tracking base of all visitors (CRTP: `Derived` is the concrete visitor).
template <class Derived>
class PathVisitor {
 public:
  /// Visits a nested config struct under "name.".
  template <class Sub>
  void Section(std::string_view name, Sub& sub) {
    const std::string saved = prefix_;
    prefix_ += std::string(name) + ".";
    sub.Visit(static_cast<Derived&>(*this));
    prefix_ = saved;
  }
  /// Visits a list of config structs: entry i as the section "name.i." (keys such as
  /// "sensors.1.name"; a YAML list under `name` gives the same keys). A visitor that assigns
  /// values grows the list first to hold every index it is given (GrowList).
  template <class Item>
  void List(std::string_view name, std::vector<Item>& items) {
    static_cast<Derived&>(*this).GrowList(Key(name), items);
    for (size_t i = 0; i < items.size(); ++i) Section(std::string(name) + "." + std::to_string(i), items[i]);
  }
  /// Only AssignVisitor grows lists.
  template <class Item>
  void GrowList(const std::string&, std::vector<Item>&) {}
  /// Full dotted key of a field in the current section.
  std::string Key(std::string_view name) const { return prefix_ + std::string(name); }

 protected:
  std::string prefix_;
};

/// Checks a numeric value against its bounds; throws InputError
/// "key = value: must be ...".
void CheckBounds(const std::string& key, double v, const Bounds& b);
/// Checks a string value against its choices.
void CheckChoice(const std::string& key, const std::string& v, const Choices& c);

}  // namespace config_detail

/// Flat map from dotted key to scalar text; the common currency of YAML files and
/// `--set` overrides.
using FlatConfig = std::map<std::string, std::string>;

/// Parses YAML text into a FlatConfig; throws InputError on malformed YAML, naming
/// `source` and the line.
FlatConfig FlattenYaml(const std::string& yaml_text, const std::string& source);
/// Reads and flattens a YAML file; throws InputError if it is missing or malformed.
FlatConfig FlattenYamlFile(const std::string& path);
/// Parses "key=value"; throws InputError if there is no '=', the key is empty, or the text
/// holds a control character (a line break: a value is one line).
std::pair<std::string, std::string> ParseAssignment(const std::string& text);

/// Most entries a config list may have.
inline constexpr size_t kMaxListEntries = 64;

/// Visitor that assigns values from a FlatConfig, erasing each key it consumes.
class AssignVisitor : public config_detail::PathVisitor<AssignVisitor> {
 public:
  explicit AssignVisitor(FlatConfig& values) : values_(values) {}
  /// Appends default entries to the list at dotted key `list_key` up to the largest index
  /// the values name ("list_key.I.field"). Throws InputError for an index past the next new
  /// entry ("sensors.3.name: the list 'sensors' has 1 entry; add sensors.1 first") or past
  /// kMaxListEntries.
  template <class Item>
  void GrowList(const std::string& list_key, std::vector<Item>& items) {
    const size_t needed = ListEntriesNamed(list_key, items.size());
    if (needed > items.size()) items.resize(needed);
  }
  void operator()(std::string_view name, double& f, std::string_view, std::string_view, const Bounds&);
  void operator()(std::string_view name, int& f, std::string_view, std::string_view, const Bounds&);
  void operator()(std::string_view name, bool& f, std::string_view, std::string_view);
  void operator()(std::string_view name, std::string& f, std::string_view, std::string_view, const Choices&);

 private:
  const std::string* Take(std::string_view name);
  size_t ListEntriesNamed(const std::string& list_key, size_t size) const;
  FlatConfig& values_;
  std::string taken_;
};

/// Visitor that checks every field against its bounds; throws on the first violation.
class BoundsVisitor : public config_detail::PathVisitor<BoundsVisitor> {
 public:
  void operator()(std::string_view name, double& f, std::string_view, std::string_view, const Bounds& b);
  void operator()(std::string_view name, int& f, std::string_view, std::string_view, const Bounds& b);
  void operator()(std::string_view, bool&, std::string_view, std::string_view) {}
  void operator()(std::string_view name, std::string& f, std::string_view, std::string_view, const Choices& c);

 private:
};

/// Visitor that lists every field with its documentation.
class DocVisitor : public config_detail::PathVisitor<DocVisitor> {
 public:
  void operator()(std::string_view name, double& f, std::string_view unit, std::string_view doc, const Bounds& b);
  void operator()(std::string_view name, int& f, std::string_view unit, std::string_view doc, const Bounds& b);
  void operator()(std::string_view name, bool& f, std::string_view unit, std::string_view doc);
  void operator()(std::string_view name, std::string& f, std::string_view unit, std::string_view doc, const Choices& c);
  std::vector<FieldDoc> fields;  ///< collected in declaration order

 private:
};

/// Applies `values` to `cfg`; throws InputError naming the first unknown key.
template <class Config>
void ApplyFlat(Config& cfg, FlatConfig values) {
  AssignVisitor v(values);
  cfg.Visit(v);
  if (!values.empty()) {
    throw InputError("unknown config key '" + config_detail::Escaped(values.begin()->first) + "'");
  }
}

/// Checks bounds of every field, then the config's own cross-field rules.
template <class Config>
void ValidateConfig(Config& cfg) {
  BoundsVisitor v;
  cfg.Visit(v);
  cfg.ValidateRules();
}

/// Lists every field of `cfg` with unit, bounds and documentation.
template <class Config>
std::vector<FieldDoc> DescribeConfig(Config cfg) {
  DocVisitor v;
  cfg.Visit(v);
  return v.fields;
}

/// Writes the fully resolved config as nested YAML (every field, current values).
std::string FieldsToYaml(const std::vector<FieldDoc>& fields);

/// The same with each field's documentation and unit as comments above it, after a
/// `header` (comment lines); for config files meant to be read and edited.
std::string FieldsToCommentedYaml(const std::vector<FieldDoc>& fields, const std::string& header);

/// The resolved config as YAML text, as stored in datasets.
template <class Config>
std::string ConfigToYaml(const Config& cfg) {
  return FieldsToYaml(DescribeConfig(cfg));
}

/// Applies the YAML file (if `yaml_path` is non-empty), then the `key=value` overrides in
/// order, to `cfg` and checks every field's bounds, but not the cross-field rules (for a
/// caller that derives fields before the full check). Throws InputError.
template <class Config>
Config ApplyConfig(const std::string& yaml_path, const std::vector<std::string>& overrides, Config cfg = Config{}) {
  if (!yaml_path.empty()) ApplyFlat(cfg, FlattenYamlFile(yaml_path));
  for (const auto& o : overrides) {
    auto [key, value] = ParseAssignment(o);
    ApplyFlat(cfg, FlatConfig{{key, value}});
  }
  BoundsVisitor v;
  cfg.Visit(v);
  return cfg;
}

/// Loads a config: defaults, then the YAML file (if `yaml_path` is non-empty), then the
/// `key=value` overrides in order; validates the result. Throws InputError.
template <class Config>
Config LoadConfig(const std::string& yaml_path, const std::vector<std::string>& overrides,
                  Config cfg = Config{}) {
  cfg = ApplyConfig(yaml_path, overrides, std::move(cfg));
  cfg.ValidateRules();
  return cfg;
}

/// Throws InputError "key = value: reason" for cross-field rules in ValidateRules().
[[noreturn]] void FailRule(const std::string& key, double value, const std::string& rule);
/// The same for a text-valued key: "key = 'value': reason".
[[noreturn]] void FailRule(const std::string& key, const std::string& value, const std::string& rule);

}  // namespace tactip
