#pragma once
// The observables a baseline needs, taken out of a RINEX observation file (2.x or 3.x): per
// epoch and GPS satellite, carrier phase [cycles] and pseudorange [m] on L1 and L2, and the
// loss-of-lock flag of each phase. Which RINEX type feeds which observable, in order of
// preference (RINEX 2 codes are first mapped to RINEX 3 by rinex2_gps_observation_code):
//   L1 phase: L1C L1W L1P L1X      L1 code: C1C C1W C1P C1X
//   L2 phase: L2W L2P L2X L2L L2S L2C   L2 code: C2W C2P C2X C2L C2S C2C
// (C/A tracking first on L1, the P(Y) tracking first on L2: the pairs geodetic receivers of the
// pre-L2C era record, like the GSI files' L1 C1 L2 P2.) Mixing trackings within one frequency is
// avoided: one type per observable for the whole file.

#include <array>
#include <string>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"

namespace visors::baseline {

inline constexpr int kFrequencies = 2;  // L1, L2

struct SatelliteObservables {
  int prn = 0;
  std::array<double, kFrequencies> phase_cyc{};  // NaN when absent
  std::array<double, kFrequencies> code_m{};     // NaN when absent
  std::array<bool, kFrequencies> loss_of_lock{};  // LLI bit 0 on the phase
  std::array<bool, kFrequencies> half_cycle{};    // LLI bit 1 on the phase, RINEX 3: half-cycle ambiguity
};

struct ReceiverEpoch {
  core::GpsTime t;  // receiver time tag
  std::vector<SatelliteObservables> satellites;
};

struct ReceiverObservables {
  std::array<std::string, kFrequencies> phase_type, code_type;  // the file's types used ("" none)
  std::vector<ReceiverEpoch> epochs;
};

/// The observables of `file` (`name` for messages). Errors: no L1 phase or no L1 code type
/// (field "<name>: observation types").
core::Result<ReceiverObservables> extract_observables(const gnss::files::ObservationFile& file, const std::string& name);

}  // namespace visors::baseline
