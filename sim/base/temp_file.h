#pragma once
// A scratch file in the system's temporary folder, for libraries that read and write files only.

#include <string>

namespace tactip {

/// A unique empty file in the temporary directory (mkstemp), removed by the destructor;
/// used to pass text through libraries that only read and write files (libsvm, liblinear).
class TempFile {
 public:
  /// Creates the file; throws InputError if it cannot.
  TempFile();
  /// Removes the file (ignoring errors).
  ~TempFile();
  /// Not copyable: owns the file.
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  /// Path of the file.
  const std::string& path() const { return path_; }
  /// Replaces the file's contents with `text`; throws InputError "<for_what>: cannot write
  /// temporary file 'PATH'" if it cannot (`for_what` names what the text is, e.g. "model 'm.txt'").
  void Write(const std::string& text, const std::string& for_what) const;

 private:
  std::string path_;
};

}  // namespace tactip
