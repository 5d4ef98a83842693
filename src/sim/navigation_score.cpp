#include "sim/navigation_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/rtn_frame.hpp"
#include "nav/fix_truth.hpp"

namespace visors::sim {

namespace {

std::size_t index_of(gnc::Spacecraft s) { return s == gnc::Spacecraft::kDsc ? 0 : 1; }

double rms(double sum_sq, std::int64_t n) { return n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0; }

}  // namespace

void NavigationScore::record_phase_truth(gnc::Spacecraft receiver, const GpsReceiverEpoch& epoch) {
  const std::size_t r = index_of(receiver);
  PhaseTruth& p = truth_[r][static_cast<std::size_t>(next_truth_[r])];
  next_truth_[r] = (next_truth_[r] + 1) % kTruthEpochs;
  p.t = epoch.measurement.t;
  p.count = epoch.measurement.channel_count;
  for (int k = 0; k < p.count; ++k) {
    const GpsChannelTruth& c = epoch.truth[static_cast<std::size_t>(k)];
    p.prn[static_cast<std::size_t>(k)] = c.prn;
    p.cycles[static_cast<std::size_t>(k)] =
        static_cast<double>(c.ambiguity_cycles) + c.half_cycle_cycles + epoch.receiver_phase_cycles;
  }
}

const NavigationScore::PhaseTruth* NavigationScore::phase_truth(gnc::Spacecraft receiver, core::GpsTime t) const {
  for (const PhaseTruth& p : truth_[index_of(receiver)]) {
    if (p.count > 0 && p.t == t) return &p;
  }
  return nullptr;
}

// The fixed SD ambiguities' double differences against the truth's (file comment).
bool NavigationScore::wrong_fix(const gnc::OnboardNavigation& navigation, core::GpsTime t) const {
  const PhaseTruth* dsc = phase_truth(gnc::Spacecraft::kDsc, t);
  const PhaseTruth* osc = phase_truth(gnc::Spacecraft::kOsc, t);
  if (dsc == nullptr || osc == nullptr) return false;
  const auto true_sd = [&](int prn) {
    const auto find = [prn](const PhaseTruth& p) {
      for (int k = 0; k < p.count; ++k) {
        if (p.prn[static_cast<std::size_t>(k)] == prn) return p.cycles[static_cast<std::size_t>(k)];
      }
      return std::numeric_limits<double>::quiet_NaN();
    };
    return find(*osc) - find(*dsc);
  };
  return nav::wrong_fix(navigation.filter(), navigation.last_report(), true_sd);
}

// The processed epochs since the last step: counted, and the last one's fix scored.
void NavigationScore::count_epoch(Accumulator& a, const gnc::OnboardNavigation& navigation, double t_s) {
  const gnc::NavigationCounters& c = navigation.counters();
  const std::int64_t epochs = c.epochs_joint + c.epochs_alone;
  const core::GpsTime t = navigation.last_update();
  if (epochs == a.epochs || (a.have_scored && t <= a.last_scored)) return;
  a.epochs = epochs;
  a.have_scored = true;
  a.last_scored = t;
  if (!navigation.last_report().fix_applied) return;
  a.fixed = c.epochs_fixed;
  if (a.first_fix_s < 0.0) {
    a.first_fix_s = t_s;
    a.epochs_before_first_fix = epochs - 1;
  }
  if (wrong_fix(navigation, t)) ++a.wrong;
}

NavigationSample NavigationScore::score(gnc::Spacecraft who, const gnc::OnboardNavigation& navigation, double t_s,
                                        const FormationTruth& truth, bool in_slew) {
  NavigationSample sample;
  const auto& solution = navigation.last_solution();
  Accumulator& a = stats_[index_of(who)];
  if (solution && a.first_solution_s < 0.0) a.first_solution_s = t_s;  // the cold start
  if (a.first_solution_s >= 0.0 && t_s > a.first_solution_s) ++a.time_tags;
  if (solution) count_epoch(a, navigation, t_s);
  if (!solution || !navigation.valid()) {
    if (solution) ++a.steps_invalid;
    return sample;
  }
  const Eigen::Matrix3d R = core::gcrf_to_rtn_matrix(truth.dsc_gcrf);
  const Eigen::Vector3d position_gcrf =
      (solution->deputy_gcrf.r - solution->chief_gcrf.r) - (truth.osc_gcrf.r - truth.dsc_gcrf.r);
  // The estimated antenna is the estimated centre of mass + C (known lever + p), the true one the
  // true centre of mass + C (known lever + l), l the true minus the known lever: their difference
  // is the position error + C (p - l) per spacecraft.
  const nav::NavVector& x = navigation.fixed() ? navigation.filter().x_fixed() : navigation.filter().x();
  const auto lever = [&x](nav::Craft craft, const Eigen::Matrix3d& c, const Eigen::Vector3d& lever_error) {
    return Eigen::Vector3d(c * (nav::state::kPhaseCenterUnit * x.segment<3>(nav::state::phase_center(craft)) - lever_error));
  };
  const Eigen::Vector3d lever_gcrf = lever(nav::Craft::kOsc, truth.osc_body_to_gcrf, truth.osc_lever_error_m) -
                                     lever(nav::Craft::kDsc, truth.dsc_body_to_gcrf, truth.dsc_lever_error_m);
  sample.valid = true;
  sample.fixed = navigation.fixed();
  sample.position_rtn_m = R * position_gcrf;
  sample.antenna_rtn_m = R * (position_gcrf + lever_gcrf);
  sample.velocity_rtn_mps =
      R * ((solution->deputy_gcrf.v - solution->chief_gcrf.v) - (truth.osc_gcrf.v - truth.dsc_gcrf.v));
  sample.sigma_rtn_m = solution->relative_covariance_rtn.diagonal().head<3>().cwiseMax(0.0).cwiseSqrt();
  using nav::Craft;
  sample.empirical_dsc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kDsc));
  sample.empirical_osc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kOsc));
  const double p2 = sample.position_rtn_m.squaredNorm();
  const double a2 = sample.antenna_rtn_m.squaredNorm();
  ++a.steps;
  a.position_sq += p2;
  a.antenna_sq += a2;
  a.velocity_sq += sample.velocity_rtn_mps.squaredNorm();
  a.antenna_worst = std::max(a.antenna_worst, std::sqrt(a2));
  if (!in_slew) {
    ++a.steps_outside_slews;
    a.position_outside_sq += p2;
    a.antenna_outside_sq += a2;
    a.antenna_outside_worst = std::max(a.antenna_outside_worst, std::sqrt(a2));
  }
  return sample;
}

