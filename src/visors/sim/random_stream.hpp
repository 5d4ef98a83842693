#pragma once
// Deterministic random numbers for the simulator: one independent stream per model and spacecraft,
// derived from the scenario seed and a name ("osc.propulsion", "nav.dsc"), so adding a draw to one
// model never shifts another's, and the same seed gives the same run bit for bit on any platform
// (std::mt19937_64 is fully specified by the standard; the distributions here are written out,
// unlike std::normal_distribution whose algorithm is implementation-defined).

#include <cstdint>
#include <random>
#include <string_view>

namespace visors::sim {

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::string_view name);

  /// Uniform on [0, 1), 53 random bits.
  double uniform();
  /// Standard normal (Marsaglia polar method; Marsaglia & Bray 1964).
  double normal();
  /// Normal with standard deviation sigma (sigma >= 0).
  double normal(double sigma) { return sigma * normal(); }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace visors::sim
