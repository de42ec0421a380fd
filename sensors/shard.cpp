#include "sensors/shard.h"

#include <cstdint>

#include <fmt/format.h>

#include "sim/base/number_text.h"
#include "sim/config.h"

namespace tactip {

int ShardSpec::first_run() const {
  return static_cast<int>(static_cast<std::int64_t>(index) * runs_total / count);
}

int ShardSpec::end_run() const {
  return static_cast<int>((static_cast<std::int64_t>(index) + 1) * runs_total / count);
}

std::string ShardSpec::text() const { return fmt::format("{}/{}", index, count); }

std::string ShardSpec::runs_text() const {
  return fmt::format("{} of {}", RunRangeText(first_run(), end_run()), runs_total);
}

std::string RunRangeText(int first, int end) {
  if (end - first == 1) return fmt::format("run {}", first);
  return fmt::format("runs {}-{}", first, end - 1);
}

std::string ParseShard(const std::string& text, int runs_total, ShardSpec& out) {
  // Shape first: two integers around one slash.
  const size_t slash = text.find('/');
  long long i = 0, n = 0;
  if (slash == std::string::npos || !ParseWhole(text.substr(0, slash), i) || !ParseWhole(text.substr(slash + 1), n)) {
    return "expected i/n, two integers with 0 <= i < n (e.g. 0/4)";
  }
  // Then the rules, one message each.
  if (n < 1) return "n must be >= 1";
  if (i < 0) return "i must be >= 0 (shards are numbered 0 to n-1)";
  if (i >= n) return "i must be < n (shards are numbered 0 to n-1)";
  if (n > runs_total) {
    return fmt::format("n must be <= the job's number of runs (--runs {}), so that every shard has a run", runs_total);
  }
  out = ShardSpec{static_cast<int>(i), static_cast<int>(n), runs_total};
  return "";
}

ShardSpec ParseShardOption(const std::string& text, int runs_total) {
  ShardSpec spec;
  const std::string problem = ParseShard(text, runs_total, spec);
  if (!problem.empty()) throw InputError(fmt::format("--shard '{}': {}", text, problem));
  return spec;
}

}  // namespace tactip
