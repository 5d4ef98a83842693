#pragma once
// A synthetic run directory for the report tests, written into a per-process temporary folder
// (CTest runs test cases as parallel processes) and removed afterwards. The formation follows
// the linear near-circular relative motion of a passively safe standby orbit (parallel relative
// e- and i-vectors), with a slow relative-perigee drift, an osculating ripple at twice the orbit
// rate, a mode sequence standby -> transfer -> science -> transfer -> standby, a few observations
// in the science stretch and a handful of events.

#include <cstddef>
#include <filesystem>
#include <string>

namespace visors::test {

struct SyntheticRunOptions {
  double orbits = 3.0;
  double step_s = 10.0;
  bool observations = true;        // false: no observations.csv
  bool events = true;              // false: no events.csv
  std::size_t filler_events = 0;   // extra "plan" events appended to the log
  std::string detail = "escape burn \"B1\", dv <0.01 m/s> & <script>alert('x')</script>";
};

class SyntheticRun {
 public:
  explicit SyntheticRun(const SyntheticRunOptions& options = {});
  ~SyntheticRun();
  SyntheticRun(const SyntheticRun&) = delete;
  SyntheticRun& operator=(const SyntheticRun&) = delete;

  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }
  [[nodiscard]] std::size_t rows() const { return rows_; }

 private:
  void write_timeseries(const SyntheticRunOptions& options);
  void write_observations() const;
  void write_events(const SyntheticRunOptions& options) const;
  void write_summary(const SyntheticRunOptions& options) const;

  std::filesystem::path dir_;
  std::size_t rows_ = 0;
  double duration_s_ = 0.0;
};

/// The chief's mean motion [rad/s] and orbit period [s] used by the synthetic run (a 500 km
/// circular orbit).
double synthetic_mean_motion();
double synthetic_period_s();

}  // namespace visors::test
