#include "visors/control/impulse.hpp"

#include <cmath>
#include <string>

namespace visors::control {

double total_delta_v(const std::vector<Impulse>& impulses) {
  double sum = 0.0;
  for (const Impulse& i : impulses) sum += i.dv_rtn.norm();
  return sum;
}

core::Result<std::vector<Impulse>> validate_impulses(std::vector<Impulse> impulses, double t_min, double t_max) {
  for (std::size_t k = 0; k < impulses.size(); ++k) {
    const std::string name = "impulses[" + std::to_string(k) + "]";
    const Impulse& i = impulses[k];
    if (!std::isfinite(i.t) || i.t < t_min || i.t > t_max) {
      return core::Error{name + ".t", "must be a finite time within the plan's interval"};
    }
    if (k > 0 && i.t < impulses[k - 1].t) return core::Error{name + ".t", "times must not decrease"};
    if (!i.dv_rtn.allFinite()) return core::Error{name + ".dv_rtn", "must be finite"};
  }
  return impulses;
}

}  // namespace visors::control
