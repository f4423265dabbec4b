// Ideal gas: the gamma-law relations P = (gamma-1) rho e and c^2 = gamma P / rho.
#include "Tolerance.hpp"
#include "material/eos/IdealGas.hpp"

#include <gtest/gtest.h>

using hvi::material::IdealGas;
using hvi::test::near;

TEST(IdealGas, PressureAndSoundSpeedFollowTheGammaLaw) {
    for (double gamma : {5.0 / 3.0, 1.4}) {
        const IdealGas gas{gamma};
        for (double rho : {0.125, 1.0, 4.0}) {
            for (double e : {0.0, 0.25, 2.5}) {
                const auto s = gas.evaluate(rho, e);
                // One or two multiplications each: 1e-15 relative is round-off.
                EXPECT_TRUE(near("P", s.pressure, (gamma - 1.0) * rho * e, 1e-300, 1e-15));
                EXPECT_TRUE(
                    near("c^2", s.soundSpeedSquared, gamma * s.pressure / rho, 1e-300, 1e-15));
            }
        }
    }
}

TEST(IdealGas, MonatomicValuesByHand) {
    // gamma = 5/3, rho = 1, e = 1.5: P = 2/3 * 1.5 = 1, c^2 = 5/3.
    const auto s = IdealGas{5.0 / 3.0}.evaluate(1.0, 1.5);
    EXPECT_TRUE(near("P", s.pressure, 1.0, 0.0, 1e-15));
    EXPECT_TRUE(near("c^2", s.soundSpeedSquared, 5.0 / 3.0, 0.0, 1e-15));
}

TEST(IdealGas, NegativeEnergyGivesNoImaginarySoundSpeed) {
    EXPECT_EQ(IdealGas{}.evaluate(1.0, -0.1).soundSpeedSquared, 0.0);
}
