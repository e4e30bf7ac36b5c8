// Real-time mode: scans paced by the wall clock at a speed factor (Engine::runRealTime).

#include "real_target_sim.h"

#include <atomic>
#include <chrono>

using namespace rung;
using namespace rung::simulator;

// Scan k is due k periods / factor after the start: 20 scans of 10 ms take at least 190 ms
// at x1 and 19 ms at x10. Only lower bounds hold on a loaded machine; the x10 run must
// still beat the x1 run (that would take a stall of about 170 ms to break).
TEST(EngineRealTime, ScansArePacedByTheWallClockAtTheSpeedFactor) {
    using Clock = std::chrono::steady_clock;
    test::RealTargetSim s(model::Family::Vigor, "LD M9000\nINC D0\nEND");
    ASSERT_TRUE(s.result.ok());
    Engine &engine = *s.engine;
    std::atomic<bool> stop{false};
    auto elapsedMs = [&](double factor) {
        const auto start = Clock::now();
        EXPECT_EQ(engine.runRealTime(factor, stop, 20), 20u);
        return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    };
    const double slow = elapsedMs(1.0);
    EXPECT_GE(slow, 150.0);
    const double fast = elapsedMs(10.0);
    EXPECT_GE(fast, 15.0);
    EXPECT_LT(fast, slow);
    EXPECT_EQ(engine.statistics().timeMs, 400); // virtual time is exact either way
    EXPECT_EQ(s.value("D0"), 40);
}
