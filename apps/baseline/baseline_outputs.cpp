#include "apps/baseline/baseline_outputs.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/core.h>

#include "visors/core/files/output_file.hpp"

namespace visors::baseline_app {
namespace {

using baseline::EpochRecord;
using baseline::PositionEstimate;
using baseline::SolutionStatus;
using nlohmann::json;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

json estimate_json(const PositionEstimate& e) {
  if (!e.valid) return nullptr;
  return {{"rover_ecef_m", vec(e.r_ecef_m)}, {"baseline_enu_m", vec(e.baseline_enu_m)},
          {"sigma_enu_m", vec(e.sigma_enu_m)}, {"baseline_length_m", e.baseline_enu_m.norm()}};
}

// Mean, standard deviation and largest 3D distance from the mean of a set of ENU positions.
json scatter_json(const std::vector<Eigen::Vector3d>& enu) {
  if (enu.empty()) return nullptr;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : enu) mean += p;
  mean /= static_cast<double>(enu.size());
  Eigen::Vector3d var = Eigen::Vector3d::Zero();
  double max_3d = 0.0;
  for (const auto& p : enu) {
    var += (p - mean).cwiseAbs2();
    max_3d = std::max(max_3d, (p - mean).norm());
  }
  var /= static_cast<double>(enu.size());
  return {{"epochs", enu.size()}, {"mean_enu_m", vec(mean)}, {"std_enu_m", vec(var.cwiseSqrt())},
          {"max_3d_from_mean_m", max_3d}};
}

json epoch_statistics(const baseline::BaselineResult& r) {
  std::map<std::string, int> status;
  for (const char* s : {"fix", "partial", "float", "code", "none"}) status[s] = 0;
  int refused = 0;
  std::optional<double> ttff;
  for (const auto& e : r.epochs) {
    ++status[std::string(baseline::to_string(e.status))];
    refused += e.iar == "wrong_fix_refused";
    if (!ttff && e.status == SolutionStatus::kFix) ttff = e.t.seconds_since(r.epochs.front().t);
  }
  const auto n = static_cast<double>(r.epochs.size());
  return {{"epochs_per_status", status},
          {"fix_rate", n > 0 ? status["fix"] / n : 0.0},
          {"fix_or_partial_rate", n > 0 ? (status["fix"] + status["partial"]) / n : 0.0},
          {"fixes_refused_by_residual_check", refused},
          {"time_to_first_fix_s", ttff ? json(*ttff) : json(nullptr)}};
}

json solutions_json(const baseline::BaselineResult& r) {
  std::vector<Eigen::Vector3d> fixed, code, floating;
  for (const auto& e : r.epochs) {
    if (e.status == SolutionStatus::kFix) fixed.push_back(e.solution.baseline_enu_m);
    if (e.code.valid) code.push_back(e.code.baseline_enu_m);
    if (e.floating.valid) floating.push_back(e.floating.baseline_enu_m);
  }
  return {{"final_fixed", estimate_json(r.final_fixed)},
          {"final_float", estimate_json(r.final_float)},
          {"fixed_epochs", scatter_json(fixed)},
          {"float_epochs", scatter_json(floating)},
          {"code_only_epochs", scatter_json(code)}};
}

json events_json(const baseline::BaselineResult& r) {
  json events = json::array();
  for (const auto& ev : r.events) {
    events.push_back({{"gps_time", ev.t.format(core::TimeScale::kGps, 1)}, {"prn", ev.prn},
                      {"frequency", ev.frequency == 0 ? "L1" : "L2"}, {"reason", ev.reason}});
  }
  return events;
}

json settings_json(const BaselineRun& run) {
  const auto& s = run.settings;
  return {{"mode", baseline::to_string(s.position_model)},
          {"frequencies", baseline::to_string(s.frequencies)},
          {"ambiguity_resolution", baseline::to_string(s.ambiguity_mode)},
          {"elevation_mask_deg", s.elevation_mask_deg},
          {"phase_sigma_m", {s.phase_sigma_m, s.phase_sigma_elevation_m}},
          {"code_to_phase_sigma", s.code_to_phase_sigma},
          {"min_success_rate", s.acceptance.min_success_rate},
          {"min_ratio", s.acceptance.min_ratio},
          {"partial_fixing", s.acceptance.partial},
          {"hold_variance_cyc2", s.hold_variance_cyc2}};
}

std::string csv_row(const EpochRecord& e) {
  const auto& s = e.solution;
  const auto v = [](const PositionEstimate& p, int i) { return p.valid ? p.baseline_enu_m(i) : NAN; };
  return fmt::format(
      "{},{},{:.3f},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{},{},{},{},{:.3f},{:.6f},{},"
      "{:.4f},{:.4f},{:.4f},{:.3f},{:.3f},{:.3f}\n",
      e.t.format(core::TimeScale::kGps, 3), e.t.week(), e.t.seconds_of_week(), baseline::to_string(e.status),
      s.r_ecef_m.x(), s.r_ecef_m.y(), s.r_ecef_m.z(), s.baseline_enu_m.x(), s.baseline_enu_m.y(), s.baseline_enu_m.z(),
      s.sigma_enu_m.x(), s.sigma_enu_m.y(), s.sigma_enu_m.z(), e.satellites, e.phase_rows, e.ambiguities, e.fixed,
      e.ratio, e.success_rate, e.iar, v(e.floating, 0), v(e.floating, 1), v(e.floating, 2), v(e.code, 0), v(e.code, 1),
      v(e.code, 2));
}

core::Result<bool> write_csv(const std::filesystem::path& path, const baseline::BaselineResult& r) {
  auto file = core::files::open_output_file(path);
  if (!file) return core::Error{path.string(), "cannot be written"};
  std::fputs("gps_time,gps_week,gps_tow_s,status,x_m,y_m,z_m,east_m,north_m,up_m,sigma_east_m,sigma_north_m,"
             "sigma_up_m,satellites,dd_phase,dd_ambiguities,fixed,ratio,success_rate,iar,float_east_m,"
             "float_north_m,float_up_m,code_east_m,code_north_m,code_up_m\n",
             file.get());
  for (const auto& e : r.epochs) std::fputs(csv_row(e).c_str(), file.get());
  if (std::fflush(file.get()) != 0 || std::ferror(file.get())) return core::Error{path.string(), "write failed"};
  return true;
}

}  // namespace

