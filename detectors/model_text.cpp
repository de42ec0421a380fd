// Line-by-line reading of detector model files and the standardiser's lines.

#include "detectors/model_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "sim/base/number_text.h"

namespace tactip {

void AppendStandardizer(const Standardizer& s, std::string& out) {
  out += "mean";
  for (Eigen::Index j = 0; j < s.mean.size(); ++j) out += " " + RoundTripText(s.mean[j]);
  out += "\ninv_std";
  for (Eigen::Index j = 0; j < s.inv_std.size(); ++j) out += " " + RoundTripText(s.inv_std[j]);
  out += "\n";
}

namespace {

// Parses one "key value" line of a parameter model into `keys`, marking it in `seen`.
void ParseKeyValueLine(const std::string& line, const std::string& at, const std::vector<ModelKey>& keys,
                       std::vector<bool>& seen) {
  std::istringstream fields(line);
  std::string key, value, extra;
  if (!(fields >> key)) return;
  if (!(fields >> value) || (fields >> extra)) throw InputError(at + "expected 'key value'");
  const auto it = std::find_if(keys.begin(), keys.end(), [&](const ModelKey& k) { return k.name == key; });
  if (it == keys.end()) throw InputError(at + "unknown key '" + key + "'");
  const size_t index = static_cast<size_t>(it - keys.begin());
  if (seen[index]) throw InputError(at + "duplicate " + key);
  if (!it->parse(value)) throw InputError(at + key + " '" + value + "' is not a number");
  seen[index] = true;
}

}  // namespace

void ReadKeyValueModel(const std::string& text, const std::string& path, std::string_view header,
                       const std::vector<ModelKey>& keys) {
  const std::string where = "model '" + path + "': ";
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<bool> seen(keys.size(), false);
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_no == 1) {
      if (line != header) throw InputError(where + "line 1 is '" + line + "', expected '" + std::string(header) + "'");
      continue;
    }
    ParseKeyValueLine(line, where + "line " + std::to_string(line_no) + ": ", keys, seen);
  }
  if (line_no == 0) throw InputError(where + "empty file, expected '" + std::string(header) + "'");
  for (size_t k = 0; k < keys.size(); ++k) {
    if (!seen[k]) throw InputError(where + "missing " + std::string(keys[k].name));
  }
}

ModelTextReader::ModelTextReader(std::string text, std::string path, int line_offset)
    : text_(std::move(text)), path_(std::move(path)), line_no_(line_offset) {}

void ModelTextReader::Fail(const std::string& problem) const {
  const std::string line = line_no_ > 0 ? "line " + std::to_string(line_no_) + ": " : "";
  throw InputError("model '" + path_ + "': " + line + problem);
}

std::string ModelTextReader::ReadLine(std::string_view expected) {
  if (pos_ >= text_.size()) {
    line_no_ += 1;
    Fail("file ends early, expected '" + std::string(expected) + "'");
  }
  const size_t end = text_.find('\n', pos_);
  std::string line = text_.substr(pos_, end == std::string::npos ? std::string::npos : end - pos_);
  pos_ = end == std::string::npos ? text_.size() : end + 1;
  ++line_no_;
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

void ModelTextReader::ExpectExact(std::string_view line) {
  const std::string got = ReadLine(line);
  if (got != line) Fail("'" + got.substr(0, 80) + "', expected '" + std::string(line) + "'");
}

std::vector<std::string> ModelTextReader::ExpectKey(std::string_view key, int n_values) {
  const std::string line = ReadLine(std::string(key) + " ...");
  // Whitespace-separated tokens.
  std::vector<std::string> tokens;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  if (tokens.empty() || tokens.front() != key) {
    Fail("'" + line.substr(0, 80) + "', expected a '" + std::string(key) + "' line");
  }
  tokens.erase(tokens.begin());
  if (n_values >= 0 && static_cast<int>(tokens.size()) != n_values) {
    Fail("'" + std::string(key) + "' has " + std::to_string(tokens.size()) + " values, expected " +
         std::to_string(n_values));
  }
  return tokens;
}

double ModelTextReader::ParseDouble(const std::string& token, std::string_view what) const {
  double v = 0.0;
  if (!ParseWhole(token, v) || !std::isfinite(v)) {
    Fail(std::string(what) + " '" + token.substr(0, 40) + "' is not a finite number");
  }
  return v;
}

float ModelTextReader::ParseFloat(const std::string& token, std::string_view what) const {
  float v = 0.0f;
  if (!ParseWhole(token, v) || !std::isfinite(v)) {
    Fail(std::string(what) + " '" + token.substr(0, 40) + "' is not a finite number");
  }
  return v;
}

int ModelTextReader::ParseInt(const std::string& token, std::string_view what) const {
  int v = 0;
  if (!ParseWhole(token, v)) Fail(std::string(what) + " '" + token.substr(0, 40) + "' is not an integer");
  return v;
}

Standardizer ModelTextReader::ReadStandardizer(int dim) {
  Standardizer s;
  s.mean.resize(dim);
  s.inv_std.resize(dim);
  const std::vector<std::string> mean = ExpectKey("mean", dim);
  for (int j = 0; j < dim; ++j) s.mean[j] = ParseFloat(mean[j], "mean value");
  const std::vector<std::string> inv_std = ExpectKey("inv_std", dim);
  for (int j = 0; j < dim; ++j) {
    s.inv_std[j] = ParseFloat(inv_std[j], "inv_std value");
    if (!(s.inv_std[j] > 0.0f)) Fail("inv_std value '" + inv_std[j] + "' must be > 0");
  }
  return s;
}

std::string ModelTextReader::Rest() const { return text_.substr(pos_); }

bool ModelTextReader::AtEnd() const {
  return text_.find_first_not_of(" \t\r\n", pos_) == std::string::npos;
}

void ModelTextReader::ExpectEndOfFile(std::string_view last) const {
  if (!AtEnd()) Fail("unexpected text after the last " + std::string(last));
  const size_t end = text_.find_last_not_of(" \t\r");
  if (end == std::string::npos || text_[end] != '\n') {
    Fail("the last " + std::string(last) + " has no end of line: the file is cut off");
  }
}

FeatureSet ModelTextReader::ReadFeatures() {
  const std::string name = ExpectKey("features", 1)[0];
  try {
    return ParseFeatureSet(name);
  } catch (const InputError& e) {
    Fail(e.what());
  }
}

double ModelTextReader::ReadC() {
  const double c = ParseDouble(ExpectKey("C", 1)[0], "C");
  if (!(c > 0.0)) Fail("C must be > 0");
  return c;
}

int ModelTextReader::ReadDim() {
  const int dim = ParseInt(ExpectKey("dim", 1)[0], "dim");
  if (dim < 1 || dim > 1000000) Fail("dim must be in [1, 1000000]");
  return dim;
}

}  // namespace tactip
