#include "visors/dynamics/nrlmsise00_profile.hpp"

#include <algorithm>
#include <cmath>

#include "visors/dynamics/nrlmsise00_expansion.hpp"

namespace visors::dynamics::nrlmsise00_detail {

Gravity gravity_at(double latitude_deg) {
  // The model's latitude-dependent surface gravity and effective radius (glatf).
  const double c2 = std::cos(2.0 * kDegree * latitude_deg);
  Gravity g;
  g.surface = 980.616 * (1.0 - 0.0026373 * c2);
  g.radius = 2.0 * g.surface / (3.085462e-6 + 2.27e-9 * c2) * 1.0e-5;
  return g;
}

double scale_height(const Gravity& g, double z, double amu, double kelvin) {
  const double gz = g.surface / std::pow(1.0 + z / g.radius, 2.0);
  return kGasConstant * kelvin / (gz * amu);
}

// Clamped cubic spline: the second derivatives m_i solve the tridiagonal system
//   h_{i-1} m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_i m_{i+1} = 6 (delta_i - delta_{i-1}),  0 < i < N-1,
//   2 h_0 m_0 + h_0 m_1 = 6 (delta_0 - slope_first),
//   h_{N-2} m_{N-2} + 2 h_{N-2} m_{N-1} = 6 (slope_last - delta_{N-2}),
// with h_i = x_{i+1} - x_i and delta_i = (y_{i+1} - y_i) / h_i (solved by elimination downwards
// and back substitution).
template <std::size_t N>
void ClampedSpline<N>::fit(const std::array<double, N>& x, const std::array<double, N>& y, double slope_first,
                           double slope_last) {
  x_ = x;
  y_ = y;
  std::array<double, N> diag{};
  std::array<double, N> rhs{};
  std::array<double, N> upper{};
  // Row 0.
  double h = x[1] - x[0];
  double delta = (y[1] - y[0]) / h;
  diag[0] = 2.0 * h;
  upper[0] = h;
  rhs[0] = 6.0 * (delta - slope_first);
  for (std::size_t i = 1; i + 1 < N; ++i) {
    const double h_prev = h;
    const double delta_prev = delta;
    h = x[i + 1] - x[i];
    delta = (y[i + 1] - y[i]) / h;
    // Eliminate m_{i-1} with row i-1.
    const double factor = h_prev / diag[i - 1];
    diag[i] = 2.0 * (h_prev + h) - factor * upper[i - 1];
    upper[i] = h;
    rhs[i] = 6.0 * (delta - delta_prev) - factor * rhs[i - 1];
  }
  const double factor = h / diag[N - 2];
  diag[N - 1] = 2.0 * h - factor * upper[N - 2];
  rhs[N - 1] = 6.0 * (slope_last - delta) - factor * rhs[N - 2];
  m_[N - 1] = rhs[N - 1] / diag[N - 1];
  for (std::size_t i = N - 1; i-- > 0;) m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
}

template <std::size_t N>
double ClampedSpline<N>::value(double t) const {
  // The interval [x_k, x_{k+1}] holding t (the first or last one outside the nodes).
  std::size_t k = 0;
  while (k + 2 < N && x_[k + 1] <= t) ++k;
  const double h = x_[k + 1] - x_[k];
  const double a = (x_[k + 1] - t) / h;
  const double b = (t - x_[k]) / h;
  return a * y_[k] + b * y_[k + 1] + ((a * a * a - a) * m_[k] + (b * b * b - b) * m_[k + 1]) * h * h / 6.0;
}

template <std::size_t N>
double ClampedSpline<N>::integral(double t) const {
  // Sum over the intervals from x_0 up to t of the exact integral of the cubic: with
  // a = (x_{k+1} - u)/h, b = 1 - a, the cubic a y_k + b y_{k+1} + ((a^3 - a) m_k + (b^3 - b) m_{k+1}) h^2/6
  // integrates from x_k to u to
  //   h [ (1 - a^2)/2 y_k + b^2/2 y_{k+1} + ((a^2/2 - (1 + a^4)/4) m_k + (b^4/4 - b^2/2) m_{k+1}) h^2/6 ].
  double sum = 0.0;
  for (std::size_t k = 0; k + 1 < N && t > x_[k]; ++k) {
    const double u = k + 2 < N ? std::min(t, x_[k + 1]) : t;  // the last interval extends beyond
    const double h = x_[k + 1] - x_[k];
    const double a = (x_[k + 1] - u) / h;
    const double b = (u - x_[k]) / h;
    const double a2 = a * a;
    const double b2 = b * b;
    sum += ((1.0 - a2) * y_[k] / 2.0 + b2 * y_[k + 1] / 2.0 +
            ((-(1.0 + a2 * a2) / 4.0 + a2 / 2.0) * m_[k] + (b2 * b2 / 4.0 - b2 / 2.0) * m_[k + 1]) * h * h / 6.0) *
           h;
  }
  return sum;
}

template class ClampedSpline<4>;
template class ClampedSpline<5>;

ThermosphereProfile::ThermosphereProfile(const Gravity& g, double t_inf, double t_lb, double sigma, double z_lb,
                                         double z_a, const std::array<double, kNodes - 1>& node_t,
                                         double bottom_gradient, bool need_spline, bool exp_log)
    : g_(g), t_inf_(t_inf), t_lb_(t_lb), sigma_(sigma), z_lb_(z_lb), z_a_(z_a), node_t_(node_t),
      bottom_gradient_(bottom_gradient), exp_log_(exp_log) {
  const double r = g.radius;
  t_a_ = t_inf - (t_inf - t_lb) * std::exp(-sigma * zeta(z_a, z_lb, r));
  g_lb_ = g.surface / std::pow(1.0 + z_lb / r, 2.0);
  g_a_ = g.surface / std::pow(1.0 + z_a / r, 2.0);
  zeta_span_ = zeta(kLowerNodes.back(), z_a, r);
  if (!need_spline) return;
  // Nodes in x = zeta(z, z_a) / zeta(72.5, z_a), values 1/T; end slopes d(1/T)/dx from the Bates
  // gradient at z_a and the given gradient at 72.5 km (converted to geopotential height).
  const double gradient_a = (t_inf - t_a_) * sigma * std::pow((r + z_lb) / (r + z_a), 2.0);
  std::array<double, kNodes> x{};
  std::array<double, kNodes> y{};
  x[0] = zeta(z_a, z_a, r) / zeta_span_;
  y[0] = 1.0 / t_a_;
  for (std::size_t k = 1; k < kNodes; ++k) {
    x[k] = zeta(kLowerNodes[k - 1], z_a, r) / zeta_span_;
    y[k] = 1.0 / node_t[k - 1];
  }
  const double t_bottom = node_t.back();
  const double slope_first = -gradient_a / (t_a_ * t_a_) * zeta_span_;
  const double slope_last =
      -bottom_gradient / (t_bottom * t_bottom) * zeta_span_ * std::pow((r + kLowerNodes.back()) / (r + z_a), 2.0);
  spline_.fit(x, y, slope_first, slope_last);
}

ThermosphereProfile ThermosphereProfile::isothermal(double kelvin, bool need_spline) const {
  return ThermosphereProfile(g_, kelvin, kelvin, sigma_, z_lb_, z_a_, node_t_, bottom_gradient_, need_spline,
                             exp_log_);
}

double ThermosphereProfile::spline_x(double z) const {
  return zeta(std::max(z, kLowerNodes.back()), z_a_, g_.radius) / zeta_span_;
}

const ThermosphereProfile::AboveZa& ThermosphereProfile::above_za(double z) const {
  const double zz = std::max(z, z_a_);
  if (memo_.z == zz) return memo_;
  memo_.z = zz;
  memo_.zeta = zeta(zz, z_lb_, g_.radius);
  memo_.t = t_inf_ - (t_inf_ - t_lb_) * std::exp(-sigma_ * memo_.zeta);
  if (exp_log_ && memo_.t > 0.0) memo_.log_ratio = std::log(t_lb_ / memo_.t);
  return memo_;
}

double ThermosphereProfile::temperature(double z) const {
  if (z >= z_a_) return above_za(z).t;
  return 1.0 / spline_.value(spline_x(z));
}

double ThermosphereProfile::density(double z, double d_lb, double amu, double alpha) const {
  // Above z_a (Hedin 1987 appendix; the published densu): with gamma = M g_lb / (sigma R T_inf),
  //   n = n_lb (T_lb / T)^(1 + alpha + gamma) exp(-sigma gamma zeta(z, z_lb)).
  const AboveZa& a = above_za(z);
  const double gamma = amu * g_lb_ / (sigma_ * kGasConstant * t_inf_);
  double above = 0.0;
  if (exp_log_ && a.t > 0.0) {
    // The published guard below caps exp(-sigma gamma zeta) at 50.
    const double decay_log = std::min(-sigma_ * gamma * a.zeta, std::log(50.0));
    above = d_lb * std::exp((1.0 + alpha + gamma) * a.log_ratio + decay_log);
  } else {
    double decay = std::exp(-sigma_ * gamma * a.zeta);
    if (decay > 50.0 || a.t <= 0.0) decay = 50.0;  // the published guard
    above = d_lb * std::pow(t_lb_ / a.t, 1.0 + alpha + gamma) * decay;
  }
  if (z >= z_a_) return above;
  // Below z_a (Hedin 1991): hydrostatic integration of the spline temperature,
  //   n = n(z_a) (T_a / T)^(1 + alpha) exp(-M g_a zeta_span / R  integral(1/T dx)).
  const double x = spline_x(z);
  const double tz = 1.0 / spline_.value(x);
  double exponent = amu * g_a_ * zeta_span_ / kGasConstant * spline_.integral(x);
  if (exponent > 50.0 || tz <= 0.0) exponent = 50.0;
  return above * std::pow(t_a_ / tz, 1.0 + alpha) * std::exp(-exponent);
}

MiddleAtmosphereProfile::MiddleAtmosphereProfile(const Gravity& g, const std::array<double, 4>& upper_t,
                                                 const std::array<double, 2>& upper_gradient,
                                                 const std::array<double, 5>& lower_t,
                                                 const std::array<double, 2>& lower_gradient, bool with_lower)
    : g_(g), upper_t_(upper_t), lower_t_(lower_t) {
  const double r = g.radius;
  // One spline of 1/T per segment, as in the thermosphere below z_a.
  auto build = [r](auto& spline, const auto& nodes, const auto& temperatures, const std::array<double, 2>& gradient) {
    const double z1 = nodes.front();
    const double z2 = nodes.back();
    const double span = zeta(z2, z1, r);
    auto x = nodes;
    auto y = temperatures;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      x[k] = zeta(nodes[k], z1, r) / span;
      y[k] = 1.0 / temperatures[k];
    }
    const double t1 = temperatures.front();
    const double t2 = temperatures.back();
    const double slope_first = -gradient[0] / (t1 * t1) * span;
    const double slope_last = -gradient[1] / (t2 * t2) * span * std::pow((r + z2) / (r + z1), 2.0);
    spline.fit(x, y, slope_first, slope_last);
    return span;
  };
  upper_span_ = build(upper_, kUpperNodes, upper_t, upper_gradient);
  if (with_lower) lower_span_ = build(lower_, kLowerNodes, lower_t, lower_gradient);
}

