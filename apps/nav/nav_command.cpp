#include "apps/nav/nav_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <random>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "visors/config/cdgps_settings_toml.hpp"
#include "visors/config/toml_fields.hpp"
#include "visors/core/files/output_file.hpp"
#include "visors/core/files/text_file.hpp"
#include "visors/nav/cdgps_filter.hpp"
#include "visors/nav/cold_start.hpp"
#include "apps/nav/nav_inputs.hpp"
#include "apps/nav/nav_replay.hpp"
#include "apps/nav/nav_score.hpp"
#include "visors/sim/navigation_setup.hpp"

namespace visors::nav_app {
namespace {

using nav::Craft;
using Json = nlohmann::json;
constexpr int kExitBadInput = 2;

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The error of a set-up step as the command's input error.
template <class T>
T or_input_error(core::Result<T> result) {
  if (!result.ok()) throw InputError(result.error().describe());
  return std::move(result).value();
}

const nav::GpsReceiverEpoch* at(const std::vector<nav::GpsReceiverEpoch>& epochs, std::size_t hint, core::GpsTime t) {
  if (hint < epochs.size() && epochs[hint].t == t) return &epochs[hint];
  const auto it = std::lower_bound(epochs.begin(), epochs.end(), t,
                                   [](const nav::GpsReceiverEpoch& e, core::GpsTime value) { return e.t < value; });
  return it != epochs.end() && it->t == t ? &*it : nullptr;
}

// Cold start (as on board, nav/cold_start.hpp) from the joint epoch; the antennas in the
// attitudes known at t_s, the data sets the local receiver has decoded.
bool try_cold_start(nav::CdgpsFilter& filter, nav::ColdStart& cold, const nav::GpsReceiverEpoch* epochs[2], const RunInputs& in,
                    const gnss::EphemerisSource& ephemerides, core::OnboardEarthFrame& frame) {
  if (epochs[0] == nullptr || epochs[1] == nullptr) return false;
  const auto* attitudes = known_attitudes_at(in, epochs[0]->t.seconds_since(in.scenario.t0));
  if (attitudes == nullptr) return false;
  const auto solution = cold.add(*epochs[0], *epochs[1], antenna_geometry(in.scenario.flight, (*attitudes)[0]), antenna_geometry(in.scenario.flight, (*attitudes)[1]),
                                 ephemerides, frame);
  if (!solution) return false;
  filter.initialise(solution->t, solution->dsc_gcrf, solution->osc_gcrf, solution->dsc_clock_m, solution->osc_clock_m);
  return true;
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

// What the replay changes in the filter and its inputs (NavOptions).
struct ReplaySettings {
  double duration_s = 0.0;
  bool elevation_weighting = false;
  bool ambiguity_resolution = true;
  bool fuse_laser = true;
  ReplayFaults faults;
  double latency_s = 0.0;  // the crosslink delay rounded up to whole epochs [s]
  const toml::table* settings_file = nullptr;  // the --settings file's tables, if any
};

// The filter's settings: those of the run (sim::cdgps_settings: the defaults, the receiver's
// specification, the scenario's [nav]), the --settings file, the command line's switches, in
// that order of precedence (the last wins).
nav::CdgpsFilter make_filter(const RunInputs& in, Craft local, const ReplaySettings& r) {
  nav::CdgpsSettings settings = or_input_error(sim::cdgps_settings(in.scenario));
  settings.local = local;
  if (r.settings_file != nullptr) {
    if (auto ok = config::read_cdgps_settings(*r.settings_file, settings); !ok) {
      throw InputError("--settings: " + ok.error().describe());
    }
  }
  settings.elevation_weighting = settings.elevation_weighting || r.elevation_weighting;
  settings.ambiguity_resolution = settings.ambiguity_resolution && r.ambiguity_resolution;
  auto created = nav::CdgpsFilter::create(settings, or_input_error(sim::onboard_force_model(in.scenario.flight, gnc::Spacecraft::kDsc)),
                                          or_input_error(sim::onboard_force_model(in.scenario.flight, gnc::Spacecraft::kOsc)));
  if (!created) throw InputError("filter settings: " + created.error().describe());
  return std::move(created).value();
}

// The commanded impulses executed before t_s (from the previous epoch on), each applied at its own
// instant: gnss-sim measures an epoch before the impulses of that instant.
void apply_impulses(nav::CdgpsFilter& f, const RunInputs& in, std::size_t& next, double t_s, Replay& out) {
  for (; next < in.impulses.size() && in.impulses[next].t_s < t_s - 1e-9; ++next) {
    const CommandedImpulse& impulse = in.impulses[next];
    const core::GpsTime t = in.scenario.t0 + impulse.t_s;
    if (!f.initialised() || t < f.epoch()) continue;  // before the cold start: in its states already
    f.predict(t);
    if (f.apply_impulse(impulse.craft, impulse.dv_gcrf_mps)) out.impulse_t_s.push_back(impulse.t_s);
  }
}

// The laser range of this epoch, if any and if it reached this filter, into the filter.
const char* fuse_laser_range(nav::CdgpsFilter& f, const RunInputs& in, double t_s,
                             const std::array<Eigen::Quaterniond, 2>& attitudes) {
  const auto z = in.laser_ranges_m.find(key_ms(t_s));
  if (z == in.laser_ranges_m.end()) return "";
  const nav::ScalarUpdateStatus status =
      f.update_laser_range(z->second, in.scenario.flight.lrf_sigma_m, laser_geometry(in.scenario.flight, attitudes[0], attitudes[1]));
  return status == nav::ScalarUpdateStatus::kAccepted ? "used" : "rejected";
}

// The epoch's solution as it is used latency_s later (a crosslink delay: the joint epoch is
// processed when the remote data arrive): carried by the mean dynamics, plus the commanded
// impulses of that interval (their velocity change and the drift it adds by then; an impulse at
// the epoch itself comes after its measurements), scored against the truth then.
void score_forecast(nav::CdgpsFilter& f, const nav::CdgpsEpochReport& report, const RunInputs& in, double t_s,
                    double latency_s, EpochScore& e) {
  const double later = t_s + latency_s;
  nav::NavVector x = f.forecast(report.fix_applied ? f.x_fixed() : f.x(), in.scenario.t0 + later);
  const auto first = std::lower_bound(in.impulses.begin(), in.impulses.end(), t_s - 1e-9,
                                      [](const CommandedImpulse& i, double t) { return i.t_s < t; });
  for (auto i = first; i != in.impulses.end() && i->t_s < later - 1e-9; ++i) {
    x.segment<3>(nav::state::velocity(i->craft)) += i->dv_gcrf_mps / nav::state::kVelocityUnit;
    x.segment<3>(nav::state::position(i->craft)) += i->dv_gcrf_mps * (later - i->t_s);
  }
  const RelativeErrors errors = relative_errors(x, in, later);
  if (!errors.valid) return;
  e.forecast_antenna_rtn_m = errors.antenna_rtn_m;
  e.forecast_velocity_rtn_mps = errors.velocity_rtn_mps;
}

// The --settings file's tables (nullopt without one); checked against a default filter now, so
// that a bad key is reported before the run is read.
std::optional<toml::table> read_settings_file(const std::string& path) {
  if (path.empty()) return std::nullopt;
  const auto text = core::files::read_text_file(path);
  if (!text) throw InputError("--settings: " + path + " cannot be read");
  auto table = config::toml_fields::parse(*text);
  if (!table) throw InputError("--settings: " + path + ": " + table.error().describe());
  for (const auto& [key, value] : table.value()) {
    if (key.str() != "nav") throw InputError("--settings: " + path + ": unknown table '" + std::string(key.str()) + "' (only [nav])");
  }
  nav::CdgpsSettings check;
  if (auto ok = config::read_cdgps_settings(table.value(), check); !ok) {
    throw InputError("--settings: " + path + ": " + ok.error().describe());
  }
  return std::move(table).value();
}

// The full fix's double-difference integers of this epoch (CdgpsEpochReport::dd_integer_cycles).
void record_fixes(const nav::CdgpsEpochReport& report, double t_s, std::vector<FixedDoubleDifference>& out) {
  if (!report.fix_applied || report.fix.outcome != nav::FixOutcome::kFixed) return;
  for (int j = 1; j <= report.double_differences; ++j) {
    const auto k = static_cast<std::size_t>(j);
    out.push_back({t_s, report.dd_prns[0], report.dd_prns[k], report.dd_integer_cycles[k]});
  }
}

// The run's epochs (truth.csv: one row per receiver time tag, recorded or in a data gap) up to
// duration_s (0: all).
std::vector<double> time_tags(const RunInputs& in, double duration_s) {
  std::vector<double> out;
  for (const auto& epoch : in.truth) {
    const double t_s = static_cast<double>(epoch.first) / 1000.0;  // key_ms's inverse
    if (duration_s > 0.0 && t_s > duration_s) break;
    out.push_back(t_s);
  }
  return out;
}

// One filter over the run, driven by its own receiver's epochs, with the attitudes the ADCSs
// reported and the data sets its own receiver has decoded (nav_inputs.hpp).
Replay replay(const RunInputs& in, Craft local, const ReplaySettings& r) {
  Replay out;
  out.local = local;
  out.name = local == Craft::kDsc ? "dsc" : "osc";
  out.latency_s = r.latency_s;
  out.time_tags_s = time_tags(in, r.duration_s);
  nav::CdgpsFilter f = make_filter(in, local, r);
  core::OnboardEarthFrame frame(or_input_error(sim::uplinked_earth_orientation(in.scenario)));
  nav::ColdStart cold;
  std::mt19937_64 rng(in.scenario.seed + 7 + static_cast<std::uint64_t>(local));  // the drops
  std::bernoulli_distribution drop(r.faults.crosslink_drop);
  bool back_from_outage = false;
  nav::GpsReceiverEpoch flagged[2];
  std::size_t next_impulse = 0;
  const std::size_t remote = local == Craft::kDsc ? 1 : 0;
  const DecodedEphemerides& ephemerides = in.decoded_ephemerides[static_cast<std::size_t>(local)];
  const std::vector<nav::GpsReceiverEpoch>& own = local == Craft::kDsc ? in.dsc : in.osc;
  const std::vector<nav::GpsReceiverEpoch>& other = local == Craft::kDsc ? in.osc : in.dsc;
  for (std::size_t i = 0; i < own.size(); ++i) {
    const core::GpsTime t = own[i].t;
    const double t_s = t.seconds_since(in.scenario.t0);
    if (r.duration_s > 0.0 && t_s > r.duration_s) break;
    const nav::GpsReceiverEpoch* epochs[2] = {nullptr, nullptr};
    epochs[remote == 1 ? 0 : 1] = &own[i];
    epochs[remote] = at(other, i, t);
    const auto start = std::chrono::steady_clock::now();
    apply_impulses(f, in, next_impulse, t_s, out);
    if (f.initialised() && in_outage(r.faults, t_s)) {
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
    const bool crosslink_lost = drop(rng);
    if (crosslink_lost) epochs[remote] = nullptr;
    const auto* attitudes = known_attitudes_at(in, t_s);
    if (attitudes == nullptr) continue;
    if (!f.initialised()) {
      if (try_cold_start(f, cold, epochs, in, ephemerides, frame)) out.start_s = t_s;
      continue;
    }
    f.predict(t);
    const nav::CdgpsEpochInput input{epochs[0], epochs[1], antenna_geometry(in.scenario.flight, (*attitudes)[0]),
                                     antenna_geometry(in.scenario.flight, (*attitudes)[1])};
    const nav::CdgpsEpochReport report = f.update(input, ephemerides, frame);
    // The LRF is on the OSC: the DSC's filter gets its range over the crosslink.
    const bool laser_here = r.fuse_laser && (local == Craft::kOsc || !crosslink_lost);
    const char* laser = laser_here ? fuse_laser_range(f, in, t_s, *attitudes) : "";
    const double step_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    EpochScore e = score(f, report, in, t_s, local);
    if (r.latency_s > 0.0) score_forecast(f, report, in, t_s, r.latency_s, e);
    e.step_us = step_us;
    e.laser = laser;
    record_fixes(report, t_s, out.fixes);
    if (out.first_fix_s < 0.0 && std::string_view(e.status) == "fixed") out.first_fix_s = t_s - out.start_s;
    out.epochs.push_back(e);
  }
  return out;
}

// A state's six columns (GCRF): 0.1 um and 1 nm/s, so that differences of two states (the
// relative errors of the file, written to 1 um) can be recomputed from them.
void write_state(std::FILE* file, const core::StateVector& x) {
  std::fprintf(file, ",%.7f,%.7f,%.7f,%.9f,%.9f,%.9f", x.r.x(), x.r.y(), x.r.z(), x.v.x(), x.v.y(), x.v.z());
}

void write_epochs(const Replay& r, const std::filesystem::path& dir) {
  const auto path = dir / (std::string("nav_") + r.name + ".csv");
  auto file = core::files::open_output_file(path);
  if (!file.get()) throw std::runtime_error(path.string() + ": cannot be written");
  std::fprintf(file.get(),
               "t_s,status,wrong_fix,sdcp,sdcp_rejected,graphic,graphic_rejected,double_differences,rel_r_m,rel_t_m,rel_n_m,rel_antenna_r_m,rel_antenna_t_m,"
               "rel_antenna_n_m,rel_vr_mps,rel_vt_mps,rel_vn_mps,abs_position_m,abs_velocity_mps,clock_error_dsc_m,clock_error_osc_m,"
               "detected_slips,antenna_nees,"
               "rel_antenna_sigma_r_m,rel_antenna_sigma_t_m,rel_antenna_sigma_n_m,nis_sum,nis_count,graphic_nis_sum,sdcp_nis_sum,sdcp_used,step_us,"
               "in_observation,in_slew,"
               "payload_los_m,payload_lateral_m,laser");
  for (const char* craft : {"dsc", "osc"}) {
    for (const char* point : {"com", "antenna"}) {
      std::fprintf(file.get(), ",%s_%s_x_m,%s_%s_y_m,%s_%s_z_m,%s_%s_vx_mps,%s_%s_vy_mps,%s_%s_vz_mps", craft, point, craft,
                   point, craft, point, craft, point, craft, point, craft, point);
    }
  }
  std::fputc('\n', file.get());
  for (const EpochScore& e : r.epochs) {
    std::fprintf(file.get(),
                 "%.3f,%s,%d,%d,%d,%d,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.8f,%.8f,%.8f,%.4f,%.6f,%.4f,%.4f,%d,"
                 "%.4f,%.6f,%.6f,%.6f,%.4f,%d,%.4f,%.4f,%d,%.1f,%d,%d,%.6f,%.6f,%s",
                 e.t_s, e.status, e.wrong_fix ? 1 : 0, e.satellites, e.sdcp_rejected, e.graphic_used, e.graphic_rejected,
                 e.double_differences, e.relative_position_rtn_m(0),
                 e.relative_position_rtn_m(1), e.relative_position_rtn_m(2), e.relative_antenna_rtn_m(0),
                 e.relative_antenna_rtn_m(1), e.relative_antenna_rtn_m(2), e.relative_velocity_rtn_mps(0),
                 e.relative_velocity_rtn_mps(1), e.relative_velocity_rtn_mps(2), e.absolute_position_m,
                 e.absolute_velocity_mps, e.clock_error_dsc_m, e.clock_error_osc_m, e.detected_slips, e.nees, e.antenna_sigma_rtn_m(0), e.antenna_sigma_rtn_m(1),
                 e.antenna_sigma_rtn_m(2), e.nis_sum, e.nis_count, e.graphic_nis_sum, e.sdcp_nis_sum, e.sdcp_used, e.step_us,
                 e.in_observation ? 1 : 0, e.in_slew ? 1 : 0, e.payload_los_m, e.payload_lateral_m, e.laser);
    for (std::size_t k = 0; k < 2; ++k) {
      write_state(file.get(), e.com_gcrf[k]);
      write_state(file.get(), e.antenna_gcrf[k]);
    }
    std::fputc('\n', file.get());
  }
}

// fixes_<craft>.csv: one row per double-difference integer of each full fix.
void write_fixes(const Replay& r, const std::filesystem::path& dir) {
  const auto path = dir / (std::string("fixes_") + r.name + ".csv");
  auto file = core::files::open_output_file(path);
  if (!file.get()) throw std::runtime_error(path.string() + ": cannot be written");
  std::fprintf(file.get(), "t_s,signal,reference_prn,prn,integer_cycles\n");
  for (const FixedDoubleDifference& f : r.fixes) {
    std::fprintf(file.get(), "%.3f,L1C,%d,%d,%lld\n", f.t_s, f.reference_prn, f.prn, static_cast<long long>(f.integer_cycles));
  }
}

void print_window(const char* label, const Json& w) {
  fmt::print("    {}: fix {:.2f} % of the epochs present, {:.2f} % of all {} time tags; partial {:.2f} %, wrong-fix epochs {}; "
             "relative position {:.2f} mm RMS (worst {:.2f}), "
             "antennas {:.2f} mm RMS (worst {:.2f}, NEES {:.2f} of 3); relative velocity {:.1f} um/s RMS; absolute {:.2f} m, "
             "{:.2f} mm/s RMS\n",
             label, 100.0 * w["fix_rate"].get<double>(), 100.0 * w["fix_rate_all_epochs"].get<double>(),
             w["time_tags"].get<std::size_t>(), 100.0 * w["partial_rate"].get<double>(),
             w["wrong_fix_epochs"].get<int>(), 1e3 * w["relative_position_rms_m"].get<double>(),
             1e3 * w["relative_position_worst_m"].get<double>(), 1e3 * w["relative_antenna_rms_m"].get<double>(),
             1e3 * w["relative_antenna_worst_m"].get<double>(), w["antenna_nees_mean"].get<double>(),
             1e6 * w["relative_velocity_rms_mps"].get<double>(),
             w["absolute_position_rms_m"].get<double>(), 1e3 * w["absolute_velocity_rms_mps"].get<double>());
}

void print_overview(const Json& s) {
  const double first_fix_s = s["time_to_first_fix_s"].get<double>();
  fmt::print("  {} filter: cold start at {:.0f} s, {}; NIS {:.2f}; slips detected {}; ephemeris switches {}; step {:.0f} us "
             "median, {:.0f} us p99.9\n",
             s["filter"].get<std::string>(), s["start_s"].get<double>(),
             first_fix_s >= 0.0 ? fmt::format("first fix {:.0f} s later", first_fix_s) : std::string("never fixed"),
             s["nis_mean"].get<double>(), s["detected_slips"].get<int>(), s["ephemeris_switches"].get<int>(),
             s["step_us"]["median"].get<double>(),
             s["step_us"]["p99_9"].get<double>());
  if (s["refix_after_outage_s"].get<double>() >= 0.0) {
    fmt::print("    refixed {:.0f} s after the outage; longest wrong fix held {} s\n", s["refix_after_outage_s"].get<double>(),
               s["longest_wrong_fix_s"].get<int>());
  }
  const bool fixed = s["window_from"].get<std::string>() == "first_fix";
  print_window(fixed ? "after the first fix" : "after the cold start (never fixed)", s["after_first_fix"]);
  print_window("from 300 s after it", s["converged"]);
  if (s["latency_s"].get<double>() > 0.0) {
    const Json& c = s["converged"];
    fmt::print("    in use {:.0f} s later (crosslink delay), from 300 s after the first fix: antennas {:.2f} mm RMS (worst {:.2f}), "
               "relative velocity {:.1f} um/s RMS\n",
               s["latency_s"].get<double>(), 1e3 * c["forecast_antenna_rms_m"].get<double>(),
               1e3 * c["forecast_antenna_worst_m"].get<double>(), 1e6 * c["forecast_velocity_rms_mps"].get<double>());
  }
  const Json& o = s["observations"];
  if (o["epochs"].get<int>() > 0 || o["laser_ranges_used"].get<int>() > 0) {
    fmt::print("    observations: {} epochs, payload points {:.2f} mm RMS along the line of sight (worst {:.2f}), {:.2f} mm "
               "across; laser ranges used {}, rejected {}; impulses applied {}\n",
               o["epochs"].get<int>(), 1e3 * o["payload_los_rms_m"].get<double>(), 1e3 * o["payload_los_worst_m"].get<double>(),
               1e3 * o["payload_lateral_rms_m"].get<double>(), o["laser_ranges_used"].get<int>(),
               o["laser_ranges_rejected"].get<int>(), s["impulses_applied"].get<int>());
  } else if (s["impulses_applied"].get<int>() > 0) {
    fmt::print("    impulses applied {}\n", s["impulses_applied"].get<int>());
  }
}

}  // namespace

int run_nav_command(const NavOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  try {
    if (!(options.duration_s >= 0.0)) throw InputError("--duration: must be >= 0 s");
    if (!(options.crosslink_drop >= 0.0 && options.crosslink_drop <= 1.0)) throw InputError("--crosslink-drop: must be in [0, 1]");
    if (!(options.outage_s >= 0.0)) throw InputError("--outage: the duration must be >= 0 s");
    if (!(options.crosslink_delay_s >= 0.0 && options.crosslink_delay_s <= 60.0)) {
      throw InputError("--crosslink-delay: must be in [0, 60] s");
    }
    const std::optional<toml::table> settings_file = read_settings_file(options.settings_file);
    auto inputs = read_run(options.run_dir);
    if (!inputs) throw InputError(inputs.error().describe());
    std::filesystem::create_directories(options.out);
    Json summary{{"run_dir", options.run_dir}, {"filters", Json::array()}};
    fmt::print("visors nav: {} ({} epochs)\n", options.run_dir, inputs.value().dsc.size());
    std::vector<Replay> replays;
    for (Craft local : {Craft::kDsc, Craft::kOsc}) {
      const ReplaySettings settings{options.duration_s, options.elevation_weighting, !options.float_only, !options.no_laser,
                                    {options.crosslink_drop, options.outage_start_s, options.outage_s},
                                    std::ceil(options.crosslink_delay_s - 1e-9), settings_file ? &*settings_file : nullptr};
      replays.push_back(replay(inputs.value(), local, settings));
      const Json s = summarise(replays.back());
      write_epochs(replays.back(), options.out);
      write_fixes(replays.back(), options.out);
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
