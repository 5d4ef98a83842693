// mc/box_statistics against numpy: numpy.percentile([1..9, 100], (25, 50, 75)) = (3.25, 5.5, 7.75)
// (linear interpolation, numpy's default); Tukey fences 3.25 - 6.75 and 7.75 + 6.75 = 14.5.
#include "visors/mc/box_statistics.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace visors::mc {
namespace {

BoxStatistics sample() { return box_statistics({9, 1, 8, 2, 100, 7, 3, 6, 4, 5}); }

TEST(BoxStatistics, FirstQuartileIsNumpys) { EXPECT_DOUBLE_EQ(sample().q1, 3.25); }
TEST(BoxStatistics, MedianIsNumpys) { EXPECT_DOUBLE_EQ(sample().median, 5.5); }
TEST(BoxStatistics, ThirdQuartileIsNumpys) { EXPECT_DOUBLE_EQ(sample().q3, 7.75); }
TEST(BoxStatistics, UpperWhiskerIsTheLargestValueInsideTheFence) { EXPECT_DOUBLE_EQ(sample().whisker_high, 9.0); }
TEST(BoxStatistics, LowerWhiskerIsTheSmallestValue) { EXPECT_DOUBLE_EQ(sample().whisker_low, 1.0); }
TEST(BoxStatistics, TheFarValueIsAnOutlier) { EXPECT_EQ(sample().outliers, std::vector<double>{100.0}); }

TEST(BoxStatistics, NanValuesAreLeftOut) {
  EXPECT_EQ(box_statistics({1.0, std::numeric_limits<double>::quiet_NaN(), 3.0}).count, 2);
}

TEST(BoxStatistics, NoValueGivesAnEmptyBox) { EXPECT_EQ(box_statistics({}).count, 0); }

TEST(BoxStatistics, OneValueIsItsOwnBox) { EXPECT_DOUBLE_EQ(box_statistics({4.0}).median, 4.0); }

}  // namespace
}  // namespace visors::mc
