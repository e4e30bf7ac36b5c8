#pragma once

// A SimulatorSession on the real Vigor table, driven from the test's thread (the owner) while
// its worker scans. Waits are loops that process events until a condition holds, with
// generous time limits; no sleep is an assertion.

#include "real_target_sim.h"
#include "tests/eventually.h"

#include "simulator/session.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>

namespace rung::simulator::test {

using waits::eventually;
using waits::kPatienceMs;

struct SessionFixture {
    explicit SessionFixture(const char *program)
        : sim(model::Family::Vigor, program) {
        EXPECT_TRUE(sim.result.ok());
        session = std::make_unique<SimulatorSession>(sim.result.program);
    }
    model::Address at(const char *name) const { return sim.at(name); }
    // The latest snapshot; the worker publishes the first one soon after the start, so a
    // test waits for it before reading.
    std::shared_ptr<const model::Snapshot> latest() const {
        EXPECT_TRUE(eventually([&] { return session->snapshot() != nullptr; }));
        return session->snapshot();
    }
    // Waits for the command's completion and returns its result.
    std::pair<bool, QString> finish(model::MonitorSource::CommandId id) {
        std::pair<bool, QString> result{false, QStringLiteral("no answer")};
        bool done = false;
        QObject context;
        QObject::connect(session.get(), &model::MonitorSource::commandFinished, &context,
                         [&](model::MonitorSource::CommandId finished, bool ok, const QString &e) {
                             if (finished == id) {
                                 result = {ok, e};
                                 done = true;
                             }
                         });
        EXPECT_TRUE(eventually([&] { return done; })) << "command " << id;
        return result;
    }
    // Runs change on this thread while the worker is held: it waits for the history lock
    // after every scan, and readHistory holds that lock. The pause first lets a scanning
    // worker reach the lock, so everything change submits is seen by the worker at once.
    template <typename Change> void whileWorkerHeld(Change change) {
        session->readHistory([&](const model::HistoryRecorder &) {
            // A fixed pause, not a condition: nothing outside the worker tells that it waits
            // for the lock; five scan periods let a scanning worker get there.
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            change();
        });
    }

    test::RealTargetSim sim;
    std::unique_ptr<SimulatorSession> session;
};

} // namespace rung::simulator::test
