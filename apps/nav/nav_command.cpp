#include "nav/nav_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <random>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "astro/sun_moon.hpp"
#include "core/files/data_path.hpp"
#include "core/files/eop_file.hpp"
#include "core/files/output_file.hpp"
#include "core/rtn_frame.hpp"
#include "dynamics/files/force_model_files.hpp"
#include "nav/cdgps_filter.hpp"
#include "nav/nav_inputs.hpp"
#include "nav/nav_replay.hpp"
#include "nav/point_positioning.hpp"
#include "sim/attitude_profile.hpp"
#include "sim/spacecraft_geometry.hpp"

namespace visors::nav_app {
namespace {

using nav::Craft;
using Json = nlohmann::json;
constexpr int kExitBadInput = 2;
constexpr double kColdStartGapS = 10.0;  // between the two point solutions of the cold start [s]

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The antenna as the spacecraft knows it: the nominal (zenith) attitude law of gnss-sim's
// "nominal" profile evaluated on the filter's own estimate, the nominal centre of mass, the
// antenna reference point and the phase-centre offset along the boresight (body +Z).
nav::AntennaGeometry antenna_for(const core::StateVector& x, core::GpsTime t, const sim::CampaignScenario& s) {
  const Eigen::Vector3d sun = (astro::sun_position_gcrf(t) - x.r).normalized();
  nav::AntennaGeometry a;
  a.body_to_gcrf = sim::AttitudeProfile::nominal_body_to_gcrf(x.r, x.v, sun).toRotationMatrix();
  a.arp_body_m = s.gnss.receiver.antenna_body_m - sim::GeometrySettings{}.com_nominal_body_m;
  a.pco_body_m = s.gnss.receiver.phase_center_offset_m * Eigen::Vector3d::UnitZ();
  a.boresight_body = Eigen::Vector3d::UnitZ();  // gnss-sim's nominal boresight
  return a;
}

dynamics::ForceModel onboard_model(const sim::SpacecraftSettings& sc, const char* name) {
  dynamics::SpacecraftProperties p;
  p.mass = sc.mass_kg;
  p.cd = sc.cd;
  p.cr = sc.cr;
  p.srp_area = sc.srp_area_m2;
  auto model = dynamics::files::load_force_model(dynamics::ForceModelConfig::onboard(), p);
  if (!model) throw InputError(std::string(name) + " on-board force model: " + model.error().describe());
  return std::move(model).value();
}

long long key_ms(double t_s) { return std::llround(t_s * 1000.0); }

// A full fix is wrong when any of the epoch's double differences of the fixed SDCP ambiguities
// differs from the truth's by more than half a cycle.
bool wrong_fix(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& r,
               const std::map<int, std::pair<double, double>>& truth) {
  const auto slots = filter.sdcp_slots();
  const auto state_of = [&slots](int prn) {
    for (int i = 0; i < slots.count; ++i) {
      if (slots.prn[static_cast<std::size_t>(i)] == prn) return slots.state[static_cast<std::size_t>(i)];
    }
    return -1;
  };
  const auto true_sd = [&truth](int prn) {
    const auto it = truth.find(prn);
    return it == truth.end() ? NAN : it->second.second - it->second.first;
  };
  const int reference = r.dd_prns[0];
  for (int j = 1; j <= r.double_differences; ++j) {
    const int prn = r.dd_prns[static_cast<std::size_t>(j)];
    const double estimated = filter.x_fixed()(state_of(prn)) - filter.x_fixed()(state_of(reference));
    const double expected = true_sd(prn) - true_sd(reference);
    if (std::isfinite(expected) && std::abs(estimated - expected) > 0.5) return true;
  }
  return false;
}

// Normalised estimation error squared of the antennas' relative position, r_osc + C_osc p_osc -
// r_dsc - C_dsc p_dsc, with its covariance J P J' (J over the scaled states).
double antenna_nees(const nav::NavMatrix& P, const Eigen::Vector3d& error_gcrf, const Eigen::Matrix3d& c_dsc,
                    const Eigen::Matrix3d& c_osc) {
  Eigen::Matrix<double, 3, nav::kNavStates> J = Eigen::Matrix<double, 3, nav::kNavStates>::Zero();
  J.block<3, 3>(0, nav::state::position(Craft::kOsc)) = Eigen::Matrix3d::Identity();
  J.block<3, 3>(0, nav::state::position(Craft::kDsc)) = -Eigen::Matrix3d::Identity();
  J.block<3, 3>(0, nav::state::phase_center(Craft::kOsc)) = nav::state::kPhaseCenterUnit * c_osc;
  J.block<3, 3>(0, nav::state::phase_center(Craft::kDsc)) = -nav::state::kPhaseCenterUnit * c_dsc;
  const Eigen::Matrix3d S = J * P * J.transpose();
  return error_gcrf.dot(S.ldlt().solve(error_gcrf));
}

EpochScore score(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& r, const RunInputs& in, double t_s,
                 Craft local) {
  EpochScore e;
  e.t_s = t_s;
  const bool full = r.fix_applied && r.fix.outcome == nav::FixOutcome::kFixed;
  e.status = full ? "fixed" : r.fix_applied ? "partial" : "float";
  const nav::NavVector& x = r.fix_applied ? filter.x_fixed() : filter.x();
  const auto truth = in.truth.find(key_ms(t_s));
  if (truth == in.truth.end()) return e;
  const core::StateVector& dsc = truth->second.first;
  const core::StateVector& osc = truth->second.second;
  const core::StateVector est_dsc = nav::CdgpsFilter::centre_of_mass(x, Craft::kDsc);
  const core::StateVector est_osc = nav::CdgpsFilter::centre_of_mass(x, Craft::kOsc);
  const Eigen::Matrix3d to_rtn = core::gcrf_to_rtn_matrix(dsc);
  e.relative_position_rtn_m = to_rtn * ((est_osc.r - est_dsc.r) - (osc.r - dsc.r));
  e.relative_velocity_rtn_mps = to_rtn * ((est_osc.v - est_dsc.v) - (osc.v - dsc.v));
  // Antenna error = (estimated - true centre of mass) + C (estimated phase-centre error + true
  // minus nominal centre of mass): the estimate's antenna is CoM + C (arp + pco + p), the truth's
  // CoM_true + C (arp + pco - delta).
  const core::GpsTime t = in.scenario.t0 + t_s;
  const auto lever_error = [&](const core::StateVector& truth_x, Craft c, std::size_t k) {
    const Eigen::Vector3d p = nav::state::kPhaseCenterUnit * x.segment<3>(nav::state::phase_center(c));
    return Eigen::Vector3d(antenna_for(truth_x, t, in.scenario).body_to_gcrf * (p + in.com_knowledge_error_body_m[k]));
  };
  const Eigen::Vector3d com_offsets = lever_error(osc, Craft::kOsc, 1) - lever_error(dsc, Craft::kDsc, 0);
  e.relative_antenna_rtn_m = e.relative_position_rtn_m + to_rtn * com_offsets;
  e.nees = antenna_nees(r.fix_applied ? filter.P_fixed() : filter.P(), to_rtn.transpose() * e.relative_antenna_rtn_m,
                        antenna_for(dsc, t, in.scenario).body_to_gcrf, antenna_for(osc, t, in.scenario).body_to_gcrf);
  const core::StateVector& own_truth = local == Craft::kDsc ? dsc : osc;
  const core::StateVector& own = local == Craft::kDsc ? est_dsc : est_osc;
  e.absolute_position_m = (own.r - own_truth.r).norm();
  e.absolute_velocity_mps = (own.v - own_truth.v).norm();
  if (full) {
    const auto phases = in.phase_truth.find(key_ms(t_s));
    e.wrong_fix = phases != in.phase_truth.end() && wrong_fix(filter, r, phases->second);
  }
  e.empirical_dsc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kDsc));
  e.empirical_osc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kOsc));
  e.double_differences = r.double_differences;
  e.satellites = r.sdcp_used;
  e.graphic_used = r.graphic_used;
  e.graphic_rejected = r.graphic_rejected;
  e.sdcp_rejected = r.sdcp_rejected;
  e.nis_sum = r.nis_sum;
  e.nis_count = r.nis_count;
  e.detected_slips = r.detected_slips;
  return e;
}


