#include "apps/nav/nav_inputs.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <span>
#include <string_view>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "visors/baseline/receiver_observables.hpp"
#include "visors/core/files/csv_file.hpp"
#include "visors/core/files/text_file.hpp"
#include "visors/gnc/onboard_navigation.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"
#include "visors/sim/random_stream.hpp"
#include "visors/sim/spacecraft_geometry.hpp"

namespace visors::nav_app {
namespace {

using core::Error;
using Fields = std::span<const std::string_view>;  // a CSV row's wanted fields (core/files/csv_file.hpp)

core::Result<std::vector<nav::GpsReceiverEpoch>> read_observations(const std::filesystem::path& path) {
  auto file = gnss::files::read_rinex_observations(path);
  if (!file) return Error{path.string() + ": " + file.error().field, file.error().message};
  auto observables = baseline::extract_observables(file.value(), path.string());
  if (!observables) return observables.error();
  std::vector<nav::GpsReceiverEpoch> out;
  for (const auto& e : observables.value().epochs) {
    nav::GpsReceiverEpoch epoch;
    epoch.t = e.t;
    for (const auto& s : e.satellites) {
      if (!std::isfinite(s.phase_cyc[0]) || !std::isfinite(s.code_m[0]) || epoch.count == nav::kGpsSlots) continue;
      nav::GpsObservation& o = epoch.observations[static_cast<std::size_t>(epoch.count++)];
      o.prn = s.prn;
      o.code_m = s.code_m[0];
      o.phase_cycles = s.phase_cyc[0];
      o.loss_of_lock = s.loss_of_lock[0];
      o.half_cycle = s.half_cycle[0];
    }
    out.push_back(epoch);
  }
  return out;
}

core::Result<gnss::EphemerisSet> read_ephemerides(const std::filesystem::path& path) {
  auto nav = gnss::files::read_rinex_navigation(path);
  if (!nav) return Error{path.string() + ": " + nav.error().field, nav.error().message};
  if (nav.value().records.empty()) return Error{path.string(), "holds no GPS record"};
  return gnss::EphemerisSet::screen(nav.value().records, nav.value().record_lines);
}

// The numbers of a row's fields [first, first + out.size()); false at the first that is not one.
bool parse_fields(Fields fields, std::size_t first, std::span<double> out) {
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto value = core::files::parse_finite_number(fields[first + i]);
    if (!value) return false;
    out[i] = *value;
  }
  return true;
}

core::Result<nav::Craft> craft_named(std::string_view name, std::size_t line) {
  if (name == "dsc") return nav::Craft::kDsc;
  if (name == "osc") return nav::Craft::kOsc;
  return Error{"line " + std::to_string(line), "spacecraft '" + std::string(name) + "' is neither dsc nor osc"};
}

// Each row of a CSV file of the run, row by row (core/files/csv_file.hpp); errors name the file.
core::Result<bool> read_rows(const std::filesystem::path& path, std::span<const std::string_view> columns,
                             const char* what, const core::files::CsvRowVisitor& visit) {
  auto ok = core::files::for_each_csv_row(path, columns, what, visit);
  if (!ok) return Error{path.string() + ": " + ok.error().field, ok.error().message};
  return true;
}

Error not_a_number(std::size_t line) { return Error{"line " + std::to_string(line), "not a number"}; }

core::Result<bool> read_truth(const std::filesystem::path& path, RunInputs& in) {
  constexpr std::array<std::string_view, 13> columns = {
      "t_s",         "spacecraft",  "x_gcrf_m",        "y_gcrf_m",        "z_gcrf_m",        "vx_gcrf_mps",      "vy_gcrf_mps",
      "vz_gcrf_mps", "qw_body_to_gcrf", "qx_body_to_gcrf", "qy_body_to_gcrf", "qz_body_to_gcrf", "receiver_clock_m"};
  return read_rows(path, columns, "truth file", [&in](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 12> v{};
    if (!parse_fields(fields, 2, std::span(v).subspan(1)) || !parse_fields(fields, 0, std::span(v).first(1))) {
      return not_a_number(line);
    }
    const auto craft = craft_named(fields[1], line);
    if (!craft) return craft.error();
    const Eigen::Quaterniond q(v[7], v[8], v[9], v[10]);
    if (std::abs(q.norm() - 1.0) > 1e-6) return Error{"line " + std::to_string(line), "attitude quaternion is not unit"};
    in.truth[key_ms(v[0])][static_cast<std::size_t>(*craft)] =
        CraftTruth{{Eigen::Vector3d(v[1], v[2], v[3]), Eigen::Vector3d(v[4], v[5], v[6])}, q.normalized(), v[11]};
    return true;
  });
}

// A file gnss-sim writes since the ADCS and the decoding delay: its absence is an older run.
core::Result<bool> require(const std::filesystem::path& path, const char* what) {
  if (std::filesystem::exists(path)) return true;
  return Error{path.string(), std::string("is missing: ") + what +
                                  "; the run is of a gnss-sim before it (re-run gnss-sim: visors nav never gives the "
                                  "filter the truth in its place)"};
}

// attitude_reported.csv: what each ADCS reported (the filter's attitude), both spacecraft at every
// epoch listed.
core::Result<bool> read_known_attitude(const std::filesystem::path& path, RunInputs& in) {
  if (auto ok = require(path, "the attitude each ADCS reported"); !ok) return ok;
  constexpr std::array<std::string_view, 6> columns = {"t_s", "spacecraft", "qw_body_to_gcrf", "qx_body_to_gcrf",
                                                       "qy_body_to_gcrf", "qz_body_to_gcrf"};
  std::map<long long, int> crafts_listed;  // per epoch: bit 0 DSC, bit 1 OSC
  auto ok = read_rows(path, columns, "reported attitude file", [&](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 5> v{};
    if (!parse_fields(fields, 0, std::span(v).first(1)) || !parse_fields(fields, 2, std::span(v).subspan(1))) {
      return not_a_number(line);
    }
    const auto craft = craft_named(fields[1], line);
    if (!craft) return craft.error();
    const Eigen::Quaterniond q(v[1], v[2], v[3], v[4]);
    if (std::abs(q.norm() - 1.0) > 1e-6) return Error{"line " + std::to_string(line), "attitude quaternion is not unit"};
    in.known_attitude[key_ms(v[0])][static_cast<std::size_t>(*craft)] = q.normalized();
    crafts_listed[key_ms(v[0])] |= 1 << static_cast<int>(*craft);
    return true;
  });
  if (!ok) return ok;
  for (const auto& [t_ms, listed] : crafts_listed) {
    if (listed != 3) return Error{path.string(), fmt::format("t_s {:.3f}: not both spacecraft", static_cast<double>(t_ms) / 1000.0)};
  }
  return true;
}

// ephemeris_decoded.csv: per receiver, when it decoded each data set of brdc.rnx.
core::Result<bool> read_decoded_data_sets(const std::filesystem::path& path, RunInputs& in) {
  if (auto ok = require(path, "when each receiver decoded each broadcast data set"); !ok) return ok;
  constexpr std::array<std::string_view, 5> columns = {"t_s", "spacecraft", "prn", "toe_week", "toe_sow"};
  std::array<std::vector<DecodedDataSet>, 2> decoded;
  auto ok = read_rows(path, columns, "ephemeris decoding file", [&](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 4> v{};  // t_s, then prn, toe week, toe seconds of week
    if (!parse_fields(fields, 0, std::span(v).first(1)) || !parse_fields(fields, 2, std::span(v).subspan(1))) {
      return not_a_number(line);
    }
    const auto craft = craft_named(fields[1], line);
    if (!craft) return craft.error();
    const auto toe = core::GpsTime::from_week_seconds(static_cast<int>(v[2]), v[3]);
    if (!toe) return Error{"line " + std::to_string(line), "toe_week, toe_sow: " + toe.error().message};
    decoded[static_cast<std::size_t>(*craft)].push_back({static_cast<int>(v[1]), *toe, in.scenario.t0 + v[0]});
    return true;
  });
  if (!ok) return ok;
  for (std::size_t k = 0; k < 2; ++k) {
    auto made = DecodedEphemerides::create(in.ephemerides, decoded[k], path.string());
    if (!made) return made.error();
    in.decoded_ephemerides[k] = std::move(made).value();
  }
  return true;
}

// maneuvers.csv: the commanded columns only (the executed ones are the truth).
core::Result<bool> read_impulses(const std::filesystem::path& path, RunInputs& in) {
  if (!std::filesystem::exists(path)) return true;
  constexpr std::array<std::string_view, 5> columns = {"t_s", "spacecraft", "dv_cmd_x_gcrf_mps", "dv_cmd_y_gcrf_mps",
                                                       "dv_cmd_z_gcrf_mps"};
  return read_rows(path, columns, "maneuver file", [&in](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 4> v{};
    if (!parse_fields(fields, 0, std::span(v).first(1)) || !parse_fields(fields, 2, std::span(v).subspan(1))) {
      return not_a_number(line);
    }
    const auto craft = craft_named(fields[1], line);
    if (!craft) return craft.error();
    if (!in.impulses.empty() && v[0] < in.impulses.back().t_s) {
      return Error{"line " + std::to_string(line), "impulses out of time order"};
    }
    in.impulses.push_back({v[0], *craft, Eigen::Vector3d(v[1], v[2], v[3])});
    return true;
  });
}

// lrf.csv: the measured ranges (true_range_m is the truth).
core::Result<bool> read_laser_ranges(const std::filesystem::path& path, RunInputs& in) {
  if (!std::filesystem::exists(path)) return true;
  constexpr std::array<std::string_view, 2> columns = {"t_s", "range_m"};
  return read_rows(path, columns, "laser range file", [&in](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 2> v{};
    if (!parse_fields(fields, 0, v)) return not_a_number(line);
    in.laser_ranges_m[key_ms(v[0])] = v[1];
    return true;
  });
}

// summary.json's "observations" (absent in runs without the campaign attitude).
// gnss-sim's summary.json: the observation spans, and each receiver's true phase centre and
// centre of mass (body frame).
core::Result<bool> read_summary(const std::filesystem::path& path, RunInputs& in) {
  std::ifstream file(path);
  if (!file) return Error{path.string(), "is missing (gnss-sim writes it)"};
  const nlohmann::json summary = nlohmann::json::parse(file, nullptr, false);
  if (summary.is_discarded()) return Error{path.string(), "is not JSON"};
  const char* names[2] = {"dsc", "osc"};
  for (std::size_t k = 0; k < 2; ++k) {
    const auto vector = [&](const char* key) -> core::Result<Eigen::Vector3d> {
      const nlohmann::json* v = nullptr;
      if (summary.contains("receivers") && summary["receivers"].contains(names[k])) v = &summary["receivers"][names[k]];
      if (v == nullptr || !v->contains(key) || !(*v)[key].is_array() || (*v)[key].size() != 3) {
        return Error{path.string() + ": receivers." + names[k] + "." + key, "must be an array of 3 numbers"};
      }
      return Eigen::Vector3d((*v)[key][0].get<double>(), (*v)[key][1].get<double>(), (*v)[key][2].get<double>());
    };
    auto phase_center = vector("phase_center_body_m");
    if (!phase_center) return phase_center.error();
    auto com = vector("center_of_mass_body_m");
    if (!com) return com.error();
    in.true_antenna_lever_body_m[k] = *phase_center - *com;
  }
  if (!summary.contains("observations")) return true;
  for (const auto& o : summary["observations"]) {
    if (!o.contains("slew_start_s") || !o.contains("start_s") || !o.contains("end_s") || !o["start_s"].is_number() ||
        !o["end_s"].is_number() || !o["slew_start_s"].is_number()) {
      return Error{path.string() + ": observations", "each needs numbers slew_start_s, start_s, end_s"};
    }
    in.observations.push_back({o["slew_start_s"].get<double>(), o["start_s"].get<double>(), o["end_s"].get<double>()});
  }
  return true;
}

core::Result<bool> read_phase_truth(const std::filesystem::path& path, RunInputs& in) {
  constexpr std::array<std::string_view, 5> columns = {"t_s", "spacecraft", "prn", "ambiguity_cycles",
                                                       "receiver_phase_cycles"};
  return read_rows(path, columns, "channel truth file", [&in](std::size_t line, Fields fields) -> core::Result<bool> {
    std::array<double, 4> v{};  // t_s, then prn, ambiguity, receiver phase
    if (!parse_fields(fields, 0, std::span(v).first(1)) || !parse_fields(fields, 2, std::span(v).subspan(1))) {
      return not_a_number(line);
    }
    auto& entry = in.phase_truth[key_ms(v[0])][static_cast<int>(v[1])];
    (fields[1] == "dsc" ? entry.first : entry.second) = v[2] + v[3];
    return true;
  });
}

}  // namespace

