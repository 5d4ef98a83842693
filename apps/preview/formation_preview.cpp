#include "apps/preview/formation_preview.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <fmt/os.h>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/astro/sun_moon.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::preview {
namespace {

using core::Error;

struct EopSource {
  std::optional<core::EopTable> table;
  std::string note;
};

EopSource load_eop(const std::optional<std::string>& file) {
  if (!file) return {std::nullopt, "no eop_file given: zero EOP (ITRF columns are off by ~10 m)"};
  const auto path = core::files::find_data_file(*file);
  if (!path) {
    return {std::nullopt, "eop_file '" + *file + "' not found in VISORS_DATA_PATH: zero EOP"};
  }
  auto table = core::files::read_eop_file(*path);
  if (!table.ok()) return {std::nullopt, "eop_file unusable (" + table.error().describe() + "): zero EOP"};
  return {std::move(table).value(), "EOP from " + path->string()};
}

core::EarthOrientation eop_at(const EopSource& eop, core::GpsTime t) {
  if (!eop.table) return {};
  auto value = eop.table->at(t);
  return value.ok() ? value.value() : core::EarthOrientation{};
}

core::Result<core::StateVector> osculating_state(const astro::KeplerianElements& mean,
                                                 const core::EarthGravityConstants& earth) {
  auto osc = astro::osculating_from_mean(mean, earth);
  if (!osc.ok()) return osc.error();
  return astro::cartesian_from_keplerian(osc.value(), earth.mu);
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) / core::kDegToRad;
}

