#pragma once
// Body-frame geometry of one spacecraft with its truth errors, drawn once per run (ground side of
// the simulator): where the centre of mass really is, where the payload reference point really is
// (photon sieve centre on the OSC, detector aperture centre on the DSC) and where the payload
// really points. The flight code knows only the nominal values; the difference is what the
// alignment budget must absorb.
//
// Positions are body-frame vectors from the structural origin [m] (docs/conventions.md).
//
// Draws, in this order, from the stream given to draw(): centre-of-mass offset (x, y, z), each
// N(0, com_sigma_m); payload-point mounting offset (x, y, z), each N(0, payload_position_sigma_m);
// payload pointing tilts t1, t2, each N(0, payload_pointing_sigma_rad), about the two unit axes
// e1, e2 normal to the nominal payload axis (right-handed (e1, e2, axis), e1 = axis x the
// coordinate axis least aligned with it). The true axis is the nominal one rotated by the rotation
// vector t1 e1 + t2 e2: a per-axis 1-sigma tilt, so the total misalignment has RMS sqrt(2) sigma.
// Eight numbers are drawn whatever the sigmas, so zero-sigma runs keep the stream aligned. Then
// the static error in the knowledge of the centre of mass (Guffanti et al., AAS 23-149, 2023,
// sec. 5, "Monte Carlo alignment performances", the swept centre-of-mass knowledge error: the
// on-board centre of mass is off the true one by this much, whatever its variation): a vector of
// length com_knowledge_error_m along a uniformly random direction (three more normal draws,
// normalised; drawn whatever the length), added to the true centre of mass. Last, the error of
// the GPS antenna's phase centre (x, y, z), each N(0, phase_center_knowledge_sigma_m): the true
// phase centre is the nominal one (antenna reference point + the calibrated offset along the true
// boresight, sim/gps_receiver.hpp) plus this vector; the flight software knows the nominal one only.
// Defaults and their sources: docs/requirements.md#internal-geometry ("the paper" below:
// Guffanti et al., AAS 23-149, 2023, whose Table 1(a) gives the 1-sigma geometry uncertainties).

#include <Eigen/Core>

#include "visors/core/constants.hpp"
#include "visors/core/result.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct GeometrySettings {
  Eigen::Vector3d com_nominal_body_m = Eigen::Vector3d::Zero();  // known centre of mass [m]
  double com_sigma_m = 3.0e-3;  // 1-sigma centre-of-mass variation per axis [m] (paper, Table 1(a))
  double com_knowledge_error_m = 0.0;  // length of the centre-of-mass knowledge error [m] (3D)
  /// Known payload reference point [m]; default on the +X face (project choice: the paper gives
  /// no payload position; docs/requirements.md#internal-geometry).
  Eigen::Vector3d payload_nominal_body_m = Eigen::Vector3d(0.15, 0.0, 0.0);
  double payload_position_sigma_m = 0.5e-3;  // 1-sigma mounting error per axis [m] (paper, Table 1(a))
  Eigen::Vector3d payload_axis_nominal_body = Eigen::Vector3d::UnitX();  // known line of sight (unit)
  double payload_pointing_sigma_rad = 30.0 * core::kArcsecToRad;  // 1-sigma tilt per axis [rad] (paper, Table 1(a))
  /// 1-sigma error per axis of the GPS antenna phase centre against its calibration [m]. The
  /// paper lists the phase-centre offset among the uncertain internal components and
  /// estimates it on board; 5 mm is larger than the 3 mm centre-of-mass variation, as the paper
  /// expects of an uncalibrated CubeSat patch antenna (docs/truth-and-knowledge.md).
  double phase_center_knowledge_sigma_m = 5.0e-3;

  /// Ok, or the offending field by name (sigmas finite and >= 0, vectors finite, axis non-zero).
  [[nodiscard]] core::Result<bool> validate() const;
};

class SpacecraftGeometry {
 public:
  /// Draws the truth errors (file comment) around the nominal values. `settings` should have
  /// passed validate(); the nominal axis is normalised here.
  static SpacecraftGeometry draw(const GeometrySettings& settings, RandomStream& rng);

  // Truth (simulator only).
  [[nodiscard]] const Eigen::Vector3d& com_body_m() const { return com_body_m_; }
  [[nodiscard]] const Eigen::Vector3d& payload_body_m() const { return payload_body_m_; }
  /// True payload point minus true centre of mass, body frame [m].
  [[nodiscard]] Eigen::Vector3d payload_from_com_body_m() const { return payload_body_m_ - com_body_m_; }
  /// True payload line of sight, body frame (unit).
  [[nodiscard]] const Eigen::Vector3d& payload_axis_body() const { return payload_axis_body_; }
  /// True GPS antenna phase centre minus its nominal (calibrated) position, body frame [m].
  [[nodiscard]] const Eigen::Vector3d& phase_center_error_body_m() const { return phase_center_error_body_m_; }

  // Nominal (known on board).
  [[nodiscard]] const Eigen::Vector3d& com_nominal_body_m() const { return com_nominal_body_m_; }
  [[nodiscard]] const Eigen::Vector3d& payload_nominal_body_m() const { return payload_nominal_body_m_; }
  [[nodiscard]] Eigen::Vector3d payload_from_com_nominal_body_m() const {
    return payload_nominal_body_m_ - com_nominal_body_m_;
  }
  [[nodiscard]] const Eigen::Vector3d& payload_axis_nominal_body() const { return payload_axis_nominal_body_; }

 private:
  SpacecraftGeometry() = default;

  Eigen::Vector3d com_body_m_, payload_body_m_, payload_axis_body_, phase_center_error_body_m_;
  Eigen::Vector3d com_nominal_body_m_, payload_nominal_body_m_, payload_axis_nominal_body_;
};

}  // namespace visors::sim
