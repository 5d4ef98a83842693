// The ambiguity resolution allocates nothing after creation (CONTRIBUTING.md, flight-code rules,
// "Memory"): this file counts every heap allocation of the test_nav executable
// (support/allocation_counter.hpp, malloc level) around decorrelation, search, partial search and
// acceptance, on 24-ambiguity dual-frequency problems and on the capacity-sized 64; and around the
// SD -> DD transformation, the fixed constraints and the fixed-solution update of a filter of 3 +
// 64 states with 62 DD ambiguities (32 satellites, L1 and L2); around the Gauss-Markov chain
// (transition and process noise of the empirical accelerations); and around the 98-state navigation
// filter's ambiguity slots (acquire, reinitialise, release, checks), its scalar Joseph update
// (accepted, gated, refused) and its whole epoch (CdgpsFilter predict + update).
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <memory>
#include <random>
#include <vector>

#include "visors/gnss/ephemeris_set.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"
#include "visors/nav/ambiguity_slots.hpp"
#include "visors/nav/cdgps_filter.hpp"
#include "visors/nav/double_difference.hpp"
#include "visors/nav/fixed_solution.hpp"
#include "visors/nav/gauss_markov.hpp"
#include "visors/nav/integer_least_squares.hpp"
#include "visors/nav/scalar_update.hpp"
#include "support/allocation_counter.hpp"
#include "support/dd_geometry.hpp"
#include "support/synthetic_gps.hpp"

namespace visors::nav {
namespace {

// (The counter's control tests, an Eigen dynamic matrix and a new, come with the header.)

struct Problem {
  Eigen::VectorXd a;
  Eigen::MatrixXd Q;
};

Problem dd_problem(int satellites, std::mt19937_64& rng) {
  test::DdGeometryOptions o;
  o.satellites = satellites;
  o.frequencies = 2;
  Problem p;
  p.Q = test::dd_ambiguity_covariance(o, rng);
  const Eigen::MatrixXd chol = p.Q.llt().matrixL();
  p.a = test::float_ambiguities(test::random_integers(p.Q.rows(), 1e6, rng), chol, rng);
  return p;
}

TEST(NavAllocation, ResolveAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(3);
  for (int k = 0; k < 10; ++k) {
    const Problem p = dd_problem(13, rng);  // n = 24
    IlsStatus status = IlsStatus::kEmpty;
    EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(p.a, p.Q); }), 0);
    EXPECT_EQ(status, IlsStatus::kOk);
  }
}

TEST(NavAllocation, PartialSearchAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(4);
  const Problem p = dd_problem(13, rng);
  ASSERT_EQ(ils.decorrelate(p.a, p.Q), IlsStatus::kOk);
  IlsStatus status = IlsStatus::kEmpty;
  EXPECT_EQ(test::count_allocations([&] { status = ils.search(10); }), 0);
  EXPECT_EQ(status, IlsStatus::kOk);
}

TEST(NavAllocation, AcceptanceAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(5);
  const Problem p = dd_problem(13, rng);
  AmbiguityFix fix;
  EXPECT_EQ(test::count_allocations([&] { fix = resolve_ambiguities(ils, p.a, p.Q, AcceptanceSettings{}); }), 0);
  EXPECT_NE(fix.reason, FloatReason::kInvalidInput);
}

TEST(NavAllocation, CapacitySizedProblemAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  std::mt19937_64 rng(6);
  const Problem p = dd_problem(33, rng);  // n = 64 = kMaxAmbiguities
  ASSERT_EQ(p.a.size(), kMaxAmbiguities);
  IlsStatus status = IlsStatus::kEmpty;
  EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(p.a, p.Q); }), 0);
  EXPECT_EQ(status, IlsStatus::kOk);
}

TEST(NavAllocation, RejectedInputAllocatesNothing) {
  auto ils = IntegerLeastSquares::create().value();
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(4, 4);
  Q(0, 1) = 0.5;  // not symmetric
  const Eigen::VectorXd a = Eigen::VectorXd::Zero(4);
  IlsStatus status = IlsStatus::kOk;
  EXPECT_EQ(test::count_allocations([&] { status = ils.resolve(a, Q); }), 0);
  EXPECT_EQ(status, IlsStatus::kNotSymmetric);
}

