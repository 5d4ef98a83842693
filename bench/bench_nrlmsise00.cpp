// NRLMSISE-00 cost per density evaluation (the campaign makes ~2.4 million truth
// density evaluations and must stay <= 60 s in total). Points along the mission chief's 500 km
// orbit, 1 s apart, October 2024 activity: the path the truth force model takes (AtmosphereModel
// query, cached day/activity terms), the straightforward evaluation for comparison, and the
// Harris-Priester density the truth used before. The coefficients come from the repository's
// data/ (or VISORS_DATA_PATH).

#include <benchmark/benchmark.h>

#include <cmath>
#include <optional>
#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/nrlmsise00_file.hpp"
#include "visors/dynamics/harris_priester.hpp"
#include "visors/dynamics/nrlmsise00.hpp"

namespace {
using namespace visors;
using namespace visors::dynamics;

const core::GpsTime kEpoch = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();
constexpr int kPoints = 5700;  // one orbit at 1 s

// Queries along one orbit of the mission chief (GCRF from Keplerian elements, ITRF with zero EOP),
// with October 2024 activity (F10.7 244.6 of 2024-10-01 as the previous day's, its centred mean
// 215.3, Ap 5: CelesTrak's observed space weather) and a quiet ap history.
std::vector<AtmosphereQuery> orbit_queries(bool with_history) {
  std::vector<AtmosphereQuery> queries;
  const double gm = 3.986004415e14;
  const astro::KeplerianElements chief{6878136.3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad,
                                       90.0 * core::kDegToRad, 0.0};
  const double n = std::sqrt(gm / std::pow(chief.a, 3.0));
  for (int k = 0; k < kPoints; ++k) {
    astro::KeplerianElements e = chief;
    e.M = n * k;
    AtmosphereQuery q;
    q.t = kEpoch + static_cast<double>(k);
    q.r_gcrf = astro::cartesian_from_keplerian(e, gm).r;
    q.r_itrf = core::gcrf_to_itrf_matrix(q.t, core::EarthOrientation{}) * q.r_gcrf;
    q.sun_gcrf = Eigen::Vector3d(1.4e11, 0.4e11, 0.1e11);
    q.activity.f107 = 244.6;
    q.activity.f107a = 215.3;
    q.activity.ap = 5.0;
    if (with_history) q.activity.ap_history = std::array<double, 7>{5, 4, 3, 4, 6, 5, 7};
    queries.push_back(q);
  }
  return queries;
}

bool make(benchmark::State& state, std::optional<Nrlmsise00Atmosphere>& model) {
  const auto path = core::files::find_data_file("atmosphere/nrlmsise00_coefficients.txt");
  if (!path) {
    state.SkipWithError("atmosphere/nrlmsise00_coefficients.txt not found");
    return false;
  }
  auto c = files::read_nrlmsise00_coefficients(*path);
  if (!c) {
    state.SkipWithError(c.error().describe().c_str());
    return false;
  }
  model.emplace(Nrlmsise00Atmosphere::create(c.value()).value());
  return true;
}

void density(benchmark::State& state, bool with_history) {
  std::optional<Nrlmsise00Atmosphere> model;
  if (!make(state, model)) return;
  const std::vector<AtmosphereQuery> queries = orbit_queries(with_history);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model->density(queries[i]));
    if (++i == queries.size()) i = 0;
  }
}

void BM_Nrlmsise00Density_ApHistory(benchmark::State& state) { density(state, true); }
BENCHMARK(BM_Nrlmsise00Density_ApHistory);

void BM_Nrlmsise00Density_DailyAp(benchmark::State& state) { density(state, false); }
BENCHMARK(BM_Nrlmsise00Density_DailyAp);

// The straightforward evaluation (no cache, no identities) of the same points, inputs prepared.
void BM_Nrlmsise00EvaluateUncached_ApHistory(benchmark::State& state) {
  std::optional<Nrlmsise00Atmosphere> model;
  if (!make(state, model)) return;
  std::vector<Nrlmsise00Input> inputs;
  for (const AtmosphereQuery& q : orbit_queries(true)) inputs.push_back(Nrlmsise00Atmosphere::input_at(q));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model->evaluate_uncached(inputs[i]));
    if (++i == inputs.size()) i = 0;
  }
}
BENCHMARK(BM_Nrlmsise00EvaluateUncached_ApHistory);

// For comparison: the Harris-Priester apex density (the truth's former stand-in).
void BM_HarrisPriesterMaximumDensity(benchmark::State& state) {
  HarrisPriesterSettings settings;
  settings.bulge = HarrisPriesterBulge::kApexMaximum;
  const HarrisPriesterAtmosphere model = HarrisPriesterAtmosphere::create(settings).value();
  const std::vector<AtmosphereQuery> queries = orbit_queries(false);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(model.density(queries[i]));
    if (++i == queries.size()) i = 0;
  }
}
BENCHMARK(BM_HarrisPriesterMaximumDensity);

}  // namespace