double MiddleAtmosphereProfile::temperature(double z) const {
  const double r = g_.radius;
  if (z > kLowerNodes.front()) {
    const double x = zeta(std::max(z, kUpperNodes.back()), kUpperNodes.front(), r) / upper_span_;
    return 1.0 / upper_.value(x);
  }
  return 1.0 / lower_.value(zeta(z, kLowerNodes.front(), r) / lower_span_);
}

double MiddleAtmosphereProfile::density(double z, double d_top, double amu) const {
  // Hydrostatic, fully mixed: n = n_1 (T_1 / T) exp(-M g_1 span / R integral(1/T dx)) per segment.
  const double r = g_.radius;
  double d = d_top;
  const double x_upper = zeta(std::max(z, kUpperNodes.back()), kUpperNodes.front(), r) / upper_span_;
  const double t_upper = 1.0 / upper_.value(x_upper);
  const double g_upper = g_.surface / std::pow(1.0 + kUpperNodes.front() / r, 2.0);
  double exponent = amu * g_upper * upper_span_ / kGasConstant * upper_.integral(x_upper);
  if (exponent > 50.0) exponent = 50.0;
  d = d * (upper_t_.front() / t_upper) * std::exp(-exponent);
  if (z > kLowerNodes.front()) return d;
  const double x_lower = zeta(z, kLowerNodes.front(), r) / lower_span_;
  const double t_lower = 1.0 / lower_.value(x_lower);
  const double g_lower = g_.surface / std::pow(1.0 + kLowerNodes.front() / r, 2.0);
  exponent = amu * g_lower * lower_span_ / kGasConstant * lower_.integral(x_lower);
  if (exponent > 50.0) exponent = 50.0;
  return d * (lower_t_.front() / t_lower) * std::exp(-exponent);
}