const nav::GpsReceiverEpoch* at(const std::vector<nav::GpsReceiverEpoch>& epochs, std::size_t hint, core::GpsTime t) {
  if (hint < epochs.size() && epochs[hint].t == t) return &epochs[hint];
  const auto it = std::lower_bound(epochs.begin(), epochs.end(), t,
                                   [](const nav::GpsReceiverEpoch& e, core::GpsTime value) { return e.t < value; });
  return it != epochs.end() && it->t == t ? &*it : nullptr;
}

// Cold start (as on board): a point solution of each receiver, another kColdStartGapS later; the
// velocity is their chord plus half the two-body acceleration times the gap (the chord is the
// mean velocity over the gap: 42 m/s off without it), the centre of mass the phase centre minus
// the antenna's lever arm in the nominal attitude.
struct ColdStart {
  bool have_first = false;
  core::GpsTime t_first;
  nav::PointSolution first[2];
};

bool try_cold_start(nav::CdgpsFilter& filter, ColdStart& cold, const nav::GpsReceiverEpoch* epochs[2], const RunInputs& in,
                    core::OnboardEarthFrame& frame) {
  nav::PointSolution now[2];
  for (int k = 0; k < 2; ++k) {
    if (epochs[k] == nullptr) return false;
    now[k] = nav::solve_point_position(*epochs[k], in.ephemerides, frame, Eigen::Vector3d::Zero());
    if (!now[k].ok) return false;
  }
  const core::GpsTime t = epochs[0]->t;
  if (!cold.have_first || t.seconds_since(cold.t_first) > 3.0 * kColdStartGapS) {
    cold = ColdStart{true, t, {now[0], now[1]}};
    return false;
  }
  const double dt = t.seconds_since(cold.t_first);
  if (dt < kColdStartGapS) return false;
  core::StateVector x[2];
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d r = now[k].r_gcrf_m;
    const Eigen::Vector3d gravity = -3.986004415e14 / std::pow(r.norm(), 3) * r;
    x[k].v = (r - cold.first[k].r_gcrf_m) / dt + 0.5 * dt * gravity;
    const nav::AntennaGeometry a = antenna_for({now[k].r_gcrf_m, x[k].v}, t, in.scenario);
    x[k].r = now[k].r_gcrf_m - a.body_to_gcrf * (a.arp_body_m + a.pco_body_m);
  }
  filter.initialise(t, x[0], x[1], now[0].clock_m, now[1].clock_m);
  return true;
}

