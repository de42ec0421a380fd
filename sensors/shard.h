#pragma once
// Shards of a dataset job: run k of an R-run job belongs to shard i of n when
// floor(i*R/n) <= k < floor((i+1)*R/n), so n machines can each simulate one block.

#include <string>

namespace tactip {

/// Shard i of n of an R-run job ("i/n" on the command line and in shard files).
struct ShardSpec {
  int index = 0;       ///< i, 0 <= i < n
  int count = 1;       ///< n, 1 <= n <= runs_total
  int runs_total = 1;  ///< R, runs of the whole job

  /// First run of this shard: floor(i*R/n).
  int first_run() const;
  /// One past the last run of this shard: floor((i+1)*R/n).
  int end_run() const;
  /// "i/n".
  std::string text() const;
  /// "runs 2-3 of 8" (or "run 2 of 8"), for messages.
  std::string runs_text() const;
};

/// Parses `text` ("i/n") as a shard of a `runs_total`-run job into `out`. Returns "" on
/// success, else the rule it breaks (malformed, i < 0, i >= n, n < 1, n > runs_total).
std::string ParseShard(const std::string& text, int runs_total, ShardSpec& out);

/// ParseShard for the command line: throws InputError "--shard 'TEXT': RULE".
ShardSpec ParseShardOption(const std::string& text, int runs_total);

/// "runs A-B" or "run A" for the half-open range [first, end), for messages.
std::string RunRangeText(int first, int end);

}  // namespace tactip
