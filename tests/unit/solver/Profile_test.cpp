// The run's profile (solver/Profile): phase and section accounts, step-size percentiles from
// the logarithmic histogram against the exact order statistics of a known sample, and the
// printed and stored forms.
#include "solver/Profile.hpp"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

using namespace hvi::solver;

TEST(Profile, PhaseTimesAddUpAndSectionsAccumulate) {
    PhaseTimes t;
    t.book(Phase::Evaluate, 2.0);
    t.book(Phase::Kick, 0.5);
    t.book(Phase::Evaluate, 1.0);
    t.bookSection("neighbour search", 0.25);
    t.bookSection("pair loops", 2.0);
    t.bookSection("neighbour search", 0.5);
    EXPECT_DOUBLE_EQ(t.phase(Phase::Evaluate), 3.0);
    EXPECT_DOUBLE_EQ(t.total(), 3.5) << "sections are inside phases, not added again";
    ASSERT_EQ(t.sections().size(), 2u);
    EXPECT_EQ(t.sections()[0].first, "neighbour search");
    EXPECT_DOUBLE_EQ(t.sections()[0].second, 0.75);
}

TEST(Profile, StepPercentilesWithinTheBinWidth) {
    // 10,000 steps spread log-uniformly over two decades, shuffled by a fixed stride.
    const int n = 10000;
    std::vector<double> dts;
    StepSizeHistogram h;
    for (int k = 0; k < n; ++k) {
        const int j = (k * 7919) % n;
        const double dt = 1e-4 * std::pow(100.0, (j + 0.5) / n);
        dts.push_back(dt);
        h.add(dt, j % 10 == 0 ? "fe" : "sph");
    }
    std::sort(dts.begin(), dts.end());
    EXPECT_EQ(h.count(), n);
    EXPECT_DOUBLE_EQ(h.min(), dts.front());
    EXPECT_DOUBLE_EQ(h.max(), dts.back());
    for (const double q : {0.1, 0.5, 0.9}) {
        const double exact = dts[static_cast<std::size_t>(q * n) - 1];
        // A bin is 1 % wide and the percentile is its geometric middle: within 1 %.
        EXPECT_NEAR(h.percentile(q) / exact, 1.0, 0.01) << "q " << q;
    }
    EXPECT_EQ(h.limiterSteps().at("fe"), n / 10);
    EXPECT_EQ(h.limiterSteps().at("sph"), n - n / 10);
}

TEST(Profile, NoStepIsNotCounted) {
    StepSizeHistogram h;
    h.add(0.0, "sph");
    h.add(std::nan(""), "sph");
    h.add(-1.0, "sph");
    EXPECT_EQ(h.count(), 0);
    EXPECT_EQ(h.percentile(0.5), 0.0);
    EXPECT_TRUE(h.limiterSteps().empty());
}

TEST(Profile, TextAndJsonSayTheSame) {
    RunProfile p;
    PhaseTimes sph;
    sph.book(Phase::Evaluate, 6.0);
    sph.bookSection("neighbour search", 1.0);
    PhaseTimes contact;
    contact.book(Phase::Constrain, 2.0);
    p.packages = {{"sph", sph}, {"contact", contact}};
    p.loop = {{"output", 1.0}};
    p.wallSeconds = 10.0;
    p.steps.add(1e-3, "sph");
    p.steps.add(2e-3, "contact");
    BinnedWork sphBins;
    const std::vector<double> steps{1e-3, 4e-3}; // bins 0 and 2: 1.25 of 2 evaluations
    sphBins.add(steps, 1e-3);
    p.binned = {{"sph", sphBins}};

    const auto json = profileJson(p);
    EXPECT_DOUBLE_EQ(json["time_bins"]["sph"]["evaluated_point_steps"].get<double>(), 2.0);
    EXPECT_DOUBLE_EQ(json["time_bins"]["sph"]["binned_point_steps"].get<double>(), 1.25);
    EXPECT_DOUBLE_EQ(json["time_bins"]["sph"]["fraction"].get<double>(), 0.625);
    EXPECT_DOUBLE_EQ(json["packages"]["sph"]["total_s"].get<double>(), 6.0);
    EXPECT_DOUBLE_EQ(json["packages"]["sph"]["phases_s"]["evaluate"].get<double>(), 6.0);
    EXPECT_DOUBLE_EQ(json["packages"]["sph"]["sections_s"]["neighbour search"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(json["loop_s"]["output"].get<double>(), 1.0);
    EXPECT_EQ(json["steps"], 2);
    EXPECT_EQ(json["dt_limiter_steps"]["contact"], 1);

    const std::string text = profileText(p);
    EXPECT_NE(text.find("where the 10.0 s went (2 steps"), std::string::npos) << text;
    EXPECT_NE(text.find("sph"), std::string::npos) << text;
    EXPECT_NE(text.find("60.0 %"), std::string::npos) << text;
    EXPECT_NE(text.find("neighbour search 1"), std::string::npos) << text;
    // 10 s less 6 + 2 + 1 accounted: 1 s the profile cannot place.
    EXPECT_NE(text.find("other              1.0 s  10.0 %"), std::string::npos) << text;
    EXPECT_NE(text.find("set by contact 50.0 %, sph 50.0 %"), std::string::npos) << text;
    EXPECT_NE(text.find("would evaluate 62 % of sph's points"), std::string::npos) << text;
}
