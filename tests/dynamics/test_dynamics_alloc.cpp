// Flight-code memory rule (CONTRIBUTING "Memory"): after construction, a force-model evaluation,
// a propagation step sequence and a gravity evaluation with its gradient allocate nothing. This
// file counts every heap allocation of test_dynamics (malloc level).

#include <gtest/gtest.h>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"
#include "support/allocation_counter.hpp"

namespace visors::dynamics {
namespace {

using visors::test::count_allocations;

const core::GpsTime kEpoch = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();

core::StateVector chief() {
  return astro::cartesian_from_keplerian(
      {6878136.3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad, 1.5707963, 0.0}, 3.986004415e14);
}

TEST(DynamicsAllocation, CounterSeesConstructionAllocations) {
  EXPECT_GT(count_allocations([] { (void)files::load_force_model(ForceModelConfig::onboard(), {}); }), 0);
}

// Both presets: gravity, frame refresh, space weather lookup, atmosphere, SRP, Sun, Moon.
TEST(DynamicsAllocation, ForceModelEvaluationAllocatesNothing) {
  for (const ForceModelConfig& config : {ForceModelConfig::onboard(), ForceModelConfig::truth()}) {
    auto created = files::load_force_model(config, {});
    ASSERT_TRUE(created.ok());
    ForceModel forces = std::move(created).value();
    forces.set_empirical_acceleration_rtn({1e-7, 2e-7, 0.0});
    const core::StateVector x = chief();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    const long allocations = count_allocations([&] {
      for (int k = 0; k < 100; ++k) sum += forces.acceleration(kEpoch + 700.0 * k, x);  // crosses refreshes
    });
    EXPECT_EQ(allocations, 0);
    EXPECT_TRUE(sum.allFinite());
  }
}

// RK4 (dynamic step) and the DP8(7) reference over 20 minutes with a maneuver.
TEST(DynamicsAllocation, PropagationAllocatesNothing) {
  auto created = files::load_force_model(ForceModelConfig::onboard(), {});
  ASSERT_TRUE(created.ok());
  ForceModel forces = std::move(created).value();
  for (const IntegratorKind kind : {IntegratorKind::kRk4Dynamic, IntegratorKind::kDormandPrince87}) {
    PropagatorSettings settings;
    settings.integrator = kind;
    OrbitPropagator propagator = OrbitPropagator::create(forces, settings).value();
    const ImpulsiveManeuver burn{kEpoch + 333.3, {0.0, 0.01, 0.0}, ManeuverFrame::kRtn};
    bool ok = false;
    const long allocations = count_allocations([&] {
      ok = propagator.propagate_to(kEpoch, chief(), kEpoch + 1200.0, std::span(&burn, 1)).ok();
    });
    EXPECT_TRUE(ok);
    EXPECT_EQ(allocations, 0) << "integrator " << static_cast<int>(kind);
  }
}

TEST(DynamicsAllocation, GravityAccelerationAndGradientAllocateNothing) {
  auto sh = SphericalHarmonicGravity::create(embedded_gravity_field(), 8, 8);
  ASSERT_TRUE(sh.ok());
  SphericalHarmonicGravity gravity = std::move(sh).value();
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  const long allocations = count_allocations([&] {
    g += gravity.gradient({7e6, 1e5, 2e5});
    g.col(0) += gravity.acceleration({7e6, 1e5, 2e5});
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_TRUE(g.allFinite());
}

}  // namespace
}  // namespace visors::dynamics
