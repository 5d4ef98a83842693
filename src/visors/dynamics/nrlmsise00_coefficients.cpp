#include "visors/dynamics/nrlmsise00_coefficients.hpp"

#include <cmath>
#include <cstddef>
#include <string>

namespace visors::dynamics {
namespace {

std::string entry(const char* table, std::size_t row, std::size_t column) {
  return std::string(table) + "[" + std::to_string(row) + "][" + std::to_string(column) + "]";
}

std::string entry(const char* table, std::size_t column) {
  return std::string(table) + "[" + std::to_string(column) + "]";
}

template <std::size_t N>
std::optional<core::Error> non_finite(const char* table, const std::array<double, N>& values) {
  for (std::size_t i = 0; i < N; ++i) {
    if (!std::isfinite(values[i])) return core::Error{entry(table, i), "must be finite"};
  }
  return std::nullopt;
}

template <std::size_t R, std::size_t N>
std::optional<core::Error> non_finite(const char* table, const std::array<std::array<double, N>, R>& rows) {
  for (std::size_t r = 0; r < R; ++r) {
    for (std::size_t i = 0; i < N; ++i) {
      if (!std::isfinite(rows[r][i])) return core::Error{entry(table, r, i), "must be finite"};
    }
  }
  return std::nullopt;
}

// The lower-atmosphere expansion of the published model checks that its tables carry parameter
// set 2 in element 99 (0 is taken as 2).
template <std::size_t R>
std::optional<core::Error> wrong_parameter_set(const char* table, const std::array<std::array<double, 100>, R>& rows) {
  for (std::size_t r = 0; r < R; ++r) {
    if (rows[r][99] != 0.0 && rows[r][99] != 2.0) {
      return core::Error{entry(table, r, 99), "parameter-set marker must be 0 or 2"};
    }
  }
  return std::nullopt;
}

std::optional<core::Error> first_non_finite(const Nrlmsise00Coefficients& c) {
  if (auto e = non_finite("pt", c.pt)) return e;
  if (auto e = non_finite("pd", c.pd)) return e;
  if (auto e = non_finite("ps", c.ps)) return e;
  if (auto e = non_finite("pdl", c.pdl)) return e;
  if (auto e = non_finite("ptm", c.ptm)) return e;
  if (auto e = non_finite("pdm", c.pdm)) return e;
  if (auto e = non_finite("ptl", c.ptl)) return e;
  if (auto e = non_finite("pma", c.pma)) return e;
  if (auto e = non_finite("sam", c.sam)) return e;
  return non_finite("pavgm", c.pavgm);
}

}  // namespace

std::optional<core::Error> nrlmsise00_coefficients_problem(const Nrlmsise00Coefficients& c) {
  if (auto e = first_non_finite(c)) return e;
  if (auto e = wrong_parameter_set("ptl", c.ptl)) return e;
  if (auto e = wrong_parameter_set("pma", c.pma)) return e;
  // Heights: z_a (first spline node) above the 110 km node, z_lb not above z_a.
  if (!(c.pdl[1][15] > 110.0)) return core::Error{"pdl[1][15]", "z_a must be above 110 km"};
  if (!(c.ptm[5] <= c.pdl[1][15])) return core::Error{"ptm[5]", "z_lb must not exceed z_a = pdl[1][15]"};
  // Mean temperatures: T_inf, T_lb and the spline nodes (positive, so 1/T is defined).
  if (!(c.ptm[0] * c.pt[0] > 0.0)) return core::Error{"pt[0]", "ptm[0] pt[0] (T_inf) must be > 0"};
  if (!(c.ptm[1] * c.pd[3][0] > 0.0)) return core::Error{"pd[3][0]", "ptm[1] pd[3][0] (T_lb) must be > 0"};
  if (!(c.ptm[0] * c.pt[0] > c.ptm[1] * c.pd[3][0])) {
    return core::Error{"pt[0]", "T_inf = ptm[0] pt[0] must exceed T_lb = ptm[1] pd[3][0]"};
  }
  const std::size_t node_scale[4] = {6, 2, 7, 4};  // ptm index of each ptl node
  for (std::size_t k = 0; k < 4; ++k) {
    if (!(c.ptm[node_scale[k]] * c.ptl[k][0] > 0.0)) {
      return core::Error{entry("ptl", k, 0), "node temperature must be > 0"};
    }
  }
  for (std::size_t k = 0; k < 7; ++k) {
    if (!(c.pma[k][0] * c.pavgm[k] > 0.0)) return core::Error{entry("pma", k, 0), "node temperature must be > 0"};
  }
  return std::nullopt;
}

}  // namespace visors::dynamics
