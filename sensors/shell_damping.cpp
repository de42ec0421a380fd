#include "sensors/shell_damping.h"

namespace tactip {

ShellDamping::ShellDamping(const SkinConfig& skin, double object_mass_kg, const std::vector<std::string>& sensor_prefixes,
                           CompiledModel& model, int n_pins) {
  if (skin.coupling != "shell" || skin.shell_damping != "gel" || sensor_prefixes.empty()) return;
  model_ = &model;
  for (const std::string& prefix : sensor_prefixes) {
    const SkinNames names{prefix};
    dofs_.push_back(model.JointDofAdr(model.JointId(names.Part("skin_shear_z"))));
  }
  c_shell_ = model.DofDamping(dofs_.front());
  const SkinMechanics mech = SkinMechanics::From(skin, static_cast<size_t>(n_pins));
  object_over_shell_ = object_mass_kg / mech.shell_moving_mass_kg;
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
