#pragma once
// Reading and writing the text model files of the detectors: line-by-line reading with
// errors naming the file and line, the standardiser's lines of the trained classifiers (SVM,
// logistic regression), and the "key value" files of the parameter detectors (threshold,
// incipient).

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "detectors/crossval.h"
#include "detectors/detector.h"

namespace tactip {

/// Appends "mean v1 v2 ...\ninv_std v1 v2 ...\n" (round-trip exact) to `out`.
void AppendStandardizer(const Standardizer& s, std::string& out);

/// One key of a "key value" model file and how to parse its value: `parse` stores the value
/// and returns false when it is not a number of the key's type.
struct ModelKey {
  std::string_view name;
  std::function<bool(const std::string&)> parse;
};

/// Reads a parameter detector's model file: the line `header`, then "key value" lines (blank
/// lines ignored, a trailing CR dropped), every key of `keys` exactly once, in any order.
/// Throws InputError("model 'PATH': ...") naming the line for a wrong header, a line that is
/// not "key value", an unknown or duplicate key or a value `parse` rejects ("KEY 'V' is not a
/// number"); at the end for an empty file or a missing key (the first of `keys` missing).
void ReadKeyValueModel(const std::string& text, const std::string& path, std::string_view header,
                       const std::vector<ModelKey>& keys);

/// Reads the "key values..." lines of a detector model file, one at a time, and turns every
/// problem into InputError("model 'PATH': line L: <problem>").
class ModelTextReader {
 public:
  /// Reads `text` (copied): the whole file, or a part of it that starts after line
  /// `line_offset` (line numbers in errors count from there); `path` names the file in errors.
  ModelTextReader(std::string text, std::string path, int line_offset = 0);
  /// Next line without its end-of-line; throws ("file ends early, expected <expected>") at the end.
  std::string ReadLine(std::string_view expected);
  /// True when only whitespace is left.
  bool AtEnd() const;
  /// Throws unless only whitespace is left and the text ends with an end of line (as libsvm
  /// and liblinear end every line): a file cut inside its last line can still parse, with a
  /// shortened last value. `last` names that line's content, e.g. "support vector".
  void ExpectEndOfFile(std::string_view last) const;
  /// Throws unless the next line is exactly `line`.
  void ExpectExact(std::string_view line);
  /// Reads the next line, which must start with `key`, and returns its remaining
  /// whitespace-separated tokens; throws if the key differs or the count is not `n_values`
  /// (any count when n_values < 0).
  std::vector<std::string> ExpectKey(std::string_view key, int n_values);
  /// Parses a whole token as a finite double (`what` names it in the error).
  double ParseDouble(const std::string& token, std::string_view what) const;
  /// Parses a whole token as a finite float (`what` names it in the error).
  float ParseFloat(const std::string& token, std::string_view what) const;
  /// Parses a whole token as an int (`what` names it in the error).
  int ParseInt(const std::string& token, std::string_view what) const;
  /// Reads "mean ..." and "inv_std ..." lines of `dim` values each (inv_std finite and > 0).
  Standardizer ReadStandardizer(int dim);
  /// Reads the "features <name>" line shared by the classifier models.
  FeatureSet ReadFeatures();
  /// Reads the "C <value>" line (must be > 0) shared by the classifier models.
  double ReadC();
  /// Reads the "dim <d>" line (1 .. 1000000) shared by the classifier models.
  int ReadDim();
  /// The text after the last line read (e.g. an embedded libsvm model).
  std::string Rest() const;
  /// 1-based number of the last line read.
  int line_number() const { return line_no_; }
  /// Throws InputError("model 'PATH': line L: problem") (no line part if none read).
  [[noreturn]] void Fail(const std::string& problem) const;

 private:
  std::string text_;
  std::string path_;
  size_t pos_ = 0;
  int line_no_ = 0;
};

}  // namespace tactip
