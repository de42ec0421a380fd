// The fixture that fails a test on a MuJoCo warning: it fails one in which MuJoCo really
// raised a warning (a NaN control), and passes one that stepped cleanly.

#include "mujoco_warning_guard.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/simulation.h"

namespace tactip {
namespace {

/// A pushed slider: one actuator on one slide joint.
CompiledModel PushedSlider() {
  return CompiledModel::FromXml(
      "<mujoco><option timestep='0.001' gravity='0 0 0'/><worldbody><body><joint name='j' type='slide' axis='1 0 0'/>"
      "<inertial pos='0 0 0' mass='1' diaginertia='1 1 1'/></body></worldbody>"
      "<actuator><motor name='push' joint='j'/></actuator></mujoco>");
}

/// The guard's SetUp and TearDown, callable from a test.
class GuardProbe : public testing::MujocoWarningGuard {
 public:
  using MujocoWarningGuard::SetUp;
  using MujocoWarningGuard::TearDown;
  void TestBody() override {}
};

TEST(MujocoWarningGuardTest, FailsATestInWhichMujocoRaisedAWarning) {
  const CompiledModel model = PushedSlider();
  GuardProbe guard;
  guard.SetUp();
  Simulation sim(model);
  sim.SetControl(model.ActuatorId("push"), std::nan(""));
  try {
    sim.Step();
    ADD_FAILURE() << "a NaN control raised no warning";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("MuJoCo warning BADCTRL"), std::string::npos) << e.what();
  }
  EXPECT_NONFATAL_FAILURE(guard.TearDown(), "MuJoCo raised 1 warning(s) during this test");
}

TEST(MujocoWarningGuardTest, PassesATestThatSteppedWithoutAWarning) {
  const CompiledModel model = PushedSlider();
  GuardProbe guard;
  guard.SetUp();
  Simulation sim(model);
  sim.SetControl(model.ActuatorId("push"), 1.0);
  for (int i = 0; i < 100; ++i) sim.Step();
  EXPECT_NEAR(sim.Qvel(0), 0.1, 1e-9) << "1 N on 1 kg for 0.1 s";
  guard.TearDown();  // a warning would add a failure to this test
}

}  // namespace
}  // namespace tactip
