#include "models/scene_part.h"

#include <utility>

#include <fmt/format.h>

namespace tactip {

ContactBudget SceneContactBudget(const SimConfig& sim, int n_collidable) {
  ContactBudget b;
  b.nconmax = n_collidable + 8;
  const int rows_per_contact = sim.cone == "pyramidal" ? 4 : 3;
  b.njmax = rows_per_contact * b.nconmax + 16;
  return b;
}

mjcf::Element SceneRoot(const std::string& model_name, const SimConfig& sim, const ContactConfig& contact,
                        double gravity_z, int n_collidable) {
  mjcf::Element root("mujoco");
  root.Set("model", model_name);
  const bool exact_noslip = sim.noslip == "exact" && sim.noslip_iterations > 0;
  root.Add("compiler").Set("angle", "radian").Set("inertiafromgeom", "false");
  root.Add("option")
      .Set("timestep", sim.timestep_s)
      .Set("integrator", "Euler")
      .Set("solver", "Newton")
      .Set("jacobian", "auto")
      .Set("cone", sim.cone)
      .Set("impratio", sim.impratio)
      .SetInt("iterations", sim.iterations)
      .Set("tolerance", sim.tolerance)
      .SetInt("noslip_iterations", exact_noslip ? 0 : sim.noslip_iterations)
      .Set("noslip_tolerance", sim.noslip_tolerance)
      .Set("gravity", std::vector<double>{0, 0, gravity_z});
  const ContactBudget budget = SceneContactBudget(sim, n_collidable);
  root.Add("size").SetInt("nconmax", budget.nconmax).SetInt("njmax", budget.njmax).SetInt("nuser_jnt", 1);
  const bool post_pass = sim.noslip_iterations > 0;
  if (post_pass && sim.free_sliding_speed_mm_s > 0.0) {
    root.Add("custom")
        .Add("numeric")
        .Set("name", kFreeSlidingNumeric)
        .SetInt("size", 1)
        .Set("data", std::vector<double>{sim.free_sliding_speed_mm_s * 1e-3});
  }
  if (exact_noslip) {
    // tactip's friction pass runs outside MuJoCo (tactip's Simulation reads this numeric);
    // a plain MuJoCo program loading this file runs without it, so its contacts creep.
    root.Comment(fmt::format("sim.noslip = exact: tactip replaces MuJoCo's noslip pass by its friction pass ({} rounds, "
                             "pre-sliding {} mm); plain MuJoCo runs this model without it",
                             sim.noslip_iterations, contact.presliding_mm));
    root.Add("custom")
        .Add("numeric")
        .Set("name", kFrictionPassNumeric)
        .SetInt("size", 2)
        .Set("data", std::vector<double>{static_cast<double>(sim.noslip_iterations), contact.presliding_mm * 1e-3});
  }
  return root;
}


BuiltScene AssembleScene(mjcf::Element root, std::vector<ScenePart> parts) {
  BuiltScene out;
  // The world: every part's bodies, in part order.
  mjcf::Element& world = root.Add("worldbody");
  for (ScenePart& part : parts) {
    for (mjcf::Element& body : part.bodies) world.Append(std::move(body));
  }
  // The passive coupling (skin tendons), then the actuators, each in part order.
  bool any_tendon = false;
  for (const ScenePart& part : parts) any_tendon = any_tendon || !part.tendons.empty();
  if (any_tendon) {
    mjcf::Element& tendon = root.Add("tendon");
    for (ScenePart& part : parts) {
      for (mjcf::Element& t : part.tendons) tendon.Append(std::move(t));
    }
  }
  bool any_actuator = false;
  for (const ScenePart& part : parts) any_actuator = any_actuator || !part.actuators.empty();
  if (any_actuator) {
    mjcf::Element& act = root.Add("actuator");
    for (ScenePart& part : parts) {
      for (mjcf::Element& a : part.actuators) {
        out.actuators.push_back(a.Get("name"));
        act.Append(std::move(a));
      }
    }
  }
  // What the run must find: the objects and the sensors, in part order.
  for (ScenePart& part : parts) {
    for (ObjectPartNames& o : part.objects) out.objects.push_back(std::move(o));
    for (SensorPartNames& s : part.sensors) out.sensors.push_back(std::move(s));
    out.n_collidable += part.n_collidable;
  }
  if (!out.sensors.empty()) out.n_pins = out.sensors.front().n_pins;
  out.xml = root.ToXml();
  return out;
}

}  // namespace tactip
