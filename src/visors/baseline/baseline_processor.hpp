#pragma once
// Post-processed differential GPS between a rover and a base receiver of known position: pairs
// the two files' epochs, models both receivers' signals, computes each epoch's code-only (DD
// pseudorange least-squares) solution, detects cycle slips (loss-of-lock indicator of either
// receiver, geometry-free jump of either receiver when L2 exists, gaps; the DD innovation gate
// is the filter's), and runs the float filter with ambiguity resolution (baseline_filter.hpp).
// Everything that is not used is counted with its reason.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "visors/baseline/baseline_filter.hpp"
#include "visors/baseline/baseline_settings.hpp"
#include "visors/baseline/receiver_observables.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/klobuchar.hpp"

namespace visors::baseline {

struct BaselineInputs {
  ReceiverObservables rover;
  ReceiverObservables base;
  gnss::EphemerisSet ephemerides;
  std::optional<gnss::KlobucharCoefficients> ionosphere;
  Eigen::Vector3d base_ecef_m = Eigen::Vector3d::Zero();
};

/// A position estimate: rover Earth-fixed, baseline (rover - base) in the base's ENU, 1-sigma.
struct PositionEstimate {
  bool valid = false;
  Eigen::Vector3d r_ecef_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d baseline_enu_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d sigma_enu_m = Eigen::Vector3d::Zero();
};

struct EpochRecord {
  core::GpsTime t;                 // rover time tag
  SolutionStatus status = SolutionStatus::kNone;
  PositionEstimate solution;       // the reported one (fixed, else float, else code)
  PositionEstimate code;           // DD code least squares
  PositionEstimate floating;       // float filter
  int satellites = 0;              // common satellites above the mask
  int phase_rows = 0;              // DD phase measurements used
  Eigen::Index ambiguities = 0;    // DD ambiguities offered to the search
  Eigen::Index fixed = 0;          // integer combinations fixed
  double ratio = 0.0;
  double success_rate = 0.0;
  std::string iar;                 // "fixed", "partial", "float:<reason>", "wrong_fix_refused", "off"
};

struct RejectedEvent {
  core::GpsTime t;
  int prn = 0;
  int frequency = 0;
  std::string reason;
};

struct BaselineResult {
  std::vector<EpochRecord> epochs;
  int rover_epochs = 0, base_epochs = 0;
  int rover_unpaired = 0, base_unpaired = 0;   // epochs without a partner in the other file
  std::map<std::string, long> rejected_counts;  // reason -> satellite-epochs (or slots)
  std::vector<RejectedEvent> events;            // slips and gate failures, in time order
  PositionEstimate final_float;                 // the filter at the last epoch
  PositionEstimate final_fixed;                 // the last full fixed solution (status fix)
};

core::Result<BaselineResult> process_baseline(const BaselineInputs& inputs, const BaselineSettings& settings);

}  // namespace visors::baseline
