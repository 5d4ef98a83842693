#include "visors/sim/run_recorder.hpp"

#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "visors/core/constants.hpp"
#include "visors/report/run_directory.hpp"

namespace visors::sim {

namespace {

core::Result<core::files::OutputFile> open_file(const std::filesystem::path& path) {
  core::files::OutputFile f = core::files::open_output_file(path);
  if (!f) return core::Error{"output file " + path.string(), "cannot be written"};
  return f;
}

template <std::size_t N>
void write_header(std::FILE* f, const std::array<std::string_view, N>& columns, bool more = false) {
  for (std::size_t i = 0; i < N; ++i) std::fprintf(f, "%s%.*s", i ? "," : "", static_cast<int>(columns[i].size()), columns[i].data());
  std::fputc(more ? ',' : '\n', f);
}

// CSV quoting of free text: doubled quotes inside double quotes.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

}  // namespace

core::Result<RunRecorder> RunRecorder::open(const std::filesystem::path& dir, const std::string& scenario_toml) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return core::Error{"--out " + dir.string(), "cannot create the directory (" + ec.message() + ")"};
  {
    std::ofstream scenario(dir / std::string(report::kScenarioFile));
    if (!scenario) return core::Error{"output file " + (dir / std::string(report::kScenarioFile)).string(), "cannot be written"};
    scenario << scenario_toml;
  }
  RunRecorder r;
  r.dir_ = dir;
  auto ts = open_file(dir / std::string(report::kTimeseriesFile));
  if (!ts.ok()) return ts.error();
  r.timeseries_ = std::move(ts).value();
  auto obs = open_file(dir / std::string(report::kObservationsFile));
  if (!obs.ok()) return obs.error();
  r.observations_ = std::move(obs).value();
  auto ev = open_file(dir / std::string(report::kEventsFile));
  if (!ev.ok()) return ev.error();
  r.events_ = std::move(ev).value();
  auto samples = open_file(dir / std::string(report::kAlignmentSamplesFile));
  if (!samples.ok()) return samples.error();
  r.alignment_samples_ = std::move(samples).value();
  write_header(r.timeseries_.get(), report::kTimeseriesColumns);
  write_header(r.observations_.get(), report::kObservationColumns, true);
  write_header(r.observations_.get(), report::kObservationPointingColumns, true);
  write_header(r.observations_.get(), report::kObservationBudgetColumns);
  write_header(r.events_.get(), report::kEventColumns);
  write_header(r.alignment_samples_.get(), report::kAlignmentSampleColumns);
  return r;
}

core::Result<bool> RunRecorder::open_navigation() {
  auto file = open_file(dir_ / std::string(report::kNavigationFile));
  if (!file.ok()) return file.error();
  navigation_ = std::move(file).value();
  write_header(navigation_.get(), report::kNavigationColumns);
  return true;
}

void RunRecorder::navigation(double t_s, std::string_view spacecraft, const NavigationSample& s, double fixed_fraction,
                             bool in_slew, bool in_observation) {
  if (!navigation_ || !s.valid) return;
  std::string line = fmt::format("{:.17g},{},{},{:.6g}", t_s, spacecraft, s.fixed ? 1 : 0, fixed_fraction);
  for (const Eigen::Vector3d* v : {&s.position_rtn_m, &s.antenna_rtn_m, &s.velocity_rtn_mps, &s.sigma_rtn_m,
                                   &s.empirical_dsc_rtn_mps2, &s.empirical_osc_rtn_mps2}) {
    for (int i = 0; i < 3; ++i) line += fmt::format(",{:.9g}", (*v)(i));
  }
  line += fmt::format(",{},{}\n", in_slew ? 1 : 0, in_observation ? 1 : 0);
  std::fputs(line.c_str(), navigation_.get());
}

