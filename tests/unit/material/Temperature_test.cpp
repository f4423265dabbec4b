// Temperature estimate T = T_room + e / c_v and the homologous temperature T*.
#include "Tolerance.hpp"
#include "core/Units.hpp"
#include "material/Temperature.hpp"

#include <gtest/gtest.h>

using hvi::material::ThermalParams;
using hvi::test::near;

namespace {
// Al 6061-T6: c_v 885 J/(kg K), T_room 294.26 K, T_melt 925.37 K (data/hydro_materials.json).
const ThermalParams kAl{hvi::units::jPerKgKToMjPerKgK(885.0), 294.26, 925.37};
} // namespace

TEST(Temperature, SpecificHeatIsConvertedToMegajoulesPerKilogram) {
    // 0.1 MJ/kg = 1e5 J/kg heats 1 kg by 1e5 / 885 = 112.9943503 K.
    EXPECT_TRUE(near("T(e=0.1 MJ/kg)", kAl.temperature(0.1), 294.26 + 1.0e5 / 885.0, 0.0, 1e-14));
    EXPECT_EQ(kAl.temperature(0.0), 294.26);
    EXPECT_EQ(kAl.temperature(-10.0), 0.0); // never below absolute zero
}

TEST(Temperature, HomologousTemperatureIsClampedToUnitInterval) {
    EXPECT_EQ(kAl.homologousTemperature(200.0), 0.0);
    EXPECT_EQ(kAl.homologousTemperature(2000.0), 1.0);
    EXPECT_TRUE(
        near("T* half way", kAl.homologousTemperature(0.5 * (294.26 + 925.37)), 0.5, 0.0, 1e-14));
    // The energy that reaches melt: c_v (T_melt - T_room) = 885 J/kg/K * 631.11 K = 0.5585 MJ/kg.
    const double eMelt = 885.0e-6 * (925.37 - 294.26);
    EXPECT_TRUE(near("T* at melt energy", kAl.homologousFromEnergy(eMelt), 1.0, 0.0, 1e-14));
}
