#include "visors/astro/control_input_matrix.hpp"

#include <cmath>

#include "visors/astro/kepler_equation.hpp"
#include "visors/astro/relative_orbital_elements.hpp"

namespace visors::astro {
namespace {

ControlInputMatrix eccentric(const KeplerianElements& chief, double mu, bool with_lambda_terms) {
  using namespace roe;
  const double a = chief.a;
  const double e = chief.e;
  const double n = std::sqrt(mu / (a * a * a));
  const double eta2 = (1.0 - e) * (1.0 + e);
  const double eta = std::sqrt(eta2);
  const double nu = true_from_mean(chief.M, e);
  const double cn = std::cos(nu);
  const double sn = std::sin(nu);
  const double k = 1.0 + e * cn;
  const double theta = chief.argp + nu;
  const double ct = std::cos(theta);
  const double st = std::sin(theta);
  const double ex = e * std::cos(chief.argp);
  const double ey = e * std::sin(chief.argp);
  const double tan_i = std::tan(chief.i);

  ControlInputMatrix g = ControlInputMatrix::Zero();
  g(kDa, 0) = 2.0 * e * sn / eta;
  g(kDa, 1) = 2.0 * k / eta;
  g(kDlambda, 0) = -2.0 * eta2 / k;
  if (with_lambda_terms) {
    // dlambda = dM + domega + cos i dRAAN; the GVE of M carries (eta/e)(...) terms whose O(1/e)
    // parts cancel against domega, leaving these O(e) remainders (with (1-eta)/e = e/(1+eta)).
    g(kDlambda, 0) += -eta * e * cn / (1.0 + eta);
    g(kDlambda, 1) = eta * e * (2.0 + e * cn) * sn / ((1.0 + eta) * k);
  }
  g(kDex, 0) = eta * st;
  g(kDex, 1) = eta * ((2.0 + e * cn) * ct + ex) / k;
  g(kDex, 2) = eta * ey * st / (k * tan_i);
  g(kDey, 0) = -eta * ct;
  g(kDey, 1) = eta * ((2.0 + e * cn) * st + ey) / k;
  g(kDey, 2) = -eta * ex * st / (k * tan_i);
  g(kDix, 2) = eta * ct / k;
  g(kDiy, 2) = eta * st / k;
  return g / (a * n);
}

}  // namespace

ControlInputMatrix control_input_matrix(const KeplerianElements& chief, double mu) {
  return eccentric(chief, mu, true);
}

ControlInputMatrix control_input_matrix_without_lambda_terms(const KeplerianElements& chief,
                                                             double mu) {
  return eccentric(chief, mu, false);
}

ControlInputMatrix control_input_matrix_near_circular(const KeplerianElements& chief, double mu) {
  using namespace roe;
  const double a = chief.a;
  const double n = std::sqrt(mu / (a * a * a));
  const double u = chief.argp + chief.M;
  const double cu = std::cos(u);
  const double su = std::sin(u);
  ControlInputMatrix g = ControlInputMatrix::Zero();
  g(kDa, 1) = 2.0;
  g(kDlambda, 0) = -2.0;
  g(kDex, 0) = su;
  g(kDex, 1) = 2.0 * cu;
  g(kDey, 0) = -cu;
  g(kDey, 1) = 2.0 * su;
  g(kDix, 2) = cu;
  g(kDiy, 2) = su;
  return g / (a * n);
}

}  // namespace visors::astro
