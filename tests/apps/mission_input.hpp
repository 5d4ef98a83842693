#pragma once
// Test support for the tool tests: JSON fragments of the mission chief (mean elements: a = R_E +
// 500 km, e = 0.004, i = 97.8 deg, RAAN 157.5 deg, argp 90 deg, M 0; angles in rad).

#include <string>

namespace visors::test {

inline std::string mission_chief_json() {
  return R"("chief":{"a":6878136.3,"e":0.004,"i":1.7069320084504542,"raan":2.748893571891069,)"
         R"("argp":1.5707963267948966,"M":0.0})";
}

/// "{" + the mission chief + `rest` (which starts with a comma and closes the object). Built with
/// += (operator+ chains on temporaries trip GCC 12's -Wrestrict).
inline std::string with_mission_chief(const std::string& rest) {
  std::string s = "{";
  s += mission_chief_json();
  s += rest;
  return s;
}

}  // namespace visors::test
