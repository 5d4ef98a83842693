#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/sim/adcs_model.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace {

using visors::core::kArcsecToRad;
using visors::sim::AdcsModel;
using visors::sim::AdcsSettings;
using visors::sim::RandomStream;

AdcsModel make_model(const AdcsSettings& settings, std::uint64_t seed = 3) {
  auto model = AdcsModel::create(settings, RandomStream(seed, "test.adcs"));
  EXPECT_TRUE(model.ok());
  return std::move(model).value();
}

// Only the slow control error, on one axis.
AdcsSettings slow_error_only(double sigma_rad, double tau_s) {
  AdcsSettings s;
  s.pointing_sigma_rad = Eigen::Vector3d(0.0, sigma_rad, 0.0);
  s.pointing_tau_s = tau_s;
  s.jitter_sigma_rad.setZero();
  s.knowledge_sigma_rad.setZero();
  return s;
}

// Body Y component of the control error at 1 s steps.
std::vector<double> series(AdcsModel& model, int steps) {
  std::vector<double> y;
  for (int k = 0; k < steps; ++k) {
    model.step(static_cast<double>(k));
    y.push_back(model.pointing_error_body_rad().y());
  }
  return y;
}

double rms(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v * v;
  return std::sqrt(sum / static_cast<double>(x.size()));
}

double correlation(const std::vector<double>& x, std::size_t lag) {
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k + lag < x.size(); ++k) num += x[k] * x[k + lag];
  for (double v : x) den += v * v;
  return num / den * static_cast<double>(x.size()) / static_cast<double>(x.size() - lag);
}

// A first-order Gauss-Markov process is stationary with variance sigma^2 (Gelb, Applied Optimal
// Estimation, 1974, table 3.4-1): 200,000 steps of a 60 s process are ~1,700 independent
// samples, so the RMS is sigma within ~2 % (1 sigma); 5 % allowed.
TEST(AdcsModel, ControlErrorHasItsStationarySigma) {
  const double sigma = 14.0 * kArcsecToRad;
  AdcsModel model = make_model(slow_error_only(sigma, 60.0));
  EXPECT_NEAR(rms(series(model, 200000)), sigma, 0.05 * sigma);
}

// Its autocorrelation at a lag of tau is exp(-1) (same reference); +-0.05 for ~1,700 samples.
TEST(AdcsModel, ControlErrorDecorrelatesOverItsCorrelationTime) {
  AdcsModel model = make_model(slow_error_only(14.0 * kArcsecToRad, 60.0));
  EXPECT_NEAR(correlation(series(model, 200000), 60), std::exp(-1.0), 0.05);
}

// The jitter is white at the step: no correlation from one step to the next (+-0.01 for 20,000
// samples, 1/sqrt(N) = 0.007) and its sigma (+-2 %).
TEST(AdcsModel, JitterIsWhiteAtTheStep) {
  AdcsSettings s = slow_error_only(0.0, 60.0);
  s.jitter_sigma_rad = Eigen::Vector3d(0.0, 11.0 * kArcsecToRad, 0.0);
  AdcsModel model = make_model(s);
  const std::vector<double> y = series(model, 20000);
  EXPECT_NEAR(correlation(y, 1), 0.0, 0.02);
  EXPECT_NEAR(rms(y), 11.0 * kArcsecToRad, 0.02 * 11.0 * kArcsecToRad);
}

// Sign convention (docs/conventions.md): the error is a rotation about the body axes, so a
// positive error about body Y turns the payload axis +X towards body -Z: in GCRF, X_true =
// cos a X_cmd - sin a Z_cmd with X_cmd, Z_cmd the commanded body axes (a commanded attitude away
// from the identity, where a rotation about GCRF axes would differ).
TEST(AdcsModel, ErrorAboutBodyYTurnsThePayloadAxisTowardsBodyMinusZ) {
  AdcsModel model = make_model(slow_error_only(1e-3, 60.0));
  model.step(0.0);
  const double a = model.pointing_error_body_rad().y();
  ASSERT_NE(a, 0.0);
  const Eigen::Quaterniond q_cmd(Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, 1.0, -0.4).normalized()));
  const Eigen::Vector3d x_true = model.true_attitude(q_cmd) * Eigen::Vector3d::UnitX();
  const Eigen::Vector3d expected = std::cos(a) * (q_cmd * Eigen::Vector3d::UnitX()) - std::sin(a) * (q_cmd * Eigen::Vector3d::UnitZ());
  EXPECT_LT((x_true - expected).norm(), 1e-15);
}