double blend_mixed(double dd, double dm, double zhm, double xmm, double xm) {
  // The published root-mean blend (dnet): n = n_d (1 + (n_m / n_d)^a)^(1/a), a = zhm / (xmm - xm),
  // with the published limits for |a ln(n_m/n_d)| > 10 and zero densities.
  const double a = zhm / (xmm - xm);
  if (!(dm > 0.0 && dd > 0.0)) {
    if (dd == 0.0 && dm == 0.0) dd = 1.0;
    if (dm == 0.0) return dd;
    if (dd == 0.0) return dm;
  }
  const double ylog = a * std::log(dm / dd);
  if (ylog < -10.0) return dd;
  if (ylog > 10.0) return dm;
  return dd * std::pow(1.0 + std::exp(ylog), 1.0 / a);
}

double chemistry_factor(double z, double r, double h1, double zh) {
  const double e = (z - zh) / h1;
  if (e > 70.0) return 1.0;
  if (e < -70.0) return std::exp(r);
  return std::exp(r / (1.0 + std::exp(e)));
}

double chemistry_factor2(double z, double r, double h1, double zh, double h2) {
  const double e1 = (z - zh) / h1;
  const double e2 = (z - zh) / h2;
  if (e1 > 70.0 || e2 > 70.0) return 1.0;
  if (e1 < -70.0 && e2 < -70.0) return std::exp(r);
  return std::exp(r / (1.0 + 0.5 * (std::exp(e1) + std::exp(e2))));
}

}  // namespace visors::dynamics::nrlmsise00_detail