// One formation: mean chief and deputy elements propagated with the secular J2 rates and turned
// into osculating Cartesian states (the "exact" relative motion of the J2 problem to first order
// in J2), against the linear model the flight code plans with (J2 STM on the mean ROE and the
// eccentric ROE->RTN map).
core::Result<FormationSummary> preview_formation(const PreviewScenario& s, const FormationSpec& f,
                                                 const EopSource& eop,
                                                 const std::filesystem::path& out_dir) {
  const double a = s.chief_mean.a;
  astro::RelativeOrbitalElements roe0;
  for (int k = 0; k < 6; ++k) roe0[k] = f.roe_m[static_cast<std::size_t>(k)] / a;
  auto deputy0 = astro::deputy_from_roe(s.chief_mean, roe0);
  if (!deputy0.ok()) return Error{"formation." + f.name + ".roe_m", deputy0.error().describe()};

  FormationSummary summary;
  summary.name = f.name;
  summary.csv = out_dir / (f.name + ".csv");
  summary.min_separation_m = std::numeric_limits<double>::infinity();
  summary.min_rn_separation_m = std::numeric_limits<double>::infinity();
  summary.best_sun_alignment_deg = 180.0;

  const double period = core::kTwoPi * std::sqrt(a * a * a / s.earth.mu);
  const astro::RelativeOrbitalElements drift =
      astro::j2_roe_stm(s.chief_mean, period, s.earth) * roe0 - roe0;
  summary.drift_along_track_m_per_orbit = a * drift[astro::roe::kDlambda];

  std::ofstream csv(summary.csv);
  if (!csv) return Error{summary.csv.string(), "cannot be written"};
  csv << "# visors preview, formation '" << f.name << "', epoch " << s.epoch.format(core::TimeScale::kGps)
      << " GPS; RTN = chief (DSC) frame, relative = deputy (OSC) - chief\n"
      << "t_s,chief_x_gcrf_m,chief_y_gcrf_m,chief_z_gcrf_m,chief_x_itrf_m,chief_y_itrf_m,"
         "chief_z_itrf_m,r_rtn_m,t_rtn_m,n_rtn_m,vr_rtn_mps,vt_rtn_mps,vn_rtn_mps,"
         "r_rtn_linear_m,t_rtn_linear_m,n_rtn_linear_m,model_error_m,"
         "ada_m,adlambda_m,adex_m,adey_m,adix_m,adiy_m,sun_angle_deg\n";

  const double duration = s.orbits * period;
  const auto steps = static_cast<long>(std::floor(duration / s.step_s + 1e-9));
  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * s.step_s;
    const core::GpsTime time = s.epoch + t;
    const auto chief_mean = astro::propagate_mean_j2(s.chief_mean, t, s.earth);
    const auto deputy_mean = astro::propagate_mean_j2(deputy0.value(), t, s.earth);
    auto chief = osculating_state(chief_mean, s.earth);
    auto deputy = osculating_state(deputy_mean, s.earth);
    if (!chief.ok()) return Error{"chief", chief.error().describe()};
    if (!deputy.ok()) return Error{"formation." + f.name, deputy.error().describe()};
    const auto rel = core::relative_state_rtn(chief.value(), deputy.value());

    const astro::RelativeOrbitalElements roe_t = astro::j2_roe_stm(s.chief_mean, t, s.earth) * roe0;
    const astro::RelativeRtnVector linear = astro::rtn_from_roe(chief_mean, roe_t, s.earth.mu);
    const double model_error = (linear.head<3>() - rel.dr_rtn).norm();

    const Eigen::Vector3d dr_gcrf = deputy.value().r - chief.value().r;
    const double sun_angle = angle_deg(dr_gcrf, astro::sun_position_gcrf(time) - chief.value().r);
    const auto chief_itrf = core::gcrf_to_itrf(time, chief.value(), eop_at(eop, time));

    const double separation = rel.dr_rtn.norm();
    const double rn = std::hypot(rel.dr_rtn.x(), rel.dr_rtn.z());
    summary.min_separation_m = std::min(summary.min_separation_m, separation);
    summary.max_separation_m = std::max(summary.max_separation_m, separation);
    summary.min_rn_separation_m = std::min(summary.min_rn_separation_m, rn);
    summary.max_model_error_m = std::max(summary.max_model_error_m, model_error);
    if (sun_angle < summary.best_sun_alignment_deg) {
      summary.best_sun_alignment_deg = sun_angle;
      summary.best_sun_alignment_time_s = t;
      summary.separation_at_best_alignment_m = separation;
    }

    csv << fmt::format("{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},", t, chief.value().r.x(),
                       chief.value().r.y(), chief.value().r.z(), chief_itrf.r.x(), chief_itrf.r.y(),
                       chief_itrf.r.z())
        << fmt::format("{:.6f},{:.6f},{:.6f},{:.9f},{:.9f},{:.9f},", rel.dr_rtn.x(), rel.dr_rtn.y(),
                       rel.dr_rtn.z(), rel.dv_rtn.x(), rel.dv_rtn.y(), rel.dv_rtn.z())
        << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},", linear[0], linear[1], linear[2], model_error)
        << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.4f}\n", a * roe_t[0],
                       a * roe_t[1], a * roe_t[2], a * roe_t[3], a * roe_t[4], a * roe_t[5],
                       sun_angle);
  }
  if (!csv) return Error{summary.csv.string(), "write failed"};
  return summary;
}

}  // namespace

core::Result<PreviewSummary> run_formation_preview(const PreviewScenario& scenario,
                                                   const std::filesystem::path& out_dir) {
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) return Error{out_dir.string(), "cannot create the output folder: " + ec.message()};

  PreviewSummary summary;
  const double a = scenario.chief_mean.a;
  summary.chief_period_s = core::kTwoPi * std::sqrt(a * a * a / scenario.earth.mu);
  const auto eop = load_eop(scenario.eop_file);
  summary.eop_used = eop.table.has_value();
  summary.eop_note = eop.note;

  auto chief = osculating_state(scenario.chief_mean, scenario.earth);
  if (!chief.ok()) return Error{"chief", chief.error().describe()};
  const Eigen::Vector3d h_hat = chief.value().r.cross(chief.value().v).normalized();
  const Eigen::Vector3d sun_hat = astro::sun_position_gcrf(scenario.epoch).normalized();
  summary.beta_angle_deg = std::asin(h_hat.dot(sun_hat)) / core::kDegToRad;

  for (const auto& f : scenario.formations) {
    auto formation = preview_formation(scenario, f, eop, out_dir);
    if (!formation.ok()) return formation.error();
    summary.formations.push_back(formation.value());
  }
  return summary;
}

}  // namespace visors::preview