// The Earth orientation uplinked to the spacecraft: the IERS values at the run's start from the
// scenario's EOP file (zero when it has none). Without them the GCRF of the filter turns against
// the truth's by UT1-UTC and polar motion: ~35 m at 500 km in October 2024.
core::EarthOrientation uplinked_earth_orientation(const sim::CampaignScenario& s) {
  if (s.forces.earth_frame.eop.empty()) return {};
  const auto path = core::files::find_data_file(s.forces.earth_frame.eop);
  if (!path) return {};
  auto table = core::files::read_eop_file(*path);
  if (!table) throw InputError("forces.earth_frame.eop: " + table.error().describe());
  auto at = table.value().at(s.t0);
  return at.ok() ? at.value() : core::EarthOrientation{};
}

// Faults injected by the replay (the data stay those of the run): crosslink drops of the other
// receiver's epoch, and a GPS outage of both receivers, after which every satellite is
// re-acquired (loss of lock flagged on its first epoch back).
struct ReplayFaults {
  double crosslink_drop = 0.0;   // probability per epoch
  double outage_start_s = -1.0;  // [s after the scenario start]; < 0: none
  double outage_s = 0.0;
};

bool in_outage(const ReplayFaults& f, double t_s) {
  return f.outage_start_s >= 0.0 && t_s >= f.outage_start_s && t_s < f.outage_start_s + f.outage_s;
}

nav::GpsReceiverEpoch reacquired(const nav::GpsReceiverEpoch& e) {
  nav::GpsReceiverEpoch out = e;
  for (int i = 0; i < out.count; ++i) out.observations[static_cast<std::size_t>(i)].loss_of_lock = true;
  return out;
}

