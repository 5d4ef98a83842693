#pragma once
// The flight component's maneuver buffer (Guffanti et al., AAS 23-149, 2023, sec. 4.3, control
// stack: planned maneuvers are kept, spread to the actuator's limits, until they are due): each
// planned impulse is split into actuator-sized, quantised pieces by control::buffer_impulse and
// stored with its absolute time. A new plan replaces the pieces not yet commanded. A piece is
// released when its time has come and the plenum has refilled since the previous one
// (ActuatorLimits::spacing_s); pieces of neighbouring impulses that overlap in time are therefore
// released late, in order, and the next plan corrects the small effect of the delay.
//
// Impulses are in the deputy convention (the OSC's velocity change, chief RTN); the component
// flips the sign when the DSC is the one firing.

#include <span>
#include <vector>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/control/maneuver_buffer.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/status.hpp"

namespace visors::gnc {

struct QueuedPiece {
  core::GpsTime t;
  Eigen::Vector3d dv_rtn = Eigen::Vector3d::Zero();  // deputy convention [m/s]
};

class ManeuverQueue {
 public:
  /// Room for `capacity` pieces (reserved once).
  explicit ManeuverQueue(int capacity = 2048);

  /// Drops every piece not yet released.
  void clear() { pieces_.clear(); next_ = 0; }
  /// Buffers the impulses of a plan made at `epoch` (impulse times in seconds since epoch;
  /// chief_mean_epoch the chief's mean elements there) for a spacecraft of `mass_kg` and appends
  /// the pieces, sorted by time. Errors: the buffer's, or "queue" when the capacity is exceeded.
  core::Outcome<int> add(core::GpsTime epoch, const astro::KeplerianElements& chief_mean_epoch,
                        std::span<const control::Impulse> impulses, double mass_kg,
                        const control::BufferSettings& settings);
  /// The next piece if its time has come (t >= piece time) and `spacing` seconds have passed since
  /// the last release.
  [[nodiscard]] bool due(core::GpsTime now, double spacing_s) const;
  QueuedPiece pop(core::GpsTime now);

  /// Time of the next piece (only when not empty).
  [[nodiscard]] core::GpsTime next_time() const { return pieces_[next_].t; }
  [[nodiscard]] int pending() const { return static_cast<int>(pieces_.size() - next_); }
  [[nodiscard]] bool empty() const { return pending() == 0; }
  [[nodiscard]] bool has_released() const { return released_; }
  [[nodiscard]] core::GpsTime last_release() const { return last_release_; }

 private:
  control::ImpulseBuffer buffer_;
  std::vector<QueuedPiece> pieces_;
  std::size_t next_ = 0;
  std::size_t capacity_ = 0;
  bool released_ = false;
  core::GpsTime last_release_;
};

}  // namespace visors::gnc
