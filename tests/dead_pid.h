#pragma once
// A process id that no running process has, for tests of stale temporary files.

#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

namespace tactip::testing {

/// The id of a process that has exited and been reaped: no process has it (until reused).
inline pid_t DeadPid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return pid;
}

}  // namespace tactip::testing