// An SD filter at capacity: [baseline 3, SD L1 of 32 satellites, SD L2 of the same 32] (67
// states), DD ambiguities with the highest satellite as reference on both frequencies (62).
struct SdFilterAtCapacity {
  static constexpr int kSatellites = 32;
  static constexpr Eigen::Index kStates = 3 + 2 * kSatellites;
  Eigen::VectorXd x;
  Eigen::MatrixXd P;
  DoubleDifferenceAmbiguities dd = DoubleDifferenceAmbiguities::create(kStates).value();
};

SdFilterAtCapacity sd_filter_at_capacity(std::mt19937_64& rng) {
  test::DdGeometryOptions o;
  o.satellites = SdFilterAtCapacity::kSatellites;
  o.frequencies = 2;
  const test::LinesOfSight sight = test::draw_lines_of_sight(o.satellites, rng);
  SdFilterAtCapacity f;
  f.P = test::sd_filter_covariance(sight, o, 0.05);
  Eigen::VectorXd truth = Eigen::VectorXd::Zero(SdFilterAtCapacity::kStates);
  truth.tail(2 * o.satellites) = test::random_integers(2 * o.satellites, 1e6, rng).array() + 0.37;
  const Eigen::MatrixXd chol = f.P.llt().matrixL();
  f.x = test::float_ambiguities(truth, chol, rng);
  EXPECT_TRUE(f.dd.reset(SdFilterAtCapacity::kStates));
  for (int frequency = 0; frequency < 2; ++frequency) {
    const Eigen::Index first = 3 + frequency * o.satellites;
    std::vector<Eigen::Index> others;
    for (int i = 0; i < o.satellites; ++i) {
      if (i != sight.reference) others.push_back(first + i);
    }
    EXPECT_TRUE(f.dd.add_group(first + sight.reference, others));
  }
  return f;
}

TEST(NavAllocation, DoubleDifferenceEvaluateAllocatesNothing) {
  std::mt19937_64 rng(7);
  SdFilterAtCapacity f = sd_filter_at_capacity(rng);
  ASSERT_EQ(f.dd.size(), 62);
  bool ok = false;
  EXPECT_EQ(test::count_allocations([&] { ok = f.dd.evaluate(f.x, f.P); }), 0);
  EXPECT_TRUE(ok);
}

struct FixedAtCapacity {
  AmbiguityFix fix;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(kMaxAmbiguities, SdFilterAtCapacity::kStates);
  Eigen::VectorXd z = Eigen::VectorXd::Zero(kMaxAmbiguities);
  Eigen::Index k = 0;
};

TEST(NavAllocation, FixedConstraintsAllocateNothing) {
  std::mt19937_64 rng(8);
  SdFilterAtCapacity f = sd_filter_at_capacity(rng);
  ASSERT_TRUE(f.dd.evaluate(f.x, f.P));
  auto ils = IntegerLeastSquares::create().value();
  FixedAtCapacity fixed;
  fixed.fix = resolve_ambiguities(ils, f.dd.a(), f.dd.Q(), AcceptanceSettings{});
  ASSERT_EQ(fixed.fix.outcome, FixOutcome::kFixed);
  EXPECT_EQ(test::count_allocations([&] { fixed.k = fixed_constraints(fixed.fix, ils, f.dd, fixed.C, fixed.z); }), 0);
  EXPECT_EQ(fixed.k, 62);
}

// The fixed-solution update of a filter at capacity, exact (0) and hold (1e-3) variances, with
// `mask` (empty: the optimal form): allocations counted around apply() only.
void expect_fixed_solution_update_allocates_nothing(std::uint64_t seed, const Eigen::VectorXd& mask) {
  std::mt19937_64 rng(seed);
  SdFilterAtCapacity f = sd_filter_at_capacity(rng);
  ASSERT_TRUE(f.dd.evaluate(f.x, f.P));
  auto ils = IntegerLeastSquares::create().value();
  FixedAtCapacity fixed;
  fixed.fix = resolve_ambiguities(ils, f.dd.a(), f.dd.Q(), AcceptanceSettings{});
  fixed.k = fixed_constraints(fixed.fix, ils, f.dd, fixed.C, fixed.z);
  ASSERT_EQ(fixed.k, 62);
  auto update = FixedSolutionUpdate::create(SdFilterAtCapacity::kStates).value();
  for (const double variance : {0.0, 1e-3}) {  // exact conditioning and hold
    Eigen::VectorXd x = f.x;
    Eigen::MatrixXd P = f.P;
    auto status = FixedSolutionUpdate::Status::kSizeMismatch;
    const auto C = fixed.C.topRows(fixed.k);
    const auto z = fixed.z.head(fixed.k);
    EXPECT_EQ(test::count_allocations([&] {
                status = mask.size() == 0 ? update.apply(x, P, C, z, variance) : update.apply(x, P, C, z, variance, mask);
              }),
              0);
    EXPECT_EQ(status, FixedSolutionUpdate::Status::kOk) << variance;
  }
}

