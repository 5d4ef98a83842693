#pragma once
// The independent gravity oracle of the tests: GeographicLib's SphericalHarmonic (Clenshaw
// summation) loaded with the coefficients of a project GravityField.

#include <vector>

#include <Eigen/Core>
#include <GeographicLib/SphericalHarmonic.hpp>

#include "visors/dynamics/gravity_field.hpp"

namespace visors::test {

// GeographicLib's SphericalHarmonic holds pointers to C and S: keep them with it.
struct GeographicLibGravity {
  std::vector<double> c, s;
  GeographicLib::SphericalHarmonic harmonic;
  double gm_over_a;

  // Degree n_max, order m_max, FULL normalisation (geodesy convention, no Condon-Shortley
  // phase), a = model radius. Layout: column-major by order, (n, m) at m*N - m(m-1)/2 + n; S
  // omits the m = 0 column (GeographicLib SphericalHarmonic.hpp, constructor documentation).
  GeographicLibGravity(const dynamics::GravityField& field, int n_max, int m_max) : gm_over_a(field.gm / field.radius) {
    const int big_n = n_max;
    c.assign(static_cast<std::size_t>((big_n + 1) * (big_n + 2) / 2), 0.0);
    s.assign(static_cast<std::size_t>(big_n * (big_n + 1) / 2), 0.0);
    for (int m = 0; m <= big_n; ++m) {
      for (int n = m; n <= big_n; ++n) {
        const int k = m * big_n - m * (m - 1) / 2 + n;
        c[static_cast<std::size_t>(k)] = field.c(n, m);
        if (m > 0) s[static_cast<std::size_t>(k - (big_n + 1))] = field.s(n, m);
      }
    }
    harmonic = GeographicLib::SphericalHarmonic(c, s, big_n, n_max, m_max, field.radius,
                                                GeographicLib::SphericalHarmonic::FULL);
  }
  // V is Σ q^(n+1) ...: the potential is (GM/a) V and the acceleration (GM/a) grad V.
  void evaluate(const Eigen::Vector3d& r, Eigen::Vector3d* a, double* u) const {
    double gx = 0.0, gy = 0.0, gz = 0.0;
    const double v = harmonic(r.x(), r.y(), r.z(), gx, gy, gz);
    *a = gm_over_a * Eigen::Vector3d(gx, gy, gz);
    *u = gm_over_a * v;
  }
};

}  // namespace visors::test
