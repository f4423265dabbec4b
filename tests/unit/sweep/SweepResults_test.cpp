// The tests a sweep's picture sets beside the simulated limit: those of the swept shield, found in
// the shipped validation set by its geometry and alloys. Checked on series whose members are
// known from the test database (data/validation/nasa_tests.json), including a series of the
// same geometry in other alloys that must not be drawn.
#include "sweep/SweepResults.hpp"
#include "sweep/SweepSpec.hpp"
#include "validation/CaseInputs.hpp"
#include "validation/ValidationCase.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <string>
#include <vector>

using namespace hvi;

namespace {

std::vector<std::string> testIds(const std::string& caseId, sweep::Parameter parameter) {
    const validation::Case& c = validation::findCase(caseId);
    sweep::SweepRequest request;
    request.id = c.id;
    request.panel = validation::panelInput(c);
    request.writer = "hcomb2rings";
    request.parameter = parameter;
    request.speedKmS = 5.0;
    request.guessMm = 1.0;
    std::vector<std::string> ids;
    for (const auto& t : sweep::testsOfShield(sweep::makeSpec(request))) {
        ids.push_back(t.id);
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

using Ids = std::vector<std::string>;

} // namespace

TEST(TestsOfShield, AreTheSeriesOfTheSameAlloysOnly) {
    // 0.406 mm 7075-T6 facesheets on a 25.4 mm 5052 core: two shots. Schaefer et al.'s 22 shots
    // (0.4 mm 2024-T3 over a 25 mm 5056 core) are within 2 % in every size but another shield.
    EXPECT_EQ(testIds("hc-56.0", sweep::Parameter::Diameter), (Ids{"hc-52.0", "hc-56.0"}));
}

TEST(TestsOfShield, KeepEveryShotOfOneSeries) {
    // Turner et al. 2001: 0.4 mm 2024-T81 over a 35.8 mm 5052 core, seven shots; the same
    // alloys with 0.6 mm facesheets (A001, A003) are another shield.
    EXPECT_EQ(
        testIds("hc-1-001", sweep::Parameter::Diameter),
        (Ids{"hc-1-001", "hc-1-003", "hc-1-008", "hc-2-003", "hc-2-006", "hc-4-003", "hc-B002"}));
}

TEST(TestsOfShield, HoldTheDiameterWhenTheWallIsSwept) {
    // Swift et al.'s 3.18 mm spheres on a 0.84 mm bumper 12.7 mm from a 6061-T6 wall.
    const Ids ids = testIds("WPL-0341", sweep::Parameter::RearWall);
    for (const char* id : {"WPL-0199", "WPL-0256", "WPL-0282", "WPL-0341", "WPL-0395"}) {
        EXPECT_NE(std::find(ids.begin(), ids.end(), id), ids.end()) << id;
    }
    for (const auto& id : ids) {
        const validation::Case& c = validation::findCase(id);
        EXPECT_NEAR(c.diameterMm, 3.18, 0.02 * 3.18) << id;
        EXPECT_NEAR(c.gapMm, 12.7, 0.02 * 12.7) << id;
    }
}