TEST(NavAllocation, FixedSolutionUpdateAllocatesNothing) { expect_fixed_solution_update_allocates_nothing(9, {}); }

// The consider form (phase-centre states held between attitude turns): its Joseph products at
// capacity, in the caller's and the update's preallocated storage.
TEST(NavAllocation, ConsiderFixedSolutionUpdateAllocatesNothing) {
  Eigen::VectorXd mask = Eigen::VectorXd::Ones(SdFilterAtCapacity::kStates);
  mask.head(3).setZero();
  expect_fixed_solution_update_allocates_nothing(10, mask);
}

// The Gauss-Markov chain is computed in a step when dt varies: fixed-size Eigen only.
TEST(NavAllocation, GaussMarkovChainAllocatesNothing) {
  GaussMarkovChain chain{};
  EXPECT_EQ(test::count_allocations([&] {
              chain = gauss_markov_chain(10.0, 600.0, 5e-8);  // series branch
              chain.noise += gauss_markov_chain(10.0, 1.0, 5e-8).noise;  // closed-form branch
            }),
            0);
}

// The 98-state filter, built (heap) before counting.
struct NavFilter {
  NavVector x = NavVector::Zero();
  NavMatrix P = NavMatrix::Identity();
  ScalarUpdateWorkspace ws;
  AmbiguitySlotBank sdcp = AmbiguitySlotBank::create(state::kSdcpAmbiguities).value();
};

TEST(NavAllocation, AmbiguitySlotsAllocateNothing) {
  auto f = std::make_unique<NavFilter>();
  f->sdcp.release_all(f->x, f->P);
  int refused = 0;
  bool all_ok = true;
  EXPECT_EQ(test::count_allocations([&] {
              for (int prn = 1; prn <= kGpsSlots + 1; ++prn) {  // the 25th is refused: bank full
                if (f->sdcp.acquire(prn, 0.5 * prn, 1e4, f->x, f->P) < 0) ++refused;
              }
              all_ok = f->sdcp.reinitialise(3, 1.0, 1e4, f->x, f->P) && f->sdcp.consistent(f->x, f->P);
              for (const int slot : f->sdcp.active_slots()) all_ok = f->sdcp.release(slot, f->x, f->P) && all_ok;
              all_ok = all_ok && f->sdcp.consistent(f->x, f->P);
            }),
            0);
  EXPECT_EQ(refused, 1);
  EXPECT_TRUE(all_ok);
}

TEST(NavAllocation, ScalarUpdateAllocatesNothing) {
  auto f = std::make_unique<NavFilter>();
  f->sdcp.release_all(f->x, f->P);
  const int slot = f->sdcp.acquire(7, 2.0, 1e4, f->x, f->P);
  ASSERT_GE(slot, 0);
  NavRow h = NavRow::Zero();
  h(state::position(Craft::kOsc)) = -0.6;
  h(state::position(Craft::kDsc)) = 0.6;
  h(f->sdcp.state_of(slot)) = 0.19;  // lambda [m/cycle]
  ScalarUpdateStatus accepted = ScalarUpdateStatus::kInvalid;
  ScalarUpdateStatus gated = ScalarUpdateStatus::kInvalid;
  ScalarUpdateStatus refused = ScalarUpdateStatus::kAccepted;
  bool row_ok = false;
  EXPECT_EQ(test::count_allocations([&] {
              row_ok = f->sdcp.row_on_active_only(h);
              accepted = scalar_update(f->x, f->P, h, 0.01, 1e-5, 5.0, f->ws).status;
              gated = scalar_update(f->x, f->P, h, 1e3, 1e-5, 5.0, f->ws).status;
              refused = scalar_update(f->x, f->P, h, 0.01, -1.0, 5.0, f->ws).status;
            }),
            0);
  EXPECT_TRUE(row_ok);
  EXPECT_EQ(accepted, ScalarUpdateStatus::kAccepted);
  EXPECT_EQ(gated, ScalarUpdateStatus::kRejected);
  EXPECT_EQ(refused, ScalarUpdateStatus::kInvalid);
}


