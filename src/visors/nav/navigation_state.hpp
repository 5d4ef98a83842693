#pragma once
// The state of the carrier-phase differential GPS navigation filter that each spacecraft runs on
// board, estimating both (the 74 states of Guffanti et al., AAS 23-149, 2023, sec. 4.2, eq. (1),
// extended by the multipath bank M; docs/algorithms/cdgps-filter.md#state): 98 states in a fixed
// layout, the same on both spacecraft, DSC block first:
//
//   [ DSC: r(3) v(3) a_emp(3) c dt(1) p(3) | OSC: r(3) v(3) a_emp(3) c dt(1) p(3) |
//     B(24): the local receiver's GRAPHIC ambiguities | N(24): SDCP ambiguities, OSC minus DSC |
//     M(24): SD carrier multipath, OSC minus DSC, one per N slot ]
//
// r, v: centre of mass, GCRF, at the filter epoch (the GPS time tag of the measurements);
// a_emp: empirical acceleration, first-order Gauss-Markov, in the spacecraft's RTN frame;
// c dt: receiver clock offset times c; p: error of the antenna phase-centre offset, body frame;
// B: GRAPHIC ambiguity of a satellite tracked by the local receiver (half the phase ambiguity);
// N: single-difference phase ambiguity of a satellite tracked by both receivers (not an integer:
// the receivers' phase offsets remain; only double differences are, nav/double_difference.hpp).
// M: the SD phase's multipath of the satellite in the same N slot, first-order Gauss-Markov
// (nav/sd_multipath.hpp); parked with its slot.
// Ambiguity slots are assigned to satellites as they rise, set and slip (nav/ambiguity_slots.hpp).
//
// Units: chosen so the diagonal of P spans less than ~1e10 from a converged relative solution to
// the priors (in SI it spans 1e-16 (m/s^2)^2 to 1e4 m^2, beyond double precision's reach in the
// Joseph products; docs/algorithms/cdgps-filter.md#units-and-scaling): velocity in mm/s, empirical
// acceleration in um/s^2, phase-centre offset error and multipath in mm; positions, clocks and B in
// m, N in cycles. to_si() / from_si() convert at the filter's edges; measurement partials and
// transitions are scaled by unit().

#include <Eigen/Core>

namespace visors::nav {

inline constexpr int kGpsSlots = 24;          // ambiguity slots per bank (GRAPHIC, SDCP)
inline constexpr int kSpacecraftStates = 13;  // r, v, a_emp, c dt, p
inline constexpr int kNavStates = 2 * kSpacecraftStates + 3 * kGpsSlots;  // 98

/// The two spacecraft, in the order of their blocks (conventions: DSC = chief, OSC = deputy).
enum class Craft { kDsc = 0, kOsc = 1 };

namespace state {
constexpr int block(Craft c) { return kSpacecraftStates * static_cast<int>(c); }
constexpr int position(Craft c) { return block(c) + 0; }              // 3 states [m]
constexpr int velocity(Craft c) { return block(c) + 3; }              // 3 states [mm/s]
constexpr int empirical_acceleration(Craft c) { return block(c) + 6; }  // 3 states, RTN [um/s^2]
constexpr int clock(Craft c) { return block(c) + 9; }                 // 1 state [m]
constexpr int phase_center(Craft c) { return block(c) + 10; }         // 3 states, body [mm]
inline constexpr int kGraphicAmbiguities = 2 * kSpacecraftStates;     // 24 states [m]
inline constexpr int kSdcpAmbiguities = kGraphicAmbiguities + kGpsSlots;  // 24 states [cycles]
inline constexpr int kSdMultipath = kSdcpAmbiguities + kGpsSlots;        // 24 states [mm]

inline constexpr double kVelocityUnit = 1e-3;     // [m/s] per state unit
inline constexpr double kEmpiricalUnit = 1e-6;    // [m/s^2] per state unit
inline constexpr double kPhaseCenterUnit = 1e-3;  // [m] per state unit
inline constexpr double kMultipathUnit = 1e-3;    // [m] per state unit
}  // namespace state

using NavVector = Eigen::Matrix<double, kNavStates, 1>;
using NavMatrix = Eigen::Matrix<double, kNavStates, kNavStates>;
/// One scalar measurement's partials dh/dx (a row of H), in state units.
using NavRow = Eigen::Matrix<double, 1, kNavStates>;

/// SI value of one unit of state i (m, m/s, m/s^2 or cycles): the diagonal of the scaling S with
/// x_si = S x.
double unit(int i);

}  // namespace visors::nav
