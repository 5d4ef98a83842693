#include "visors/sim/formation_keeping.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"

namespace visors::sim {

namespace {

core::Result<astro::KeplerianElements> mean_elements(const core::StateVector& x_gcrf,
                                                     const core::EarthGravityConstants& gravity, const std::string& who) {
  const auto osculating = astro::cartesian_to_keplerian(x_gcrf.r, x_gcrf.v, gravity.mu);
  if (!osculating.ok()) return core::Error{who, osculating.error().describe()};
  const auto mean = astro::mean_from_osculating(*osculating, gravity);
  if (!mean.ok()) return core::Error{who, mean.error().describe()};
  return *mean;
}

}  // namespace

core::Result<astro::RelativeOrbitalElements> mean_roe_from_states(const core::StateVector& chief_gcrf,
                                                                  const core::StateVector& deputy_gcrf,
                                                                  const core::EarthGravityConstants& gravity) {
  const auto chief = mean_elements(chief_gcrf, gravity, "chief");
  if (!chief.ok()) return chief.error();
  const auto deputy = mean_elements(deputy_gcrf, gravity, "deputy");
  if (!deputy.ok()) return deputy.error();
  return astro::roe_from_keplerian(*chief, *deputy);
}

core::Result<AlongTrackCorrection> along_track_correction(const core::StateVector& chief_gcrf,
                                                          const core::StateVector& deputy_gcrf,
                                                          const astro::RelativeOrbitalElements& target_roe,
                                                          double planned_dv_t_deputy_mps,
                                                          const core::EarthGravityConstants& gravity) {
  const auto chief = mean_elements(chief_gcrf, gravity, "chief");
  if (!chief.ok()) return chief.error();
  const auto roe = mean_roe_from_states(chief_gcrf, deputy_gcrf, gravity);
  if (!roe.ok()) return roe.error();
  AlongTrackCorrection c;
  c.mean_roe = *roe;
  c.chief_mean_a_m = chief->a;
  c.chief_mean_u_rad = chief->argp + chief->M;
  c.mean_motion_radps = std::sqrt(gravity.mu / (chief->a * chief->a * chief->a));
  // dlambda error removed in one orbit by d(dlambda)/dt = -(3/2) n da (header, step 2). Both
  // dlambda are wrapped to (-pi, pi]; the 40 m formation is far from the wrap.
  const double dlambda_error = c.mean_roe(astro::roe::kDlambda) - target_roe(astro::roe::kDlambda);
  c.da_target = target_roe(astro::roe::kDa) + dlambda_error / (3.0 * core::kPi);
  // Gauss: delta(da) = 2 dv_T / (n a_c) (header, step 3).
  const double dv_t_total_mps = 0.5 * c.mean_motion_radps * c.chief_mean_a_m * (c.da_target - c.mean_roe(astro::roe::kDa));
  c.dv_t_deputy_mps = dv_t_total_mps - planned_dv_t_deputy_mps;
  return c;
}

double eccentricity_tangential_dv_mps(const AlongTrackCorrection& now, const astro::RelativeOrbitalElements& target_roe,
                                      int bursts_per_orbit) {
  if (bursts_per_orbit < 3) return 0.0;
  const double dex_error = target_roe(astro::roe::kDex) - now.mean_roe(astro::roe::kDex);
  const double dey_error = target_roe(astro::roe::kDey) - now.mean_roe(astro::roe::kDey);
  const double u = now.chief_mean_u_rad;
  // x_0 = (n a_c / m) (de_target - de) . (cos u_0, sin u_0) (header, step 4).
  return now.mean_motion_radps * now.chief_mean_a_m / bursts_per_orbit * (dex_error * std::cos(u) + dey_error * std::sin(u));
}

double fit_tangential_correction(const Eigen::Vector3d& random_rtn_mps, double wanted_mps, double min_dv_mps,
                                 double max_dv_mps) {
  // |random + c T|^2 = c^2 + 2 c r_T + |random|^2: the c with |.| = L are -r_T +- sqrt(r_T^2 - |random|^2 + L^2).
  const double r_t = random_rtn_mps(1);
  const double r2 = random_rtn_mps.squaredNorm();
  const double max_disc = r_t * r_t - r2 + max_dv_mps * max_dv_mps;
  if (max_disc < 0.0) return 0.0;  // the random part alone is off the tangential line's reach
  // Under the maximum: clamp the correction (the random part is kept whole).
  double c = std::clamp(wanted_mps, -r_t - std::sqrt(max_disc), -r_t + std::sqrt(max_disc));
  // Over the minimum: out of the band where the total would be refused as too small.
  const double min_disc = r_t * r_t - r2 + min_dv_mps * min_dv_mps;
  if (min_disc > 0.0) {
    const double low = -r_t - std::sqrt(min_disc), high = -r_t + std::sqrt(min_disc);
    if (c > low && c < high) c = (c - low < high - c) ? low : high;
  }
  return c;
}

}  // namespace visors::sim
