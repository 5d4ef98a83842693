// The truth's per-run spacecraft values (sim/truth_dynamics.hpp draw_true_spacecraft): nominal
// plus a clamped normal deviation per quantity, three draws in a fixed order.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/sim/random_stream.hpp"
#include "visors/sim/truth_dynamics.hpp"

namespace {

using visors::sim::draw_true_spacecraft;
using visors::sim::RandomStream;
using visors::sim::SpacecraftSettings;

TEST(DrawTrueSpacecraft, ZeroSigmasGiveTheNominal) {
  SpacecraftSettings nominal;
  nominal.mass_sigma_kg = nominal.cd_sigma = nominal.cr_sigma = 0.0;
  RandomStream rng(1, "dsc.ballistics");
  EXPECT_EQ(draw_true_spacecraft(nominal, rng).cd, nominal.cd);
}

TEST(DrawTrueSpacecraft, DrawsTheSameStreamWhateverTheSigmas) {
  // Three numbers are drawn either way: the next draw of the stream is the same.
  SpacecraftSettings zero;
  zero.mass_sigma_kg = zero.cd_sigma = zero.cr_sigma = 0.0;
  RandomStream a(2, "osc.ballistics"), b(2, "osc.ballistics");
  (void)draw_true_spacecraft(zero, a);
  (void)draw_true_spacecraft(SpacecraftSettings{}, b);
  EXPECT_EQ(a.normal(), b.normal());
}

// Sample moments over 20000 draws, 5-standard-error bands (sigma / sqrt(N), sigma / sqrt(2N)).
TEST(DrawTrueSpacecraft, CdDeviationHasItsSigma) {
  constexpr int n = 20000;
  const SpacecraftSettings nominal;
  RandomStream rng(3, "stats.ballistics");
  double sum = 0.0, sum2 = 0.0;
  for (int k = 0; k < n; ++k) {
    const double d = draw_true_spacecraft(nominal, rng).cd - nominal.cd;
    sum += d;
    sum2 += d * d;
  }
  const double mean = sum / n;
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), nominal.cd_sigma, 5.0 * nominal.cd_sigma / std::sqrt(2.0 * n));
}

TEST(DrawTrueSpacecraft, MassDeviationIsUnbiased) {
  constexpr int n = 20000;
  const SpacecraftSettings nominal;
  RandomStream rng(4, "stats.ballistics");
  double sum = 0.0;
  for (int k = 0; k < n; ++k) sum += draw_true_spacecraft(nominal, rng).mass_kg - nominal.mass_kg;
  EXPECT_LT(std::abs(sum / n), 5.0 * nominal.mass_sigma_kg / std::sqrt(n));
}

}  // namespace
