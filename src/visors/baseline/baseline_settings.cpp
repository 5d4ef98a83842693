#include "visors/baseline/baseline_settings.hpp"

#include <cmath>
#include <string>

namespace visors::baseline {

std::string_view to_string(PositionModel m) { return m == PositionModel::kStatic ? "static" : "kinematic"; }
std::string_view to_string(FrequencySet f) { return f == FrequencySet::kL1 ? "L1" : "L1L2"; }
std::string_view to_string(AmbiguityMode m) {
  switch (m) {
    case AmbiguityMode::kOff: return "off";
    case AmbiguityMode::kContinuous: return "continuous";
    case AmbiguityMode::kHold: return "hold";
  }
  return "?";
}

namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

core::Result<BaselineSettings> validate(const BaselineSettings& s) {
  const auto bad = [](const char* field, const char* message) { return core::Error{field, message}; };
  if (!(s.elevation_mask_deg >= 0.0 && s.elevation_mask_deg < 90.0)) return bad("elevation_mask", "must be in [0, 90) deg");
  if (!(std::isfinite(s.phase_sigma_m) && s.phase_sigma_m >= 0.0)) return bad("phase_sigma", "must be >= 0 m");
  if (!(std::isfinite(s.phase_sigma_elevation_m) && s.phase_sigma_elevation_m >= 0.0)) {
    return bad("phase_sigma_elevation", "must be >= 0 m");
  }
  if (!(s.phase_sigma_m + s.phase_sigma_elevation_m > 0.0)) return bad("phase_sigma", "a + b must be > 0 m");
  if (!positive(s.code_to_phase_sigma)) return bad("code_to_phase_sigma", "must be > 0");
  if (!positive(s.initial_ambiguity_sigma_cyc)) return bad("initial_ambiguity_sigma", "must be > 0 cycles");
  if (!(std::isfinite(s.ambiguity_noise_cyc_per_sqrt_s) && s.ambiguity_noise_cyc_per_sqrt_s >= 0.0)) {
    return bad("ambiguity_noise", "must be >= 0 cycles/sqrt(s)");
  }
  if (!positive(s.kinematic_position_sigma_m)) return bad("kinematic_position_sigma", "must be > 0 m");
  if (!positive(s.slip_geometry_free_m)) return bad("slip_geometry_free", "must be > 0 m");
  if (!positive(s.max_gap_s)) return bad("max_gap", "must be > 0 s");
  if (!positive(s.phase_gate_sigma)) return bad("phase_gate_sigma", "must be > 0");
  if (!positive(s.hold_variance_cyc2)) return bad("hold_variance", "must be > 0 cycles^2");
  if (!(std::isfinite(s.epoch_tolerance_s) && s.epoch_tolerance_s >= 0.0 && s.epoch_tolerance_s < 1.0)) {
    return bad("epoch_tolerance", "must be in [0, 1) s");
  }
  if (const core::Status a = nav::validate(s.acceptance); !a) return a.within("acceptance").error();
  return s;
}

}  // namespace visors::baseline
