#include "scenarios/rail/shell_damping.h"

#include "models/skin.h"

namespace tactip {

ShellDamping::ShellDamping(const RailScenarioConfig& cfg, CompiledModel& model, int n_pins) {
  if (cfg.skin.coupling != "shell" || cfg.skin.shell_damping != "gel") return;
  model_ = &model;
  for (const SensorMountConfig& mount : cfg.sensors) {
    const SkinNames names{mount.Prefix()};
    dofs_.push_back(model.JointDofAdr(model.JointId(names.Part("skin_shear_z"))));
  }
  c_shell_ = model.DofDamping(dofs_.front());
  const SkinMechanics mech = SkinMechanics::From(cfg.skin, static_cast<size_t>(n_pins));
  object_over_shell_ = cfg.object.mass_kg / mech.shell_moving_mass_kg;
}

void ShellDamping::Update(const std::vector<double>& stuck) {
  if (!active()) return;
  int touching = 0;
  for (double s : stuck) touching += s > 0.0 ? 1 : 0;
  for (size_t k = 0; k < stuck.size(); ++k) {
    const double share = touching > 0 ? stuck[k] / touching : 0.0;
    model_->SetDofDamping(dofs_[k], c_shell_ * Factor(share * object_over_shell_));
  }
}

}  // namespace tactip
