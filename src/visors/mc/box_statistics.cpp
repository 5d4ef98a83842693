#include "visors/mc/box_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace visors::mc {

double percentile(const std::vector<double>& sorted, double p) {
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (rank - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

BoxStatistics box_statistics(std::vector<double> values) {
  std::erase_if(values, [](double v) { return std::isnan(v); });
  BoxStatistics b;
  b.count = static_cast<int>(values.size());
  if (values.empty()) return b;
  std::sort(values.begin(), values.end());
  b.q1 = percentile(values, 25.0);
  b.median = percentile(values, 50.0);
  b.q3 = percentile(values, 75.0);
  const double reach = 1.5 * (b.q3 - b.q1);
  b.whisker_low = b.q1;
  b.whisker_high = b.q3;
  for (const double v : values) {
    if (v < b.q1 - reach || v > b.q3 + reach) {
      b.outliers.push_back(v);
      continue;
    }
    b.whisker_low = std::min(b.whisker_low, v);
    b.whisker_high = std::max(b.whisker_high, v);
  }
  return b;
}

}  // namespace visors::mc
