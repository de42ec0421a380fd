#pragma once
// Progress of long commands on stderr: lines from any thread, and a heartbeat that says the
// work is still going when a long step (training a model, one slow run) has printed nothing
// for a while, so a terminal is never silent for long.

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace tactip {

/// Writes `line` and a newline to stderr (whole, from any thread) and notes it as the latest
/// progress line of the process, with its time.
void Progress(const std::string& line);
/// The same, printf-style.
void ProgressF(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// While alive, a thread that prints "PREFIX: still working, N s since: LAST" whenever
/// `interval` passes without a progress line (LAST is the latest one), and counts as one.
class Heartbeat {
 public:
  explicit Heartbeat(std::string prefix, std::chrono::milliseconds interval = std::chrono::seconds(10));
  ~Heartbeat();
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

 private:
  void Beat();

  const std::string prefix_;
  const std::chrono::milliseconds interval_;
  std::mutex mu_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace tactip
