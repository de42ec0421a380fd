#include "sim/config.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "sim/base/number_text.h"

namespace tactip {

std::string Bounds::Check(double v) const {
  if (!std::isfinite(v)) return "must be a finite number";
  // Name the violated side only: "must be > 0", "must be <= 100".
  if (lo_open ? !(v > lo) : !(v >= lo)) {
    return std::string("must be ") + (lo_open ? "> " : ">= ") + config_detail::FormatReal(lo);
  }
  if (hi_open ? !(v < hi) : !(v <= hi)) {
    return std::string("must be ") + (hi_open ? "< " : "<= ") + config_detail::FormatReal(hi);
  }
  return {};
}

std::string Bounds::Describe() const {
  auto num = [](double x) { return std::isinf(x) ? std::string(x < 0 ? "-inf" : "inf") : config_detail::FormatReal(x); };
  return std::string(lo_open || std::isinf(lo) ? "(" : "[") + num(lo) + ", " + num(hi) +
         (hi_open || std::isinf(hi) ? ")" : "]");
}

namespace config_detail {

std::string FormatReal(double v) {
  // Shortest text that parses back to the same double.
  return RoundTripText(v);
}

namespace {

// `v` to `digits` significant digits, rounded towards -inf (down) or +inf, such that the
// text parses back to a value on that side of `v`; more digits where rounding alone is
// not enough.
std::string FormatRounded(double v, bool down) {
  if (v == 0.0 || !std::isfinite(v)) return FormatReal(v);
  for (int digits = 3; digits <= 17; ++digits) {
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(v))));
    const double r = (down ? std::floor(v * scale) : std::ceil(v * scale)) / scale;
    const std::string text = fmt::format("{:.{}g}", r, digits);
    const double back = std::strtod(text.c_str(), nullptr);
    if (down ? back <= v : back >= v) return text;
  }
  return FormatReal(v);
}

}  // namespace

std::string FormatAtMost(double limit) { return FormatRounded(limit, true); }
std::string FormatAtLeast(double limit) { return FormatRounded(limit, false); }

std::string Escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\r') {
      out += "\\r";
    } else if (ch == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += ch;
    }
  }
  return out;
}

double ParseReal(const std::string& key, const std::string& text) {
  double v = 0.0;
  if (!ParseWhole(text, v)) {
    throw InputError(Escaped(key) + " = '" + Escaped(text) + "': not a number");
  }
  return v;
}

long long ParseInt(const std::string& key, const std::string& text) {
  long long v = 0;
  if (!ParseWhole(text, v)) {
    throw InputError(Escaped(key) + " = '" + Escaped(text) + "': not an integer");
  }
  return v;
}

bool ParseBool(const std::string& key, const std::string& text) {
  if (text == "true" || text == "1" || text == "yes" || text == "on") return true;
  if (text == "false" || text == "0" || text == "no" || text == "off") return false;
  throw InputError(Escaped(key) + " = '" + Escaped(text) + "': not a boolean (true/false)");
}

void CheckBounds(const std::string& key, double v, const Bounds& b) {
  const std::string rule = b.Check(v);
  if (!rule.empty()) throw InputError(key + " = " + FormatReal(v) + ": " + rule);
}

void CheckChoice(const std::string& key, const std::string& v, const Choices& c) {
  for (const auto& x : c) {
    if (x == v) return;
  }
  std::string list;
  for (const auto& x : c) list += (list.empty() ? "" : ", ") + x;
  throw InputError(Escaped(key) + " = '" + Escaped(v) + "': must be one of " + list);
}

}  // namespace config_detail

