#include "visors/dynamics/force_model_config.hpp"

namespace visors::dynamics {

ForceModelConfig ForceModelConfig::truth() {
  ForceModelConfig c;
  c.gravity = {"gravity/GGM05S_d90.gfc", 60, 60, true};
  c.drag.atmosphere = AtmosphereKind::kNrlmsise00;
  c.drag.space_weather = "space_weather/SW-Observed_2024-07-01_2025-01-31.csv";
  c.srp.shadow = ShadowModel::kConical;
  c.earth_frame = {"eop/finals2000A_2024-07-01_2025-01-31.txt", 60.0};
  return c;
}

ForceModelConfig ForceModelConfig::onboard() {
  ForceModelConfig c;
  c.gravity = {"gravity/GGM01S.gfc", 20, 20, true};
  c.drag.atmosphere = AtmosphereKind::kHarrisPriester;
  // Mean solar activity: the Harris-Priester table's level.
  c.drag.activity.f107 = 150.0;
  c.drag.activity.f107a = 150.0;
  c.drag.activity.ap = 15.0;
  c.earth_frame = {"", 600.0};
  return c;
}

ForceModelConfig ForceModelConfig::gravity_only(int degree, int order) {
  ForceModelConfig c = onboard();
  c.gravity.degree = degree;
  c.gravity.order = order;
  c.drag.enabled = false;
  c.srp.enabled = false;
  c.sun = false;
  c.moon = false;
  return c;
}

}  // namespace visors::dynamics
