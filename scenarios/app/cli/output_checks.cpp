#include "scenarios/app/cli/output_checks.h"

#include <fmt/format.h>

#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip::cli {

namespace fs = std::filesystem;

void CheckOutputsAreNotInputs(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (const NamedPath& out : outputs) {
    if (out.path.empty()) continue;
    for (const NamedPath& in : inputs) {
      if (in.path.empty() || !SameFile(out.path, in.path)) continue;
      throw InputError(fmt::format("{} '{}' is the same file as {} '{}': the output would overwrite the input; "
                                   "write it to another file",
                                   out.option, out.path, in.option, in.path));
    }
  }
}

std::vector<NamedPath> FilesInFolder(const std::string& option, const std::string& dir,
                                     const std::vector<std::string>& names) {
  std::vector<NamedPath> out;
  for (const auto& name : names) out.push_back({option, (fs::path(dir) / name).string()});
  return out;
}

namespace {

// True when anything (a dangling symbolic link included) is at `p`.
bool Occupied(const fs::path& p) {
  std::error_code ec;
  return fs::exists(fs::symlink_status(p, ec));
}

}  // namespace

NewFolderGuard::NewFolderGuard(const std::string& dir) {
  if (dir.empty()) return;
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (ec || p.empty()) return;
  if (!p.has_filename()) p = p.parent_path();  // "out/" -> "out"
  if (Occupied(p)) return;
  dir_ = p;
  while (p.parent_path() != p && !Occupied(p.parent_path())) p = p.parent_path();
  created_ = p;
}

void PrepareOutputFolder(const std::string& dir, const std::string& file) {
  if (dir.empty()) return;
  CreateOutputFolder(dir);
  CheckWritableLocation((std::filesystem::path(dir) / file).string());
}

NewFolderGuard::~NewFolderGuard() {
  if (created_.empty()) return;
  // Innermost first; a folder holding anything stops the walk (remove fails on it).
  for (fs::path p = dir_;; p = p.parent_path()) {
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(p, ec))) fs::remove(p, ec);
    if (ec || p == created_ || p.parent_path() == p) break;
  }
}

}  // namespace tactip::cli
