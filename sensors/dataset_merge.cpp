#include "sensors/dataset_merge.h"

#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "sensors/dataset.h"
#include "sim/base/errors.h"
#include "sim/config.h"
#include "sim/base/files.h"

namespace tactip {

namespace {

/// One input: its path, header and the runs it holds.
struct ShardFile {
  std::string path;          ///< as given
  DatasetHeader header;      ///< root attributes (header.shard is set)
  std::vector<int> runs;     ///< run indices present, ascending
  const ShardSpec& shard() const { return *header.shard; }
};

/// "runs 0-1, 3" for a sorted list of run indices ("no runs" if empty).
std::string RunsText(const std::vector<int>& runs) {
  if (runs.empty()) return "no runs";
  std::string text;
  for (size_t i = 0; i < runs.size();) {
    size_t j = i + 1;
    while (j < runs.size() && runs[j] == runs[j - 1] + 1) ++j;
    text += (text.empty() ? "" : ", ") + RunRangeText(runs[i], runs[j - 1] + 1);
    i = j;
  }
  return text;
}

/// "'part1.h5' (shard 1/2, runs 2-3 of 4)", for messages.
std::string Describe(const ShardFile& f) {
  return fmt::format("'{}' (shard {}, {})", f.path, f.shard().text(), f.shard().runs_text());
}

/// Reads the header and run list of `path`; throws unless it is a complete shard file.
ShardFile OpenShard(const std::string& path) {
  const DatasetReader reader(path);
  ShardFile f{path, reader.header(), reader.run_indices()};
  if (!f.header.shard) {
    throw InputError(fmt::format(
        "merge: '{}' is not a shard file (no root attribute 'shard'; shards are written by "
        "'tactip generate ... --shard i/n')",
        path));
  }
  // A shard holds exactly its block of runs.
  std::vector<int> expected(static_cast<size_t>(f.shard().end_run() - f.shard().first_run()));
  for (size_t k = 0; k < expected.size(); ++k) expected[k] = f.shard().first_run() + static_cast<int>(k);
  if (f.runs != expected) {
    throw InputError(fmt::format("merge: '{}' is corrupt: shard {} should hold {} but holds {}", path,
                                 f.shard().text(), f.shard().runs_text(), RunsText(f.runs)));
  }
  return f;
}

/// Throws unless `f` comes from the same job as `ref` (scenario, seed, config, version,
/// layout, runs).
void CheckSameJob(const ShardFile& ref, const ShardFile& f) {
  const DatasetHeader &a = ref.header, &b = f.header;
  std::string diff;
  if (b.scenario != a.scenario) {
    diff = fmt::format("scenario '{}', not '{}'", b.scenario, a.scenario);
  } else if (b.seed != a.seed) {
    diff = fmt::format("seed {}, not {}", b.seed, a.seed);
  } else if (b.config_yaml != a.config_yaml) {
    diff = "a different config (root attribute 'config_yaml')";
  } else if (b.tactip_version != a.tactip_version) {
    diff = fmt::format("tactip version '{}', not '{}'", b.tactip_version, a.tactip_version);
  } else if (b.layout_version != a.layout_version) {
    diff = fmt::format("layout_version {}, not {}", b.layout_version, a.layout_version);
  } else if (b.shard->runs_total != a.shard->runs_total) {
    diff = fmt::format("runs_total {}, not {}", b.shard->runs_total, a.shard->runs_total);
  }
  if (!diff.empty()) {
    throw InputError(fmt::format("merge: '{}' is from a different job than '{}': it has {}", f.path, ref.path, diff));
  }
}

/// Throws if two inputs are the same file.
void CheckDistinctFiles(const std::vector<ShardFile>& files) {
  for (size_t i = 0; i < files.size(); ++i) {
    for (size_t j = i + 1; j < files.size(); ++j) {
      std::error_code ec;
      if (std::filesystem::equivalent(files[i].path, files[j].path, ec)) {
        throw InputError(files[i].path == files[j].path
                             ? fmt::format("merge: '{}' is given twice", files[i].path)
                             : fmt::format("merge: '{}' and '{}' are the same file", files[i].path, files[j].path));
      }
    }
  }
}

/// With `files` sorted by first run: throws on a duplicate or overlapping shard, or on
/// runs no file holds (naming them, and the missing shards when all share one n).
void CheckCoverage(const std::vector<ShardFile>& files) {
  const int total = files.front().shard().runs_total;
  std::vector<std::string> gaps;
  int covered = 0;  // runs [0, covered) are held by the files seen so far
  for (size_t k = 0; k < files.size(); ++k) {
    const ShardSpec& s = files[k].shard();
    if (k > 0 && s.first_run() < covered) {
      const ShardFile& prev = files[k - 1];
      if (prev.shard().first_run() == s.first_run() && prev.shard().end_run() == s.end_run()) {
        throw InputError(fmt::format("merge: {} is a duplicate: '{}' holds the same runs", Describe(files[k]),
                                     prev.path));
      }
      throw InputError(fmt::format("merge: {} overlaps {}", Describe(files[k]), Describe(prev)));
    }
    if (s.first_run() > covered) gaps.push_back(RunRangeText(covered, s.first_run()));
    covered = s.end_run();
  }
  if (covered < total) gaps.push_back(RunRangeText(covered, total));
  if (gaps.empty()) return;
  // Name the missing shards too when every file splits the job the same way.
  const int n = files.front().shard().count;
  std::string shards;
  if (std::all_of(files.begin(), files.end(), [&](const ShardFile& f) { return f.shard().count == n; })) {
    std::vector<bool> given(static_cast<size_t>(n), false);
    for (const auto& f : files) given[static_cast<size_t>(f.shard().index)] = true;
    int missing = 0;
    for (int i = 0; i < n; ++i) {
      if (given[static_cast<size_t>(i)]) continue;
      shards += fmt::format("{}{}/{}", shards.empty() ? "" : ", ", i, n);
      ++missing;
    }
    shards = fmt::format(" ({} {} not given)", missing == 1 ? "shard" : "shards", shards);
  }
  std::string list;
  for (const auto& g : gaps) list += (list.empty() ? "" : ", ") + g;
  throw InputError(fmt::format("merge: missing {} of {}{}", list, total, shards));
}

/// Throws if `out_path` exists and is one of the inputs.
void CheckOutputIsNoInput(const std::vector<std::string>& inputs, const std::string& out_path) {
  std::error_code ec;
  if (!std::filesystem::exists(out_path, ec)) return;
  for (const auto& in : inputs) {
    if (std::filesystem::equivalent(in, out_path, ec)) {
      throw InputError(fmt::format("merge: --out '{}' is one of the input files; write the merged dataset to a new file",
                                   out_path));
    }
  }
}

}  // namespace

MergeResult MergeShards(const std::vector<std::string>& inputs, const std::string& out_path,
                        const MergeOptions& opts) {
  // Everything is checked before the output is opened.
  if (inputs.empty()) throw InputError("merge: no shard files given");
  if (out_path.empty()) throw InputError("merge: no output file given (--out)");
  CheckWritableLocation(out_path);
  CheckOutputIsNoInput(inputs, out_path);
  std::vector<ShardFile> files;
  for (const auto& path : inputs) files.push_back(OpenShard(path));
  CheckDistinctFiles(files);
  for (const auto& f : files) CheckSameJob(files.front(), f);
  std::stable_sort(files.begin(), files.end(), [](const ShardFile& a, const ShardFile& b) {
    return a.shard().first_run() < b.shard().first_run();
  });
  CheckCoverage(files);

  // The header of the whole job: the shards' common one without the shard attributes.
  DatasetHeader header = files.front().header;
  header.shard.reset();
  DatasetWriter writer(out_path, header);
  MergeResult result;
  for (const auto& f : files) {
    const DatasetReader reader(f.path);
    for (const int index : f.runs) {
      if (opts.stop && opts.stop->load()) throw Interrupted();
      writer.WriteRun(reader.ReadRun(index));
      ++result.runs;
    }
    ++result.shards;
    if (opts.progress) opts.progress(f.path, f.shard());
  }
  writer.Commit();
  return result;
}

}  // namespace tactip
