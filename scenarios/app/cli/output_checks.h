#pragma once
// Checks and guards of a command's outputs: no output may be one of its inputs, and a
// command that fails leaves no output folder it created behind.

#include <filesystem>
#include <string>
#include <vector>

namespace tactip::cli {

/// A file a command reads or writes and the option (or argument) that names it.
struct NamedPath {
  std::string option;  ///< e.g. "--out", "--data", "FILE"
  std::string path;    ///< "" when not given
};

/// Throws InputError naming both options when an output is the same file as an input
/// (also through symbolic or hard links), before anything is read or written.
void CheckOutputsAreNotInputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs);

/// The files `names` inside the output folder `dir`, each named by `option`.
std::vector<NamedPath> FilesInFolder(const std::string& option, const std::string& dir,
                                     const std::vector<std::string>& names);

/// Before a long command starts: creates the output folder `dir` (nothing when `dir` is
/// empty) and checks that its first output file `file` can be written in it; throws
/// InputError naming the folder or file otherwise. Construct the NewFolderGuard first.
void PrepareOutputFolder(const std::string& dir, const std::string& file);

/// Remembers which part of the output folder `dir` does not exist yet; unless Keep() is
/// called, removes the folders of that part that are still empty when destroyed, so a
/// command that fails or is interrupted before writing anything leaves no folder behind
/// (files it did write completely are kept). A folder that existed before is never touched.
class NewFolderGuard {
 public:
  explicit NewFolderGuard(const std::string& dir);
  ~NewFolderGuard();
  NewFolderGuard(const NewFolderGuard&) = delete;
  NewFolderGuard& operator=(const NewFolderGuard&) = delete;
  /// The command succeeded: keep the folder, empty or not.
  void Keep() { created_.clear(); }

 private:
  std::filesystem::path dir_;      ///< the output folder, absolute
  std::filesystem::path created_;  ///< its outermost missing ancestor or itself ("" when it exists)
};

}  // namespace tactip::cli
