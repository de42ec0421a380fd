#include "scenarios/app/cli/lean_command.h"

#include <cstdio>
#include <filesystem>

#include "sim/base/files.h"
#include "sim/base/progress.h"

namespace tactip::cli {

int RunLeanStudy(const std::vector<std::string>& scenes, const LeanOptions& options, const std::string& out_dir) {
  const std::vector<SpeedScene> chosen = ChooseLeanScenes(scenes);  // an unknown scene is named before anything runs
  const std::string path = out_dir.empty() ? std::string() : (std::filesystem::path(out_dir) / "lean.csv").string();
  if (!path.empty()) {
    CreateOutputFolder(out_dir);
    CheckWritableLocation(path);
  }
  ProgressF("bench --lean: %zu scene(s) x %zu variants, one core, every step timed\n", chosen.size(),
               LeanVariants().size());
  LeanOptions o = options;
  o.progress = [](const std::string& line) { ProgressF("bench --lean: %s\n", line.c_str()); };
  const std::vector<LeanRow> rows = MeasureLean(chosen, o);
  std::printf("%s", FormatLeanTable(rows).c_str());
  if (!path.empty()) {
    WriteFileAtomic(path, LeanCsv(rows));
    ProgressF("wrote %s\n", path.c_str());
  }
  return 0;
}

}  // namespace tactip::cli
