#pragma once
// Joining shard files (`tactip generate ... --shard i/n`) into the dataset one machine
// would have written for the whole job.

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "sensors/shard.h"

namespace tactip {

/// What a merge joined.
struct MergeResult {
  int shards = 0;  ///< shard files read
  int runs = 0;    ///< runs written
};

/// Options of a merge.
struct MergeOptions {
  /// Called after each shard file is copied, in run order, with its path and shard.
  std::function<void(const std::string&, const ShardSpec&)> progress;
  const std::atomic<bool>* stop = nullptr;  ///< cooperative interruption flag
};

/// Joins the shard files `inputs` (any order) into `out_path`, written atomically: runs
/// in index order, root attributes without the shard ones, every sensor, array, action
/// and attribute copied through DatasetWriter (in layout 2, whatever the shards' layout),
/// so the file is byte for byte the one a single `tactip generate` of the whole job
/// writes. Shards of one job share their layout. Throws InputError naming the file and the
/// problem, before anything is written, when an input is missing, corrupt or not a shard
/// file, shards come from different jobs, runs overlap or are missing, or `out_path` is
/// an input; throws Interrupted when `*stop` becomes true. On any failure `out_path` is
/// left untouched.
MergeResult MergeShards(const std::vector<std::string>& inputs, const std::string& out_path,
                        const MergeOptions& opts = {});

}  // namespace tactip