// The reported attitude is the true one rotated by exactly the determination error.
TEST(AdcsModel, ReportedAttitudeDiffersFromTheTruthByTheKnowledgeError) {
  AdcsModel model = make_model(AdcsSettings{});
  model.step(0.0);
  const Eigen::Quaterniond q_true =
      model.true_attitude(Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized())));
  const Eigen::AngleAxisd delta(q_true.conjugate() * model.reported_attitude(q_true));
  const Eigen::Vector3d theta = delta.angle() * delta.axis();
  EXPECT_LT((theta - model.knowledge_error_body_rad()).norm(), 1e-12);
}

// Zero errors: the bus holds and reports exactly the commanded attitude.
TEST(AdcsModel, ZeroSigmasHoldTheCommandedAttitude) {
  AdcsSettings s = slow_error_only(0.0, 60.0);
  AdcsModel model = make_model(s);
  model.step(0.0);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.2, Eigen::Vector3d::UnitZ()));
  EXPECT_EQ(model.true_attitude(q).coeffs(), q.normalized().coeffs());
  EXPECT_EQ(model.reported_attitude(q).coeffs(), q.normalized().coeffs());
}

TEST(AdcsModel, SameSeedSameErrors) {
  AdcsModel a = make_model(AdcsSettings{}, 9);
  AdcsModel b = make_model(AdcsSettings{}, 9);
  EXPECT_EQ(series(a, 100), series(b, 100));
}

TEST(AdcsSettings, NegativeSigmaNamesTheField) {
  AdcsSettings s;
  s.jitter_sigma_rad.x() = -1e-6;
  EXPECT_EQ(s.validate().error().field, "jitter_sigma_arcsec");
}

TEST(AdcsSettings, NonFiniteCorrelationTimeNamesTheField) {
  AdcsSettings s;
  s.pointing_tau_s = std::nan("");
  EXPECT_EQ(s.validate().error().field, "pointing_tau_s");
}

TEST(AdcsSettings, ZeroSlewRateNamesTheField) {
  AdcsSettings s;
  s.slew_rate_radps = 0.0;
  EXPECT_EQ(s.validate().error().field, "slew_rate_deg_s");
}

// The scenario's [attitude] table: read in its units, and errors name the key.
TEST(AttitudeScenario, KeysAreReadInDegreesAndArcseconds) {
  auto s = visors::sim::campaign_from_toml("[attitude]\nslew_rate_deg_s = 1.0\njitter_sigma_arcsec = [1.0, 2.0, 3.0]\n");
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_DOUBLE_EQ(s->adcs.slew_rate_radps, visors::core::kDegToRad);
  EXPECT_DOUBLE_EQ(s->adcs.jitter_sigma_rad.z(), 3.0 * kArcsecToRad);
}

TEST(AttitudeScenario, ShortVectorNamesTheKey) {
  auto s = visors::sim::campaign_from_toml("[attitude]\npointing_sigma_arcsec = [1.0, 2.0]\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "attitude.pointing_sigma_arcsec");
}

TEST(AttitudeScenario, NegativeSigmaNamesTheKey) {
  auto s = visors::sim::campaign_from_toml("[attitude]\nknowledge_sigma_arcsec = [1.0, -2.0, 3.0]\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "attitude.knowledge_sigma_arcsec");
}

TEST(AttitudeScenario, ResolvedScenarioReadsBackTheSame) {
  auto s = visors::sim::campaign_from_toml("[attitude]\npointing_tau_s = 12.5\nknowledge_sigma_arcsec = [7.0, 8.0, 9.0]\n");
  ASSERT_TRUE(s.ok());
  auto again = visors::sim::campaign_from_toml(visors::sim::campaign_to_toml(*s));
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_EQ(again->adcs.pointing_tau_s, 12.5);
  EXPECT_EQ(again->adcs.knowledge_sigma_rad, s->adcs.knowledge_sigma_rad);
}

}  // namespace
