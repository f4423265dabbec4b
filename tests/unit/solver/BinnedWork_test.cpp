// What time-step bins would evaluate (solver/BinnedWork.hpp), against the power-of-two
// hierarchy worked by hand: a point whose stable step is between 2^k and 2^(k+1) times the
// smallest steps at 2^k times it and costs 2^-k of an evaluation per smallest step.
#include "solver/BinnedWork.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <limits>
#include <omp.h>
#include <vector>

using hvi::solver::BinnedWork;

TEST(BinnedWork, EachPointStepsAtTheLargestPowerOfTwoNotAboveItsOwnStep) {
    EXPECT_EQ(BinnedWork::binOf(1.0), 0);
    EXPECT_EQ(BinnedWork::binOf(1.999), 0);
    EXPECT_EQ(BinnedWork::binOf(2.0), 1);
    EXPECT_EQ(BinnedWork::binOf(3.9), 1);
    EXPECT_EQ(BinnedWork::binOf(4.0), 2);
    EXPECT_EQ(BinnedWork::binOf(63.9), 5);
    EXPECT_EQ(BinnedWork::binOf(64.0), BinnedWork::kMaxBin);
    EXPECT_EQ(BinnedWork::binOf(1e9), BinnedWork::kMaxBin);
    EXPECT_EQ(BinnedWork::binOf(std::numeric_limits<double>::infinity()), BinnedWork::kMaxBin);
    EXPECT_EQ(BinnedWork::binOf(0.5), 0); // below the smallest vote (a later vote): bin 0
    EXPECT_EQ(BinnedWork::binOf(std::nan("")), BinnedWork::kMaxBin);
    // floor(log2) everywhere between, each power of two and its neighbours included.
    for (int b = 1; b <= BinnedWork::kMaxBin; ++b) {
        const double edge = std::ldexp(1.0, b);
        EXPECT_EQ(BinnedWork::binOf(std::nextafter(edge, 0.0)), b - 1) << "below 2^" << b;
        EXPECT_EQ(BinnedWork::binOf(edge), b) << "2^" << b;
    }
    for (double r = 1.0; r < 64.0; r *= 1.013) {
        EXPECT_EQ(BinnedWork::binOf(r), std::ilogb(r)) << "ratio " << r;
    }
}

TEST(BinnedWork, CountsTheEvaluationsOfEachBin) {
    const double inf = std::numeric_limits<double>::infinity();
    // Smallest step 2 us: ratios 1, 1.5, 2, 3.9, 4, 100, inf -> bins 0, 0, 1, 1, 2, 6, 6.
    const std::vector<double> steps{2.0, 3.0, 4.0, 7.8, 8.0, 200.0, inf};
    BinnedWork work;
    work.add(steps, 2.0);
    const double expected = 1.0 + 1.0 + 0.5 + 0.5 + 0.25 + 1.0 / 64.0 + 1.0 / 64.0;
    EXPECT_DOUBLE_EQ(work.evaluated(), 7.0);
    EXPECT_DOUBLE_EQ(work.binned(), expected);
    EXPECT_DOUBLE_EQ(work.fraction(), expected / 7.0);
    // A second step adds to both sums; one without a finite smallest vote adds nothing.
    work.add(std::vector<double>{2.0}, 2.0);
    work.add(steps, inf);
    work.add(steps, 0.0);
    EXPECT_DOUBLE_EQ(work.evaluated(), 8.0);
    EXPECT_DOUBLE_EQ(work.binned(), expected + 1.0);
    EXPECT_DOUBLE_EQ(BinnedWork{}.fraction(), 1.0);
}

TEST(BinnedWork, ManyPointsAtAnyThreadCount) {
    // Above the threading threshold: the counts per bin are integers, so one and two threads
    // give the same sum bit for bit, and it equals the sum worked per point.
    std::vector<double> steps;
    for (int k = 0; k < 50000; ++k) {
        steps.push_back(1.0 + 0.37 * static_cast<double>(k % 200)); // ratios 1 to 74.6
    }
    double expected = 0.0;
    for (const double s : steps) {
        expected += 1.0 / static_cast<double>(1 << BinnedWork::binOf(s));
    }
    std::vector<double> sums;
    for (const int threads : {1, 2}) {
        const int before = omp_get_max_threads();
        omp_set_num_threads(threads);
        BinnedWork work;
        work.add(steps, 1.0);
        omp_set_num_threads(before);
        EXPECT_DOUBLE_EQ(work.evaluated(), 50000.0);
        EXPECT_NEAR(work.binned(), expected, 1e-9 * expected);
        sums.push_back(work.binned());
    }
    EXPECT_EQ(sums[0], sums[1]);
}
