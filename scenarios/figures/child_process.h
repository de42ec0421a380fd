#pragma once
// Running another program without a shell and capturing what it prints.

#include <string>
#include <vector>

namespace tactip {

/// What a finished child process returned and printed.
struct ChildResult {
  int exit_code = -1;  ///< exit status, or -1 when a signal ended it
  int signal = 0;      ///< the signal that ended it (0 if it exited)
  std::string out;     ///< everything it wrote to standard output
  std::string err;     ///< everything it wrote to standard error
};

/// Runs `argv` (argv[0] is looked up on PATH when it has no '/') with posix_spawn, no
/// shell, standard input from /dev/null and this process's environment; waits for it and
/// returns its status and output. Throws std::system_error (with errno, e.g. ENOENT) if it
/// cannot be started, std::invalid_argument if `argv` is empty.
ChildResult RunChild(const std::vector<std::string>& argv);

/// The last non-empty line of `text` ("" if none): a failed program's one-line reason.
std::string LastLine(const std::string& text);

}  // namespace tactip
