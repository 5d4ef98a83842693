#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

double unit(int i) {
  const int within = i < state::kGraphicAmbiguities ? i % kSpacecraftStates : -1;
  if (within >= 3 && within < 6) return state::kVelocityUnit;
  if (within >= 6 && within < 9) return state::kEmpiricalUnit;
  if (within >= 10 && within < 13) return state::kPhaseCenterUnit;
  if (i >= state::kSdMultipath) return state::kMultipathUnit;
  return 1.0;  // positions, clocks [m]; B [m]; N [cycles]
}

}  // namespace visors::nav
