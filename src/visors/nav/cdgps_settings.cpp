#include "visors/nav/cdgps_settings.hpp"

#include <cmath>

#include "visors/nav/gauss_markov.hpp"

namespace visors::nav {
namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

core::Status check(const CdgpsSettings& s) {
  if (s.local != Craft::kDsc && s.local != Craft::kOsc) return core::Status{core::Problem::kUnknown, "local", "must be dsc or osc"};
  if (!positive(s.max_step_s)) return core::Status{core::Problem::kOutOfRange, "max_step_s", "must be a finite number > 0"};
  if (const core::Status e = check_gauss_markov(s.empirical_tau_s, s.empirical_sigma_mps2); !e) return e;
  if (const core::Status e = check_gauss_markov(s.empirical_tau_s, s.empirical_common_sigma_mps2); !e) {
    return e.renamed("empirical_common_sigma_mps2");
  }
  if (s.empirical_along_track_sigma_mps2 >= 0.0 || std::isnan(s.empirical_along_track_sigma_mps2)) {
    if (const core::Status e = check_gauss_markov(s.empirical_tau_s, s.empirical_along_track_sigma_mps2); !e) {
      return e.renamed("empirical_along_track_sigma_mps2");
    }
  }
  const struct {
    const char* field;
    double value;
  } sigmas[] = {{"clock_random_walk_m", s.clock_random_walk_m},
                {"position_sigma_m", s.position_sigma_m},
                {"velocity_sigma_mps", s.velocity_sigma_mps},
                {"clock_sigma_m", s.clock_sigma_m},
                {"phase_center_sigma_m", s.phase_center_sigma_m},
                {"graphic_ambiguity_sigma_m", s.graphic_ambiguity_sigma_m},
                {"ephemeris_switch_sigma_m", s.ephemeris_switch_sigma_m},
                {"sdcp_ambiguity_sigma_cycles", s.sdcp_ambiguity_sigma_cycles},
                {"slot_timeout_s", s.slot_timeout_s},
                {"graphic_sigma_m", s.graphic_sigma_m},
                {"sdcp_sigma_m", s.sdcp_sigma_m},
                {"gate_sigmas", s.gate_sigmas},
                {"sd_code_sigma_m", s.sd_code_sigma_m},
                {"hold_variance_cycles2", s.hold_variance_cycles2},
                {"impulse_magnitude_sigma", s.impulse_magnitude_sigma},
                {"impulse_direction_sigma_deg", s.impulse_direction_sigma_deg}};
  for (const auto& [field, value] : sigmas) {
    if (!positive(value)) return core::Status{core::Problem::kOutOfRange, field, "must be a finite number > 0"};
  }
  if (!(s.graphic_bias_random_walk_m >= 0.0 && std::isfinite(s.graphic_bias_random_walk_m))) {
    return core::Status{core::Problem::kOutOfRange, "graphic_bias_random_walk_m", "must be a finite number >= 0"};
  }
  if (!positive(s.phase_center_turn_rate_deg_s)) return core::Status{core::Problem::kOutOfRange, "phase_center_turn_rate_deg_s", "must be a finite number > 0"};
  if (!(std::isfinite(s.phase_center_free_after_turn_s) && s.phase_center_free_after_turn_s >= 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "phase_center_free_after_turn_s", "must be a finite number >= 0"};
  }
  if (!(std::isfinite(s.sdcp_correlation_inflation) && s.sdcp_correlation_inflation >= 1.0)) {
    return core::Status{core::Problem::kOutOfRange, "sdcp_correlation_inflation", "must be a finite number >= 1"};
  }
  if (!(std::isfinite(s.sdcp_multipath_sigma_m) && s.sdcp_multipath_sigma_m >= 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "sdcp_multipath_sigma_m", "must be a finite number >= 0 [m]"};
  }
  if (!(std::isfinite(s.sdcp_multipath_tau_s) && s.sdcp_multipath_tau_s > 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "sdcp_multipath_tau_s", "must be a finite number > 0 [s]"};
  }
  if (!(std::isfinite(s.code_multipath_sigma_m) && s.code_multipath_sigma_m >= 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "code_multipath_sigma_m", "must be a finite number >= 0 [m]"};
  }
  if (!(std::isfinite(s.code_multipath_tau_s) && s.code_multipath_tau_s > 0.0)) {
    return core::Status{core::Problem::kOutOfRange, "code_multipath_tau_s", "must be a finite number > 0 [s]"};
  }
  if (!(s.min_float_s_before_fix >= 0.0 && s.min_float_s_before_fix <= 3600.0)) {
    return core::Status{core::Problem::kOutOfRange, "min_float_s_before_fix", "must be in [0, 3600] s"};
  }
  if (!(s.min_fix_elevation_deg >= 0.0 && s.min_fix_elevation_deg < 90.0)) {
    return core::Status{core::Problem::kOutOfRange, "min_fix_elevation_deg", "must be in [0, 90) deg"};
  }
  if (!(s.min_weighting_elevation_deg > 0.0 && s.min_weighting_elevation_deg <= 90.0)) {
    return core::Status{core::Problem::kOutOfRange, "min_weighting_elevation_deg", "must be in (0, 90] deg"};
  }
  if (const core::Status a = validate(s.acceptance); !a) return a.within("acceptance");
  return {};
}

namespace {

// The filter's epochs: 1 Hz, the receivers' rate. At a lower rate the factor overstates the
// correlation between epochs, which weighs the code less than it could: the safe side.
constexpr double kEpochIntervalS = 1.0;

CodeVariance code_variance(double white_m2, double multipath_m2, const CdgpsSettings& s) {
  const double factor = white_equivalent_factor(kEpochIntervalS, s.code_multipath_tau_s);
  return {white_m2 + multipath_m2, white_m2 + factor * multipath_m2};
}

}  // namespace

CodeVariance graphic_variance(const CdgpsSettings& s) {
  const double half = 0.5 * s.code_multipath_sigma_m;
  return code_variance(s.graphic_sigma_m * s.graphic_sigma_m, half * half, s);
}

CodeVariance sd_code_variance(const CdgpsSettings& s) {
  return code_variance(s.sd_code_sigma_m * s.sd_code_sigma_m, 2.0 * s.code_multipath_sigma_m * s.code_multipath_sigma_m, s);
}

}  // namespace visors::nav