// The navigation filter's epoch (time update, slot management, GRAPHIC, SD code and SDCP updates, integer
// resolution, fixed solution, hold) on the synthetic constellation (support/synthetic_gps.hpp),
// after a warm-up that fixes the integers: nothing allocated.
void expect_cdgps_epoch_allocates_nothing(const CdgpsSettings& settings) {
  const core::GpsTime t0 = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value();
  const auto records = test::synthetic_constellation(t0);
  const auto ephemerides = gnss::EphemerisSet::screen(records);
  core::OnboardEarthFrame frame;
  const auto model = [] {
    dynamics::ForceModelData data;
    data.gravity_field = dynamics::embedded_gravity_field();
    return dynamics::ForceModel::create(dynamics::ForceModelConfig::gravity_only(8, 8), {}, std::move(data)).value();
  };
  auto filter = CdgpsFilter::create(settings, model(), model()).value();
  const double r = 6878137.0, v = std::sqrt(3.986004415e14 / r);
  const core::StateVector dsc{Eigen::Vector3d(r, 0, 0), Eigen::Vector3d(0, v * 0.13, v * 0.99)};
  const core::StateVector osc{dsc.r + Eigen::Vector3d(0, 0, 40), dsc.v};
  std::vector<double> integers(33, 1000.0);
  std::mt19937_64 rng(5);
  std::vector<GpsReceiverEpoch> dsc_epochs, osc_epochs;
  // Zero() spelled out: an Eigen vector initialised from {} is left uninitialised (the phase-centre
  // error of these truths was garbage, and the observations with it, in one build of two).
  for (int n = 0; n < 40; ++n) {  // static truth states: enough for the algebra, not for dynamics
    const core::GpsTime t = t0 + static_cast<double>(n);
    dsc_epochs.push_back(test::synthetic_observations(t, {dsc.r, dsc.v, 10.0, Eigen::Vector3d::Zero()}, records, frame, integers, 0.1, 0.2, 0.002, rng));
    osc_epochs.push_back(test::synthetic_observations(t, {osc.r, osc.v, -5.0, Eigen::Vector3d::Zero()}, records, frame, integers, 0.3, 0.2, 0.002, rng));
  }
  filter.initialise(t0, dsc, osc, 10.0, -5.0);
  const auto epoch = [&](int n) {
    filter.predict(t0 + static_cast<double>(n));
    return filter.update({&dsc_epochs[static_cast<std::size_t>(n)], &osc_epochs[static_cast<std::size_t>(n)], {}, {}},
                         ephemerides, frame);
  };
  for (int n = 0; n < 30; ++n) epoch(n);
  int updates = 0;
  EXPECT_EQ(test::count_allocations([&] {
              for (int n = 30; n < 40; ++n) updates += epoch(n).sdcp_used;
            }),
            0);
  EXPECT_GT(updates, 0);
  // The campaign's operations between epochs: a commanded impulse, a laser range, a forecast.
  NavVector ahead = filter.x();
  EXPECT_EQ(test::count_allocations([&] {
              (void)filter.apply_impulse(Craft::kOsc, Eigen::Vector3d(0.0, 0.002, 0.0));
              (void)filter.update_laser_range(40.0, 0.002, LaserRangeGeometry{});
              ahead = filter.forecast(filter.x(), t0 + 42.0);
            }),
            0);
  EXPECT_NE(ahead, filter.x());
}

TEST(NavAllocation, CdgpsFilterEpochAllocatesNothing) { expect_cdgps_epoch_allocates_nothing(CdgpsSettings{}); }

// With the SD multipath states and an along-track empirical sigma of its own.
TEST(NavAllocation, CdgpsFilterEpochWithMultipathStatesAllocatesNothing) {
  CdgpsSettings settings;
  settings.sdcp_multipath_sigma_m = 0.00283;
  settings.empirical_along_track_sigma_mps2 = 1e-6;
  expect_cdgps_epoch_allocates_nothing(settings);
}

}  // namespace
}  // namespace visors::nav