Replay replay(const RunInputs& in, Craft local, double duration_s, bool elevation_weighting, const ReplayFaults& faults) {
  Replay out;
  out.local = local;
  out.name = local == Craft::kDsc ? "dsc" : "osc";
  nav::CdgpsSettings settings;
  settings.local = local;
  settings.elevation_weighting = elevation_weighting;
  auto created = nav::CdgpsFilter::create(settings, onboard_model(in.scenario.dsc, "dsc"), onboard_model(in.scenario.osc, "osc"));
  if (!created) throw InputError("filter settings: " + created.error().describe());
  nav::CdgpsFilter f = std::move(created).value();
  core::OnboardEarthFrame frame(uplinked_earth_orientation(in.scenario));
  ColdStart cold;
  std::mt19937_64 rng(in.scenario.seed + 7 + static_cast<std::uint64_t>(local));  // the drops
  std::bernoulli_distribution drop(faults.crosslink_drop);
  bool back_from_outage = false;
  nav::GpsReceiverEpoch flagged[2];
  for (std::size_t i = 0; i < in.dsc.size(); ++i) {
    const core::GpsTime t = in.dsc[i].t;
    const double t_s = t.seconds_since(in.scenario.t0);
    if (duration_s > 0.0 && t_s > duration_s) break;
    const nav::GpsReceiverEpoch* epochs[2] = {&in.dsc[i], at(in.osc, i, t)};
    if (f.initialised() && in_outage(faults, t_s)) {
      f.predict(t);
      EpochScore e = score(f, nav::CdgpsEpochReport{}, in, t_s, local);
      e.status = "outage";
      out.epochs.push_back(e);
      back_from_outage = true;
      continue;
    }
    if (back_from_outage) {
      for (int k = 0; k < 2; ++k) {
        if (epochs[k] != nullptr) epochs[k] = &(flagged[k] = reacquired(*epochs[k]));
      }
      back_from_outage = false;
    }
    if (drop(rng)) epochs[local == Craft::kDsc ? 1 : 0] = nullptr;  // the crosslinked epoch lost
    if (!f.initialised()) {
      if (try_cold_start(f, cold, epochs, in, frame)) out.start_s = t_s;
      continue;
    }
    const auto start = std::chrono::steady_clock::now();
    f.predict(t);
    nav::CdgpsEpochInput input{epochs[0], epochs[1],
                               antenna_for(nav::CdgpsFilter::centre_of_mass(f.x(), Craft::kDsc), t, in.scenario),
                               antenna_for(nav::CdgpsFilter::centre_of_mass(f.x(), Craft::kOsc), t, in.scenario)};
    const nav::CdgpsEpochReport report = f.update(input, in.ephemerides, frame);
    const double step_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    EpochScore e = score(f, report, in, t_s, local);
    e.step_us = step_us;
    if (out.first_fix_s < 0.0 && std::string_view(e.status) == "fixed") out.first_fix_s = t_s - out.start_s;
    out.epochs.push_back(e);
  }
  return out;
}


double rms(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return v.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(v.size()));
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

// Error statistics over a window of epochs.
struct WindowStats {
  std::vector<double> rel_pos, rel_antenna, rel_vel, abs_pos, abs_vel;
  double nees_sum = 0.0;
  double worst = 0.0, worst_antenna = 0.0;
  int fixed = 0, partial = 0, wrong = 0;

  void add(const EpochScore& e) {
    rel_pos.push_back(e.relative_position_rtn_m.norm());
    rel_antenna.push_back(e.relative_antenna_rtn_m.norm());
    rel_vel.push_back(e.relative_velocity_rtn_mps.norm());
    abs_pos.push_back(e.absolute_position_m);
    abs_vel.push_back(e.absolute_velocity_mps);
    worst = std::max(worst, e.relative_position_rtn_m.norm());
    worst_antenna = std::max(worst_antenna, e.relative_antenna_rtn_m.norm());
    fixed += std::string_view(e.status) == "fixed" ? 1 : 0;
    partial += std::string_view(e.status) == "partial" ? 1 : 0;
    wrong += e.wrong_fix ? 1 : 0;
    nees_sum += e.nees;
  }

  [[nodiscard]] Json json() const {
    const double n = static_cast<double>(rel_pos.size());
    return Json{{"epochs", rel_pos.size()},
                {"fix_rate", n > 0 ? fixed / n : 0.0},
                {"partial_rate", n > 0 ? partial / n : 0.0},
                {"wrong_fix_epochs", wrong},
                {"relative_position_rms_m", rms(rel_pos)},
                {"relative_position_worst_m", worst},
                {"relative_antenna_rms_m", rms(rel_antenna)},
                {"relative_antenna_worst_m", worst_antenna},
                {"relative_velocity_rms_mps", rms(rel_vel)},
                {"absolute_position_rms_m", rms(abs_pos)},
                {"absolute_velocity_rms_mps", rms(abs_vel)},
                {"antenna_nees_mean", n > 0 ? nees_sum / n : 0.0}};
  }
};

