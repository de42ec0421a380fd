#include "sim/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mujoco_warning_guard.h"
#include "sim/sim_config.h"

namespace tactip {
namespace {

// One slider on a spring: mass m, stiffness k, damping c, timestep dt.
std::string SpringXml(double m, double k, double c, double dt) {
  return "<mujoco><option timestep='" + std::to_string(dt) +
         "' integrator='Euler' gravity='0 0 0'/><worldbody><body name='b'>"
         "<joint name='j' type='slide' axis='1 0 0' stiffness='" +
         std::to_string(k) + "' damping='" + std::to_string(c) + "'/><inertial pos='0 0 0' mass='" +
         std::to_string(m) + "' diaginertia='1e-6 1e-6 1e-6'/></body></worldbody></mujoco>";
}

TEST(SimulationTest, BadMjcfThrowsModelErrorWithMujocoMessage) {
  try {
    CompiledModel::FromXml("<mujoco><worldbody><body><joint type='nonsense'/></body></worldbody></mujoco>");
    FAIL() << "expected ModelError";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("MJCF does not compile"), std::string::npos) << e.what();
  }
}

TEST(SimulationTest, MissingNameThrowsModelError) {
  const auto m = CompiledModel::FromXml(SpringXml(1, 1, 0, 0.001));
  try {
    m.JointId("nope");
    FAIL();
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()), "model has no joint named 'nope'");
  }
}

TEST(SimulationTest, ContactBufferOverflowIsReported) {
  // Ten spheres resting on a plane with room for only two contacts.
  std::string xml = "<mujoco><size nconmax='2' njmax='20'/><worldbody><geom type='plane' size='1 1 0.1'/>";
  for (int i = 0; i < 10; ++i) {
    xml += "<body pos='" + std::to_string(0.1 * i) + " 0 0.009'><freejoint/><geom type='sphere' size='0.01' mass='0.01'/></body>";
  }
  xml += "</worldbody></mujoco>";
  const auto m = CompiledModel::FromXml(xml);
  const int hook_before = MujocoWarningsRaised();
  Simulation sim(m);
  try {
    for (int i = 0; i < 100; ++i) sim.Step();
    FAIL() << "expected SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("CONTACTFULL"), std::string::npos) << e.what();
  }
  // MuJoCo counts each of the eight dropped contacts and sends only the first to its hook.
  EXPECT_EQ(sim.WarningCount(), 8);
  EXPECT_EQ(MujocoWarningsRaised() - hook_before, 1);
}

// Semi-implicit Euler with implicit damping is stable for omega*dt below
// 2 (zeta + sqrt(zeta^2 + 1)); check both sides of the limit on a real MuJoCo model.
double FinalAmplitude(double zeta, double dt_factor) {
  const double m = 1e-3, k = 100.0;
  const double omega = std::sqrt(k / m);
  const double c = 2.0 * zeta * std::sqrt(k * m);
  const double dt = dt_factor * MaxStableTimestep(omega, zeta, 1.0);
  const auto model = CompiledModel::FromXml(
      "<mujoco><option timestep='" + std::to_string(dt) +
      "' integrator='Euler' gravity='0 0 0'/><worldbody><body name='b'><joint name='j' type='slide' axis='1 0 0' "
      "stiffness='" + std::to_string(k) + "' damping='" + std::to_string(c) +
      "' ref='0'/><inertial pos='0 0 0' mass='" + std::to_string(m) +
      "' diaginertia='1e-6 1e-6 1e-6'/></body></worldbody><actuator><motor name='push' joint='j'/></actuator></mujoco>");
  Simulation sim(model);
  const int a = model.ActuatorId("push");
  const int adr = model.JointQposAdr(model.JointId("j"));
  // One impulse, then free motion.
  sim.SetControl(a, 1.0);
  sim.Step();
  sim.SetControl(a, 0.0);
  double amp = 0.0;
  for (int i = 0; i < 400; ++i) {
    sim.Step();
    if (i >= 300) amp = std::max(amp, std::abs(sim.Qpos(adr)));
  }
  return amp;
}

TEST(SimulationTest, BlowUpStopsWithBadStateMessage) {
  // Three times the stability limit: the oscillation grows until MuJoCo flags it.
  try {
    for (int i = 0; i < 100; ++i) FinalAmplitude(0.0, 3.0);
    FAIL() << "expected SimulationError";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("MuJoCo warning BAD"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reduce sim.timestep_s"), std::string::npos) << e.what();
  }
}

// Tests that run MuJoCo and must raise no warning.
class SimulationPhysicsTest : public testing::MujocoWarningGuard {};

TEST_F(SimulationPhysicsTest, StableBelowTheStabilityLimitOfMujocoEuler) {
  for (double zeta : {0.0, 0.3, 0.7}) {
    EXPECT_LT(FinalAmplitude(zeta, 0.95), 1.0) << "zeta " << zeta << " should be stable below the limit";
  }
}

TEST(SimulationTest, UnstableAboveTheStabilityLimitOfMujocoEuler) {
  // Not guarded: a blow-up may end in a MuJoCo warning (and SimulationError).
  for (double zeta : {0.0, 0.3, 0.7}) {
    bool blew_up = false;
    try {
      blew_up = FinalAmplitude(zeta, 1.1) > 1.0;
    } catch (const SimulationError&) {
      blew_up = true;
    }
    EXPECT_TRUE(blew_up) << "zeta " << zeta << " should be unstable above the limit";
  }
}

}  // namespace
}  // namespace tactip