json baseline_summary(const BaselineRun& run) {
  const auto& r = run.result;
  json inputs = {{"rover", run.options.rover}, {"base", run.options.base}, {"nav", run.options.nav},
                 {"base_ecef_m", vec(run.inputs.base_ecef_m)},
                 {"rover_types", {run.inputs.rover.phase_type, run.inputs.rover.code_type}},
                 {"base_types", {run.inputs.base.phase_type, run.inputs.base.code_type}},
                 {"broadcast_ionosphere", run.inputs.ionosphere.has_value()}};
  return {{"inputs", inputs},
          {"settings", settings_json(run)},
          {"epochs", {{"rover", r.rover_epochs}, {"base", r.base_epochs}, {"paired", r.epochs.size()},
                      {"rover_without_base", r.rover_unpaired}, {"base_without_rover", r.base_unpaired}}},
          {"statistics", epoch_statistics(r)},
          {"solutions", solutions_json(r)},
          {"rejected", r.rejected_counts},
          {"events", events_json(r)},
          {"wall_time_s", run.wall_time_s}};
}

core::Result<bool> write_outputs(const BaselineRun& run, const json& summary) {
  const std::filesystem::path dir = run.options.out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return core::Error{dir.string(), "cannot be created: " + ec.message()};
  if (auto csv = write_csv(dir / "baseline.csv", run.result); !csv) return csv;
  std::ofstream(dir / "summary.json") << summary.dump(2) << '\n';
  std::ofstream(dir / "baseline.html") << baseline_page(run, summary);
  if (!std::filesystem::exists(dir / "baseline.html")) return core::Error{(dir / "baseline.html").string(), "cannot be written"};
  return true;
}

void print_overview(const BaselineRun& run, const json& s) {
  const auto& st = s["statistics"];
  fmt::print("visors baseline: {} paired epochs ({} {} {}), fix {} / partial {} / float {} / code {} / none {}, fix rate {:.1f} %\n",
             s["epochs"]["paired"].get<int>(), baseline::to_string(run.settings.position_model),
             baseline::to_string(run.settings.frequencies), baseline::to_string(run.settings.ambiguity_mode),
             st["epochs_per_status"]["fix"].get<int>(), st["epochs_per_status"]["partial"].get<int>(),
             st["epochs_per_status"]["float"].get<int>(),
             st["epochs_per_status"]["code"].get<int>(), st["epochs_per_status"]["none"].get<int>(),
             100.0 * st["fix_rate"].get<double>());
  const auto& fixed = s["solutions"]["final_fixed"];
  const auto& best = fixed.is_null() ? s["solutions"]["final_float"] : fixed;
  if (!best.is_null()) {
    const auto& b = best["baseline_enu_m"];
    const auto& sg = best["sigma_enu_m"];
    fmt::print("  last {} solution: baseline ENU {:.4f} {:.4f} {:.4f} m (sigma {:.4f} {:.4f} {:.4f} m)\n",
               fixed.is_null() ? "float" : "fixed", b[0].get<double>(), b[1].get<double>(), b[2].get<double>(),
               sg[0].get<double>(), sg[1].get<double>(), sg[2].get<double>());
  }
  fmt::print("  wrote {}/baseline.csv, summary.json, baseline.html ({:.2f} s)\n", run.options.out, run.wall_time_s);
}

}  // namespace visors::baseline_app
