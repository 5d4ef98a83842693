#include "visors/nav/point_positioning.hpp"

#include <array>
#include <cmath>

#include <Eigen/Cholesky>

#include "visors/nav/gps_range_model.hpp"

namespace visors::nav {
namespace {

constexpr int kIterations = 10;
constexpr double kConvergedM = 1e-4;  // last correction [m]

struct Design {
  Eigen::Matrix<double, kGpsSlots, 4> A = Eigen::Matrix<double, kGpsSlots, 4>::Zero();
  Eigen::Matrix<double, kGpsSlots, 1> y = Eigen::Matrix<double, kGpsSlots, 1>::Zero();
  int rows = 0;
};

Design linearise(const GpsReceiverEpoch& epoch, const gnss::EphemerisSource& ephemerides, core::OnboardEarthFrame& frame,
                 const ReceiverEstimate& at) {
  Design d;
  const AntennaGeometry antenna;  // the solution is the phase centre itself
  for (int i = 0; i < epoch.count; ++i) {
    const GpsObservation& o = epoch.observations[static_cast<std::size_t>(i)];
    const gnss::BroadcastEphemeris* e = ephemerides.select(o.prn, epoch.t);
    if (e == nullptr) continue;
    const RangePrediction p = predict_range(epoch.t, at, antenna, *e, frame);
    d.A.row(d.rows) << p.d_position, 1.0 + p.d_clock;
    d.y(d.rows) = o.code_m - (p.range_m + at.clock_m - p.satellite_clock_m);
    ++d.rows;
  }
  return d;
}

}  // namespace

PointSolution solve_point_position(const GpsReceiverEpoch& epoch, const gnss::EphemerisSource& ephemerides,
                                   core::OnboardEarthFrame& frame, const Eigen::Vector3d& guess_gcrf_m, double max_rms_m) {
  PointSolution out;
  ReceiverEstimate at;
  at.r_gcrf_m = guess_gcrf_m;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    const Design d = linearise(epoch, ephemerides, frame, at);
    out.satellites = d.rows;
    if (d.rows < 5) {
      out.reason = "too_few_satellites";
      return out;
    }
    const auto A = d.A.topRows(d.rows);
    const Eigen::Vector4d dx = (A.transpose() * A).ldlt().solve(A.transpose() * d.y.head(d.rows));
    if (!dx.allFinite()) break;
    at.r_gcrf_m += dx.head<3>();
    at.clock_m += dx(3);
    if (dx.norm() < kConvergedM) {
      const Design post = linearise(epoch, ephemerides, frame, at);
      out.rms_m = std::sqrt(post.y.head(post.rows).squaredNorm() / (post.rows - 4));
      out.r_gcrf_m = at.r_gcrf_m;
      out.clock_m = at.clock_m;
      out.ok = out.rms_m <= max_rms_m;
      out.reason = out.ok ? "" : "residuals";
      return out;
    }
  }
  out.reason = "not_converged";
  return out;
}

}  // namespace visors::nav
