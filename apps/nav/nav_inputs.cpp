#include "nav/nav_inputs.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>

#include "baseline/receiver_observables.hpp"
#include "core/files/csv_file.hpp"
#include "gnss/files/rinex_nav_file.hpp"
#include "gnss/files/rinex_obs_file.hpp"
#include "sim/random_stream.hpp"
#include "sim/spacecraft_geometry.hpp"

namespace visors::nav_app {
namespace {

using core::Error;

long long key_ms(double t_s) { return std::llround(t_s * 1000.0); }

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

core::Result<bool> read_truth(const std::filesystem::path& path, RunInputs& in) {
  constexpr std::array<std::string_view, 8> columns = {"t_s", "spacecraft", "x_gcrf_m", "y_gcrf_m", "z_gcrf_m",
                                                       "vx_gcrf_mps", "vy_gcrf_mps", "vz_gcrf_mps"};
  auto rows = core::files::read_csv_columns(path, columns, "truth file");
  if (!rows) return Error{path.string() + ": " + rows.error().field, rows.error().message};
  for (const auto& row : rows.value()) {
    std::array<double, 7> v{};
    for (std::size_t i = 0; i < 7; ++i) {
      const auto value = core::files::parse_finite_number(row.fields[i == 0 ? 0 : i + 1]);
      if (!value) return Error{path.string() + ": line " + std::to_string(row.line), "not a number"};
      v[i] = *value;
    }
    const core::StateVector x{Eigen::Vector3d(v[1], v[2], v[3]), Eigen::Vector3d(v[4], v[5], v[6])};
    auto& entry = in.truth[key_ms(v[0])];
    (row.fields[1] == "dsc" ? entry.first : entry.second) = x;
  }
  return true;
}

core::Result<bool> read_phase_truth(const std::filesystem::path& path, RunInputs& in) {
  constexpr std::array<std::string_view, 5> columns = {"t_s", "spacecraft", "prn", "ambiguity_cycles",
                                                       "receiver_phase_cycles"};
  auto rows = core::files::read_csv_columns(path, columns, "channel truth file");
  if (!rows) return Error{path.string() + ": " + rows.error().field, rows.error().message};
  for (const auto& row : rows.value()) {
    const auto t = core::files::parse_finite_number(row.fields[0]);
    const auto prn = core::files::parse_finite_number(row.fields[2]);
    const auto n = core::files::parse_finite_number(row.fields[3]);
    const auto offset = core::files::parse_finite_number(row.fields[4]);
    if (!t || !prn || !n || !offset) return Error{path.string() + ": line " + std::to_string(row.line), "not a number"};
    auto& entry = in.phase_truth[key_ms(*t)][static_cast<int>(*prn)];
    (row.fields[1] == "dsc" ? entry.first : entry.second) = *n + *offset;
  }
  return true;
}

}  // namespace

core::Result<RunInputs> read_run(const std::filesystem::path& run_dir) {
  RunInputs in;
  std::ifstream scenario_file(run_dir / "scenario.toml");
  if (!scenario_file) return Error{(run_dir / "scenario.toml").string(), "cannot be read (is this a gnss-sim run directory?)"};
  std::stringstream text;
  text << scenario_file.rdbuf();
  auto scenario = sim::campaign_from_toml(text.str());
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
  if (auto ok = read_truth(run_dir / "truth.csv", in); !ok) return ok.error();
  if (auto ok = read_phase_truth(run_dir / "channels_truth.csv", in); !ok) return ok.error();
  const char* names[2] = {"dsc", "osc"};
  for (std::size_t k = 0; k < 2; ++k) {
    sim::RandomStream rng(in.scenario.seed, std::string(names[k]) + ".geometry");  // as gnss-sim draws it
    const auto geometry = sim::SpacecraftGeometry::draw(sim::GeometrySettings{}, rng);
    in.com_knowledge_error_body_m[k] = geometry.com_body_m() - geometry.com_nominal_body_m();
  }
  return in;
}

}  // namespace visors::nav_app
