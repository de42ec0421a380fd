#include "sim/base/progress.h"

#include <cstdarg>
#include <cstdio>
#include <vector>
#include <algorithm>

namespace tactip {

namespace {

// The process's latest progress line and when it was printed. One terminal per process:
// every thread's lines, and the heartbeat that fills their silences, share this one state.
struct LastLine {
  std::mutex mu;
  std::string text;                                                       // the latest line
  std::chrono::steady_clock::time_point text_at = std::chrono::steady_clock::now();  // when it came
  std::chrono::steady_clock::time_point at = text_at;  // when anything was last printed, a heartbeat too
};

LastLine& Last() {
  static LastLine last;
  return last;
}

}  // namespace

void Progress(const std::string& line) {
  LastLine& last = Last();
  std::lock_guard lock(last.mu);
  std::fprintf(stderr, "%s\n", line.c_str());
  std::fflush(stderr);
  last.text = line;
  last.text_at = last.at = std::chrono::steady_clock::now();
}

void ProgressF(const char* format, ...) {
  std::va_list args;
  va_start(args, format);
  std::va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::vector<char> text(static_cast<size_t>(n > 0 ? n : 0) + 1);
  std::vsnprintf(text.data(), text.size(), format, args);
  va_end(args);
  std::string line(text.data());
  if (!line.empty() && line.back() == '\n') line.pop_back();
  Progress(line);
}

Heartbeat::Heartbeat(std::string prefix, std::chrono::milliseconds interval)
    : prefix_(std::move(prefix)), interval_(interval) {
  {
    LastLine& last = Last();
    std::lock_guard lock(last.mu);
    last.text_at = last.at = std::chrono::steady_clock::now();
  }
  thread_ = std::thread([this] { Beat(); });
}

Heartbeat::~Heartbeat() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void Heartbeat::Beat() {
  // Wake a few times per interval; speak when the latest line is an interval old.
  const auto tick = std::max(std::chrono::milliseconds(10), interval_ / 4);
  std::unique_lock lock(mu_);
  while (!cv_.wait_for(lock, tick, [this] { return stop_; })) {
    LastLine& last = Last();
    std::lock_guard line_lock(last.mu);
    const auto now = std::chrono::steady_clock::now();
    if (now - last.at < interval_) continue;
    const double silent_s = std::chrono::duration<double>(now - last.text_at).count();
    std::fprintf(stderr, "%s: still working, %.0f s since: %s\n", prefix_.c_str(), silent_s,
                 last.text.empty() ? "the start" : last.text.c_str());
    std::fflush(stderr);
    last.at = now;
  }
}

}  // namespace tactip
