#include "visors/dynamics/gravity_field.hpp"

namespace visors::dynamics {
namespace {

// GGM05S fully normalised coefficients, degrees 0..8, as published by ICGEM (model GGM05S,
// Tapley et al. 2013; the values of data/gravity/GGM05S_d90.gfc). {n, m, C̄, S̄}.
struct EmbeddedCoefficient {
  int n;
  int m;
  double c;
  double s;
};
constexpr EmbeddedCoefficient kGgm05sDegree8[] = {
    {0, 0, 1.000000000000e+00, 0.0},
    {2, 0, -4.841694573200e-04, 0.0},
    {2, 1, -3.183715553800e-10, 1.432170507577e-09},
    {2, 2, 2.439374598584e-06, -1.400287554684e-06},
    {3, 0, 9.571739577330e-07, 0.0},
    {3, 1, 2.030447717179e-06, 2.482356432550e-07},
    {3, 2, 9.047749228904e-07, -6.190079043255e-07},
    {3, 3, 7.212923883714e-07, 1.414398684143e-06},
    {4, 0, 5.399853533873e-07, 0.0},
    {4, 1, -5.361786622025e-07, -4.735770747989e-07},
    {4, 2, 3.504917311439e-07, 6.625021916813e-07},
    {4, 3, 9.908574388920e-07, -2.009475655717e-07},
    {4, 4, -1.884904077578e-07, 3.088195368429e-07},
    {5, 0, 6.865295795743e-08, 0.0},
    {5, 1, -6.291443819205e-08, -9.434270766598e-08},
    {5, 2, 6.520588473561e-07, -3.233441597218e-07},
    {5, 3, -4.518301141322e-07, -2.149419060333e-07},
    {5, 4, -2.953263261931e-07, 4.981208263958e-08},
    {5, 5, 1.748131765178e-07, -6.693584989617e-07},
    {6, 0, -1.499751867421e-07, 0.0},
    {6, 1, -7.594321204929e-08, 2.652551908729e-08},
    {6, 2, 4.863521615052e-08, -3.737703607081e-07},
    {6, 3, 5.724955887621e-08, 8.973058346979e-09},
    {6, 4, -8.599819097325e-08, -4.714267493844e-07},
    {6, 5, -2.671626945449e-07, -5.364950882609e-07},
    {6, 6, 9.476848430257e-09, -2.373833884330e-07},
    {7, 0, 9.050171042435e-08, 0.0},
    {7, 1, 2.808863583475e-07, 9.515955090460e-08},
    {7, 2, 3.303956821278e-07, 9.302002881123e-08},
    {7, 3, 2.504641688786e-07, -2.170971014715e-07},
    {7, 4, -2.749881969827e-07, -1.240495513726e-07},
    {7, 5, 1.646915418368e-09, 1.793002894971e-08},
    {7, 6, -3.587987635262e-07, 1.517944882424e-07},
    {7, 7, 1.520997456997e-09, 2.410335977031e-08},
    {8, 0, 4.947888296780e-08, 0.0},
    {8, 1, 2.314094409863e-08, 5.890481663055e-08},
    {8, 2, 8.002052911833e-08, 6.529987615773e-08},
    {8, 3, -1.936026267135e-08, -8.594160265972e-08},
    {8, 4, -2.443452151910e-07, 6.981209020667e-08},
    {8, 5, -2.570144866932e-08, 8.920688936506e-08},
    {8, 6, -6.597081184471e-08, 3.089447805354e-07},
    {8, 7, 6.725636222065e-08, 7.486454436427e-08},
    {8, 8, -1.240327183045e-07, 1.205413610615e-07},
};

}  // namespace

const char* to_string(TideSystem tide_system) {
  switch (tide_system) {
    case TideSystem::kZeroTide: return "zero_tide";
    case TideSystem::kTideFree: return "tide_free";
    case TideSystem::kMeanTide: return "mean_tide";
    case TideSystem::kUnknown: break;
  }
  return "unknown";
}

GravityField embedded_gravity_field() {
  GravityField field;
  field.model_name = "GGM05S (embedded, degree/order 8)";
  field.gm = 3.986004415e14;  // [m^3/s^2], GGM05S header
  field.radius = 6378136.3;   // [m], GGM05S header
  field.max_degree = 8;
  field.tide_system = TideSystem::kZeroTide;
  field.c_bar.assign(GravityField::coefficient_count(8), 0.0);
  field.s_bar.assign(GravityField::coefficient_count(8), 0.0);
  for (const EmbeddedCoefficient& k : kGgm05sDegree8) {
    field.c_bar[GravityField::index(k.n, k.m)] = k.c;
    field.s_bar[GravityField::index(k.n, k.m)] = k.s;
  }
  return field;
}

}  // namespace visors::dynamics
