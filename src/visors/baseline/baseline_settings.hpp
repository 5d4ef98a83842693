#pragma once
// Settings of the post-processed baseline (`visors baseline`): the processing choices of the
// command line and the stochastic model, each with its default and unit. Defaults follow the
// common practice of short-baseline RTK (RTKLIB 2.4.3's defaults where it has one: elevation-
// dependent sigma a + b / sin(el) with a = b = 3 mm for phase, code/phase sigma ratio 100,
// ratio 3), so results can be compared with that peer on the same data. The mask is 10 deg, not
// RTKLIB's 15: on a one-hour pair a 15 deg mask can leave 5 satellites, too few for a fixed
// kinematic height (tests/baseline/test_baseline_gsi.cpp checks the fixed kinematic epochs
// against the static solution at 10 deg).

#include <string_view>

#include "visors/core/result.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"

namespace visors::baseline {

enum class PositionModel { kStatic, kKinematic };
enum class FrequencySet { kL1, kL1L2 };
enum class AmbiguityMode { kOff, kContinuous, kHold };

/// "static"/"kinematic", "L1"/"L1L2", "off"/"continuous"/"hold".
std::string_view to_string(PositionModel m);
std::string_view to_string(FrequencySet f);
std::string_view to_string(AmbiguityMode m);

struct BaselineSettings {
  PositionModel position_model = PositionModel::kStatic;
  FrequencySet frequencies = FrequencySet::kL1L2;
  AmbiguityMode ambiguity_mode = AmbiguityMode::kContinuous;
  double elevation_mask_deg = 10.0;       // at both receivers [deg], [0, 90) (file comment)
  double phase_sigma_m = 0.003;           // a of sigma = a + b / sin(el), undifferenced phase [m]
  double phase_sigma_elevation_m = 0.003;  // b [m]
  double code_to_phase_sigma = 100.0;     // code sigma / phase sigma [-]
  double initial_ambiguity_sigma_cyc = 30.0;  // of a newly (re)initialised SD ambiguity [cycles]
  double ambiguity_noise_cyc_per_sqrt_s = 1e-4;  // random walk of the SD ambiguities [cycles/sqrt(s)]
  double kinematic_position_sigma_m = 30.0;  // a-priori sigma of the rover each epoch (white noise) [m]
  double slip_geometry_free_m = 0.05;     // geometry-free jump between epochs flagged as a slip [m]
  double max_gap_s = 120.0;               // a longer gap in a satellite's tracking resets it [s]
  double phase_gate_sigma = 5.0;          // DD phase innovation gate, in innovation sigmas [-]
  double hold_variance_cyc2 = 0.001;      // fix-and-hold pseudo-measurement variance [cycles^2]
  double epoch_tolerance_s = 0.1;         // rover and base time tags paired within this [s]
  nav::AcceptanceSettings acceptance{};   // IAR acceptance (success rate 0.999 and ratio 3)
};

/// Every value checked; the error names the field.
core::Result<BaselineSettings> validate(const BaselineSettings& settings);

}  // namespace visors::baseline
