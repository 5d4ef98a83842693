#pragma once
// Temperature and density profiles of NRLMSISE-00 (internal to nrlmsise00.cpp), in the model's
// units (km, K, cm^-3, g/cm^3, cm/s^2): Hedin (1987, JGR 92(A5) 4649) appendix as
// revised for MSISE-90 (Hedin 1991, JGR 96(A2) 1159: the spline profile below z_a), and the
// NRL code's routines densu, densm, dnet, ccor, ccor2, glatf, scalh.

#include <array>
#include <cstddef>

namespace visors::dynamics::nrlmsise00_detail {

inline constexpr double kGasConstant = 831.4;  // R in the model's units: R T / (g M) is in km
inline constexpr double kAmuGram = 1.66e-24;   // atomic mass unit as used by the model [g]

/// Surface gravity [cm/s^2] and effective Earth radius [km] at a latitude (the model's glatf).
struct Gravity {
  double surface = 0.0;
  double radius = 0.0;
};
Gravity gravity_at(double latitude_deg);

/// Geopotential height difference zeta(z, z_ref) = (z - z_ref)(R + z_ref)/(R + z) [km].
inline double zeta(double z, double z_ref, double radius) { return (z - z_ref) * (radius + z_ref) / (radius + z); }

/// Scale height [km] of mass `amu` at temperature `kelvin` and height `z` (the model's scalh).
double scale_height(const Gravity& g, double z, double amu, double kelvin);

/// A cubic spline through N nodes with given end slopes (clamped), its value and its integral
/// from the first node: the spline of 1/T in normalised geopotential height the model uses
/// (Hedin 1991). Outside the nodes the end polynomials are extended.
template <std::size_t N>
class ClampedSpline {
 public:
  void fit(const std::array<double, N>& x, const std::array<double, N>& y, double slope_first, double slope_last);
  [[nodiscard]] double value(double t) const;
  [[nodiscard]] double integral(double t) const;  // from x[0] to t

 private:
  std::array<double, N> x_{};
  std::array<double, N> y_{};
  std::array<double, N> m_{};  // second derivatives at the nodes
};

/// The thermospheric temperature profile above 72.5 km (the model's densu): the Bates-Walker
/// profile T = T_inf - (T_inf - T_lb) exp(-sigma zeta(z, z_lb)) from z_a up, and below z_a a
/// clamped spline of 1/T through z_a and the nodes 110, 100, 90, 72.5 km (temperatures given),
/// with the Bates slope at z_a and the given slope at 72.5 km.
class ThermosphereProfile {
 public:
  static constexpr std::size_t kNodes = 5;
  /// Node heights below z_a [km] (node 0 is z_a itself).
  static constexpr std::array<double, kNodes - 1> kLowerNodes{110.0, 100.0, 90.0, 72.5};

  /// `node_t` the temperatures at 110, 100, 90, 72.5 km [K], `bottom_gradient` dT/dz at 72.5 km
  /// as the model defines it (tgn1[1]); the spline is built only when `need_spline`.
  /// `exp_log`: density() above z_a as n_lb exp((1 + alpha + gamma) ln(T_lb/T) - sigma gamma zeta),
  /// one exponential with the logarithm shared by the species at one height (the cached path),
  /// instead of the published power times exponential (the same value to ~1e-15 relative).
  ThermosphereProfile(const Gravity& g, double t_inf, double t_lb, double sigma, double z_lb, double z_a,
                      const std::array<double, kNodes - 1>& node_t, double bottom_gradient, bool need_spline,
                      bool exp_log = false);

  /// Temperature at `z` [K] (z below 72.5 km is taken as 72.5).
  [[nodiscard]] double temperature(double z) const;
  /// Density at `z` [cm^-3] of a gas of mass `amu` with thermal-diffusion coefficient `alpha`,
  /// hydrostatic from `d_lb` at z_lb (mass 0: not defined, use temperature()).
  [[nodiscard]] double density(double z, double d_lb, double amu, double alpha) const;

