// core/statistics.h: the median of repeated measurements.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "core/statistics.h"

namespace fp {
namespace {

TEST(Median, OddCountIsTheMiddleValueInAnyOrder) {
    EXPECT_DOUBLE_EQ(median({7.0}), 7.0);
    EXPECT_DOUBLE_EQ(median({3.0, 1.0, 2.0}), 2.0);
    EXPECT_DOUBLE_EQ(median({5.0, 100.0, 4.0, 1.0, 4.5}), 4.5);  // one outlier does not move it
}

TEST(Median, EvenCountIsTheMeanOfTheTwoMiddleValues) {
    EXPECT_DOUBLE_EQ(median({2.0, 1.0}), 1.5);
    EXPECT_DOUBLE_EQ(median({10.0, 1.0, 4.0, 2.0}), 3.0);
    EXPECT_DOUBLE_EQ(median({1.0, 1.0, 9.0, 9.0, 9.0, 1.0}), 5.0);
}

TEST(Median, OfNothingIsABug) {
    EXPECT_THROW(median({}), std::invalid_argument);
}

}  // namespace
}  // namespace fp