nlohmann::json NavigationScore::summary() const {
  nlohmann::json out;
  const char* names[2] = {"dsc", "osc"};
  for (std::size_t k = 0; k < 2; ++k) {
    const Accumulator& a = stats_[k];
    const double epochs = static_cast<double>(std::max<std::int64_t>(a.epochs, 1));
    out[names[k]] = {
        {"steps", a.steps},
        {"steps_not_valid", a.steps_invalid},
        {"relative_position_rms_m", rms(a.position_sq, a.steps)},
        {"relative_antenna_rms_m", rms(a.antenna_sq, a.steps)},
        {"relative_antenna_worst_m", a.antenna_worst},
        {"relative_velocity_rms_mps", rms(a.velocity_sq, a.steps)},
        {"outside_slews", {{"steps", a.steps_outside_slews},
                           {"relative_position_rms_m", rms(a.position_outside_sq, a.steps_outside_slews)},
                           {"relative_antenna_rms_m", rms(a.antenna_outside_sq, a.steps_outside_slews)},
                           {"relative_antenna_worst_m", a.antenna_outside_worst}}},
        {"epochs_processed", a.epochs},
        {"fix_rate", static_cast<double>(a.fixed) / epochs},
        {"receiver_time_tags", a.time_tags},
        {"fix_rate_all_epochs", static_cast<double>(a.fixed) / static_cast<double>(std::max<std::int64_t>(a.time_tags, 1))},
        {"fix_rate_after_first_fix",
         a.first_fix_s >= 0.0 ? static_cast<double>(a.fixed) / static_cast<double>(a.epochs - a.epochs_before_first_fix) : 0.0},
        {"wrong_fix_epochs", a.wrong},
        {"wrong_fix_rate", static_cast<double>(a.wrong) / epochs},
        {"time_to_first_fix_s", a.first_fix_s >= 0.0 ? a.first_fix_s - a.first_solution_s : -1.0},
    };
  }
  return out;
}

}  // namespace visors::sim
