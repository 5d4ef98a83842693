#include "synthetic_run.hpp"

#include <atomic>
#include <cmath>
#include <fstream>
#include <string_view>
#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "visors/report/run_directory.hpp"

namespace visors::test {
namespace {

constexpr double kMu = 3.986004418e14;     // m^3/s^2
constexpr double kA = 6378137.0 + 500e3;   // m, chief semi-major axis
constexpr double kPi = 3.14159265358979323846;
constexpr double kPerigeeDrift = 6.0e-7;   // rad/s, relative e-vector rotation under J2 (order of magnitude)
constexpr double kRipple = 5.0;            // m, osculating minus mean amplitude

std::atomic<int> g_counter{0};

// The mode at fraction f of the run.
const char* mode_at(double f) {
  if (f < 0.35) return "standby";
  if (f < 0.45) return "transfer_to_science";
  if (f < 0.75) return "science";
  if (f < 0.85) return "transfer_to_standby";
  return "standby";
}

std::string csv_quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

}  // namespace

double synthetic_mean_motion() { return std::sqrt(kMu / (kA * kA * kA)); }
double synthetic_period_s() { return 2.0 * kPi / synthetic_mean_motion(); }

SyntheticRun::SyntheticRun(const SyntheticRunOptions& options)
    : dir_(std::filesystem::temp_directory_path() /
           fmt::format("visors_report_test_{}_{}", ::getpid(), g_counter++)) {
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
  duration_s_ = options.orbits * synthetic_period_s();
  write_timeseries(options);
  if (options.observations) write_observations();
  if (options.events) write_events(options);
  write_summary(options);
}

SyntheticRun::~SyntheticRun() {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

void SyntheticRun::write_timeseries(const SyntheticRunOptions& options) {
  std::ofstream out(dir_ / report::kTimeseriesFile);
  std::string header;
  for (const auto column : report::kTimeseriesColumns) {
    if (!header.empty()) header += ',';
    header += column;
  }
  out << header << '\n';
  const double n = synthetic_mean_motion();
  const auto samples = static_cast<std::size_t>(std::floor(duration_s_ / options.step_s)) + 1;
  double dv_dsc = 0.0;
  double dv_osc = 0.0;
  for (std::size_t k = 0; k < samples; ++k) {
    const double t = static_cast<double>(k) * options.step_s;
    const double u = n * t;
    const double phi = 0.5 * kPi + kPerigeeDrift * t;  // e-vector phase, parallel to the i-vector
    const double ade = 150.0, adix = 0.0, adiy = 150.0, ada = 0.0, adl = 20.0 + 1e-4 * t;
    const double adex = ade * std::cos(phi), adey = ade * std::sin(phi);
    const double rr = ada - adex * std::cos(u) - adey * std::sin(u);
    const double rt = adl + 2.0 * adex * std::sin(u) - 2.0 * adey * std::cos(u);
    const double rn = adix * std::sin(u) - adiy * std::cos(u);
    const double vr = n * (adex * std::sin(u) - adey * std::cos(u));
    const double vt = n * (2.0 * adex * std::cos(u) + 2.0 * adey * std::sin(u));
    const double vn = n * (adix * std::cos(u) + adiy * std::sin(u));
    const double ripple = kRipple * std::sin(2.0 * u);
    if (k > 0 && k % 300 == 0) dv_dsc += 0.002;
    if (k > 0 && k % 450 == 0) dv_osc += 0.001;
    // The margin is recorded only after the first on-board check.
    const std::string margin = k < 60 ? "" : fmt::format("{}", std::hypot(rr, rn) - 20.0);
    // Differential drag: the truth varies over the orbit; the estimate exists after its first baseline.
    const double drag = -1e-7 * (1.0 + 0.5 * std::sin(u));
    const std::string drag_estimate = k < 60 ? "" : fmt::format("{}", -1e-7);
    out << fmt::format("{},{},dsc,{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},0.35,0.35,{},{}\n", t,
                       mode_at(t / duration_s_), ada, adl, adex, adey, adix, adiy, ada + ripple, adl - ripple,
                       adex + 0.5 * ripple, adey - 0.5 * ripple, adix + 0.3 * ripple, adiy + 0.3 * ripple, rr, rt, rn,
                       vr, vt, vn, std::hypot(rr, rn), std::sqrt(rr * rr + rt * rt + rn * rn), margin, dv_dsc,
                       dv_osc, drag, drag_estimate);
  }
  rows_ = samples;
}

void SyntheticRun::write_observations() const {
  std::ofstream out(dir_ / report::kObservationsFile);
  std::string header = "index,t_s,lateral_error_m,lateral_velocity_mps,focus_error_m,success";
  for (const auto column : report::kObservationPointingColumns) header += fmt::format(",{}", column);
  for (const auto column : report::kObservationBudgetColumns) header += fmt::format(",{}", column);
  out << header << '\n';
  // Four observations spread over the science stretch; the second misses the lateral error. The
  // budget along x only: navigation 1 mm, phase centre 2 mm, geometry 3 mm, target direction 0,
  // last burn 0.5 mm, drag prediction 0.3 mm, control other the rest of the lateral error; no
  // velocity.
  const double start = 0.5 * duration_s_;
  const double spacing = 0.05 * duration_s_;
  const double lateral[] = {0.008, 0.031, 0.012, 0.015};
  for (int i = 0; i < 4; ++i) {
    out << fmt::format("{},{},{},{},{},{},20,25", i + 1, start + i * spacing, lateral[i], 1.1e-4 + 1e-5 * i,
                       0.004 + 0.002 * i, lateral[i] <= 0.018 ? 1 : 0);
    for (const double x : {0.001, 0.002, 0.003, 0.0, 0.0005, 0.0003, lateral[i] - 0.0068}) {
      out << fmt::format(",{},0,0,0,0", x);
    }
    out << '\n';
  }
}

void SyntheticRun::write_events(const SyntheticRunOptions& options) const {
  std::ofstream out(dir_ / report::kEventsFile);
  out << "t_s,spacecraft,kind,detail\n";
  out << "0,sim,mode," << csv_quoted("start in standby") << '\n';
  out << fmt::format("{},dsc,mode,{}\n", 0.35 * duration_s_, csv_quoted("standby -> transfer_to_science"));
  out << fmt::format("{},dsc,maneuver,{}\n", 0.36 * duration_s_, csv_quoted("dv = [0.001, 0, 0] m/s, RTN"));
  out << fmt::format("{},dsc,fdir,{}\n", 0.40 * duration_s_, csv_quoted(options.detail));
  out << fmt::format("{},dsc,mode,{}\n", 0.45 * duration_s_, csv_quoted("transfer_to_science -> science"));
  for (std::size_t i = 0; i < options.filler_events; ++i) {
    out << fmt::format("{},osc,plan,{}\n", 0.5 * duration_s_ + static_cast<double>(i), csv_quoted("plan, filler"));
  }
}

void SyntheticRun::write_summary(const SyntheticRunOptions& options) const {
  nlohmann::json modes = {{"manual", 0.0},  {"standby", 0.004},           {"transfer_to_science", 0.01},
                          {"science", 0.002}, {"transfer_to_standby", 0.0}, {"escape", 0.0}, {"total", 0.016}};
  const nlohmann::json summary = {
      {"scenario", "synthetic <test> & \"run\""},
      {"seed", 7},
      {"t0", {{"iso", "2024-10-01T00:00:00"}, {"week", 2334}, {"seconds_of_week", 172800}}},
      {"simulated_s", duration_s_},
      {"wall_s", 1.5},
      {"observations", nlohmann::json::array()},
      {"success_rate", options.observations ? 0.75 : 0.0},
      {"requirements",
       {{"lateral_error_m", 0.018}, {"lateral_velocity_mps", 0.0002}, {"focus_error_m", 0.015}, {"safety_epsilon_m", 5.0}}},
      {"delta_v_mps", {{"dsc", modes}, {"osc", modes}}},
      {"paper_budget_mps",
       {{"standby_per_week", 0.3488}, {"transfer_to_science", 0.4934}, {"transfer_to_standby", 0.4844},
        {"science_per_observation", 0.0048}}},
      {"min_separation_rn_m", 149.5},
      {"min_separation_3d_m", 150.2},
      {"safety_violations", 0},
      {"final_mode", "standby"}};
  std::ofstream(dir_ / report::kSummaryFile) << summary.dump(2) << '\n';
}

}  // namespace visors::test
