#pragma once
// Modified Harris-Priester atmosphere, Montenbruck & Gill, Satellite Orbits (2000), sec. 3.5.2.
//
// Tabulated antapex (minimum) and apex (maximum) densities rho_m(h_i), rho_M(h_i) of the diurnal
// bulge, 100..1000 km; between nodes each is interpolated exponentially,
//   rho(h) = rho_i exp((h_i - h) / H_i),  H_i = (h_i - h_{i+1}) / ln(rho_{i+1} / rho_i),
// and the density is
//   rho = rho_m(h) + (rho_M(h) - rho_m(h)) cos^n(psi / 2),  cos^2(psi/2) = (1 + cos psi) / 2,
// psi the angle between the satellite position and the bulge apex, which lags the Sun by
// lambda_lag = 30 deg in right ascension: e_b = R_z(lambda_lag) r_sun / |r_sun| (the same as
// (cos d cos(a + lag), cos d sin(a + lag), sin d) for the Sun's right ascension a, declination d).
// h is the height above the WGS-84 ellipsoid (core::geodetic_from_itrf of the query's r_itrf).
//
// Exponent conventions (all the same model, different parameters): here n is the power of
// cos(psi/2) as in the equation above; M&G's reference code has n_prm = 3 and raises cos^2(psi/2)
// to it (n = 6); Orekit's HarrisPriester also takes the power of cos(psi/2), default 4. M&G
// recommend n = 2 for low-inclination and n = 6 for polar orbits: VISORS (97.4 deg SSO) takes 6.
//
// Range: heights from the table's first to its last node, both included (100..1000 km for M&G's
// table), so every node is reachable; outside, density() returns 0 (M&G's code also returns 0 AT
// the ends; Orekit throws below 100 km).
//
// Solar activity: the published table is for mean solar activity (M&G sec. 3.5.2, "mean solar
// activity"); it is taken to represent F10.7 = 150 sfu (the conventional mean level). A model may
// hold several tables, each tagged with its F10.7 level; density() uses the table whose level is
// closest to the query's 81-day mean activity.f107a (ties: the lower level). With one table it is
// always that table. The model has no geomagnetic (Ap) dependence.
//
// Bulge variants: kDiurnal is the model above. kApexMaximum returns rho_M(h) everywhere, the
// upper envelope: the truth's fallback when the NRLMSISE-00 tables are missing, a crude stand-in
// for high activity that is NOT a validated high-activity model.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/dynamics/atmosphere.hpp"

namespace visors::dynamics {

/// One Harris-Priester table: node heights and the antapex/apex densities.
struct HarrisPriesterTable {
  std::vector<double> height_m;  // geodetic height of the nodes, strictly increasing [m]
  std::vector<double> rho_min;   // antapex density [kg/m^3]
  std::vector<double> rho_max;   // apex density [kg/m^3]
  double f107 = 150.0;           // F10.7 level the table represents [sfu]
};

/// M&G's F10.7 level of the published table [sfu] (mean solar activity, see the file comment).
inline constexpr double kHarrisPriesterMeanF107 = 150.0;

/// The published M&G table (50 nodes, 100..1000 km) compiled in, tagged F10.7 = 150 sfu.
HarrisPriesterTable embedded_harris_priester_table();

/// Checks one table: F10.7 level (check_harris_priester_f107), equal sizes, at least 2 nodes,
/// each node as harris_priester_node_problem; errors name the field and index ("node[i]").
core::Result<HarrisPriesterTable> validate_harris_priester_table(HarrisPriesterTable table);

/// The problem of one node, or nullopt when it is valid: values finite, height above
/// `previous_height_m` (the preceding node's, when there is one), densities > 0, rho_min <=
/// rho_max. The per-node rule of validate_harris_priester_table (the file reader,
/// dynamics/files/harris_priester_file.hpp, names the line with it).
std::optional<std::string> harris_priester_node_problem(double height_m, double rho_min, double rho_max,
                                                        std::optional<double> previous_height_m);

/// `f107` when finite and > 0 [sfu]; else an error naming "f107".
core::Result<double> check_harris_priester_f107(double f107);

enum class HarrisPriesterBulge {
  kDiurnal,      // rho_m + (rho_M - rho_m) cos^n(psi/2)
  kApexMaximum,  // rho_M everywhere (upper envelope, see the file comment)
};

struct HarrisPriesterSettings {
  double cosine_exponent = 6.0;       // n, power of cos(psi/2), > 0 [-] (6: polar orbits)
  double bulge_lag = 0.5235987755982988;  // lambda_lag, 30 deg, |lag| <= pi [rad]
  HarrisPriesterBulge bulge = HarrisPriesterBulge::kDiurnal;
  double density_scale = 1.0;         // multiplies the result, > 0 [-]
};

class HarrisPriesterAtmosphere final : public AtmosphereModel {
 public:
  /// Validates the settings (errors name "cosine_exponent", "bulge_lag", "density_scale") and
  /// every table ("tables[k]...."); at least one table, F10.7 levels distinct.
  static core::Result<HarrisPriesterAtmosphere> create(std::vector<HarrisPriesterTable> tables,
                                                       const HarrisPriesterSettings& settings = {});
  /// With the embedded M&G table.
  static core::Result<HarrisPriesterAtmosphere> create(const HarrisPriesterSettings& settings = {});

  /// Density [kg/m^3] at the query (uses r_gcrf, r_itrf, sun_gcrf, activity.f107a). No
  /// allocation. 0 outside [100, 1000] km or for a zero r_gcrf/sun_gcrf in the diurnal mode.
  [[nodiscard]] double density(const AtmosphereQuery& query) const override;

  /// The same with the geodetic height given [m] (no geodetic conversion).
  [[nodiscard]] double density(double height_m, const Eigen::Vector3d& r_gcrf,
                               const Eigen::Vector3d& sun_gcrf, double f107a) const;

  /// Index into tables() of the table used for an 81-day mean F10.7 [sfu].
  [[nodiscard]] std::size_t table_index(double f107a) const;
  [[nodiscard]] const std::vector<HarrisPriesterTable>& tables() const { return tables_; }
  [[nodiscard]] const HarrisPriesterSettings& settings() const { return settings_; }

 private:
  // Per table: 1/H_i of both envelopes for each interval [h_i, h_{i+1}] [1/m].
  struct InverseScaleHeights {
    std::vector<double> min;
    std::vector<double> max;
  };
  HarrisPriesterAtmosphere(std::vector<HarrisPriesterTable> tables,
                           std::vector<InverseScaleHeights> inverse_scale_heights,
                           const HarrisPriesterSettings& settings);

  std::vector<HarrisPriesterTable> tables_;  // sorted by f107
  std::vector<InverseScaleHeights> inverse_scale_heights_;
  HarrisPriesterSettings settings_;
  double cos_lag_ = 1.0;  // cos(bulge_lag) [-]
  double sin_lag_ = 0.0;  // sin(bulge_lag) [-]
};

}  // namespace visors::dynamics
