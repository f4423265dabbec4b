// The strength arrays follow the flag whether they were enabled before or after particles
// were added (a scene enables strength before it generates its bodies).
#include "sph/ParticleSet.hpp"

#include <gtest/gtest.h>

using hvi::sph::ParticleSet;

TEST(ParticleSet, StrengthEnabledBeforeParticlesAreAdded) {
    ParticleSet ps;
    ps.enableStrength();
    ps.add(0.0, 0.5, 1.0, 0.0, 1.0, 0.1, 2.7, 0.0, 0);
    ps.add(0.0, 1.5, 1.0, 0.0, 1.0, 0.1, 2.7, 0.0, 0);
    EXPECT_TRUE(ps.hasStrength());
    EXPECT_EQ(ps.szz.size(), 2u);
    EXPECT_EQ(ps.damage.size(), 2u);
}

TEST(ParticleSet, StrengthEnabledAfterParticlesAreAdded) {
    ParticleSet ps;
    ps.add(0.0, 0.5, 1.0, 0.0, 1.0, 0.1, 2.7, 0.0, 0);
    EXPECT_FALSE(ps.hasStrength());
    EXPECT_TRUE(ps.szz.empty());
    ps.enableStrength();
    EXPECT_EQ(ps.srz.size(), 1u);
}
