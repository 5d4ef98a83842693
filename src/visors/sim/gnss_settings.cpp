#include "visors/sim/gnss_settings.hpp"

#include <cmath>

#include <fmt/format.h>

#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/config/toml_fields.hpp"

namespace visors::sim {

using core::Error;
using namespace config::toml_fields;

namespace {

core::Result<bool> read_receiver(const toml::table& table, GpsReceiverSettings& r) {
  const std::string sec = "gnss.receiver";
  if (auto e = check_keys(table, sec,
                          {"elevation_mask_deg", "channels", "code_sigma_m", "phase_sigma_m", "doppler_sigma_hz",
                           "clock_step_sigma_m", "initial_clock_sigma_m", "phase_center_offset_m", "mounting_sigma_arcsec",
                           "antenna_body_m", "occultation_altitude_m", "cycle_slip_probability", "max_slip_cycles",
                           "ionosphere", "topside_fraction", "shell_height_m", "unflagged_slip_fraction",
                           "half_cycle_slip_probability", "half_cycle_resolve_s", "elevation_dependent_noise",
                           "code_multipath_m", "phase_multipath_m", "multipath_tau_s", "data_gap_probability",
                           "data_gap_s"})) {
    return *e;
  }
  VISORS_TRY(mask, number_at(table, sec, "elevation_mask_deg", r.elevation_mask_rad / core::kDegToRad));
  VISORS_TRY(channels, integer_at(table, sec, "channels", r.channels));
  VISORS_TRY(code, number_at(table, sec, "code_sigma_m", r.code_sigma_m));
  VISORS_TRY(phase, number_at(table, sec, "phase_sigma_m", r.phase_sigma_m));
  VISORS_TRY(doppler, number_at(table, sec, "doppler_sigma_hz", r.doppler_sigma_hz));
  VISORS_TRY(clock_step, number_at(table, sec, "clock_step_sigma_m", r.clock_step_sigma_m));
  VISORS_TRY(clock0, number_at(table, sec, "initial_clock_sigma_m", r.initial_clock_sigma_m));
  VISORS_TRY(pco, number_at(table, sec, "phase_center_offset_m", r.phase_center_offset_m));
  VISORS_TRY(mounting, number_at(table, sec, "mounting_sigma_arcsec", r.mounting_sigma_rad / core::kArcsecToRad));
  VISORS_TRY(antenna, vector3_at(table, sec, "antenna_body_m", r.antenna_body_m));
  VISORS_TRY(occultation, number_at(table, sec, "occultation_altitude_m", r.occultation_altitude_m));
  VISORS_TRY(slip, number_at(table, sec, "cycle_slip_probability", r.cycle_slip_probability));
  VISORS_TRY(slip_size, integer_at(table, sec, "max_slip_cycles", r.max_slip_cycles));
  VISORS_TRY(ionosphere, bool_at(table, sec, "ionosphere", r.ionosphere));
  VISORS_TRY(fraction, number_at(table, sec, "topside_fraction", r.topside.topside_fraction));
  VISORS_TRY(shell, number_at(table, sec, "shell_height_m", r.topside.shell_height_m));
  VISORS_TRY(unflagged, number_at(table, sec, "unflagged_slip_fraction", r.unflagged_slip_fraction));
  VISORS_TRY(half, number_at(table, sec, "half_cycle_slip_probability", r.half_cycle_slip_probability));
  VISORS_TRY(half_resolve, number_at(table, sec, "half_cycle_resolve_s", r.half_cycle_resolve_s));
  VISORS_TRY(elevation_noise, bool_at(table, sec, "elevation_dependent_noise", r.elevation_dependent_noise));
  VISORS_TRY(code_mp, number_at(table, sec, "code_multipath_m", r.code_multipath_m));
  VISORS_TRY(phase_mp, number_at(table, sec, "phase_multipath_m", r.phase_multipath_m));
  VISORS_TRY(mp_tau, number_at(table, sec, "multipath_tau_s", r.multipath_tau_s));
  VISORS_TRY(gap_p, number_at(table, sec, "data_gap_probability", r.data_gap_probability));
  VISORS_TRY(gap_s, number_at(table, sec, "data_gap_s", r.data_gap_s));
  if (channels < 1 || channels > 12) return Error{sec + ".channels", "must be in 1..12"};
  if (slip_size < 1 || slip_size > 1000000) return Error{sec + ".max_slip_cycles", "must be in 1..1000000"};
  GpsReceiverSettings out = r;
  out.elevation_mask_rad = mask * core::kDegToRad;
  out.channels = static_cast<int>(channels);
  out.code_sigma_m = code;
  out.phase_sigma_m = phase;
  out.doppler_sigma_hz = doppler;
  out.clock_step_sigma_m = clock_step;
  out.initial_clock_sigma_m = clock0;
  out.phase_center_offset_m = pco;
  out.mounting_sigma_rad = mounting * core::kArcsecToRad;
  out.antenna_body_m = antenna;
  out.occultation_altitude_m = occultation;
  out.cycle_slip_probability = slip;
  out.max_slip_cycles = static_cast<int>(slip_size);
  out.ionosphere = ionosphere;
  out.topside.topside_fraction = fraction;
  out.topside.shell_height_m = shell;
  out.unflagged_slip_fraction = unflagged;
  out.half_cycle_slip_probability = half;
  out.half_cycle_resolve_s = half_resolve;
  out.elevation_dependent_noise = elevation_noise;
  out.code_multipath_m = code_mp;
  out.phase_multipath_m = phase_mp;
  out.multipath_tau_s = mp_tau;
  out.data_gap_probability = gap_p;
  out.data_gap_s = gap_s;
  if (auto valid = out.validate(); !valid) return Error{sec + "." + valid.error().field, valid.error().message};
  r = out;
  return true;
}

core::Result<bool> read_errors(const toml::table& table, BroadcastErrorSettings& b) {
  const std::string sec = "gnss.broadcast_errors";
  if (auto e = check_keys(table, sec, {"radial_m", "along_m", "cross_m", "clock_m", "clock_drift_sps", "refresh_s",
                                       "refresh_correlation"})) {
    return *e;
  }
  VISORS_TRY(radial, number_at(table, sec, "radial_m", b.radial_m));
  VISORS_TRY(along, number_at(table, sec, "along_m", b.along_m));
  VISORS_TRY(cross, number_at(table, sec, "cross_m", b.cross_m));
  VISORS_TRY(clock, number_at(table, sec, "clock_m", b.clock_m));
  VISORS_TRY(drift, number_at(table, sec, "clock_drift_sps", b.clock_drift_sps));
  VISORS_TRY(refresh, number_at(table, sec, "refresh_s", b.refresh_s));
  VISORS_TRY(rho, number_at(table, sec, "refresh_correlation", b.refresh_correlation));
  const BroadcastErrorSettings out{radial, along, cross, clock, drift, refresh, rho};
  if (auto valid = out.validate(); !valid) return Error{sec + "." + valid.error().field, valid.error().message};
  b = out;
  return true;
}

// Limits of the new tables: a day's worth of bursts per orbit and pieces per burst is far beyond
// any use (a burst of 100 pieces spans 77 min at 46.5 s), and keeps every count an int.
constexpr std::int64_t kMaxBurstsPerOrbit = 100;
constexpr std::int64_t kMaxPiecesPerBurst = 100;

core::Result<bool> read_observations(const toml::table& table, GnssObservationSettings& o) {
  const std::string sec = "gnss.observations";
  if (auto e = check_keys(table, sec, {"first_start_s", "period_s", "duration_s", "slew_lead_s"})) return *e;
  VISORS_TRY(first, number_at(table, sec, "first_start_s", o.first_start_s));
  VISORS_TRY(period, number_at(table, sec, "period_s", o.period_s));
  VISORS_TRY(duration, number_at(table, sec, "duration_s", o.duration_s));
  VISORS_TRY(lead, number_at(table, sec, "slew_lead_s", o.slew_lead_s));
  if (!(first >= 0.0)) return Error{sec + ".first_start_s", "must be >= 0 s"};
  if (!(period >= 0.0)) return Error{sec + ".period_s", "must be > 0 s (or 0: the chief's Keplerian period)"};
  if (!(duration > 0.0)) return Error{sec + ".duration_s", "must be > 0 s"};
  if (!(lead >= 0.0)) return Error{sec + ".slew_lead_s", "must be > 0 s (or 0: a 180 deg slew plus settling)"};
  if (period > 0.0 && period <= duration + lead) {
    return Error{sec + ".period_s", "must exceed duration_s + slew_lead_s (windows must not overlap)"};
  }
  o = GnssObservationSettings{first, period, duration, lead};
  return true;
}

core::Result<bool> read_maneuvers(const toml::table& table, GnssManeuverSettings& m) {
  const std::string sec = "gnss.maneuvers";
  if (auto e = check_keys(table, sec, {"spacecraft", "bursts_per_orbit", "pieces_per_burst", "dv_mps", "first_burst_s",
                                         "keeping"})) {
    return *e;
  }
  VISORS_TRY(spacecraft, string_at(table, sec, "spacecraft", m.spacecraft));
  VISORS_TRY(bursts, integer_at(table, sec, "bursts_per_orbit", m.bursts_per_orbit));
  VISORS_TRY(pieces, integer_at(table, sec, "pieces_per_burst", m.pieces_per_burst));
  VISORS_TRY(dv, number_at(table, sec, "dv_mps", m.dv_mps));
  VISORS_TRY(first, number_at(table, sec, "first_burst_s", m.first_burst_s));
  VISORS_TRY(keeping, bool_at(table, sec, "keeping", m.keeping));
  if (spacecraft != "none" && spacecraft != "osc" && spacecraft != "dsc" && spacecraft != "both") {
    return Error{sec + ".spacecraft", "must be \"none\", \"osc\", \"dsc\" or \"both\", got \"" + spacecraft + "\""};
  }
  if (bursts < 1 || bursts > kMaxBurstsPerOrbit) return Error{sec + ".bursts_per_orbit", "must be in 1..100"};
  if (pieces < 1 || pieces > kMaxPiecesPerBurst) return Error{sec + ".pieces_per_burst", "must be in 1..100"};
  if (!(dv > 0.0 && dv <= 1.0)) return Error{sec + ".dv_mps", "must be in (0, 1] m/s"};
  if (!(first >= 0.0)) return Error{sec + ".first_burst_s", "must be >= 0 s"};
  m = GnssManeuverSettings{spacecraft, static_cast<int>(bursts), static_cast<int>(pieces), dv, first, keeping};
  return true;
}

core::Result<bool> read_lrf(const toml::table& table, GnssLrfSettings& l) {
  const std::string sec = "gnss.lrf";
  if (auto e = check_keys(table, sec, {"enabled", "interval_s", "sigma_m", "bias_m"})) return *e;
  VISORS_TRY(enabled, bool_at(table, sec, "enabled", l.enabled));
  VISORS_TRY(interval, number_at(table, sec, "interval_s", l.interval_s));
  VISORS_TRY(sigma, number_at(table, sec, "sigma_m", l.sigma_m));
  VISORS_TRY(bias, number_at(table, sec, "bias_m", l.bias_m));
  if (!(interval > 0.0)) return Error{sec + ".interval_s", "must be > 0 s"};
  if (!(sigma >= 0.0)) return Error{sec + ".sigma_m", "must be >= 0 m"};
  if (!(std::abs(bias) <= 1.0)) return Error{sec + ".bias_m", "must be in [-1, 1] m"};
  l = GnssLrfSettings{enabled, interval, sigma, bias};
  return true;
}

}  // namespace

core::Result<bool> read_gnss_settings(const toml::table& root, GnssSettings& s) {
  const toml::table* g = root.get_as<toml::table>("gnss");
  if (g == nullptr) return true;
  const std::string sec = "gnss";
  if (auto e = check_keys(*g, sec, {"nav_file", "source_time_gps", "duration_s", "rinex", "attitude", "receiver",
                                    "broadcast_errors", "observations", "maneuvers", "lrf"})) {
    return *e;
  }
  VISORS_TRY(nav, string_at(*g, sec, "nav_file", s.nav_file));
  VISORS_TRY(source, string_at(*g, sec, "source_time_gps", s.source_time_gps));
  VISORS_TRY(duration, number_at(*g, sec, "duration_s", s.duration_s));
  VISORS_TRY(rinex, bool_at(*g, sec, "rinex", s.rinex));
  VISORS_TRY(attitude, string_at(*g, sec, "attitude", s.attitude));
  if (nav.empty()) return Error{"gnss.nav_file", "must name a RINEX navigation file"};
  if (auto t = core::GpsTime::parse(source, core::TimeScale::kGps); !t) {
    return Error{"gnss.source_time_gps", t.error().describe()};
  }
  if (!(duration >= 0.0 && duration <= 30.0 * 86400.0)) return Error{"gnss.duration_s", "must be in [0, 2592000] s"};
  if (attitude != "nominal" && attitude != "observation" && attitude != "campaign") {
    return Error{"gnss.attitude", "must be \"nominal\", \"observation\" or \"campaign\", got \"" + attitude + "\""};
  }
  GnssSettings out = s;
  out.nav_file = nav;
  out.source_time_gps = source;
  out.duration_s = duration;
  out.rinex = rinex;
  out.attitude = attitude;
  if (const toml::table* r = g->get_as<toml::table>("receiver")) {
    if (auto ok = read_receiver(*r, out.receiver); !ok) return ok.error();
  }
  if (const toml::table* b = g->get_as<toml::table>("broadcast_errors")) {
    if (auto ok = read_errors(*b, out.broadcast_errors); !ok) return ok.error();
  }
  if (const toml::table* o = g->get_as<toml::table>("observations")) {
    if (auto ok = read_observations(*o, out.observations); !ok) return ok.error();
  }
  if (const toml::table* m = g->get_as<toml::table>("maneuvers")) {
    if (auto ok = read_maneuvers(*m, out.maneuvers); !ok) return ok.error();
  }
  if (const toml::table* l = g->get_as<toml::table>("lrf")) {
    if (auto ok = read_lrf(*l, out.lrf); !ok) return ok.error();
  }
  if (out.lrf.enabled && out.attitude != "campaign") {
    return Error{"gnss.lrf.enabled", "needs gnss.attitude = \"campaign\" (measurements only during observations)"};
  }
  s = out;
  return true;
}

std::string gnss_settings_to_toml(const GnssSettings& s) {
  const auto& r = s.receiver;
  const auto& b = s.broadcast_errors;
  std::string out = fmt::format("[gnss]\nnav_file = \"{}\"\nsource_time_gps = \"{}\"\nduration_s = {:.17g}\nrinex = {}\nattitude = \"{}\"\n\n",
                                s.nav_file, s.source_time_gps, s.duration_s, s.rinex, s.attitude);
  out += fmt::format(
      "[gnss.receiver]\nelevation_mask_deg = {:.17g}\nchannels = {}\ncode_sigma_m = {:.17g}\nphase_sigma_m = {:.17g}\n"
      "doppler_sigma_hz = {:.17g}\nclock_step_sigma_m = {:.17g}\ninitial_clock_sigma_m = {:.17g}\n"
      "phase_center_offset_m = {:.17g}\nmounting_sigma_arcsec = {:.17g}\nantenna_body_m = [{:.17g}, {:.17g}, {:.17g}]\n"
      "occultation_altitude_m = {:.17g}\ncycle_slip_probability = {:.17g}\nmax_slip_cycles = {}\nionosphere = {}\n"
      "topside_fraction = {:.17g}\nshell_height_m = {:.17g}\n",
      r.elevation_mask_rad / core::kDegToRad, r.channels, r.code_sigma_m, r.phase_sigma_m, r.doppler_sigma_hz,
      r.clock_step_sigma_m, r.initial_clock_sigma_m, r.phase_center_offset_m, r.mounting_sigma_rad / core::kArcsecToRad,
      r.antenna_body_m.x(), r.antenna_body_m.y(), r.antenna_body_m.z(), r.occultation_altitude_m, r.cycle_slip_probability,
      r.max_slip_cycles, r.ionosphere, r.topside.topside_fraction, r.topside.shell_height_m);
  out += fmt::format(
      "unflagged_slip_fraction = {:.17g}\nhalf_cycle_slip_probability = {:.17g}\nhalf_cycle_resolve_s = {:.17g}\n"
      "elevation_dependent_noise = {}\ncode_multipath_m = {:.17g}\nphase_multipath_m = {:.17g}\nmultipath_tau_s = {:.17g}\n"
      "data_gap_probability = {:.17g}\ndata_gap_s = {:.17g}\n\n",
      r.unflagged_slip_fraction, r.half_cycle_slip_probability, r.half_cycle_resolve_s, r.elevation_dependent_noise,
      r.code_multipath_m, r.phase_multipath_m, r.multipath_tau_s, r.data_gap_probability, r.data_gap_s);
  out += fmt::format("[gnss.broadcast_errors]\nradial_m = {:.17g}\nalong_m = {:.17g}\ncross_m = {:.17g}\nclock_m = {:.17g}\nclock_drift_sps = {:.17g}\n"
                     "refresh_s = {:.17g}\nrefresh_correlation = {:.17g}\n\n",
                     b.radial_m, b.along_m, b.cross_m, b.clock_m, b.clock_drift_sps, b.refresh_s, b.refresh_correlation);
  const auto& o = s.observations;
  out += fmt::format("[gnss.observations]\nfirst_start_s = {:.17g}\nperiod_s = {:.17g}\nduration_s = {:.17g}\nslew_lead_s = {:.17g}\n\n",
                     o.first_start_s, o.period_s, o.duration_s, o.slew_lead_s);
  const auto& m = s.maneuvers;
  out += fmt::format(
      "[gnss.maneuvers]\nspacecraft = \"{}\"\nbursts_per_orbit = {}\npieces_per_burst = {}\ndv_mps = {:.17g}\n"
      "first_burst_s = {:.17g}\nkeeping = {}\n\n",
      m.spacecraft, m.bursts_per_orbit, m.pieces_per_burst, m.dv_mps, m.first_burst_s, m.keeping);
  const auto& l = s.lrf;
  out += fmt::format("[gnss.lrf]\nenabled = {}\ninterval_s = {:.17g}\nsigma_m = {:.17g}\nbias_m = {:.17g}\n\n", l.enabled,
                     l.interval_s, l.sigma_m, l.bias_m);
  return out;
}

}  // namespace visors::sim
