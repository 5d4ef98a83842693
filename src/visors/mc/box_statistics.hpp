#pragma once
// The statistics of a whisker (box) plot, Tukey's convention: quartiles by linear interpolation
// between order statistics (numpy.percentile's default, "type 7" of Hyndman & Fan 1996), whiskers
// at the most extreme data within 1.5 interquartile ranges of the box, the rest outliers.

#include <vector>

namespace visors::mc {

struct BoxStatistics {
  int count = 0;
  double q1 = 0.0, median = 0.0, q3 = 0.0;
  double whisker_low = 0.0, whisker_high = 0.0;
  std::vector<double> outliers;
};

/// Percentile p in [0, 100] of `sorted` (ascending, non-empty), linear interpolation.
double percentile(const std::vector<double>& sorted, double p);

/// The box statistics of `values` (NaN values ignored; count 0 when none is left).
BoxStatistics box_statistics(std::vector<double> values);

}  // namespace visors::mc
