#include "visors/sim/navigation_score.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "visors/core/rtn_frame.hpp"
#include "visors/gnss/ephemeris_store.hpp"
#include "visors/nav/fix_truth.hpp"

namespace visors::sim {

namespace {

std::size_t index_of(gnc::Spacecraft s) { return s == gnc::Spacecraft::kDsc ? 0 : 1; }

double rms(double sum_sq, std::int64_t n) { return n > 0 ? std::sqrt(sum_sq / static_cast<double>(n)) : 0.0; }

// The navigation's counters as summary.json names them.
void add_counters(nlohmann::json& n, const gnc::NavigationCounters& c) {
  nlohmann::json ephemerides;
  for (std::size_t e = 0; e < c.ephemerides.size(); ++e) {
    ephemerides[gnss::to_string(static_cast<gnss::EphemerisStore::AcceptStatus>(e))] = c.ephemerides[e];
  }
  n["epochs_joint"] = c.epochs_joint;
  n["epochs_alone"] = c.epochs_alone;
  n["epochs_refused"] = c.epochs_refused;
  n["wrong_fixes_refused"] = c.wrong_fixes_refused;
  n["impulses_applied"] = c.impulses_applied;
  n["impulses_late"] = c.impulses_late;
  n["laser_ranges_used"] = c.laser_used;
  n["laser_ranges_rejected"] = c.laser_rejected;
  n["clock_jumps"] = c.clock_jumps;
  n["ephemerides"] = ephemerides;
}

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

double NavigationScore::true_sd(const PhaseTruth& dsc, const PhaseTruth& osc, int prn) {
  const auto find = [prn](const PhaseTruth& p) {
    for (int k = 0; k < p.count; ++k) {
      if (p.prn[static_cast<std::size_t>(k)] == prn) return p.cycles[static_cast<std::size_t>(k)];
    }
    return std::numeric_limits<double>::quiet_NaN();
  };
  return find(osc) - find(dsc);
}

// The fixed SD ambiguities' double differences against the truth's (file comment).
bool NavigationScore::wrong_fix(const gnc::OnboardNavigation& navigation, core::GpsTime t) const {
  const PhaseTruth* dsc = phase_truth(gnc::Spacecraft::kDsc, t);
  const PhaseTruth* osc = phase_truth(gnc::Spacecraft::kOsc, t);
  if (dsc == nullptr || osc == nullptr) return false;
  return nav::wrong_fix(navigation.filter(), navigation.last_report(), [&](int prn) { return true_sd(*dsc, *osc, prn); });
}

// The record's fix against the truth of its epoch: a full fix's integers, a partial fix's
// combinations (file comment); a NaN (a satellite the truth or the filter lacks) leaves what
// needs it unjudged, as nav::wrong_fix does.
bool NavigationScore::wrong_fix(const gnc::NavigationTelemetry& record) const {
  const PhaseTruth* dsc = phase_truth(gnc::Spacecraft::kDsc, record.update_t);
  const PhaseTruth* osc = phase_truth(gnc::Spacecraft::kOsc, record.update_t);
  if (dsc == nullptr || osc == nullptr) return false;
  const double reference = true_sd(*dsc, *osc, record.dd_reference_prn);
  const int count = std::clamp(record.dd_count, 0, gnc::kTelemetryDoubleDifferences);
  std::array<double, gnc::kTelemetryDoubleDifferences> true_dd{};
  for (int j = 0; j < count; ++j) {
    true_dd[static_cast<std::size_t>(j)] = true_sd(*dsc, *osc, record.dd[static_cast<std::size_t>(j)].prn) - reference;
  }
  if (!record.full_fix) {
    for (int i = 0; i < std::clamp(record.combination_count, 0, count); ++i) {
      const gnc::FixedCombination& c = record.combinations[static_cast<std::size_t>(i)];
      const auto coefficient = [&c](int j) { return c.dd_coefficients[static_cast<std::size_t>(j)]; };
      const auto dd = [&true_dd](int j) { return true_dd[static_cast<std::size_t>(j)]; };
      if (nav::wrong_combination(c.integer_cycles, 0, count - 1, coefficient, dd)) return true;
    }
    return false;
  }
  for (int j = 0; j < count; ++j) {
    const double expected = true_dd[static_cast<std::size_t>(j)];
    if (std::isfinite(expected) && std::abs(static_cast<double>(record.dd[static_cast<std::size_t>(j)].integer_cycles) - expected) > 0.5) {
      return true;
    }
  }
  return false;
}

// The cold start, the receiver time tags after it, the processed epochs since the last step; the
// last one's fix is the one judged.
bool NavigationScore::count_step(Accumulator& a, bool has_solution, const gnc::NavigationCounters& counters,
                                 core::GpsTime update_t, bool fix_applied, double t_s) {
  a.have_counters = true;
  a.counters = counters;
  if (has_solution && a.first_solution_s < 0.0) a.first_solution_s = t_s;  // the cold start
  if (a.first_solution_s >= 0.0 && t_s > a.first_solution_s) ++a.time_tags;
  if (!has_solution) return false;
  const std::int64_t epochs = counters.epochs_joint + counters.epochs_alone;
  if (epochs == a.epochs || (a.have_scored && update_t <= a.last_scored)) return false;
  a.epochs = epochs;
  a.have_scored = true;
  a.last_scored = update_t;
  if (!fix_applied) return false;
  a.fixed = counters.epochs_fixed;
  if (a.first_fix_s < 0.0) {
    a.first_fix_s = t_s;
    a.epochs_before_first_fix = epochs - 1;
  }
  return true;
}

NavigationSample NavigationScore::score(gnc::Spacecraft who, const gnc::NavigationTelemetry& record, double t_s,
                                        const FormationTruth& truth, bool in_slew) {
  Accumulator& a = stats_[index_of(who)];
  if (count_step(a, record.has_solution, record.counters, record.update_t, record.fix_applied, t_s) && wrong_fix(record)) {
    ++a.wrong;
  }
  if (!record.has_solution || !record.valid) {
    if (record.has_solution) ++a.steps_invalid;
    return {};
  }
  const Estimate e{record.dsc_gcrf,           record.osc_gcrf,           record.p_dsc_body_m,         record.p_osc_body_m,
                   record.empirical_dsc_rtn_mps2, record.empirical_osc_rtn_mps2, record.relative_sigma_rtn_m, record.fixed};
  return add_solution(a, e, truth, in_slew);
}

NavigationSample NavigationScore::score(gnc::Spacecraft who, const gnc::OnboardNavigation& navigation, double t_s,
                                        const FormationTruth& truth, bool in_slew) {
  const auto& solution = navigation.last_solution();
  Accumulator& a = stats_[index_of(who)];
  const core::GpsTime t = navigation.last_update();
  if (count_step(a, solution.has_value(), navigation.counters(), t, navigation.last_report().fix_applied, t_s) &&
      wrong_fix(navigation, t)) {
    ++a.wrong;
  }
  if (!solution || !navigation.valid()) {
    if (solution) ++a.steps_invalid;
    return {};
  }
  const nav::NavVector& x = navigation.fixed() ? navigation.filter().x_fixed() : navigation.filter().x();
  namespace st = nav::state;
  using nav::Craft;
  Estimate e;
  e.dsc_gcrf = solution->chief_gcrf;
  e.osc_gcrf = solution->deputy_gcrf;
  e.p_dsc_body_m = st::kPhaseCenterUnit * x.segment<3>(st::phase_center(Craft::kDsc));
  e.p_osc_body_m = st::kPhaseCenterUnit * x.segment<3>(st::phase_center(Craft::kOsc));
  e.empirical_dsc_rtn_mps2 = st::kEmpiricalUnit * x.segment<3>(st::empirical_acceleration(Craft::kDsc));
  e.empirical_osc_rtn_mps2 = st::kEmpiricalUnit * x.segment<3>(st::empirical_acceleration(Craft::kOsc));
  e.sigma_rtn_m = solution->relative_covariance_rtn.diagonal().head<3>().cwiseMax(0.0).cwiseSqrt();
  e.fixed = navigation.fixed();
  return add_solution(a, e, truth, in_slew);
}

NavigationSample NavigationScore::add_solution(Accumulator& a, const Estimate& e, const FormationTruth& truth, bool in_slew) {
  NavigationSample sample;
  const Eigen::Matrix3d R = core::gcrf_to_rtn_matrix(truth.dsc_gcrf);
  const Eigen::Vector3d position_gcrf = (e.osc_gcrf.r - e.dsc_gcrf.r) - (truth.osc_gcrf.r - truth.dsc_gcrf.r);
  // The estimated antenna is the estimated centre of mass + C (known lever + p), the true one the
  // true centre of mass + C (known lever + l), l the true minus the known lever: their difference
  // is the position error + C (p - l) per spacecraft.
  const auto lever = [](const Eigen::Matrix3d& c, const Eigen::Vector3d& p, const Eigen::Vector3d& lever_error) {
    return Eigen::Vector3d(c * (p - lever_error));
  };
  const Eigen::Vector3d lever_gcrf = lever(truth.osc_body_to_gcrf, e.p_osc_body_m, truth.osc_lever_error_m) -
                                     lever(truth.dsc_body_to_gcrf, e.p_dsc_body_m, truth.dsc_lever_error_m);
  sample.valid = true;
  sample.fixed = e.fixed;
  sample.position_rtn_m = R * position_gcrf;
  sample.antenna_rtn_m = R * (position_gcrf + lever_gcrf);
  sample.velocity_rtn_mps = R * ((e.osc_gcrf.v - e.dsc_gcrf.v) - (truth.osc_gcrf.v - truth.dsc_gcrf.v));
  sample.sigma_rtn_m = e.sigma_rtn_m;
  sample.empirical_dsc_rtn_mps2 = e.empirical_dsc_rtn_mps2;
  sample.empirical_osc_rtn_mps2 = e.empirical_osc_rtn_mps2;
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
    if (a.have_counters) add_counters(out[names[k]], a.counters);
  }
  return out;
}

}  // namespace visors::sim