constexpr double kConvergenceS = 300.0;  // the "converged" window starts this long after the first fix [s]

// The figures of the acceptance over the epochs after the first fix, and over those from
// kConvergenceS later (the velocity takes minutes to converge after a cold start).
Json summarise(const Replay& r) {
  WindowStats after_fix, converged;
  std::vector<double> steps;
  int slips = 0, nis_count = 0, wrong_run = 0, longest_wrong_run = 0;
  double nis = 0.0, outage_end_s = -1.0, refix_s = -1.0;
  for (const EpochScore& e : r.epochs) {
    if (std::string_view(e.status) == "outage") outage_end_s = e.t_s + 1.0;
    if (outage_end_s >= 0.0 && refix_s < 0.0 && std::string_view(e.status) == "fixed") refix_s = e.t_s - outage_end_s;
    wrong_run = e.wrong_fix ? wrong_run + 1 : 0;
    longest_wrong_run = std::max(longest_wrong_run, wrong_run);
    steps.push_back(e.step_us);
    slips += e.detected_slips;
    nis += e.nis_sum;
    nis_count += e.nis_count;
    if (r.first_fix_s < 0.0 || e.t_s - r.start_s < r.first_fix_s) continue;
    after_fix.add(e);
    if (e.t_s - r.start_s >= r.first_fix_s + kConvergenceS) converged.add(e);
  }
  return Json{{"filter", r.name},
              {"epochs", r.epochs.size()},
              {"start_s", r.start_s},
              {"time_to_first_fix_s", r.first_fix_s},
              {"after_first_fix", after_fix.json()},
              {"converged", converged.json()},
              {"detected_slips", slips},
              {"longest_wrong_fix_s", longest_wrong_run},
              {"refix_after_outage_s", refix_s},
              {"nis_mean", nis_count > 0 ? nis / nis_count : 0.0},
              {"step_us", {{"median", percentile(steps, 0.5)}, {"p99_9", percentile(steps, 0.999)}}}};
}

void write_epochs(const Replay& r, const std::filesystem::path& dir) {
  const auto path = dir / (std::string("nav_") + r.name + ".csv");
  auto file = core::files::open_output_file(path);
  if (!file.get()) throw std::runtime_error(path.string() + ": cannot be written");
  std::fprintf(file.get(),
               "t_s,status,wrong_fix,sdcp,sdcp_rejected,graphic,graphic_rejected,double_differences,rel_r_m,rel_t_m,rel_n_m,rel_antenna_r_m,rel_antenna_t_m,"
               "rel_antenna_n_m,rel_vr_mps,rel_vt_mps,rel_vn_mps,abs_position_m,abs_velocity_mps,detected_slips,antenna_nees,"
               "nis_sum,nis_count,step_us\n");
  for (const EpochScore& e : r.epochs) {
    std::fprintf(file.get(),
                 "%.3f,%s,%d,%d,%d,%d,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.8f,%.8f,%.8f,%.4f,%.6f,%d,"
                 "%.4f,%.4f,%d,%.1f\n",
                 e.t_s, e.status, e.wrong_fix ? 1 : 0, e.satellites, e.sdcp_rejected, e.graphic_used, e.graphic_rejected,
                 e.double_differences, e.relative_position_rtn_m(0),
                 e.relative_position_rtn_m(1), e.relative_position_rtn_m(2), e.relative_antenna_rtn_m(0),
                 e.relative_antenna_rtn_m(1), e.relative_antenna_rtn_m(2), e.relative_velocity_rtn_mps(0),
                 e.relative_velocity_rtn_mps(1), e.relative_velocity_rtn_mps(2), e.absolute_position_m,
                 e.absolute_velocity_mps, e.detected_slips, e.nees, e.nis_sum, e.nis_count, e.step_us);
  }
}

