#include "visors/dynamics/harris_priester.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "visors/core/constants.hpp"
#include "visors/core/geodetic.hpp"

namespace visors::dynamics {
namespace {

// Montenbruck & Gill (2000) Table 3.8, modified Harris-Priester densities for mean solar activity:
// height [km], antapex rho_m and apex rho_M [kg/m^3] (the book's g/km^3 times 1e-12). Published
// numbers; identical to data/atmosphere/harris_priester_mg_table3-8.csv (tested).
struct Node {
  double height_km;
  double rho_min;  // [kg/m^3]
  double rho_max;  // [kg/m^3]
};
constexpr std::array<Node, 50> kMontenbruckGillTable{{
    {100.0, 4.974e-07, 4.974e-07},
    {120.0, 2.490e-08, 2.490e-08},
    {130.0, 8.377e-09, 8.710e-09},
    {140.0, 3.899e-09, 4.059e-09},
    {150.0, 2.122e-09, 2.215e-09},
    {160.0, 1.263e-09, 1.344e-09},
    {170.0, 8.008e-10, 8.758e-10},
    {180.0, 5.283e-10, 6.010e-10},
    {190.0, 3.617e-10, 4.297e-10},
    {200.0, 2.557e-10, 3.162e-10},
    {210.0, 1.839e-10, 2.396e-10},
    {220.0, 1.341e-10, 1.853e-10},
    {230.0, 9.949e-11, 1.455e-10},
    {240.0, 7.488e-11, 1.157e-10},
    {250.0, 5.709e-11, 9.308e-11},
    {260.0, 4.403e-11, 7.555e-11},
    {270.0, 3.430e-11, 6.182e-11},
    {280.0, 2.697e-11, 5.095e-11},
    {290.0, 2.139e-11, 4.226e-11},
    {300.0, 1.708e-11, 3.526e-11},
    {320.0, 1.099e-11, 2.511e-11},
    {340.0, 7.214e-12, 1.819e-11},
    {360.0, 4.824e-12, 1.337e-11},
    {380.0, 3.274e-12, 9.955e-12},
    {400.0, 2.249e-12, 7.492e-12},
    {420.0, 1.558e-12, 5.684e-12},
    {440.0, 1.091e-12, 4.355e-12},
    {460.0, 7.701e-13, 3.362e-12},
    {480.0, 5.474e-13, 2.612e-12},
    {500.0, 3.916e-13, 2.042e-12},
    {520.0, 2.819e-13, 1.605e-12},
    {540.0, 2.042e-13, 1.267e-12},
    {560.0, 1.488e-13, 1.005e-12},
    {580.0, 1.092e-13, 7.997e-13},
    {600.0, 8.070e-14, 6.390e-13},
    {620.0, 6.012e-14, 5.123e-13},
    {640.0, 4.519e-14, 4.121e-13},
    {660.0, 3.430e-14, 3.325e-13},
    {680.0, 2.632e-14, 2.691e-13},
    {700.0, 2.043e-14, 2.185e-13},
    {720.0, 1.607e-14, 1.779e-13},
    {740.0, 1.281e-14, 1.452e-13},
    {760.0, 1.036e-14, 1.190e-13},
    {780.0, 8.496e-15, 9.776e-14},
    {800.0, 7.069e-15, 8.059e-14},
    {840.0, 4.680e-15, 5.741e-14},
    {880.0, 3.200e-15, 4.210e-14},
    {920.0, 2.210e-15, 3.130e-14},
    {960.0, 1.560e-15, 2.360e-14},
    {1000.0, 1.150e-15, 1.810e-14},
}};

std::string number_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace

std::optional<std::string> harris_priester_node_problem(double height, double rho_min, double rho_max,
                                                        std::optional<double> previous_height) {
  if (!std::isfinite(height) || !std::isfinite(rho_min) || !std::isfinite(rho_max)) {
    return "values must be finite";
  }
  if (previous_height && !(height > *previous_height)) {
    return "height " + number_text(height) + " m does not increase (previous " +
           number_text(*previous_height) + " m)";
  }
  if (!(rho_min > 0.0)) return "rho_min must be > 0";
  if (!(rho_max > 0.0)) return "rho_max must be > 0";
  if (rho_min > rho_max) {
    return "rho_min " + number_text(rho_min) + " exceeds rho_max " + number_text(rho_max);
  }
  return std::nullopt;
}

core::Result<double> check_harris_priester_f107(double f107) {
  if (!std::isfinite(f107) || !(f107 > 0.0)) return core::Error{"f107", "must be finite and > 0"};
  return f107;
}

HarrisPriesterTable embedded_harris_priester_table() {
  HarrisPriesterTable table;
  table.f107 = kHarrisPriesterMeanF107;
  for (const Node& node : kMontenbruckGillTable) {
    table.height_m.push_back(node.height_km * 1e3);
    table.rho_min.push_back(node.rho_min);
    table.rho_max.push_back(node.rho_max);
  }
  return table;
}

core::Result<HarrisPriesterTable> validate_harris_priester_table(HarrisPriesterTable table) {
  const auto f107 = check_harris_priester_f107(table.f107);
  if (!f107.ok()) return f107.error();
  const std::size_t n = table.height_m.size();
  if (table.rho_min.size() != n || table.rho_max.size() != n) {
    return core::Error{"rho_min", "height_m, rho_min and rho_max must have the same size"};
  }
  if (n < 2) return core::Error{"height_m", "needs at least 2 nodes"};
  for (std::size_t i = 0; i < n; ++i) {
    std::optional<double> previous_height;
    if (i > 0) previous_height = table.height_m[i - 1];
    const auto problem =
        harris_priester_node_problem(table.height_m[i], table.rho_min[i], table.rho_max[i], previous_height);
    if (problem) return core::Error{"node[" + std::to_string(i) + "]", *problem};
  }
  return table;
}

HarrisPriesterAtmosphere::HarrisPriesterAtmosphere(
    std::vector<HarrisPriesterTable> tables, std::vector<InverseScaleHeights> inverse_scale_heights,
    const HarrisPriesterSettings& settings)
    : tables_(std::move(tables)),
      inverse_scale_heights_(std::move(inverse_scale_heights)),
      settings_(settings),
      cos_lag_(std::cos(settings.bulge_lag)),
      sin_lag_(std::sin(settings.bulge_lag)) {}

core::Result<HarrisPriesterAtmosphere> HarrisPriesterAtmosphere::create(
    std::vector<HarrisPriesterTable> tables, const HarrisPriesterSettings& settings) {
  if (!std::isfinite(settings.cosine_exponent) || !(settings.cosine_exponent > 0.0)) {
    return core::Error{"cosine_exponent", "must be finite and > 0"};
  }
  if (!std::isfinite(settings.bulge_lag) || std::abs(settings.bulge_lag) > core::kPi) {
    return core::Error{"bulge_lag", "must be finite, |lag| <= pi rad"};
  }
  if (!std::isfinite(settings.density_scale) || !(settings.density_scale > 0.0)) {
    return core::Error{"density_scale", "must be finite and > 0"};
  }
  if (settings.bulge != HarrisPriesterBulge::kDiurnal &&
      settings.bulge != HarrisPriesterBulge::kApexMaximum) {
    return core::Error{"bulge", "unknown variant"};
  }
  if (tables.empty()) return core::Error{"tables", "needs at least one table"};
  for (std::size_t k = 0; k < tables.size(); ++k) {
    auto checked = validate_harris_priester_table(std::move(tables[k]));
    if (!checked.ok()) {
      return core::Error{"tables[" + std::to_string(k) + "]." + checked.error().field,
                         checked.error().message};
    }
    tables[k] = std::move(checked).value();
  }
  std::stable_sort(tables.begin(), tables.end(),
                   [](const HarrisPriesterTable& l, const HarrisPriesterTable& r) {
                     return l.f107 < r.f107;
                   });
  for (std::size_t k = 1; k < tables.size(); ++k) {
    if (tables[k].f107 == tables[k - 1].f107) {
      return core::Error{"tables",
                         "two tables have the same f107 level " + number_text(tables[k].f107)};
    }
  }
  // Scale heights of every interval (M&G sec. 3.5.2):
  //   1/H_i = ln(rho_{i+1} / rho_i) / (h_i - h_{i+1}).
  std::vector<InverseScaleHeights> inverse(tables.size());
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const HarrisPriesterTable& t = tables[k];
    for (std::size_t i = 0; i + 1 < t.height_m.size(); ++i) {
      const double dh = t.height_m[i] - t.height_m[i + 1];  // [m], < 0
      inverse[k].min.push_back(std::log(t.rho_min[i + 1] / t.rho_min[i]) / dh);
      inverse[k].max.push_back(std::log(t.rho_max[i + 1] / t.rho_max[i]) / dh);
    }
  }
  return HarrisPriesterAtmosphere(std::move(tables), std::move(inverse), settings);
}

core::Result<HarrisPriesterAtmosphere> HarrisPriesterAtmosphere::create(
    const HarrisPriesterSettings& settings) {
  return create({embedded_harris_priester_table()}, settings);
}

std::size_t HarrisPriesterAtmosphere::table_index(double f107a) const {
  // Closest level; tables_ is sorted by f107, so on a tie the lower level (found first) wins.
  // A non-finite f107a compares false everywhere and selects table 0.
  std::size_t best = 0;
  for (std::size_t k = 1; k < tables_.size(); ++k) {
    if (std::abs(tables_[k].f107 - f107a) < std::abs(tables_[best].f107 - f107a)) best = k;
  }
  return best;
}

double HarrisPriesterAtmosphere::density(const AtmosphereQuery& query) const {
  const double height = core::geodetic_from_itrf(query.r_itrf).height;
  return density(height, query.r_gcrf, query.sun_gcrf, query.activity.f107a);
}

double HarrisPriesterAtmosphere::density(double height_m, const Eigen::Vector3d& r_gcrf,
                                         const Eigen::Vector3d& sun_gcrf, double f107a) const {
  const std::size_t k = table_index(f107a);
  const HarrisPriesterTable& table = tables_[k];
  const std::vector<double>& h = table.height_m;
  if (!(height_m >= h.front() && height_m <= h.back())) return 0.0;  // also rejects NaN

  // Interval i with h_i <= height < h_{i+1}; the top node uses the last interval.
  const auto upper = std::upper_bound(h.begin(), h.end(), height_m);
  const std::size_t i = std::min(static_cast<std::size_t>(upper - h.begin()) - 1, h.size() - 2);
  const double dh = h[i] - height_m;  // [m], <= 0
  // Exponential interpolation of both envelopes (M&G sec. 3.5.2).
  const double rho_m = table.rho_min[i] * std::exp(dh * inverse_scale_heights_[k].min[i]);
  const double rho_big = table.rho_max[i] * std::exp(dh * inverse_scale_heights_[k].max[i]);

  if (settings_.bulge == HarrisPriesterBulge::kApexMaximum) {
    return settings_.density_scale * rho_big;
  }
  const double r_norm = r_gcrf.norm();
  const double sun_norm = sun_gcrf.norm();
  if (!(r_norm > 0.0) || !(sun_norm > 0.0)) return 0.0;
  // Apex direction (M&G sec. 3.5.2): the Sun direction rotated by +lag about the z axis.
  const Eigen::Vector3d e_b(cos_lag_ * sun_gcrf.x() - sin_lag_ * sun_gcrf.y(),
                            sin_lag_ * sun_gcrf.x() + cos_lag_ * sun_gcrf.y(), sun_gcrf.z());
  const double cos_psi = e_b.dot(r_gcrf) / (sun_norm * r_norm);
  // cos^2(psi/2) = (1 + cos psi) / 2, clamped against rounding below 0 or above 1.
  const double cos2_half = std::clamp(0.5 * (1.0 + cos_psi), 0.0, 1.0);
  const double weight = std::pow(cos2_half, 0.5 * settings_.cosine_exponent);
  return settings_.density_scale * (rho_m + (rho_big - rho_m) * weight);
}

}  // namespace visors::dynamics
