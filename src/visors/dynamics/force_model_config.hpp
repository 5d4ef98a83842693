#pragma once
// Force-model configuration as plain data: which terms, the gravity field and its truncation, the
// atmosphere, the spacecraft's ballistic properties. Two presets follow Guffanti et al.,
// AAS 23-149, 2023, Table 4 (ground-truth vs on-board numerical model; the departures are listed
// in docs/algorithms/dynamics.md#truth-and-on-board-models); everything can be overridden from
// TOML (config/force_model_toml.hpp) or in code.

#include <string>

#include <Eigen/Core>

#include "visors/dynamics/atmosphere.hpp"
#include "visors/dynamics/solar_radiation_pressure.hpp"

namespace visors::dynamics {

/// Ballistic properties of one spacecraft. Defaults: the detector spacecraft (DSC) of Guffanti et
/// al., AAS 23-149, 2023, Table 4 (wet mass 11.35 kg, Cd 2.2, Cr 1.8, cross-section 0.15-0.55 m^2:
/// the mean 0.35 m^2).
struct SpacecraftProperties {
  double mass = 11.35;     // [kg]
  double drag_area = 0.35; // [m^2], attitude dependent; updated by the caller when it changes
  double cd = 2.2;         // drag coefficient [-]
  double srp_area = 0.35;  // [m^2]
  double cr = 1.8;         // radiation-pressure coefficient [-]
};

struct GravityConfig {
  /// ICGEM file, absolute or relative to the data search path.
  std::string model = "gravity/GGM05S_d90.gfc";
  int degree = 60;
  int order = 60;
  /// When the file is not found, use the embedded degree-8 field instead of failing (the truth
  /// and on-board models then differ only in truncation; a warning is recorded).
  bool allow_embedded_fallback = true;
};

enum class AtmosphereKind {
  kHarrisPriester,         // modified Harris-Priester, diurnal bulge (on board)
  kHarrisPriesterMaximum,  // apex (maximum) densities everywhere (a crude high-activity stand-in)
  kNrlmsise00,             // NRLMSISE-00 (dynamics/nrlmsise00.hpp), the truth
};

struct DragConfig {
  bool enabled = true;
  AtmosphereKind atmosphere = AtmosphereKind::kHarrisPriester;
  int cosine_exponent = 6;   // Harris-Priester n (6: polar orbits)
  double density_scale = 1.0;
  /// CelesTrak space-weather CSV (data-relative or absolute); empty: use `activity` constantly.
  std::string space_weather;
  /// With NRLMSISE-00 and a space-weather file: drive the model's ap-history mode (switch 9 = -1)
  /// with the file's 3-hourly ap, refreshed every 3 hours; false: the daily-Ap mode, refreshed
  /// daily. The history mode follows storms within the day; the price is a forcing that jumps
  /// every 3 hours (as the published model's input does), which integrators cross with an error
  /// of order (jump x step) that is not truncation error (tests/dynamics/test_orbit_propagator.cpp).
  bool ap_history = true;
  SolarActivity activity;
  /// NRLMSISE-00 coefficient tables (data-relative or absolute), read when `atmosphere` is
  /// kNrlmsise00; not found: Harris-Priester maximum with a warning.
  std::string nrlmsise00_coefficients = "atmosphere/nrlmsise00_coefficients.txt";
};

enum class ShadowModel { kNone, kCylindrical, kConical };

struct SrpConfig {
  bool enabled = true;
  double pressure_1au = kSolarPressureAt1Au;  // [N/m^2]
  ShadowModel shadow = ShadowModel::kCylindrical;
};

struct EarthFrameConfig {
  /// IERS finals2000A file for x_p, y_p, UT1-UTC, LOD (data-relative or absolute); empty or not
  /// found: zero EOP (a ~0.3" / 10 m orientation error, the on-board situation without uplink).
  std::string eop;
  /// Refresh interval of the cached precession-nutation (core::OnboardEarthFrame) [s].
  double refresh_interval = 600.0;
};

struct ForceModelConfig {
  GravityConfig gravity;
  DragConfig drag;
  SrpConfig srp;
  bool sun = true;
  bool moon = true;
  EarthFrameConfig earth_frame;
  /// Constant empirical acceleration in the spacecraft's RTN frame [m/s^2] (the navigation
  /// filter's estimate, or a test input).
  Eigen::Vector3d empirical_rtn = Eigen::Vector3d::Zero();

  /// Ground truth (Guffanti et al., AAS 23-149, 2023, Table 4): GGM05S 60x60, NRLMSISE-00 driven
  /// by the observed space weather (F10.7, daily Ap and the 3-hourly ap history), SRP with the
  /// conical (penumbra) shadow (the table has the cylindrical one; the conical is continuous for
  /// fixed-step RK4), Sun and Moon, EOP from the IERS file, frame refresh 60 s.
  static ForceModelConfig truth();
  /// On-board numerical model: GGM01S 20x20, Harris-Priester with mean activity, SRP with the
  /// cylindrical shadow, Sun, Moon,
  /// no EOP file (uplinked constants), frame refresh 600 s.
  static ForceModelConfig onboard();
  /// The on-board gravity field truncated to (degree, order) and nothing else: degree 0 is
  /// two-body motion, (2, 0) the J2 problem (test references and analyses).
  static ForceModelConfig gravity_only(int degree, int order);
};

}  // namespace visors::dynamics