namespace {

// A config file has about a hundred keys; a walk that visits more nodes than this is an
// alias expanding exponentially ("billion laughs"), refused before it exhausts memory.
constexpr long kMaxYamlNodes = 10000;

// What the walk over one file carries along.
struct FlattenWalk {
  const std::string& source;
  FlatConfig& out;
  long nodes = 0;
};

// "file: ... (line N)" for a node.
std::string AtLine(const YAML::Node& node) { return " (line " + std::to_string(node.Mark().line + 1) + ")"; }

// Walks a YAML node, writing every scalar leaf under its dotted key; each node an alias
// points to is visited (and counted) again.
void Flatten(const YAML::Node& node, const std::string& prefix, FlattenWalk& walk) {
  if (++walk.nodes > kMaxYamlNodes) {
    throw InputError(walk.source + ": expands to more than " + std::to_string(kMaxYamlNodes) +
                     " YAML nodes (nested aliases?); a config file has one value per key");
  }
  const std::string key = config_detail::Escaped(prefix);
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      std::set<std::string> seen;
      for (const auto& kv : node) {
        const std::string k = kv.first.as<std::string>();
        const std::string full = prefix.empty() ? k : prefix + "." + k;
        if (!seen.insert(k).second) {
          throw InputError(walk.source + ": key '" + config_detail::Escaped(full) + "' appears twice" +
                           AtLine(kv.first) + "; give each key once");
        }
        Flatten(kv.second, full, walk);
      }
      break;
    }
    case YAML::NodeType::Sequence: {
      // A list of sections: entry i under "key.i".
      if (prefix.empty()) throw InputError(walk.source + ": top level must be a mapping of sections");
      size_t i = 0;
      for (const auto& item : node) Flatten(item, prefix + "." + std::to_string(i++), walk);
      break;
    }
    case YAML::NodeType::Scalar:
      walk.out[prefix] = node.Scalar();
      break;
    case YAML::NodeType::Null:
      if (!prefix.empty()) throw InputError(walk.source + ": key '" + key + "' has no value");
      break;
    default:
      throw InputError(walk.source + ": key '" + key + "' must be a scalar, a mapping or a list");
  }
}

}  // namespace

FlatConfig FlattenYaml(const std::string& yaml_text, const std::string& source) {
  FlatConfig out;
  try {
    const std::vector<YAML::Node> docs = YAML::LoadAll(yaml_text);
    if (docs.size() > 1) {
      throw InputError(source + ": holds " + std::to_string(docs.size()) +
                       " YAML documents (the second starts after the '---' before line " +
                       std::to_string(docs[1].Mark().line + 1) + "); a config file is one document");
    }
    if (docs.empty() || docs[0].IsNull()) return out;
    const YAML::Node& root = docs[0];
    if (!root.IsMap()) throw InputError(source + ": top level must be a mapping of sections");
    FlattenWalk walk{source, out};
    Flatten(root, "", walk);
  } catch (const YAML::Exception& e) {
    throw InputError(source + ": malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " +
                     config_detail::Escaped(e.msg));
  }
  return out;
}

FlatConfig FlattenYamlFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read config file '" + config_detail::Escaped(path) + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  return FlattenYaml(ss.str(), config_detail::Escaped(path));
}

