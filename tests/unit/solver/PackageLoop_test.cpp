// The package loop (solver/PackageLoop.hpp) on toy packages: the phases run in the documented
// order over the packages in the order they were added; the smallest vote wins and a tie goes
// to the first; a package's first vote is prepared with the step the ones before it allow;
// checkpoint and restore reach every package. A harmonic oscillator written as a package
// (kick, drift with prediction, evaluate, second kick) is integrated by the loop as the
// kick-drift-kick leapfrog: its energy error stays below (w dt)^2 / 4 (the leapfrog's modified
// energy, Hairer, Lubich & Wanner 2003, ch. IX) and its phase error after a period falls with
// dt^2.
#include "solver/PackageLoop.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

using namespace hvi;

namespace {

/// Writes "name.phase" into a shared log for every call.
class Recorder final : public solver::Package {
public:
    Recorder(std::string name, double vote, std::vector<std::string>& log)
        : m_name(std::move(name)), m_vote(vote), m_log(log) {}
    const char* name() const override { return m_name.c_str(); }
    double stableTimeStep() const override { return m_vote; }
    void kick(double) override { m_log.push_back(m_name + ".kick"); }
    void constrain(double) override { m_log.push_back(m_name + ".constrain"); }
    void drift(double) override { m_log.push_back(m_name + ".drift"); }
    void evaluate(double) override { m_log.push_back(m_name + ".evaluate"); }
    void kickAgain(double) override { m_log.push_back(m_name + ".kickAgain"); }
    void finish(double) override { m_log.push_back(m_name + ".finish"); }
    void prepare(double dtGuess) override { guess = dtGuess; }
    void save(io::CheckpointState& s) const override { s.extra[m_name] = m_vote; }
    void restore(const io::CheckpointState& s) override { m_vote = s.extra.at(m_name); }

    double guess = -1.0;

private:
    std::string m_name;
    double m_vote;
    std::vector<std::string>& m_log;
};

/// x'' = -w^2 x as a package: state (x, v), rate a = -w^2 x, half-step velocity vh.
class Oscillator final : public solver::Package {
public:
    explicit Oscillator(double w) : m_w(w) {}
    const char* name() const override { return "oscillator"; }
    double stableTimeStep() const override { return 2.0 / m_w; }
    void kick(double dt) override { vh = v + 0.5 * dt * a; }
    void drift(double dt) override {
        x += dt * vh;
        v = vh + 0.5 * dt * a; // the end-of-step prediction with the start's rate
    }
    void evaluate(double) override { a = -m_w * m_w * x; }
    void kickAgain(double dt) override { v = vh + 0.5 * dt * a; }
    void prepare(double) override { a = -m_w * m_w * x; }
    double energy() const { return 0.5 * v * v + 0.5 * m_w * m_w * x * x; }

    double x = 1.0, v = 0.0, vh = 0.0, a = 0.0;

private:
    double m_w;
};

/// The oscillator's phase error after one period of n steps.
double periodError(int n) {
    const double w = 2.0;
    Oscillator osc(w);
    solver::PackageLoop loop;
    loop.add(osc);
    loop.prepare(0.0, 1.0);
    const double dt = 2.0 * M_PI / w / n;
    for (int k = 0; k < n; ++k) {
        loop.step(dt);
    }
    return std::hypot(osc.x - 1.0, osc.v / w);
}

} // namespace

TEST(PackageLoop, PhasesRunInOrderOverPackagesInOrder) {
    std::vector<std::string> log;
    Recorder a("a", 1.0, log), b("b", 2.0, log);
    solver::PackageLoop loop;
    loop.add(a);
    loop.add(b);
    loop.step(0.1);
    const std::vector<std::string> expected = {
        "a.kick",     "b.kick",     "a.constrain", "b.constrain", "a.drift",  "b.drift",
        "a.evaluate", "b.evaluate", "a.kickAgain", "b.kickAgain", "a.finish", "b.finish"};
    EXPECT_EQ(log, expected);
}

TEST(PackageLoop, SmallestVoteWinsAndATieGoesToTheFirst) {
    std::vector<std::string> log;
    const double inf = std::numeric_limits<double>::infinity();
    Recorder a("a", 3.0, log), b("b", 2.0, log), c("c", 2.0, log);
    solver::PackageLoop loop;
    loop.add(a);
    loop.add(b);
    loop.add(c);
    EXPECT_EQ(loop.smallestVote().limiter, &b);
    EXPECT_EQ(loop.smallestVote().dt, 2.0);

    Recorder x("x", inf, log), y("y", inf, log);
    solver::PackageLoop idle;
    idle.add(x);
    idle.add(y);
    EXPECT_EQ(idle.smallestVote().limiter, &x);
    EXPECT_TRUE(std::isinf(idle.smallestVote().dt));
}

TEST(PackageLoop, PrepareGivesEachTheStepOfThoseBeforeIt) {
    std::vector<std::string> log;
    Recorder a("a", 4.0, log), b("b", 2.0, log), c("c", 1.0, log);
    solver::PackageLoop loop;
    loop.add(a);
    loop.add(b);
    loop.add(c);
    loop.prepare(0.0, 0.5);
    EXPECT_TRUE(std::isinf(a.guess));
    EXPECT_EQ(b.guess, 0.5 * 4.0);
    EXPECT_EQ(c.guess, 0.5 * 2.0);
    loop.prepare(0.3, 0.5); // a known step is everyone's
    EXPECT_EQ(a.guess, 0.3);
    EXPECT_EQ(c.guess, 0.3);
}

TEST(PackageLoop, CheckpointReachesEveryPackage) {
    std::vector<std::string> log;
    Recorder a("a", 4.0, log), b("b", 2.0, log);
    solver::PackageLoop loop;
    loop.add(a);
    loop.add(b);
    io::CheckpointState state;
    loop.save(state);
    EXPECT_EQ(state.extra.at("a"), 4.0);
    EXPECT_EQ(state.extra.at("b"), 2.0);
    state.extra["b"] = 0.5;
    loop.restore(state);
    EXPECT_EQ(b.stableTimeStep(), 0.5);
}

TEST(PackageLoop, OscillatorIsALeapfrog) {
    const double w = 2.0, dt = 0.05;
    Oscillator osc(w);
    solver::PackageLoop loop;
    loop.add(osc);
    loop.prepare(0.0, 1.0);
    const double e0 = osc.energy();
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) { // about 300 periods: a drift would show
        loop.step(dt);
        worst = std::max(worst, std::fabs(osc.energy() - e0) / e0);
    }
    EXPECT_LE(worst, 0.25 * (w * dt) * (w * dt)) << "worst relative energy error " << worst;
    EXPECT_GT(worst, 0.0);
    // Second order: halving dt divides the phase error by 4 (+-10 %).
    const double ratio = periodError(200) / periodError(400);
    EXPECT_NEAR(ratio, 4.0, 0.4) << "period error ratio " << ratio;
}