nav::AntennaGeometry antenna_geometry(const sim::FlightKnowledge& told, const Eigen::Quaterniond& body_to_gcrf) {
  nav::AntennaGeometry a;
  a.body_to_gcrf = body_to_gcrf.toRotationMatrix();
  // The flight software's calibrated antenna, not the truth receiver's (docs/truth-and-knowledge.md).
  a.arp_body_m = told.antenna_arp_body_m;
  a.pco_body_m = told.antenna_pco_m * Eigen::Vector3d::UnitZ();
  a.boresight_body = Eigen::Vector3d::UnitZ();  // gnss-sim's nominal boresight
  return a;
}

const std::array<Eigen::Quaterniond, 2>* known_attitudes_at(const RunInputs& in, double t_s) {
  const auto it = in.known_attitude.find(key_ms(t_s));
  return it == in.known_attitude.end() ? nullptr : &it->second;
}

Eigen::Vector3d known_angular_velocity_gcrf(const RunInputs& in, double t_s, std::size_t craft) {
  const double step_s = in.scenario.step_s;
  const auto attitude_at = [&](double at_s) -> const Eigen::Quaterniond* {
    const auto* both = known_attitudes_at(in, at_s);
    return both == nullptr ? nullptr : &(*both)[craft];
  };
  const Eigen::Quaterniond* now = attitude_at(t_s);
  const Eigen::Quaterniond* before = attitude_at(t_s - step_s);
  const Eigen::Quaterniond* after = attitude_at(t_s + step_s);
  if (before == nullptr) before = now;
  if (after == nullptr) after = now;
  if (before == nullptr || after == nullptr || before == after) return Eigen::Vector3d::Zero();
  const double interval_s = (before == now || after == now) ? step_s : 2.0 * step_s;
  const Eigen::AngleAxisd turn(*after * before->conjugate());  // about GCRF axes
  return turn.angle() / interval_s * turn.axis();
}

