#pragma once
// An X display for tests that render: $DISPLAY when it is set, else an Xvfb server that the
// test starts on a free display number and stops again.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace tactip::testing {

/// Provides a display for the lifetime of the object. When DISPLAY is unset it starts
/// `Xvfb -displayfd` (which picks a free display number and reports it when it is ready),
/// points DISPLAY at it, and on destruction stops that server and unsets DISPLAY again.
class TestDisplay {
 public:
  TestDisplay() {
    const char* display = std::getenv("DISPLAY");
    if (display != nullptr && *display != '\0') return;
    StartXvfb();
  }
  ~TestDisplay() {
    if (xvfb_ <= 0) return;
    ::kill(xvfb_, SIGTERM);
    int status = 0;
    ::waitpid(xvfb_, &status, 0);
    ::unsetenv("DISPLAY");
  }
  TestDisplay(const TestDisplay&) = delete;
  TestDisplay& operator=(const TestDisplay&) = delete;

  /// Empty when a display is available, else why not (for GTEST_SKIP).
  const std::string& unavailable() const { return unavailable_; }

 private:
  static constexpr int kStartTimeoutMs = 20000;

  void StartXvfb() {
    int fds[2];
    if (::pipe(fds) != 0) {
      unavailable_ = "no DISPLAY and no pipe to start Xvfb";
      return;
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
      // Child: Xvfb writes its display number to the pipe once it accepts clients.
      ::close(fds[0]);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      ::execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten", "tcp",
               static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    const std::string number = ReadDisplayNumber(fds[0]);
    ::close(fds[0]);
    if (number.empty()) {
      if (pid > 0) {
        ::kill(pid, SIGTERM);
        int status = 0;
        ::waitpid(pid, &status, 0);
      }
      unavailable_ = "no DISPLAY set and Xvfb could not be started (install xvfb or run under xvfb-run)";
      return;
    }
    xvfb_ = pid;
    ::setenv("DISPLAY", (":" + number).c_str(), 1);
  }

  // The digits Xvfb writes to `fd` (up to its newline), "" on end of file or timeout.
  static std::string ReadDisplayNumber(int fd) {
    std::string digits;
    pollfd p{fd, POLLIN, 0};
    while (::poll(&p, 1, kStartTimeoutMs) > 0) {
      char c = 0;
      if (::read(fd, &c, 1) != 1) return "";
      if (c == '\n') return digits;
      digits += c;
    }
    return "";
  }

  pid_t xvfb_ = -1;
  std::string unavailable_;
};

}  // namespace tactip::testing
