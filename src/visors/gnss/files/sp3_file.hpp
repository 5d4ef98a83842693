#pragma once
// Precise GPS orbits and clocks in the SP3 format, versions c and d (IGS / NGS, "The Extended
// Standard Product 3 Orbit Format (SP3-d)", Hilla 2016, sections 2-3; SP3-c, Hilla 2010). Ground
// side. Positions are Earth-fixed (the file's ITRF realisation) of the satellite's CENTRE OF MASS;
// the broadcast ephemeris instead gives the antenna phase centre the control segment uses.
//
// Read: the '#c'/'#d' line (version, position/velocity flag, start, number of epochs, coordinate
// system), the '+ ' satellite list, the '%c' time system (only GPS time is accepted), the '*'
// epoch lines and the 'P' records of GPS satellites ('G' or a blank system letter); records of
// other systems, 'V'/'E'/'EP'/'EV' lines and comments are skipped. Units converted at the edge:
// km -> m, microseconds -> s. A zero position (0, 0, 0) or a 999999.999999 clock is "missing".
//
// Interpolation: Lagrange polynomial of degree 9 in time through 10 consecutive epochs centred on
// t (shifted inside the file at its ends). On 15-minute IGS orbits this reproduces a held-out
// epoch to a few millimetres (tests/gnss/test_sp3_file.cpp).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss::files {

class Sp3Orbit {
 public:
  /// Reads an SP3-c or SP3-d file. Errors name "<path>:<line>" (or the path) and the field.
  static core::Result<Sp3Orbit> read(const std::filesystem::path& path);

  [[nodiscard]] char version() const { return version_; }  // 'c' or 'd'
  [[nodiscard]] const std::string& coordinate_system() const { return coordinate_system_; }
  [[nodiscard]] const std::vector<core::GpsTime>& epochs() const { return epochs_; }

  /// Position [m] of `prn` at epoch `index`; nullopt when missing (or prn outside 1..32).
  [[nodiscard]] std::optional<Eigen::Vector3d> position_m(int prn, std::size_t index) const;
  /// Clock offset [s] of `prn` at epoch `index`; nullopt when missing.
  [[nodiscard]] std::optional<double> clock_s(int prn, std::size_t index) const;

  /// Lagrange-interpolated position [m] at t. Errors: "t" outside the file's span, or fewer than
  /// 10 epochs; "prn" when one of the 10 epochs used has no position for it.
  [[nodiscard]] core::Result<Eigen::Vector3d> interpolate_m(int prn, core::GpsTime t) const;

  /// The same orbit without epoch `index` (to test interpolation on held-out epochs).
  [[nodiscard]] Sp3Orbit without_epoch(std::size_t index) const;

 private:
  static constexpr std::size_t kSlots = kMaxGpsPrn;
  struct Sample {
    Eigen::Vector3d r_m = Eigen::Vector3d::Zero();
    double clock_s = 0.0;
    bool has_position = false;
    bool has_clock = false;
  };
  const Sample* sample(int prn, std::size_t index) const;

  char version_ = 'd';
  std::string coordinate_system_;
  std::vector<core::GpsTime> epochs_;
  std::vector<Sample> samples_;  // epoch-major: samples_[index * kSlots + prn - 1]
};

}  // namespace visors::gnss::files