nav::LaserRangeGeometry laser_geometry(const sim::FlightKnowledge& told, const Eigen::Quaterniond& dsc_body_to_gcrf,
                                       const Eigen::Quaterniond& osc_body_to_gcrf) {
  nav::LaserRangeGeometry g;
  g.dsc_body_to_gcrf = dsc_body_to_gcrf.toRotationMatrix();
  g.osc_body_to_gcrf = osc_body_to_gcrf.toRotationMatrix();
  g.dsc_lever_body_m = told.lrf_lever_body_m;
  g.osc_lever_body_m = told.lrf_lever_body_m;
  g.bias_m = told.lrf_bias_m;
  return g;
}

core::Result<RunInputs> read_run(const std::filesystem::path& run_dir) {
  RunInputs in;
  const auto text = core::files::read_text_file(run_dir / "scenario.toml");
  if (!text) return Error{(run_dir / "scenario.toml").string(), "cannot be read (is this a gnss-sim run directory?)"};
  auto scenario = sim::campaign_from_toml(*text);
  if (!scenario) return Error{"scenario.toml: " + scenario.error().field, scenario.error().message};
  in.scenario = std::move(scenario).value();
  auto dsc = read_observations(run_dir / "dsc.rnx");
  if (!dsc) return dsc.error();
  auto osc = read_observations(run_dir / "osc.rnx");
  if (!osc) return osc.error();
  in.dsc = std::move(dsc).value();
  in.osc = std::move(osc).value();
  auto ephemerides = read_ephemerides(run_dir / "brdc.rnx");
  if (!ephemerides) return ephemerides.error();
  in.ephemerides = std::move(ephemerides).value();
  if (auto ok = read_decoded_data_sets(run_dir / "ephemeris_decoded.csv", in); !ok) return ok.error();
  if (auto ok = read_known_attitude(run_dir / "attitude_reported.csv", in); !ok) return ok.error();
  if (auto ok = read_truth(run_dir / "truth.csv", in); !ok) return ok.error();
  if (auto ok = read_impulses(run_dir / "maneuvers.csv", in); !ok) return ok.error();
  if (auto ok = read_laser_ranges(run_dir / "lrf.csv", in); !ok) return ok.error();
  if (auto ok = read_summary(run_dir / "summary.json", in); !ok) return ok.error();
  if (auto ok = read_phase_truth(run_dir / "channels_truth.csv", in); !ok) return ok.error();
  const char* names[2] = {"dsc", "osc"};
  for (std::size_t k = 0; k < 2; ++k) {
    sim::RandomStream rng(in.scenario.seed, std::string(names[k]) + ".geometry");  // as gnss-sim draws it
    const auto geometry = sim::SpacecraftGeometry::draw(in.scenario.geometry, rng);
    in.true_payload_lever_body_m[k] = geometry.payload_from_com_body_m();
  }
  return in;
}

}  // namespace visors::nav_app
