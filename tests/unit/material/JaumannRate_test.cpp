// Jaumann deviatoric stress rate: invariance under rotation, the sign of the spin terms
// against an exactly rotated tensor, and the elastic responses to uniaxial strain and to
// axisymmetric radial expansion.
#include "Tolerance.hpp"
#include "material/strength/JaumannRate.hpp"

#include <cmath>
#include <gtest/gtest.h>

using hvi::material::jaumannRate;
using hvi::material::StressDeviator;
using hvi::material::VelocityGradient2D;
using hvi::test::near;

namespace {

constexpr double kG = 27.6;

// dJ2/dt = S : dS/dt over all three diagonal components (S_thth included).
double j2Rate(const StressDeviator& s, const StressDeviator& rate) {
    return s.zz * rate.zz + s.rr * rate.rr + s.thetaTheta() * rate.thetaTheta() +
           2.0 * s.rz * rate.rz;
}

StressDeviator add(const StressDeviator& a, const StressDeviator& b, double f) {
    return {a.zz + f * b.zz, a.rr + f * b.rr, a.rz + f * b.rz};
}

} // namespace

TEST(JaumannRate, PureSpinLeavesJ2Unchanged) {
    const StressDeviator s{0.3, -0.12, 0.17};
    // Rigid rotation rate omega: v_z = -omega r, v_r = omega z, so L = [[0, -w], [w, 0]].
    const double omega = 0.8;
    const VelocityGradient2D l{0.0, -omega, omega, 0.0};
    const StressDeviator rate = jaumannRate(s, l, 0.0, kG);
    // The rate is O(omega S) ~ 0.3 GPa/us; J2 rate must cancel to round-off (~1e-16 of that).
    EXPECT_TRUE(near("dJ2/dt under spin", j2Rate(s, rate), 0.0, 1e-15, 0.0));
    EXPECT_GT(std::fabs(rate.zz) + std::fabs(rate.rz), 0.1); // the stress does rotate
}

TEST(JaumannRate, IntegratedSpinRotatesTheTensorLikeARigidBody) {
    // Integrate dS/dt over a rigid rotation by angle theta = omega t with RK4 and compare with
    // Q S0 Q^T, Q the rotation by theta in the (z, r) plane. The opposite spin sign would
    // rotate by -theta and miss by O(S).
    const StressDeviator s0{0.3, -0.12, 0.17};
    const double omega = 0.8;
    const VelocityGradient2D l{0.0, -omega, omega, 0.0};
    const int steps = 1000;
    const double tEnd = 1.0;
    const double dt = tEnd / steps;
    StressDeviator s = s0;
    auto f = [&](const StressDeviator& x) { return jaumannRate(x, l, 0.0, kG); };
    for (int i = 0; i < steps; ++i) {
        const StressDeviator k1 = f(s);
        const StressDeviator k2 = f(add(s, k1, 0.5 * dt));
        const StressDeviator k3 = f(add(s, k2, 0.5 * dt));
        const StressDeviator k4 = f(add(s, k3, dt));
        s = {s.zz + dt / 6.0 * (k1.zz + 2 * k2.zz + 2 * k3.zz + k4.zz),
             s.rr + dt / 6.0 * (k1.rr + 2 * k2.rr + 2 * k3.rr + k4.rr),
             s.rz + dt / 6.0 * (k1.rz + 2 * k2.rz + 2 * k3.rz + k4.rz)};
    }
    const double c = std::cos(omega * tEnd);
    const double sn = std::sin(omega * tEnd);
    // Q = [[c, -sn], [sn, c]]; (Q S Q^T) components:
    const double zz = c * c * s0.zz - 2 * c * sn * s0.rz + sn * sn * s0.rr;
    const double rr = sn * sn * s0.zz + 2 * c * sn * s0.rz + c * c * s0.rr;
    const double rz = c * sn * (s0.zz - s0.rr) + (c * c - sn * sn) * s0.rz;
    // RK4 error ~ (omega dt)^4 * omega t * |S| ~ 1e-13; 1e-10 leaves margin, O(S) does not fit.
    EXPECT_TRUE(near("S_zz after rotation", s.zz, zz, 1e-10, 0.0));
    EXPECT_TRUE(near("S_rr after rotation", s.rr, rr, 1e-10, 0.0));
    EXPECT_TRUE(near("S_rz after rotation", s.rz, rz, 1e-10, 0.0));
}

TEST(JaumannRate, UniaxialStrainRateGivesFourThirdsG) {
    // Planar (or axisymmetric with v_r = 0): only dv_z/dz = eps_dot. Deviatoric strain rate
    // diag(2/3, -1/3, -1/3) eps_dot, so dS_zz/dt = 4G/3 eps_dot, dS_rr/dt = -2G/3 eps_dot.
    const double epsDot = 0.01;
    const StressDeviator rate =
        jaumannRate(StressDeviator{}, VelocityGradient2D{epsDot, 0.0, 0.0, 0.0}, 0.0, kG);
    EXPECT_TRUE(near("dS_zz/dt", rate.zz, 4.0 * kG / 3.0 * epsDot, 0.0, 1e-14));
    EXPECT_TRUE(near("dS_rr/dt", rate.rr, -2.0 * kG / 3.0 * epsDot, 0.0, 1e-14));
    EXPECT_EQ(rate.rz, 0.0);
    EXPECT_TRUE(near("dS_thth/dt", rate.thetaTheta(), -2.0 * kG / 3.0 * epsDot, 0.0, 1e-14));
}

TEST(JaumannRate, AxisymmetricRadialExpansionIncludesTheHoopRate) {
    // v_r = a r: dv_r/dr = a and D_thth = v_r / r = a. D = diag(0, a, a), trace 2a:
    // dS_zz/dt = -4G/3 a, dS_rr/dt = dS_thth/dt = 2G/3 a. Without the hoop rate in the trace,
    // dS_rr/dt would be 4G/3 a instead.
    const double a = 0.02;
    const StressDeviator rate =
        jaumannRate(StressDeviator{}, VelocityGradient2D{0.0, 0.0, 0.0, a}, a, kG);
    EXPECT_TRUE(near("dS_zz/dt", rate.zz, -4.0 * kG / 3.0 * a, 0.0, 1e-14));
    EXPECT_TRUE(near("dS_rr/dt", rate.rr, 2.0 * kG / 3.0 * a, 0.0, 1e-14));
    EXPECT_TRUE(near("dS_thth/dt", rate.thetaTheta(), 2.0 * kG / 3.0 * a, 0.0, 1e-14));
}

TEST(JaumannRate, SimpleShearFromRest) {
    // v_z = gamma_dot r: D_zr = gamma_dot/2, so dS_rz/dt = G gamma_dot at S = 0.
    const double gammaDot = 0.05;
    const StressDeviator rate =
        jaumannRate(StressDeviator{}, VelocityGradient2D{0.0, gammaDot, 0.0, 0.0}, 0.0, kG);
    EXPECT_TRUE(near("dS_rz/dt", rate.rz, kG * gammaDot, 0.0, 1e-14));
    EXPECT_EQ(rate.zz, 0.0);
    EXPECT_EQ(rate.rr, 0.0);
}
