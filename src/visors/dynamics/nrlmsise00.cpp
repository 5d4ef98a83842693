#include "visors/dynamics/nrlmsise00.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "visors/core/constants.hpp"
#include "visors/core/geodetic.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/dynamics/nrlmsise00_expansion.hpp"
#include "visors/dynamics/nrlmsise00_profile.hpp"

namespace visors::dynamics {

using nrlmsise00_detail::Basis;
using nrlmsise00_detail::FullDayTerms;
using nrlmsise00_detail::FullPhaseConstants;
using nrlmsise00_detail::FullTable;
using nrlmsise00_detail::Gravity;
using nrlmsise00_detail::LowerDayTerms;
using nrlmsise00_detail::LowerTable;

namespace {

namespace d = nrlmsise00_detail;

// Heights of the published model [km].
constexpr double kThermosphereBottom = 72.5;  // gts7 above, densm below
constexpr double kFullMixing = 62.5;          // below it the thermosphere's ratios are not used
constexpr double kNodeVariationTop = 300.0;   // lower-thermosphere node variations below it only
constexpr double kHighestTurbopause = 450.0;  // the highest mixing height (N), see kMixingTop

// Mixing (turbopause) heights of each species [km]: above them the density is purely diffusive.
constexpr double kMixingTopHe = 200.0;
constexpr double kMixingTopO = 300.0;
constexpr double kMixingTopN2 = 160.0;
constexpr double kMixingTopO2 = 250.0;
constexpr double kMixingTopAr = 240.0;
constexpr double kMixingTopH = 320.0;
constexpr double kMixingTopN = 450.0;
// Thermal-diffusion coefficients (the others are 0).
constexpr double kAlphaHe = -0.38;
constexpr double kAlphaAr = 0.17;
constexpr double kAlphaH = -0.38;

// Indices of the full tables (pt, ps, pd[0..8]) and the lower ones (ptl[0..3], pma[0..9]).
constexpr std::size_t kPt = 0;
constexpr std::size_t kPs = 1;
constexpr std::size_t pd_index(std::size_t row) { return 2 + row; }
constexpr std::size_t kFullTables = 11;
constexpr std::size_t pma_index(std::size_t row) { return 4 + row; }
constexpr std::size_t kLowerTables = 14;

std::array<const FullTable*, kFullTables> full_tables(const Nrlmsise00Coefficients& c) {
  std::array<const FullTable*, kFullTables> t{};
  t[kPt] = &c.pt;
  t[kPs] = &c.ps;
  for (std::size_t k = 0; k < 9; ++k) t[pd_index(k)] = &c.pd[k];
  return t;
}

std::array<const LowerTable*, kLowerTables> lower_tables(const Nrlmsise00Coefficients& c) {
  std::array<const LowerTable*, kLowerTables> t{};
  for (std::size_t k = 0; k < 4; ++k) t[k] = &c.ptl[k];
  for (std::size_t k = 0; k < 10; ++k) t[pma_index(k)] = &c.pma[k];
  return t;
}

bool same_activity(const SolarActivity& a, const SolarActivity& b) {
  return a.f107 == b.f107 && a.f107a == b.f107a && a.ap == b.ap && a.ap_history == b.ap_history;
}

// Number densities [cm^-3] and temperatures of one evaluation, in the model's units.
struct Densities {
  double he = 0.0, o = 0.0, n2 = 0.0, o2 = 0.0, ar = 0.0, h = 0.0, n = 0.0, anomalous_o = 0.0;
  double t_inf = 0.0;
  double t_alt = 0.0;
  // Thermosphere only: the fully mixed N2 density at the height (below the N2 turbopause) and
  // the bottom node of the temperature profile (72.5 km temperature and gradient).
  double n2_mixed = 0.0;
  double t_bottom = 0.0;
  double gradient_bottom = 0.0;
};

}  // namespace

// The tables, their pointers by index, the phase constants and the day/activity cache.
struct Nrlmsise00Atmosphere::Model {
  explicit Model(const Nrlmsise00Coefficients& coefficients)
      : c(coefficients), full(full_tables(c)), lower(lower_tables(c)) {
    for (std::size_t k = 0; k < kFullTables; ++k) {
      phase_daily[k] = d::phase_constants(*full[k], false);
      phase_history[k] = d::phase_constants(*full[k], true);
    }
  }
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // The day terms of every table for a day of year and an activity (refreshed when they change).
  struct DayCache {
    bool valid = false;
    bool usable = false;  // the activity passed input_problem's checks
    int day_of_year = 0;
    SolarActivity activity;
    std::array<FullDayTerms, kFullTables> full{};
    std::array<LowerDayTerms, kLowerTables> lower{};
  };
  const DayCache& day_cache(int day_of_year, const SolarActivity& activity);