std::pair<std::string, std::string> ParseAssignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set '" + config_detail::Escaped(text) + "': expected key=value");
  }
  const bool control = std::any_of(text.begin(), text.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c < 0x20 || c == 0x7f;
  });
  if (control) {
    throw InputError("--set '" + config_detail::Escaped(text) +
                     "': holds a line break or another control character; a key=value is one line");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

const std::string* AssignVisitor::Take(std::string_view name) {
  const std::string key = Key(name);
  auto it = values_.find(key);
  if (it == values_.end()) {
    const auto below = values_.lower_bound(key + ".");
    if (below != values_.end() && below->first.rfind(key + ".", 0) == 0) {
      throw InputError(config_detail::Escaped(key) + ": expected one value, not a list or a section");
    }
    return nullptr;
  }
  taken_ = it->second;
  values_.erase(it);
  return &taken_;
}

size_t AssignVisitor::ListEntriesNamed(const std::string& list_key, size_t size) const {
  // The indices I of keys "list_key.I.rest", each of which may name an entry or the next new one.
  const std::string head = list_key + ".";
  std::map<size_t, std::string> named;  // index -> one key naming it
  for (auto it = values_.lower_bound(head); it != values_.end() && it->first.rfind(head, 0) == 0; ++it) {
    const std::string rest = it->first.substr(head.size());
    const char* end = rest.data() + std::min(rest.find('.'), rest.size());
    size_t index = 0;
    const auto [ptr, ec] = std::from_chars(rest.data(), end, index);
    const bool leading_zero = rest[0] == '0' && end - rest.data() > 1;
    if (ec == std::errc::result_out_of_range) index = kMaxListEntries;
    else if (ec != std::errc() || ptr != end || leading_zero) continue;  // not an index: an unknown key
    named.emplace(index, it->first);
  }
  size_t needed = size;
  for (const auto& [index, key] : named) {
    if (index >= kMaxListEntries) {
      throw InputError(config_detail::Escaped(key) + ": the list '" + list_key + "' has at most " +
                       std::to_string(kMaxListEntries) + " entries");
    }
    if (index > needed) {
      throw InputError(config_detail::Escaped(key) + ": the list '" + list_key + "' has " + std::to_string(needed) +
                       (needed == 1 ? " entry" : " entries") + "; add " + list_key + "." + std::to_string(needed) +
                       " first");
    }
    needed = std::max(needed, index + 1);
  }
  return needed;
}

void AssignVisitor::operator()(std::string_view name, double& f, std::string_view, std::string_view, const Bounds&) {
  if (const auto* t = Take(name)) f = config_detail::ParseReal(Key(name), *t);
}
void AssignVisitor::operator()(std::string_view name, int& f, std::string_view, std::string_view, const Bounds&) {
  if (const auto* t = Take(name)) {
    const long long v = config_detail::ParseInt(Key(name), *t);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      throw InputError(Key(name) + " = " + config_detail::Escaped(*t) + ": out of integer range");
    }
    f = static_cast<int>(v);
  }
}
void AssignVisitor::operator()(std::string_view name, bool& f, std::string_view, std::string_view) {
  if (const auto* t = Take(name)) f = config_detail::ParseBool(Key(name), *t);
}
void AssignVisitor::operator()(std::string_view name, std::string& f, std::string_view, std::string_view,
                               const Choices& c) {
  if (const auto* t = Take(name)) {
    if (!c.empty()) config_detail::CheckChoice(Key(name), *t, c);
    f = *t;
  }
}

void BoundsVisitor::operator()(std::string_view name, double& f, std::string_view, std::string_view, const Bounds& b) {
  config_detail::CheckBounds(Key(name), f, b);
}
void BoundsVisitor::operator()(std::string_view name, int& f, std::string_view, std::string_view, const Bounds& b) {
  config_detail::CheckBounds(Key(name), f, b);
}
void BoundsVisitor::operator()(std::string_view name, std::string& f, std::string_view, std::string_view,
                               const Choices& c) {
  if (!c.empty()) config_detail::CheckChoice(Key(name), f, c);
}

void DocVisitor::operator()(std::string_view name, double& f, std::string_view unit, std::string_view doc,
                            const Bounds& b) {
  fields.push_back({Key(name), "real", std::string(unit), config_detail::FormatReal(f), b.Describe(), std::string(doc)});
}
void DocVisitor::operator()(std::string_view name, int& f, std::string_view unit, std::string_view doc,
                            const Bounds& b) {
  fields.push_back({Key(name), "int", std::string(unit), std::to_string(f), b.Describe(), std::string(doc)});
}
void DocVisitor::operator()(std::string_view name, bool& f, std::string_view unit, std::string_view doc) {
  fields.push_back({Key(name), "bool", std::string(unit), f ? "true" : "false", "true|false", std::string(doc)});
}
void DocVisitor::operator()(std::string_view name, std::string& f, std::string_view unit, std::string_view doc,
                            const Choices& c) {
  std::string allowed;
  for (const auto& x : c) allowed += (allowed.empty() ? "" : "|") + x;
  fields.push_back({Key(name), "string", std::string(unit), f, allowed, std::string(doc)});
}

