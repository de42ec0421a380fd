#include "scenarios/rail/rail_generate.h"

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "tactip/version.h"

namespace tactip {

void RunRailRuns(const RailScenario& scenario, int first, int runs, std::uint64_t seed, int jobs_requested,
                 const std::atomic<bool>* stop, const std::function<void(RunRecord&&, const RailRunSummary&)>& take,
                 const ControllerFactory& make) {
  // Workers take run indices in order; this thread hands them to `take` in order.
  const int jobs = std::max(
      1, std::min(runs, jobs_requested > 0 ? jobs_requested : static_cast<int>(std::thread::hardware_concurrency())));
  std::mutex mu;
  std::condition_variable cv;
  std::map<int, RunRecord> done;
  std::map<int, RailRunSummary> summaries;
  std::exception_ptr failure;
  int next_index = 0;
  std::atomic<bool> abort{false};
  auto worker = [&] {
    for (;;) {
      int idx;
      {
        std::unique_lock lock(mu);
        // Bound memory: do not run ahead of the consumer by more than 2 * jobs runs.
        cv.wait(lock, [&] { return failure || next_index >= runs || static_cast<int>(done.size()) < 2 * jobs; });
        if (failure || next_index >= runs) return;
        idx = next_index++;
      }
      try {
        RunRecord rec;
        const RailRunSummary s = scenario.Run(first + idx, seed, rec, &abort, make);
        std::lock_guard lock(mu);
        done.emplace(idx, std::move(rec));
        summaries.emplace(idx, s);
      } catch (...) {
        std::lock_guard lock(mu);
        if (!failure) failure = std::current_exception();
        abort = true;
      }
      cv.notify_all();
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j) threads.emplace_back(worker);

  int taken = 0;
  try {
    while (taken < runs) {
      RunRecord rec;
      RailRunSummary s;
      {
        std::unique_lock lock(mu);
        // Poll, because an interrupting signal cannot notify the condition variable.
        while (!(failure || done.count(taken) > 0 || (stop && stop->load()))) {
          cv.wait_for(lock, std::chrono::milliseconds(200));
        }
        if (stop && stop->load()) {
          abort = true;
          if (!failure) failure = std::make_exception_ptr(Interrupted());
        }
        if (failure) break;
        rec = std::move(done.at(taken));
        done.erase(taken);
        s = summaries.at(taken);
      }
      cv.notify_all();
      take(std::move(rec), s);
      ++taken;
    }
  } catch (...) {
    std::lock_guard lock(mu);
    if (!failure) failure = std::current_exception();
    abort = true;
  }
  cv.notify_all();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

GenerateResult GenerateRailDataset(const RailScenarioConfig& cfg, const GenerateOptions& opts) {
  if (opts.runs < 1) throw InputError(fmt::format("--runs = {}: must be >= 1", opts.runs));
  if (opts.out_path.empty()) throw InputError("no output file given (--out)");
  if (opts.shard) {
    // The shard must be one of this job's (same R) and keep its rules.
    if (opts.shard->runs_total != opts.runs) {
      throw InputError(fmt::format("--shard {} is of a {}-run job, but --runs = {}", opts.shard->text(),
                                   opts.shard->runs_total, opts.runs));
    }
    ParseShardOption(opts.shard->text(), opts.runs);
  }
  const int first = opts.shard ? opts.shard->first_run() : 0;
  const int count = opts.shard ? opts.shard->end_run() - first : opts.runs;
  const RailScenario scenario(cfg);
  const auto wall0 = std::chrono::steady_clock::now();

  DatasetHeader header;
  header.tactip_version = TACTIP_VERSION;
  header.scenario = opts.scenario;
  header.seed = opts.seed;
  header.config_yaml = ConfigToYaml(scenario.config());
  header.shard = opts.shard;
  DatasetWriter writer(opts.out_path, header);

  GenerateResult result;
  RunRailRuns(scenario, first, count, opts.seed, opts.jobs, opts.stop, [&](RunRecord&& rec, const RailRunSummary& s) {
    writer.WriteRun(rec);
    result.sim_time_s += s.sim_time_s;
    ++result.runs;
    if (opts.progress) opts.progress(result.runs, count, rec.index, s);
  });
  writer.Commit();
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return result;
}

}  // namespace tactip
