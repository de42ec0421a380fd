// A MuJoCo internal error (here its solver stack overflowing) reaches the caller as a
// SimulationError: the process goes on, destructors above MuJoCo's frames run, and MuJoCo
// keeps working for other simulations.

#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <string>
#include <thread>

#include "mujoco_internal_error.h"
#include "sim/base/temp_file.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

using testing::DroppedBoxXml;
using testing::StepOneSecond;

TEST(MujocoInternalErrorTest, StackOverflowThrowsSimulationErrorAndMujocoGoesOn) {
  const CompiledModel tight = CompiledModel::FromXml(DroppedBoxXml(150));
  try {
    StepOneSecond(tight);
    FAIL() << "expected a SimulationError";
  } catch (const SimulationError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("MuJoCo internal error: ", 0), 0u) << what;
    EXPECT_NE(what.find("Stack overflow"), std::string::npos) << what;
  }
  // A new simulation of the same model fails the same way; one with a deep stack lands.
  EXPECT_THROW(StepOneSecond(tight), SimulationError);
  EXPECT_GE(StepOneSecond(CompiledModel::FromXml(DroppedBoxXml(100000))), 1.0);
}

TEST(MujocoInternalErrorTest, UnwindingRemovesTheTemporaryFilesOfTheFramesAbove) {
  const CompiledModel tight = CompiledModel::FromXml(DroppedBoxXml(150));
  std::string scratch;
  try {
    const TempFile file;
    scratch = file.path();
    ASSERT_TRUE(std::filesystem::exists(scratch));
    StepOneSecond(tight);
  } catch (const SimulationError&) {
  }
  ASSERT_FALSE(scratch.empty());
  EXPECT_FALSE(std::filesystem::exists(scratch)) << scratch;
}

TEST(MujocoInternalErrorTest, ErrorInAWorkerThreadReachesTheThreadThatWaits) {
  const CompiledModel tight = CompiledModel::FromXml(DroppedBoxXml(150));
  std::exception_ptr failure;
  std::thread worker([&] {
    try {
      StepOneSecond(tight);
    } catch (...) {
      failure = std::current_exception();
    }
  });
  worker.join();
  ASSERT_TRUE(failure);
  EXPECT_THROW(std::rethrow_exception(failure), SimulationError);
}

}  // namespace
}  // namespace tactip
