#include "scenarios/rail_catch/catch_controller.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "sim/config.h"

namespace tactip {

void CatchOptions::Validate() const {
  // Each option within a range a real loop could have.
  const auto check = [](const char* name, double v, double lo, double hi) {
    if (!(v >= lo && v <= hi)) {
      throw InputError(fmt::format("--{} = {}: must be in [{}, {}]", name, config_detail::FormatReal(v), config_detail::FormatReal(lo),
                                   config_detail::FormatReal(hi)));
    }
  };
  check("classify-ms", classify_ms, 0.0, 1000.0);
  check("arm-response-ms", arm_response_ms, 0.0, 1000.0);
  check("catch-speed-mm-s", catch_speed_mm_s, 1.0, 500.0);
  check("hold-s", hold_s, 0.05, 5.0);
  check("catch-extra-mm", catch_extra_mm, 0.0, 4.0);
  try {
    ResponseStrategy::Parse(response, 1);
  } catch (const std::exception& e) {
    throw InputError(fmt::format("--response '{}': {} (one sensor: NFr1Sen, e.g. 2Fr1Sen)", response, e.what()));
  }
}

void CatchOptions::ValidateFor(const RailConfig& rail) const {
  const double deepest_mm = rail.press_depth_mm + rail.press_depth_jitter_mm + catch_extra_mm;
  if (deepest_mm <= RailConfig::kMaxPressDepthMm) return;
  throw InputError(fmt::format(
      "--catch-extra-mm = {}: the catch would press rail.press_depth_mm + rail.press_depth_jitter_mm + {} = {:.3g} "
      "mm, beyond the {:.3g} mm a TacTip tolerates; use --catch-extra-mm <= {}",
      config_detail::FormatReal(catch_extra_mm), config_detail::FormatReal(catch_extra_mm), deepest_mm,
      RailConfig::kMaxPressDepthMm,
      config_detail::FormatAtMost(std::max(0.0, RailConfig::kMaxPressDepthMm - rail.press_depth_mm -
                                                    rail.press_depth_jitter_mm))));
}

CatchController::CatchController(const RailSchedule& schedule, std::unique_ptr<Detector> detector,
                                 const CatchOptions& options)
    : schedule_(schedule),
      detector_(std::move(detector)),
      response_(ResponseStrategy::Parse(options.response, 1)),
      options_(options) {
  detector_->Reset();
}

ArmTargets CatchController::Targets(double t) {
  // The protocol until the arm acts; then back in along the normal, at the catch speed, to
  // the press depth (and catch_extra_mm past it).
  if (std::isnan(act_s_) || t < act_s_) return {schedule_.X(t), schedule_.Z(t)};
  const double x = std::min(CatchX(), x_act_m_ + options_.catch_speed_mm_s * 1e-3 * (t - act_s_));
  return {x, schedule_.Z(t)};
}

void CatchController::OnFrame(const FrameInput& input) {
  // Every frame goes through the detector (it needs the history); the strategy acts only
  // once the retraction has started, and once.
  const auto wall0 = std::chrono::steady_clock::now();
  const Decision d = detector_->Update(*input.frames.at(0));
  classify_wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  ++frames_;
  const bool fire = response_.Update({d.slip});
  if (!std::isnan(declared_s_) || input.time_s < schedule_.retract_start || !fire) return;
  declared_s_ = input.time_s;
  act_s_ = declared_s_ + (options_.classify_ms + options_.arm_response_ms) * 1e-3;
  x_act_m_ = schedule_.X(act_s_);
  back_in_s_ = act_s_ + std::max(0.0, CatchX() - x_act_m_) / (options_.catch_speed_mm_s * 1e-3);
}

double CatchController::CatchX() const { return schedule_.press_dist + options_.catch_extra_mm * 1e-3; }

bool CatchController::Done(double t) const {
  // Over once the arm is back in and the object has been watched for hold_s.
  return !std::isnan(back_in_s_) && t > back_in_s_ + options_.hold_s;
}

std::map<std::string, double> CatchController::Figures() const {
  return {{"classify_us", frames_ ? classify_wall_s_ / static_cast<double>(frames_) * 1e6 : 0.0}};
}

std::vector<ControllerAction> CatchController::Actions() const {
  if (std::isnan(declared_s_)) return {};
  return {{declared_s_, "slip_declared"}, {act_s_, "catch"}, {back_in_s_, "back_in"}};
}

}  // namespace tactip
