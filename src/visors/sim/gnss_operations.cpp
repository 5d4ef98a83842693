#include "visors/sim/gnss_operations.hpp"

#include <algorithm>
#include <cmath>

#include "visors/core/constants.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

namespace {

using core::Error;

core::Result<bool> plan_windows(const CampaignScenario& s, const AttitudeProfile& profile, double last_epoch_s,
                                GnssOperations& ops) {
  const GnssObservationSettings& o = s.gnss.observations;
  ops.slew_lead_s = o.slew_lead_s > 0.0 ? o.slew_lead_s : profile.required_slew_lead_s(core::kPi);
  if (s.gnss.attitude != "campaign") return true;
  if (o.first_start_s < ops.slew_lead_s) {
    return Error{"gnss.observations.first_start_s", "must be >= the slew lead (" + std::to_string(ops.slew_lead_s) +
                                                        " s): the first slew must start at or after t0"};
  }
  if (ops.period_s <= o.duration_s + ops.slew_lead_s) {
    return Error{"gnss.observations.period_s", "must exceed duration_s + the slew lead (" +
                                                   std::to_string(o.duration_s + ops.slew_lead_s) + " s): windows overlap"};
  }
  for (int k = 0;; ++k) {
    const double start = o.first_start_s + k * ops.period_s;
    const ObservationWindow w{start - ops.slew_lead_s, start, start + o.duration_s};
    if (!(w.slew_start_s < last_epoch_s)) break;
    ops.windows.push_back(w);
  }
  return true;
}

bool in_quiet_time(const std::vector<ObservationWindow>& windows, double t_s) {
  return std::any_of(windows.begin(), windows.end(), [t_s](const ObservationWindow& w) {
    return t_s >= w.slew_start_s && t_s <= w.end_s + kManeuverQuietAfterObservation_s;
  });
}

Eigen::Vector3d isotropic_unit(RandomStream& rng) {
  for (;;) {
    const double x = rng.normal(), y = rng.normal(), z = rng.normal();
    const Eigen::Vector3d u(x, y, z);
    if (u.norm() > 1e-9) return u.normalized();
  }
}

core::Result<bool> plan_maneuvers(const CampaignScenario& s, double last_epoch_s, GnssOperations& ops) {
  const GnssManeuverSettings& m = s.gnss.maneuvers;
  if (m.spacecraft == "none") return true;
  const double burst_spacing = ops.period_s / m.bursts_per_orbit;
  const double spacing = s.propulsion.spacing_s;
  if (m.pieces_per_burst * spacing > burst_spacing + 1e-9) {
    return Error{"gnss.maneuvers.pieces_per_burst", "a burst (pieces_per_burst x " + std::to_string(spacing) +
                                                        " s) must fit in period / bursts_per_orbit (" +
                                                        std::to_string(burst_spacing) + " s)"};
  }
  RandomStream rng(s.seed, "gnss.maneuvers");
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  for (int j = 0;; ++j) {
    const double burst_t = m.first_burst_s + j * burst_spacing;
    if (!(burst_t < last_epoch_s)) break;
    // Burst 2m draws u_m, burst 2m + 1 flies -u_m (the pair cancels: file comment).
    u = j % 2 == 0 ? isotropic_unit(rng) : Eigen::Vector3d(-u);
    for (int i = 0; i < m.pieces_per_burst; ++i) {
      const double t = burst_t + i * spacing;
      if (!(t < last_epoch_s)) break;
      const int crafts = m.spacecraft == "both" ? 2 : 1;
      if (in_quiet_time(ops.windows, t)) {
        ops.skipped_pieces += crafts;
        continue;
      }
      const Eigen::Vector3d dv = m.dv_mps * u;
      if (m.spacecraft == "dsc" || m.spacecraft == "both") {
        ops.pieces.push_back(GnssManeuverPiece{t, 0, j, m.spacecraft == "both" ? Eigen::Vector3d(-dv) : dv});
      }
      if (m.spacecraft == "osc" || m.spacecraft == "both") ops.pieces.push_back(GnssManeuverPiece{t, 1, j, dv});
    }
  }
  return true;
}

core::Result<bool> plan_lrf(const CampaignScenario& s, double last_epoch_s, GnssOperations& ops) {
  const GnssLrfSettings& l = s.gnss.lrf;
  if (!l.enabled) return true;
  const double ratio = l.interval_s / s.step_s;
  const auto stride = static_cast<std::int64_t>(std::llround(ratio));
  if (stride < 1 || std::abs(ratio - static_cast<double>(stride)) > 1e-9) {
    return Error{"gnss.lrf.interval_s", "must be a multiple of time.step_s (" + std::to_string(s.step_s) + " s)"};
  }
  for (const ObservationWindow& w : ops.windows) {
    for (auto k = static_cast<std::int64_t>(std::ceil(w.start_s / s.step_s - 1e-9));; k += stride) {
      const double t = static_cast<double>(k) * s.step_s;
      if (t > w.end_s + 1e-9 || t > last_epoch_s + 1e-9) break;
      ops.lrf_epochs.push_back(k);
    }
  }
  return true;
}

}  // namespace

core::Result<GnssOperations> plan_gnss_operations(const CampaignScenario& s, const AttitudeProfile& profile,
                                                  double last_epoch_s) {
  GnssOperations ops;
  const double a = s.chief_mean.a;
  ops.period_s = s.gnss.observations.period_s > 0.0
                     ? s.gnss.observations.period_s
                     : 2.0 * core::kPi * std::sqrt(a * a * a / core::EarthGravityConstants{}.mu);
  if (auto ok = plan_windows(s, profile, last_epoch_s, ops); !ok) return ok.error();
  if (auto ok = plan_maneuvers(s, last_epoch_s, ops); !ok) return ok.error();
  if (auto ok = plan_lrf(s, last_epoch_s, ops); !ok) return ok.error();
  return ops;
}

}  // namespace visors::sim
