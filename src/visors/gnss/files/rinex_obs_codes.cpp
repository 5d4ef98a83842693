#include "visors/gnss/files/rinex_obs_codes.hpp"

namespace visors::gnss::files {

std::optional<std::string> rinex2_gps_observation_code(std::string_view rinex2_code) {
  if (rinex2_code.size() != 2) return std::nullopt;
  const char kind = rinex2_code[0], band = rinex2_code[1];
  if (band != '1' && band != '2' && band != '5') return std::nullopt;
  // The tracking attribute of each band for phase, Doppler and signal strength (file comment).
  const char attribute = band == '1' ? 'C' : band == '2' ? 'W' : 'X';
  switch (kind) {
    case 'L':
    case 'D':
    case 'S':
      return std::string{kind, band, attribute};
    case 'C':  // C1: C/A; C2: L2C (RINEX 2.11); C5: L5
      return std::string{'C', band, band == '1' ? 'C' : 'X'};
    case 'P':  // P code: L1 and L2 only
      if (band == '5') return std::nullopt;
      return std::string{'C', band, 'W'};
    default:
      return std::nullopt;
  }
}

}  // namespace visors::gnss::files
