#include "scenarios/figures/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <stdexcept>
#include <system_error>

extern char** environ;  // NOLINT: POSIX; the child gets this process's environment

namespace tactip {
namespace {

/// A pipe whose ends close themselves (and are not inherited by other children).
struct Pipe {
  int read = -1, write = -1;
  Pipe() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
    read = fds[0];
    write = fds[1];
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  ~Pipe() {
    CloseRead();
    CloseWrite();
  }
  void CloseRead() {
    if (read >= 0) ::close(read);
    read = -1;
  }
  void CloseWrite() {
    if (write >= 0) ::close(write);
    write = -1;
  }
};

/// Owns posix_spawn's file actions.
struct FileActions {
  posix_spawn_file_actions_t fa;
  FileActions() { posix_spawn_file_actions_init(&fa); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;
  ~FileActions() { posix_spawn_file_actions_destroy(&fa); }
};

/// Reads both pipes until the child closes them (poll, so neither can fill up and block it).
void Drain(Pipe& out, Pipe& err, ChildResult& r) {
  std::array<char, 4096> buf{};
  while (out.read >= 0 || err.read >= 0) {
    std::array<pollfd, 2> fds{{{out.read, POLLIN, 0}, {err.read, POLLIN, 0}}};
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::system_error(errno, std::generic_category(), "poll");
    }
    for (int k = 0; k < 2; ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      Pipe& p = k == 0 ? out : err;
      const ssize_t n = ::read(p.read, buf.data(), buf.size());
      if (n > 0) {
        (k == 0 ? r.out : r.err).append(buf.data(), static_cast<size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        p.CloseRead();  // end of output (or an unreadable pipe)
      }
    }
  }
}

}  // namespace

ChildResult RunChild(const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::invalid_argument("RunChild: no program given");
  // The child's stdin is /dev/null, its stdout and stderr our pipes.
  Pipe out, err;
  FileActions actions;
  posix_spawn_file_actions_addopen(&actions.fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions.fa, out.write, 1);
  posix_spawn_file_actions_adddup2(&actions.fa, err.write, 2);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  // Start it (posix_spawnp searches PATH for a bare name); glibc reports a failed exec here.
  pid_t pid = 0;
  const int rc = ::posix_spawnp(&pid, args[0], &actions.fa, nullptr, args.data(), environ);
  if (rc != 0) throw std::system_error(rc, std::generic_category(), argv[0]);
  out.CloseWrite();
  err.CloseWrite();

  // Collect its output, then its status.
  ChildResult r;
  Drain(out, err, r);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::system_error(errno, std::generic_category(), "waitpid");
  }
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

std::string LastLine(const std::string& text) {
  size_t end = text.size();
  while (end > 0) {
    const size_t start = text.rfind('\n', end - 1);
    const size_t from = start == std::string::npos ? 0 : start + 1;
    std::string line = text.substr(from, end - from);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) return line;
    if (start == std::string::npos) break;
    end = start;
  }
  return "";
}

}  // namespace tactip
