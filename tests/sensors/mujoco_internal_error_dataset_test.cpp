// A MuJoCo internal error while a dataset is being written, as in `tactip generate` (the
// dataset written on this thread, runs simulated on workers): the error reaches the writer's
// thread as a SimulationError and the half-written dataset leaves no file behind.

#include <gtest/gtest.h>
#include <unistd.h>

#include <exception>
#include <filesystem>
#include <string>
#include <thread>

#include "mujoco_internal_error.h"
#include "sensors/dataset.h"
#include "sim/simulation.h"

namespace tactip {
namespace {

namespace fs = std::filesystem;

TEST(MujocoInternalErrorDatasetTest, ErrorDuringGenerationLeavesNoFile) {
  const fs::path dir = fs::temp_directory_path() / ("tactip_mujoco_error_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const CompiledModel tight = CompiledModel::FromXml(testing::DroppedBoxXml(150));
  try {
    DatasetHeader header;
    header.tactip_version = "0.1.0";
    header.scenario = "rail";
    DatasetWriter writer((dir / "out.h5").string(), header);
    ASSERT_FALSE(fs::is_empty(dir)) << "the writer's temporary file";
    std::exception_ptr failure;
    std::thread worker([&] {
      try {
        testing::StepOneSecond(tight);
      } catch (...) {
        failure = std::current_exception();
      }
    });
    worker.join();
    if (failure) std::rethrow_exception(failure);
    ADD_FAILURE() << "expected a SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("MuJoCo internal error: ", 0), 0u) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "no dataset and no temporary file";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tactip