  Nrlmsise00Coefficients c;
  std::array<const FullTable*, kFullTables> full;
  std::array<const LowerTable*, kLowerTables> lower;
  std::array<FullPhaseConstants, kFullTables> phase_daily{};
  std::array<FullPhaseConstants, kFullTables> phase_history{};
  DayCache cache;
};

namespace {

// The expansions evaluated from the inputs alone (the straightforward path).
class DirectExpansions {
 public:
  static constexpr bool kCachedPath = false;
  DirectExpansions(const Nrlmsise00Coefficients& c, const Basis& b, int day_of_year, const SolarActivity& a)
      : full_(full_tables(c)), lower_(lower_tables(c)), b_(b), day_(day_of_year), a_(a),
        history_(d::history_mode(a)) {}

  [[nodiscard]] double full(std::size_t k) const {
    const FullTable& p = *full_[k];
    const FullDayTerms terms = d::full_day_terms(p, day_, a_);
    const double magnetic = d::magnetic_function(p, a_, b_.latitude_deg);
    return d::full_expansion(p, b_, terms, d::direct_phase_terms(p, b_, history_), magnetic, history_);
  }
  [[nodiscard]] double lower(std::size_t k) const {
    const LowerTable& p = *lower_[k];
    // The geomagnetic function is T_lb's (pd[3]), see lower_expansion.
    const double magnetic = d::magnetic_function(*full_[pd_index(3)], a_, b_.latitude_deg);
    return d::lower_expansion(p, b_, d::lower_day_terms(p, day_), magnetic, history_);
  }

 private:
  std::array<const FullTable*, kFullTables> full_;
  std::array<const LowerTable*, kLowerTables> lower_;
  const Basis& b_;
  int day_;
  const SolarActivity& a_;
  bool history_;
};

// The expansions from the cached day terms and the phase identities (the fast path).
class CachedExpansions {
 public:
  static constexpr bool kCachedPath = true;
  using Model = Nrlmsise00Atmosphere::Model;
  CachedExpansions(const Model& m, const Model::DayCache& cache, const Basis& b)
      : m_(m), cache_(cache), b_(b), history_(d::history_mode(cache.activity)) {}

  [[nodiscard]] double full(std::size_t k) const {
    const FullTable& p = *m_.full[k];
    const FullDayTerms& terms = cache_.full[k];
    const double magnetic = magnetic_of(k);
    const auto& phase = history_ ? m_.phase_history[k] : m_.phase_daily[k];
    return d::full_expansion(p, b_, terms, d::cached_phase_terms(phase, b_), magnetic, history_);
  }
  [[nodiscard]] double lower(std::size_t k) const {
    return d::lower_expansion(*m_.lower[k], b_, cache_.lower[k], magnetic_of(pd_index(3)), history_);
  }