  /// The profile with the same shape factor sigma and nodes but T_inf = T_lb = `kelvin` (the
  /// published anomalous-O profile), with its spline only when `need_spline`.
  [[nodiscard]] ThermosphereProfile isothermal(double kelvin, bool need_spline) const;
  [[nodiscard]] double sigma() const { return sigma_; }

  [[nodiscard]] double t_inf() const { return t_inf_; }
  [[nodiscard]] double t_lb() const { return t_lb_; }
  [[nodiscard]] double z_a() const { return z_a_; }
  [[nodiscard]] double bottom_temperature() const { return node_t_.back(); }  // at 72.5 km [K]
  [[nodiscard]] double bottom_gradient() const { return bottom_gradient_; }

 private:
  [[nodiscard]] double spline_x(double z) const;  // normalised geopotential height below z_a
  // zeta(max(z, z_a), z_lb), the Bates temperature there and ln(T_lb / T), kept for the last
  // height asked (every species is evaluated at the same height).
  struct AboveZa {
    double z = -1.0;
    double zeta = 0.0;
    double t = 0.0;
    double log_ratio = 0.0;
  };
  const AboveZa& above_za(double z) const;

  Gravity g_;
  double t_inf_, t_lb_, sigma_, z_lb_, z_a_;
  std::array<double, kNodes - 1> node_t_;
  double bottom_gradient_;
  double t_a_ = 0.0;       // temperature at z_a
  double zeta_span_ = 0.0;  // zeta(72.5, z_a) (< 0)
  double g_lb_ = 0.0;       // gravity at z_lb
  double g_a_ = 0.0;        // gravity at z_a
  ClampedSpline<kNodes> spline_;
  bool exp_log_ = false;
  mutable AboveZa memo_;
};

/// The middle-atmosphere temperature profile below 72.5 km (the model's densm): a spline of 1/T
/// through 72.5, 55, 45, 32.5 km and one through 32.5, 20, 15, 10, 0 km.
class MiddleAtmosphereProfile {
 public:
  static constexpr std::array<double, 4> kUpperNodes{72.5, 55.0, 45.0, 32.5};
  static constexpr std::array<double, 5> kLowerNodes{32.5, 20.0, 15.0, 10.0, 0.0};

  /// Temperatures at the nodes [K] and the model's end gradients (tgn2, tgn3); the lower spline is
  /// built only when `with_lower`.
  MiddleAtmosphereProfile(const Gravity& g, const std::array<double, 4>& upper_t,
                          const std::array<double, 2>& upper_gradient, const std::array<double, 5>& lower_t,
                          const std::array<double, 2>& lower_gradient, bool with_lower);

  [[nodiscard]] double temperature(double z) const;
  /// Fully mixed density at z [cm^-3] of mean mass `amu` from `d_top` at 72.5 km.
  [[nodiscard]] double density(double z, double d_top, double amu) const;

 private:
  Gravity g_;
  std::array<double, 4> upper_t_{};
  std::array<double, 5> lower_t_{};
  double upper_span_ = 0.0;  // zeta(32.5, 72.5)
  double lower_span_ = 0.0;  // zeta(0, 32.5)
  ClampedSpline<4> upper_;
  ClampedSpline<5> lower_;
};

/// Turbopause blending of diffusive `dd` and fully mixed `dm` densities (the model's dnet):
/// (dd^a + dm^a)^(1/a)-like root mean with a = zhm / (xmm - xm).
double blend_mixed(double dd, double dm, double zhm, double xmm, double xm);
/// Chemistry / dissociation correction factor exp(r / (1 + exp((z - zh)/h1))) (the model's ccor).
double chemistry_factor(double z, double r, double h1, double zh);
/// The two-scale version exp(r / (1 + (exp((z - zh)/h1) + exp((z - zh)/h2))/2)) (ccor2).
double chemistry_factor2(double z, double r, double h1, double zh, double h2);

}  // namespace visors::dynamics::nrlmsise00_detail