void print_window(const char* label, const Json& w) {
  fmt::print("    {}: fix {:.2f} %, partial {:.2f} %, wrong-fix epochs {}; relative position {:.2f} mm RMS (worst {:.2f}), "
             "antennas {:.2f} mm RMS (worst {:.2f}, NEES {:.2f} of 3); relative velocity {:.1f} um/s RMS; absolute {:.2f} m, "
             "{:.2f} mm/s RMS\n",
             label, 100.0 * w["fix_rate"].get<double>(), 100.0 * w["partial_rate"].get<double>(),
             w["wrong_fix_epochs"].get<int>(), 1e3 * w["relative_position_rms_m"].get<double>(),
             1e3 * w["relative_position_worst_m"].get<double>(), 1e3 * w["relative_antenna_rms_m"].get<double>(),
             1e3 * w["relative_antenna_worst_m"].get<double>(), w["antenna_nees_mean"].get<double>(),
             1e6 * w["relative_velocity_rms_mps"].get<double>(),
             w["absolute_position_rms_m"].get<double>(), 1e3 * w["absolute_velocity_rms_mps"].get<double>());
}

void print_overview(const Json& s) {
  fmt::print("  {} filter: cold start at {:.0f} s, first fix {:.0f} s later; NIS {:.2f}; slips detected {}; step {:.0f} us "
             "median, {:.0f} us p99.9\n",
             s["filter"].get<std::string>(), s["start_s"].get<double>(), s["time_to_first_fix_s"].get<double>(),
             s["nis_mean"].get<double>(), s["detected_slips"].get<int>(), s["step_us"]["median"].get<double>(),
             s["step_us"]["p99_9"].get<double>());
  if (s["refix_after_outage_s"].get<double>() >= 0.0) {
    fmt::print("    refixed {:.0f} s after the outage; longest wrong fix held {} s\n", s["refix_after_outage_s"].get<double>(),
               s["longest_wrong_fix_s"].get<int>());
  }
  print_window("after the first fix", s["after_first_fix"]);
  print_window("from 300 s after it", s["converged"]);
}

}  // namespace

int run_nav_command(const NavOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!(options.duration_s >= 0.0)) throw InputError("--duration: must be >= 0 s");
    if (!(options.crosslink_drop >= 0.0 && options.crosslink_drop <= 1.0)) throw InputError("--crosslink-drop: must be in [0, 1]");
    if (!(options.outage_s >= 0.0)) throw InputError("--outage: the duration must be >= 0 s");
    auto inputs = read_run(options.run_dir);
    if (!inputs) throw InputError(inputs.error().describe());
    if (inputs.value().scenario.gnss.attitude != "nominal") {
      throw InputError("scenario.toml: gnss.attitude '" + inputs.value().scenario.gnss.attitude +
                       "' is not replayed yet (only \"nominal\": the attitude profile of observations is not in the run)");
    }
    std::filesystem::create_directories(options.out);
    Json summary{{"run_dir", options.run_dir}, {"filters", Json::array()}};
    fmt::print("visors nav: {} ({} epochs)\n", options.run_dir, inputs.value().dsc.size());
    std::vector<Replay> replays;
    for (Craft local : {Craft::kDsc, Craft::kOsc}) {
      replays.push_back(replay(inputs.value(), local, options.duration_s, options.elevation_weighting,
                               {options.crosslink_drop, options.outage_start_s, options.outage_s}));
      const Json s = summarise(replays.back());
      write_epochs(replays.back(), options.out);
      print_overview(s);
      summary["filters"].push_back(s);
    }
    summary["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    auto file = core::files::open_output_file(std::filesystem::path(options.out) / "summary.json");
    if (!file.get()) throw std::runtime_error(options.out + "/summary.json: cannot be written");
    std::fprintf(file.get(), "%s\n", summary.dump(2).c_str());
    auto page = core::files::open_output_file(std::filesystem::path(options.out) / "nav.html");
    if (!page.get()) throw std::runtime_error(options.out + "/nav.html: cannot be written");
    std::fputs(nav_page(options.run_dir, replays, summary).c_str(), page.get());
    fmt::print("  output {} ({:.1f} s)\n", options.out, summary["wall_s"].get<double>());
    return 0;
  } catch (const InputError& e) {
    fmt::print(stderr, "visors nav: {}\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    fmt::print(stderr, "visors nav: {}\n", e.what());
    return 1;
  }
}

}  // namespace visors::nav_app
