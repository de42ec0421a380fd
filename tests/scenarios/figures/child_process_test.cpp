// Running a program without a shell: exit code, both outputs, no deadlock on large output,
// and a clear error for a program that does not exist.

#include "scenarios/figures/child_process.h"

#include <gtest/gtest.h>

#include <csignal>
#include <string>
#include <system_error>

namespace tactip {
namespace {

TEST(RunChildTest, CapturesExitCodeAndBothOutputs) {
  const ChildResult r = RunChild({"/bin/sh", "-c", "echo out; echo err >&2; exit 3"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_EQ(r.signal, 0);
  EXPECT_EQ(r.out, "out\n");
  EXPECT_EQ(r.err, "err\n");
}

TEST(RunChildTest, PassesArgumentsVerbatimWithoutAShell) {
  const ChildResult r = RunChild({"printf", "%s|", "a b", "$HOME", "*", "'q'"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "a b|$HOME|*|'q'|");
}

TEST(RunChildTest, LargeOutputOnBothStreamsDoesNotBlock) {
  const ChildResult r = RunChild({"/bin/sh", "-c", "head -c 300000 /dev/zero; head -c 200000 /dev/zero >&2"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.size(), 300000u);
  EXPECT_EQ(r.err.size(), 200000u);
}

TEST(RunChildTest, StdinIsEmptyAndSignalsAreReported) {
  EXPECT_EQ(RunChild({"cat"}).out, "");
  const ChildResult r = RunChild({"/bin/sh", "-c", "kill -TERM $$"});
  EXPECT_EQ(r.exit_code, -1);
  EXPECT_EQ(r.signal, SIGTERM);
}

TEST(RunChildTest, AMissingProgramThrowsWithItsErrno) {
  try {
    RunChild({"/nonexistent/program"});
    FAIL() << "no error";
  } catch (const std::system_error& e) {
    EXPECT_EQ(e.code().value(), ENOENT);
  }
  EXPECT_THROW(RunChild({}), std::invalid_argument);
}

TEST(LastLineTest, SkipsTrailingBlankLines) {
  EXPECT_EQ(LastLine("Traceback\n  ...\nValueError: bad\n\n"), "ValueError: bad");
  EXPECT_EQ(LastLine("one"), "one");
  EXPECT_EQ(LastLine("\n \n"), "");
  EXPECT_EQ(LastLine(""), "");
}

}  // namespace
}  // namespace tactip