namespace {

// "0", "12": the part of a dotted key that indexes a list entry.
bool IsListIndex(const std::string& part) {
  return !part.empty() && std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Splits "a.b.c" into its parts.
std::vector<std::string> KeyParts(const std::string& key) {
  std::vector<std::string> parts;
  std::string::size_type start = 0, dot;
  while ((dot = key.find('.', start)) != std::string::npos) {
    parts.push_back(key.substr(start, dot - start));
    start = dot + 1;
  }
  parts.push_back(key.substr(start));
  return parts;
}

}  // namespace

std::string FieldsToYaml(const std::vector<FieldDoc>& fields) {
  // Fields arrive grouped by section (declaration order), so emit a new mapping whenever
  // the section path changes; a section whose parts below are list indices is a sequence.
  YAML::Emitter out;
  out << YAML::BeginMap;
  std::vector<std::pair<std::string, bool>> open;  // current section path; true: a sequence
  auto close = [&] {
    out << (open.back().second ? YAML::EndSeq : YAML::EndMap);
    open.pop_back();
  };
  for (const auto& f : fields) {
    std::vector<std::string> parts = KeyParts(f.key);
    const std::string leaf = parts.back();
    parts.pop_back();
    size_t common = 0;
    while (common < open.size() && common < parts.size() && open[common].first == parts[common]) ++common;
    while (open.size() > common) close();
    while (open.size() < parts.size()) {
      const std::string& part = parts[open.size()];
      const bool sequence = open.size() + 1 < parts.size() && IsListIndex(parts[open.size() + 1]);
      if (!IsListIndex(part)) out << YAML::Key << part << YAML::Value;
      out << (sequence ? YAML::BeginSeq : YAML::BeginMap);
      open.emplace_back(part, sequence);
    }
    out << YAML::Key << leaf << YAML::Value;
    if (f.type == "string") {
      out << YAML::DoubleQuoted << f.value;
    } else {
      out << f.value;
    }
  }
  while (!open.empty()) close();
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

namespace {

// Appends `text` as word-wrapped "# ..." lines of at most ~100 characters, indented by `indent`.
void AppendComment(std::string& out, const std::string& text, const std::string& indent) {
  std::string line;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t sp = text.find(' ', pos);
    if (sp == std::string::npos) sp = text.size();
    const std::string word = text.substr(pos, sp - pos);
    if (!line.empty() && line.size() + 1 + word.size() > 96) {
      out += indent + "# " + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    pos = sp + 1;
  }
  if (!line.empty()) out += indent + "# " + line + "\n";
}

// A field's value as YAML text (strings double-quoted).
std::string YamlValue(const FieldDoc& f) {
  if (f.type != "string") return f.value;
  std::string q = "\"";
  for (char ch : f.value) {
    if (ch == '"' || ch == '\\') q += '\\';
    q += ch;
  }
  return q + "\"";
}

}  // namespace

std::string FieldsToCommentedYaml(const std::vector<FieldDoc>& fields, const std::string& header) {
  // Sections "name:" with their fields below; the entries of a list section "name.I" as
  // "- " items under one "name:".
  std::string out = header;
  std::string section, heading;  // the last field's section, the last "name:" written
  for (const auto& f : fields) {
    const auto dot = f.key.rfind('.');
    const std::string sec = dot == std::string::npos ? "" : f.key.substr(0, dot);
    const std::string leaf = dot == std::string::npos ? f.key : f.key.substr(dot + 1);
    const auto list_dot = sec.rfind('.');
    const bool item = list_dot != std::string::npos && IsListIndex(sec.substr(list_dot + 1));
    const bool first_of_section = sec != section;
    section = sec;
    const std::string sec_heading = item ? sec.substr(0, list_dot) : sec;
    if (sec_heading != heading) {
      heading = sec_heading;
      out += "\n" + heading + ":\n";
    }
    const std::string indent = item ? "    " : "  ";
    AppendComment(out, f.doc + (f.unit.empty() ? "" : " [" + f.unit + "]"), indent);
    out += (item && first_of_section ? "  - " : indent) + leaf + ": " + YamlValue(f) + "\n";
  }
  return out;
}

void FailRule(const std::string& key, double value, const std::string& rule) {
  throw InputError(key + " = " + config_detail::FormatReal(value) + ": " + rule);
}

void FailRule(const std::string& key, const std::string& value, const std::string& rule) {
  throw InputError(key + " = '" + config_detail::Escaped(value) + "': " + rule);
}

}  // namespace tactip
