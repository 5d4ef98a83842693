#include "visors/baseline/receiver_observables.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "visors/gnss/files/rinex_obs_codes.hpp"

namespace visors::baseline {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::array<std::vector<const char*>, kFrequencies> kPhasePreference = {
    std::vector<const char*>{"L1C", "L1W", "L1P", "L1X"},
    std::vector<const char*>{"L2W", "L2P", "L2X", "L2L", "L2S", "L2C"}};
const std::array<std::vector<const char*>, kFrequencies> kCodePreference = {
    std::vector<const char*>{"C1C", "C1W", "C1P", "C1X"},
    std::vector<const char*>{"C2W", "C2P", "C2X", "C2L", "C2S", "C2C"}};

// The file's types as RINEX 3 codes ("" for a type that has none).
std::vector<std::string> rinex3_codes(const gnss::files::ObservationFile& file) {
  std::vector<std::string> codes;
  for (const auto& type : file.header.observation_types) {
    if (file.version < 3.0) {
      codes.push_back(gnss::files::rinex2_gps_observation_code(type).value_or(""));
    } else {
      codes.push_back(type);
    }
  }
  return codes;
}

// Index of the first preferred code present, or -1.
int find_type(const std::vector<std::string>& codes, const std::vector<const char*>& preference) {
  for (const char* wanted : preference) {
    for (std::size_t i = 0; i < codes.size(); ++i) {
      if (codes[i] == wanted) return static_cast<int>(i);
    }
  }
  return -1;
}

double value_or_nan(const gnss::files::SatelliteObservations& s, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= s.values.size()) return kNaN;
  const auto& v = s.values[static_cast<std::size_t>(index)].value;
  return v.has_value() && std::isfinite(*v) ? *v : kNaN;
}

bool lli_slip(const gnss::files::SatelliteObservations& s, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= s.values.size()) return false;
  return (s.values[static_cast<std::size_t>(index)].lli & 1) != 0;
}

// RINEX 3 LLI bit 1: half-cycle ambiguity / slip possible. (RINEX 2's bit 1 means an opposite
// wavelength factor instead, so it is read for RINEX 3 only.)
bool lli_half_cycle(const gnss::files::SatelliteObservations& s, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= s.values.size()) return false;
  return (s.values[static_cast<std::size_t>(index)].lli & 2) != 0;
}

}  // namespace

core::Result<ReceiverObservables> extract_observables(const gnss::files::ObservationFile& file, const std::string& name) {
  const auto codes = rinex3_codes(file);
  std::array<int, kFrequencies> phase{}, code{};
  ReceiverObservables out;
  for (int f = 0; f < kFrequencies; ++f) {
    phase[static_cast<std::size_t>(f)] = find_type(codes, kPhasePreference[static_cast<std::size_t>(f)]);
    code[static_cast<std::size_t>(f)] = find_type(codes, kCodePreference[static_cast<std::size_t>(f)]);
    const auto fi = static_cast<std::size_t>(f);
    if (phase[fi] >= 0) out.phase_type[fi] = file.header.observation_types[static_cast<std::size_t>(phase[fi])];
    if (code[fi] >= 0) out.code_type[fi] = file.header.observation_types[static_cast<std::size_t>(code[fi])];
  }
  if (phase[0] < 0 || code[0] < 0) {
    return core::Error{name + ": observation types", "needs an L1 carrier phase and an L1 pseudorange (L1/C1 or L1C/C1C)"};
  }
  out.epochs.reserve(file.epochs.size());
  for (const auto& epoch : file.epochs) {
    ReceiverEpoch e;
    e.t = epoch.t;
    e.satellites.reserve(epoch.satellites.size());
    for (const auto& s : epoch.satellites) {
      SatelliteObservables o;
      o.prn = s.prn;
      for (std::size_t f = 0; f < kFrequencies; ++f) {
        o.phase_cyc[f] = value_or_nan(s, phase[f]);
        o.code_m[f] = value_or_nan(s, code[f]);
        o.loss_of_lock[f] = lli_slip(s, phase[f]);
        o.half_cycle[f] = file.version >= 3.0 && lli_half_cycle(s, phase[f]);
      }
      e.satellites.push_back(o);
    }
    out.epochs.push_back(std::move(e));
  }
  return out;
}

}  // namespace visors::baseline