void RunRecorder::timeseries(const TimeseriesRow& row) {
  std::string line = fmt::format("{:.17g},{},{}", row.t_s, row.mode, row.active);
  for (int i = 0; i < 6; ++i) line += fmt::format(",{:.17g}", row.roe_mean_m(i));
  for (int i = 0; i < 6; ++i) line += fmt::format(",{:.17g}", row.roe_osc_m(i));
  for (int i = 0; i < 3; ++i) line += fmt::format(",{:.17g}", row.r_rtn_m(i));
  for (int i = 0; i < 3; ++i) line += fmt::format(",{:.17g}", row.v_rtn_mps(i));
  line += fmt::format(",{:.17g},{:.17g},", row.sep_rn_m, row.sep_3d_m);
  if (row.has_margin) line += fmt::format("{:.17g}", row.safety_margin_m);
  line += fmt::format(",{:.17g},{:.17g},{:.9g},{:.9g},{:.9g},", row.dv_dsc_mps, row.dv_osc_mps, row.drag_area_m2[0],
                      row.drag_area_m2[1], row.drag_t_difference_mps2);
  if (row.has_drag_estimate) line += fmt::format("{:.9g}", row.drag_t_estimate_mps2);
  line += '\n';
  std::fputs(line.c_str(), timeseries_.get());
}

static_assert(report::kObservationBudgetColumns.size() == 5 * kBudgetTerms, "five budget columns per term");

void RunRecorder::observation(const AlignmentResult& result, bool success, const std::optional<ErrorBudget>& budget) {
  const Eigen::Vector2d pointing_arcsec = result.payload_pointing_rad / core::kArcsecToRad;
  std::string line = fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{},{:.6g},{:.6g}", result.index, result.t_s, result.lateral_error_m,
                                 result.lateral_velocity_mps, result.focus_error_m, success ? 1 : 0, pointing_arcsec.x(),
                                 pointing_arcsec.y());
  for (int i = 0; i < kBudgetTerms; ++i) {
    if (!budget) {
      line += ",,,,,";
      continue;
    }
    const BudgetComponents& c = (*budget)[static_cast<std::size_t>(i)];
    line += fmt::format(",{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", c.x_m, c.y_m, c.focus_m, c.velocity_x_mps, c.velocity_y_mps);
  }
  line += '\n';
  std::fputs(line.c_str(), observations_.get());
}

void RunRecorder::alignment_sample(int index, double t_s, const core::StateVector& dsc_gcrf, const Eigen::Quaterniond& q_dsc,
                                   const core::StateVector& osc_gcrf, const Eigen::Quaterniond& q_osc,
                                   const Eigen::Vector3d& target_unit_gcrf, const AlignmentSample& sample) {
  std::string line = fmt::format("{},{:.17g}", index, t_s);
  const auto add = [&line](const Eigen::Vector3d& v) {
    for (int i = 0; i < 3; ++i) line += fmt::format(",{:.17g}", v(i));
  };
  const auto add_q = [&line](const Eigen::Quaterniond& q) { line += fmt::format(",{:.17g},{:.17g},{:.17g},{:.17g}", q.w(), q.x(), q.y(), q.z()); };
  add(dsc_gcrf.r);
  add(dsc_gcrf.v);
  add_q(q_dsc);
  add(osc_gcrf.r);
  add(osc_gcrf.v);
  add_q(q_osc);
  add(target_unit_gcrf);
  line += fmt::format(",{:.17g},{:.17g},{:.17g}\n", sample.lateral_m, sample.lateral_velocity_mps, sample.focus_signed_m);
  std::fputs(line.c_str(), alignment_samples_.get());
}

void RunRecorder::event(double t_s, std::string_view spacecraft, std::string_view kind, std::string_view detail) {
  std::fputs(fmt::format("{:.17g},{},{},{}\n", t_s, spacecraft, kind, quoted(detail)).c_str(), events_.get());
}

core::Result<bool> RunRecorder::flight_config(const nlohmann::json& config) const {
  const auto path = dir_ / std::string(report::kFlightConfigFile);
  std::ofstream out(path);
  if (!out) return core::Error{"output file " + path.string(), "cannot be written"};
  out << config.dump(2) << '\n';
  return true;
}

core::Result<bool> RunRecorder::finish(const nlohmann::json& summary) {
  timeseries_.reset();
  observations_.reset();
  events_.reset();
  navigation_.reset();
  alignment_samples_.reset();
  const auto path = dir_ / std::string(report::kSummaryFile);
  std::ofstream out(path);
  if (!out) return core::Error{"output file " + path.string(), "cannot be written"};
  out << summary.dump(2) << '\n';
  return true;
}

}  // namespace visors::sim
