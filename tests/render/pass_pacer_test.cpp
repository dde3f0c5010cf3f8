// The choice of samples per pass (render/pass_pacer.h): pure arithmetic on the passes' times.
#include <gtest/gtest.h>

#include "core/error.h"
#include "render/pass_pacer.h"

namespace fp {
namespace {

constexpr double kTarget = 0.5;  // not the default: the figures below are for this target

TEST(PassPacer, AFixedCountIsKeptWhateverThePassesCost) {
    PassPacer pacer(4, 16, kTarget);
    EXPECT_EQ(pacer.next(100), 4);
    pacer.record(4, 0.001);
    EXPECT_EQ(pacer.next(100), 4);
    pacer.record(4, 60.0);
    EXPECT_EQ(pacer.next(100), 4);
    EXPECT_EQ(pacer.next(3), 3);  // never more than remain
}

TEST(PassPacer, StartsWithOneSampleAndTakesAsManyAsFitTheTarget) {
    PassPacer pacer(0, 16, kTarget);
    EXPECT_EQ(pacer.next(1000), 1);  // nothing known yet
    pacer.record(1, 0.1);            // 100 ms per sample: 5 fit in the target
    EXPECT_EQ(pacer.next(1000), 5);
    pacer.record(5, 0.5);
    EXPECT_EQ(pacer.next(1000), 5);
    pacer.record(5, 0.4);  // 80 ms per sample: 6.25
    EXPECT_EQ(pacer.next(1000), 6);
    EXPECT_EQ(pacer.next(4), 4);  // never more than remain
}

TEST(PassPacer, CheapPassesTakeTheMaximum) {
    PassPacer pacer(0, 16, kTarget);
    pacer.record(pacer.next(1000), 1e-3);
    EXPECT_EQ(pacer.next(1000), 16);
    pacer.record(16, 0.0);  // too fast to time
    EXPECT_EQ(pacer.next(1000), 16);
}

TEST(PassPacer, ASlowPassShortensTheNextAndNeverBelowOne) {
    PassPacer pacer(0, 16, kTarget);
    pacer.record(1, 0.01);
    ASSERT_EQ(pacer.next(1000), 16);
    pacer.record(16, 4.0);  // something else took the machine: 0.25 s per sample
    EXPECT_EQ(pacer.next(1000), 2);
    pacer.record(2, 100.0);
    EXPECT_EQ(pacer.next(1000), 1);
    pacer.record(1, 0.05);  // back to speed
    EXPECT_EQ(pacer.next(1000), 10);
}

TEST(PassPacer, RefusesCountsOutsideItsRange) {
    EXPECT_THROW(PassPacer(17, 16), Error);
    EXPECT_THROW(PassPacer(-1, 16), Error);
    EXPECT_THROW(PassPacer(0, 0), Error);
    EXPECT_THROW(PassPacer(0, 16, 0.0), Error);
}

}  // namespace
}  // namespace fp