 private:
  [[nodiscard]] double magnetic_of(std::size_t k) const {
    const auto& cached = cache_.full[k].magnetic;
    return cached ? *cached : d::magnetic_function_cached(*m_.full[k], cache_.full[k], b_.latitude_deg);
  }
  const Model& m_;
  const Model::DayCache& cache_;
  const Basis& b_;
  bool history_;
};

// The temperature profile's parameters at the height z of the thermosphere (gts7's first part):
// T_inf, the gradient, T_lb and the lower-thermosphere nodes, each with its variation where the
// published model includes it.
template <class Expansions>
d::ThermosphereProfile thermosphere_profile(const Nrlmsise00Coefficients& c, const Gravity& g, double z,
                                            const Expansions& e) {
  const double z_a = c.pdl[1][15];
  // T_inf and gradient variations are not included below z_a and 72.5 km respectively.
  const double t_inf = z > z_a ? c.ptm[0] * c.pt[0] * (1.0 + e.full(kPt)) : c.ptm[0] * c.pt[0];
  const double g0 = z > kThermosphereBottom ? c.ptm[3] * c.ps[0] * (1.0 + e.full(kPs)) : c.ptm[3] * c.ps[0];
  const double t_lb = c.ptm[1] * (1.0 + e.full(pd_index(3))) * c.pd[3][0];
  const double sigma = g0 / (t_inf - t_lb);
  // Lower-thermosphere node temperatures (110, 100, 90, 72.5 km) and the 72.5 km gradient;
  // their variations are not significant for the density above 300 km.
  const bool vary = z < kNodeVariationTop;
  auto node = [&](double scale, std::size_t k) {
    return scale * c.ptl[k][0] / (1.0 - (vary ? e.lower(k) : 0.0));
  };
  const std::array<double, 4> node_t{node(c.ptm[6], 0), node(c.ptm[2], 1), node(c.ptm[7], 2), node(c.ptm[4], 3)};
  const double bottom_mean = c.ptm[4] * c.ptl[3][0];
  const double gradient = c.ptm[8] * c.pma[8][0] * (1.0 + (vary ? e.lower(pma_index(8)) : 0.0)) * node_t[3] *
                          node_t[3] / (bottom_mean * bottom_mean);
  return d::ThermosphereProfile(g, t_inf, t_lb, sigma, c.ptm[5], z_a, node_t, gradient, z <= kHighestTurbopause,
                                Expansions::kCachedPath);
}

// The diffusive density at z blended with the fully mixed one below the turbopause: `b_zh`
// receives the mixed density at the turbopause height zh (Hedin 1987 appendix; the published dnet).
double with_mixing(const d::ThermosphereProfile& prof, double z, double diffusive, double d_lb, double amu, double alpha,
                   double zh, double zhm, double xmm, double& b_zh) {
  b_zh = prof.density(zh, d_lb, amu - xmm, alpha - 1.0);
  const double mixed = prof.density(z, b_zh, xmm, 0.0);
  return d::blend_mixed(diffusive, mixed, zhm, xmm, amu);
}

// Density at z_lb of a species: pdm[row][0] exp(G) pd[row'][0].
template <class Expansions>
double density_at_zlb(const Nrlmsise00Coefficients& c, const Expansions& e, std::size_t pdm_row, std::size_t pd_row) {
  return c.pdm[pdm_row][0] * std::exp(e.full(pd_index(pd_row))) * c.pd[pd_row][0];
}

// long-function: the eight species of the published thermosphere in their order, each with its
// mixing and correction terms (Picone et al. 2002; Hedin 1987 appendix; the published gts7).
template <class Expansions>
Densities thermosphere(const Nrlmsise00Coefficients& c, const Gravity& g, const Basis& b, int day_of_year,
                       double f107a, double z, const Expansions& e) {
  const d::ThermosphereProfile prof = thermosphere_profile(c, g, z, e);
  Densities out;
  out.t_inf = prof.t_inf();
  const auto& pdl = c.pdl;
  const auto& pdm = c.pdm;
  const double xmm = pdm[2][4];  // mean molecular mass of the mixed atmosphere
  const double flux = 1.0 + pdl[0][23] * (f107a - 150.0);
  // N2, and the mixed N2 density at its turbopause, which the other species' ground mixing
  // ratios refer to. The turbopause height varies with latitude and season.
  const double zhf = pdl[1][24] * (1.0 + pdl[0][24] * std::sin(d::kDegree * b.latitude_deg) *
                                             std::cos(d::kDay * (day_of_year - c.pt[13])));
  const double db28 = density_at_zlb(c, e, 2, 2);
  out.n2 = prof.density(z, db28, 28.0, 0.0);
  const double zhm28 = pdm[2][3] * pdl[1][5];
  double b28 = 0.0;
  if (z <= kHighestTurbopause) b28 = prof.density(pdm[2][2] * zhf, db28, 28.0 - xmm, -1.0);
  if (z <= kMixingTopN2) {
    out.n2_mixed = prof.density(z, b28, xmm, 0.0);
    out.n2 = d::blend_mixed(out.n2, out.n2_mixed, zhm28, xmm, 28.0);
  }
  // He: ground mixing ratio correction.
  const double db04 = density_at_zlb(c, e, 0, 0);
  out.he = prof.density(z, db04, 4.0, kAlphaHe);
  if (z <= kMixingTopHe) {
    double b04 = 0.0;
    out.he = with_mixing(prof, z, out.he, db04, 4.0, kAlphaHe, pdm[0][2], zhm28, xmm, b04);
    out.he *= d::chemistry_factor(z, std::log(b28 * pdm[0][1] / b04), pdm[0][5] * pdl[1][1], pdm[0][4] * pdl[1][0]);
  }
  // O: departure from diffusive equilibrium near 150 km (F10.7 dependent) and chemistry.
  const double db16 = density_at_zlb(c, e, 1, 1);
  out.o = prof.density(z, db16, 16.0, 0.0);
  if (z <= kMixingTopO) {
    double b16 = 0.0;
    out.o = with_mixing(prof, z, out.o, db16, 16.0, 0.0, pdm[1][2], zhm28, xmm, b16);
    out.o *= d::chemistry_factor2(z, pdm[1][1] * pdl[1][16] * flux, pdm[1][5] * pdl[1][3], pdm[1][4] * pdl[1][2],
                                  pdm[1][5] * pdl[1][4]);
    out.o *= d::chemistry_factor(z, pdm[1][3] * pdl[1][14], pdm[1][7] * pdl[1][13], pdm[1][6] * pdl[1][12]);
  }
  // O2: ground mixing ratio, and the general departure from diffusive equilibrium at all heights.
  const double db32 = density_at_zlb(c, e, 3, 4);
  out.o2 = prof.density(z, db32, 32.0, 0.0);
  if (z <= kMixingTopO2) {
    double b32 = 0.0;
    out.o2 = with_mixing(prof, z, out.o2, db32, 32.0, 0.0, pdm[3][2], zhm28, xmm, b32);
    out.o2 *= d::chemistry_factor(z, std::log(b28 * pdm[3][1] / b32), pdm[3][5] * pdl[1][7], pdm[3][4] * pdl[1][6]);
  }
  out.o2 *= d::chemistry_factor2(z, pdm[3][3] * pdl[1][23] * flux, pdm[3][7] * pdl[1][22], pdm[3][6] * pdl[1][21],
                                 pdm[3][7] * pdl[0][22]);
  // Ar.
  const double db40 = density_at_zlb(c, e, 4, 5);
  out.ar = prof.density(z, db40, 40.0, kAlphaAr);
  if (z <= kMixingTopAr) {
    double b40 = 0.0;
    out.ar = with_mixing(prof, z, out.ar, db40, 40.0, kAlphaAr, pdm[4][2], zhm28, xmm, b40);
    out.ar *= d::chemistry_factor(z, std::log(b28 * pdm[4][1] / b40), pdm[4][5] * pdl[1][9], pdm[4][4] * pdl[1][8]);
  }
  // H: ground mixing ratio and chemistry.
  const double db01 = density_at_zlb(c, e, 5, 6);
  out.h = prof.density(z, db01, 1.0, kAlphaH);
  if (z <= kMixingTopH) {
    double b01 = 0.0;
    out.h = with_mixing(prof, z, out.h, db01, 1.0, kAlphaH, pdm[5][2], zhm28, xmm, b01);
    out.h *= d::chemistry_factor(z, std::log(b28 * pdm[5][1] * std::abs(pdl[1][17]) / b01), pdm[5][5] * pdl[1][11],
                                 pdm[5][4] * pdl[1][10]);
    out.h *= d::chemistry_factor(z, pdm[5][3] * pdl[1][20], pdm[5][7] * pdl[1][19], pdm[5][6] * pdl[1][18]);
  }
  // N: ground mixing ratio and chemistry.
  const double db14 = density_at_zlb(c, e, 6, 7);
  out.n = prof.density(z, db14, 14.0, 0.0);
  if (z <= kMixingTopN) {
    double b14 = 0.0;
    out.n = with_mixing(prof, z, out.n, db14, 14.0, 0.0, pdm[6][2], zhm28, xmm, b14);
    out.n *= d::chemistry_factor(z, std::log(b28 * pdm[6][1] * std::abs(pdl[0][2]) / b14), pdm[6][5] * pdl[0][1],
                                 pdm[6][4] * pdl[0][0]);
    out.n *= d::chemistry_factor(z, pdm[6][3] * pdl[0][5], pdm[6][7] * pdl[0][4], pdm[6][6] * pdl[0][3]);
  }
  // Anomalous O (Picone et al. 2002): an isothermal (T = tho) diffusive profile times a
  // Chapman-like height factor of scale zsht about zmho.
  const double db16h = density_at_zlb(c, e, 7, 8);
  const double tho = pdm[7][9] * pdl[0][6];
  const d::ThermosphereProfile hot = prof.isothermal(tho, z < prof.z_a());
  const double zsht = pdm[7][5];
  const double zmho = pdm[7][4];
  const double zsho = d::scale_height(g, zmho, 16.0, tho);
  out.anomalous_o = hot.density(z, db16h, 16.0, 0.0) * std::exp(-zsht / zsho * (std::exp(-(z - zmho) / zsht) - 1.0));
  out.t_alt = prof.temperature(std::abs(z));
  out.t_bottom = prof.bottom_temperature();
  out.gradient_bottom = prof.bottom_gradient();
  return out;
}

// Below 72.5 km (gtd7's lower part): the middle-atmosphere temperature nodes, fully mixed N2 from
// its 72.5 km value, He, O2, Ar in their ground mixing ratios, joined linearly between 62.5 and
// 72.5 km to the thermosphere's ratios; O, H, N and anomalous O are 0.
template <class Expansions>
Densities middle_atmosphere(const Nrlmsise00Coefficients& c, const Gravity& g, double z, const Densities& top,
                            const Expansions& e) {
  const auto& pma = c.pma;
  const auto& pavgm = c.pavgm;
  auto node = [&](std::size_t k) { return pma[k][0] * pavgm[k] / (1.0 - e.lower(pma_index(k))); };
  const std::array<double, 4> upper_t{top.t_bottom, node(0), node(1), node(2)};
  const double upper_mean = pma[2][0] * pavgm[2];
  const std::array<double, 2> upper_gradient{
      top.gradient_bottom,
      pavgm[8] * pma[9][0] * (1.0 + e.lower(pma_index(9))) * upper_t[3] * upper_t[3] / (upper_mean * upper_mean)};
  const bool with_lower = z <= d::MiddleAtmosphereProfile::kLowerNodes.front();
  std::array<double, 5> lower_t{};
  std::array<double, 2> lower_gradient{};
  if (with_lower) {
    lower_t = {upper_t[3], node(3), node(4), node(5), node(6)};
    const double lower_mean = pma[6][0] * pavgm[6];
    lower_gradient = {upper_gradient[1], pma[7][0] * pavgm[7] * (1.0 + e.lower(pma_index(7))) * lower_t[4] *
                                             lower_t[4] / (lower_mean * lower_mean)};
  }
  const d::MiddleAtmosphereProfile mid(g, upper_t, upper_gradient, lower_t, lower_gradient, with_lower);
  const double mixing = z > kFullMixing ? 1.0 - (kThermosphereBottom - z) / (kThermosphereBottom - kFullMixing) : 0.0;
  const double xmm = c.pdm[2][4];
  Densities out;
  out.t_inf = top.t_inf;
  out.n2 = mid.density(z, top.n2_mixed, xmm) * (1.0 + (top.n2 / top.n2_mixed - 1.0) * mixing);
  auto ratio = [&](double thermosphere, std::size_t row) {
    const double ground = c.pdm[row][1];
    return out.n2 * ground * (1.0 + (thermosphere / (top.n2 * ground) - 1.0) * mixing);
  };
  out.he = ratio(top.he, 0);
  out.o2 = ratio(top.o2, 3);
  out.ar = ratio(top.ar, 4);
  out.t_alt = mid.temperature(z);
  return out;
}

// gtd7: the thermosphere at max(z, 72.5 km), and below 72.5 km the middle atmosphere.
template <class Expansions>
Densities evaluate_model(const Nrlmsise00Coefficients& c, const Nrlmsise00Input& in, const Basis& b,
                         const Expansions& e) {
  const Gravity g = d::gravity_at(in.latitude_deg);
  const double z = in.altitude_km;
  const Densities top = thermosphere(c, g, b, in.day_of_year, in.activity.f107a, std::max(z, kThermosphereBottom), e);
  if (z >= kThermosphereBottom) return top;
  return middle_atmosphere(c, g, z, top, e);
}

// SI output: number densities cm^-3 -> m^-3, mass densities g/cm^3 -> kg/m^3.
Nrlmsise00Output to_output(const Densities& n) {
  Nrlmsise00Output out;
  // Total mass [g/cm^3] (gtd7 without, gtd7d with anomalous O).
  const double mass = d::kAmuGram * (4.0 * n.he + 16.0 * n.o + 28.0 * n.n2 + 32.0 * n.o2 + 40.0 * n.ar + n.h + 14.0 * n.n);
  const double mass_drag =
      d::kAmuGram * (4.0 * n.he + 16.0 * n.o + 28.0 * n.n2 + 32.0 * n.o2 + 40.0 * n.ar + n.h + 14.0 * n.n + 16.0 * n.anomalous_o);
  out.he = n.he * 1e6;
  out.o = n.o * 1e6;
  out.n2 = n.n2 * 1e6;
  out.o2 = n.o2 * 1e6;
  out.ar = n.ar * 1e6;
  out.h = n.h * 1e6;
  out.n = n.n * 1e6;
  out.anomalous_o = n.anomalous_o * 1e6;
  out.mass_density = mass * 1e3;
  out.mass_density_with_anomalous_o = mass_drag * 1e3;
  out.exospheric_temperature = n.t_inf;
  out.temperature = n.t_alt;
  return out;
}

Basis basis_of(const Nrlmsise00Input& in, bool cached_path) {
  return d::make_basis(in.latitude_deg, in.longitude_deg, in.local_solar_time_h, in.ut_seconds, in.activity.f107a,
                       cached_path);
}

std::optional<core::Error> activity_problem(const SolarActivity& a) {
  if (!std::isfinite(a.f107) || !(a.f107 > 0.0)) return core::Error{"activity.f107", "must be finite and > 0 sfu"};
  if (!std::isfinite(a.f107a) || !(a.f107a > 0.0)) return core::Error{"activity.f107a", "must be finite and > 0 sfu"};
  if (!std::isfinite(a.ap) || !(a.ap >= 0.0)) return core::Error{"activity.ap", "must be finite and >= 0"};
  if (a.ap_history) {
    for (std::size_t k = 0; k < 7; ++k) {
      const double v = (*a.ap_history)[k];
      if (!std::isfinite(v) || !(v >= 0.0)) {
        return core::Error{"activity.ap_history[" + std::to_string(k) + "]", "must be finite and >= 0"};
      }
    }
  }
  return std::nullopt;
}

std::optional<core::Error> range_problem(const char* field, double value, double low, double high, const char* unit) {
  if (std::isfinite(value) && value >= low && value <= high) return std::nullopt;
  char text[96];
  std::snprintf(text, sizeof text, "must be finite, in [%g, %g]%s", low, high, unit);
  return core::Error{field, text};
}

int day_of_year(const core::CalendarTime& c) {
  constexpr int kBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = (c.year % 4 == 0 && c.year % 100 != 0) || c.year % 400 == 0;
  return kBefore[c.month - 1] + c.day + (leap && c.month > 2 ? 1 : 0);
}

}  // namespace

const Nrlmsise00Atmosphere::Model::DayCache& Nrlmsise00Atmosphere::Model::day_cache(int day_of_year,
                                                                                    const SolarActivity& activity) {
  if (cache.valid && cache.day_of_year == day_of_year && same_activity(cache.activity, activity)) return cache;
  cache.valid = true;
  cache.day_of_year = day_of_year;
  cache.activity = activity;
  cache.usable = !activity_problem(activity);
  if (!cache.usable) return cache;
  for (std::size_t k = 0; k < kFullTables; ++k) cache.full[k] = d::full_day_terms(*full[k], day_of_year, activity);
  for (std::size_t k = 0; k < kLowerTables; ++k) cache.lower[k] = d::lower_day_terms(*lower[k], day_of_year);
  return cache;
}

Nrlmsise00Atmosphere::Nrlmsise00Atmosphere(std::unique_ptr<Model> model) : model_(std::move(model)) {}
Nrlmsise00Atmosphere::Nrlmsise00Atmosphere(Nrlmsise00Atmosphere&&) noexcept = default;
Nrlmsise00Atmosphere& Nrlmsise00Atmosphere::operator=(Nrlmsise00Atmosphere&&) noexcept = default;
Nrlmsise00Atmosphere::~Nrlmsise00Atmosphere() = default;

core::Result<Nrlmsise00Atmosphere> Nrlmsise00Atmosphere::create(const Nrlmsise00Coefficients& coefficients) {
  if (auto problem = nrlmsise00_coefficients_problem(coefficients)) return *problem;
  return Nrlmsise00Atmosphere(std::make_unique<Model>(coefficients));
}

std::optional<core::Error> Nrlmsise00Atmosphere::input_problem(const Nrlmsise00Input& in) {
  if (in.day_of_year < 1 || in.day_of_year > 366) return core::Error{"day_of_year", "must be in [1, 366]"};
  if (auto e = range_problem("ut_seconds", in.ut_seconds, 0.0, 86400.0, " s")) return e;
  if (auto e = range_problem("altitude_km", in.altitude_km, kNrlmsise00MinHeight / 1e3, kNrlmsise00MaxHeight / 1e3,
                             " km")) {
    return e;
  }
  if (auto e = range_problem("latitude_deg", in.latitude_deg, -90.0, 90.0, " deg")) return e;
  if (auto e = range_problem("longitude_deg", in.longitude_deg, -360.0, 360.0, " deg")) return e;
  if (auto e = range_problem("local_solar_time_h", in.local_solar_time_h, -48.0, 48.0, " h")) return e;
  return activity_problem(in.activity);
}

core::Result<Nrlmsise00Output> Nrlmsise00Atmosphere::evaluate(const Nrlmsise00Input& input) const {
  if (auto problem = input_problem(input)) return *problem;
  const Model::DayCache& cache = model_->day_cache(input.day_of_year, input.activity);
  const Basis b = basis_of(input, true);
  return to_output(evaluate_model(model_->c, input, b, CachedExpansions(*model_, cache, b)));
}

Nrlmsise00Output Nrlmsise00Atmosphere::evaluate_uncached(const Nrlmsise00Input& input) const {
  const Basis b = basis_of(input, false);
  return to_output(
      evaluate_model(model_->c, input, b, DirectExpansions(model_->c, b, input.day_of_year, input.activity)));
}

Nrlmsise00Input Nrlmsise00Atmosphere::input_at(const AtmosphereQuery& query) {
  const core::GeodeticPosition geo = core::geodetic_from_itrf(query.r_itrf);
  const core::CalendarTime utc = query.t.calendar(core::TimeScale::kUtc);
  Nrlmsise00Input in;
  in.day_of_year = day_of_year(utc);
  // A leap second (23:59:60) is held at the day's end, the model's upper bound.
  in.ut_seconds = std::min(utc.hour * 3600.0 + utc.minute * 60.0 + utc.second + static_cast<double>(utc.nanosecond) * 1e-9,
                           86400.0);
  in.altitude_km = geo.height / 1e3;
  in.latitude_deg = geo.latitude / core::kDegToRad;
  in.longitude_deg = geo.longitude / core::kDegToRad;
  in.local_solar_time_h = in.ut_seconds / 3600.0 + in.longitude_deg / 15.0;
  in.activity = query.activity;
  return in;
}

double Nrlmsise00Atmosphere::density(const AtmosphereQuery& query) const {
  if (!query.r_itrf.allFinite()) return 0.0;
  const Nrlmsise00Input in = input_at(query);
  if (!(in.altitude_km * 1e3 >= kNrlmsise00MinHeight && in.altitude_km * 1e3 <= kNrlmsise00MaxHeight)) return 0.0;
  const Model::DayCache& cache = model_->day_cache(in.day_of_year, in.activity);
  if (!cache.usable) return 0.0;
  const Basis b = basis_of(in, true);
  return to_output(evaluate_model(model_->c, in, b, CachedExpansions(*model_, cache, b))).mass_density_with_anomalous_o;
}

}  // namespace visors::dynamics
