// Simulation in the IDE (issue 11, first slice): the Simulation menu and its keys, the
// status section, the watch list fed by the running session, a program with errors that does
// not start, and an edit while running (an online edit) or stopped. The session is the real one:
// its engine scans on its own thread, so the tests wait for its snapshots with the event loop
// running.

#include "app/gui/eliding_label.h"
#include "app/gui/simulation_controller.h"
#include "editor/il_editor.h"
#include "editor/io_panel.h"
#include "editor/problems_view.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "simulator/session.h"

#include "model/target/address.h"

#include <QApplication>
#include <QDockWidget>

#include "tests/editor/watch_rows.h"
#include "tests/editor/window_fixture.h"
#include "tests/eventually.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

using namespace rung;
using State = model::MonitorSource::RunState;

namespace {

// Y1 flips every scan (LDI Y1 / OUT Y1): the scan count's parity is visible.
constexpr const char *kFlipFlop = "LD X0\nOUT Y0\nLDI Y1\nOUT Y1\nEND\n";

struct Simulation : test::WindowFixture {
    app::SimulationController *sim() { return window.simulation(); }
    QString status() {
        auto *label = window.findChild<app::ElidingLabel *>(QStringLiteral("simulationStatus"));
        return label ? label->fullText() : QString();
    }
    model::Address at(const char *device) {
        return std::get<model::Address>(
            model::parseAddress(window.document()->target(), QString::fromLatin1(device)));
    }
    // The newest snapshot once it satisfies `ready`, with the event loop running meanwhile;
    // null after 5 s.
    std::shared_ptr<const model::Snapshot>
    waitFor(const std::function<bool(const model::Snapshot &)> &ready) {
        std::shared_ptr<const model::Snapshot> found;
        test::eventually([&] {
            if (sim()->session())
                if (auto s = sim()->session()->snapshot(); s && ready(*s))
                    found = s;
            return found != nullptr;
        });
        return found;
    }
    // Whether the status section comes to say what `holds` wants (it follows snapshotChanged).
    bool statusComes(const std::function<bool(const QString &)> &holds) {
        return test::eventually([&] { return holds(status()); });
    }
    void showActive() {
        window.show();
        QApplication::setActiveWindow(&window);
        ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
        view->setFocus();
    }
};

TEST(SimulationStatus, SaysStateTimeScansAndScanTimesInOneLine) {
    model::Snapshot snapshot;
    snapshot.statistics.scans = 372345;
    snapshot.statistics.timeMs = 3723450; // 1 h 2 min 3.45 s
    snapshot.statistics.periodMs = 10;
    snapshot.statistics.execNsCurrent = 2500;
    snapshot.statistics.execNsMin = 1000;
    snapshot.statistics.execNsMax = 9950;
    EXPECT_EQ(app::SimulationController::statusText(State::Running, 1000, &snapshot),
              QStringLiteral("Running x1000 | 1:02:03.45 | 372345 scans | scan 10 ms"));
    // The evaluation figures are the line's tooltip (and the Simulation dock's): in the line
    // they were cut beside the history's marks.
    EXPECT_EQ(app::SimulationController::evaluationText(&snapshot),
              QStringLiteral("Evaluation of a scan on this computer: 2.5 µs (1.0..9.9)"));
    EXPECT_EQ(app::SimulationController::statusText(State::Running, 0.1, &snapshot)
                  .section(QLatin1Char('|'), 0, 0),
              QStringLiteral("Running x0.1 "));
    EXPECT_TRUE(app::SimulationController::statusText(State::Running, 0, &snapshot)
                    .startsWith(QStringLiteral("Running at full speed | ")));
    EXPECT_TRUE(app::SimulationController::statusText(State::Paused, 1, &snapshot)
                    .startsWith(QStringLiteral("Paused | ")));
    EXPECT_TRUE(app::SimulationController::statusText(State::Stepping, 1, &snapshot)
                    .startsWith(QStringLiteral("Stepping | ")));
    EXPECT_EQ(app::SimulationController::statusText(State::Offline, 1, &snapshot),
              QStringLiteral("Simulation off"));
    EXPECT_EQ(app::SimulationController::statusText(State::Stopped, 1, nullptr),
              QStringLiteral("Stopped"));
}

TEST_F(Simulation, TheMenuHasEveryControlWithAKeyThatNothingElseUses) {
    std::map<QString, QKeySequence> keys;
    for (const char *name :
         {"Run", "Pause", "Stop (Back to Power-On)", "Single Scan", "Power Cycle"}) {
        QAction *a = test::menuAction(window, QString::fromLatin1(name));
        ASSERT_NE(a, nullptr) << name;
        ASSERT_FALSE(a->shortcut().isEmpty()) << name;
        keys[QString::fromLatin1(name)] = a->shortcut();
    }
    ASSERT_NE(test::submenu(window, QStringLiteral("Speed")), nullptr);
    EXPECT_EQ(test::submenu(window, QStringLiteral("Speed"))->actions().size(), 9);
    // No other action of the window has one of these keys.
    std::set<QAction *> seen;
    for (QAction *a : window.findChildren<QAction *>()) {
        if (!seen.insert(a).second || a->objectName().startsWith(QLatin1String("simulation")))
            continue;
        for (const QKeySequence &other : a->shortcuts())
            for (const auto &[name, key] : keys)
                EXPECT_NE(other, key) << name.toStdString() << " and " << a->text().toStdString();
    }
    // The ladder's own keys: F5..F9 with any modifier, Ctrl+F10 (ladder_view_keys.cpp).
    for (const auto &[name, key] : keys) {
        const int k = key[0].key();
        EXPECT_FALSE(k >= Qt::Key_F5 && k <= Qt::Key_F9) << name.toStdString();
        EXPECT_NE(key, QKeySequence(Qt::CTRL | Qt::Key_F10)) << name.toStdString();
    }
}

TEST_F(Simulation, TheKeysRunPauseScanAndStopFromTheLadder) {
    load(kFlipFlop);
    showActive();
    EXPECT_EQ(sim()->runState(), State::Offline);
    EXPECT_EQ(status(), QStringLiteral("Simulation off"));

    QTest::keyClick(view, Qt::Key_F10);
    ASSERT_NE(sim()->session(), nullptr);
    EXPECT_EQ(sim()->runState(), State::Running);
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans > 3; }), nullptr);
    EXPECT_TRUE(statusComes([](const QString &s) {
        return s.startsWith(QStringLiteral("Running x")) &&
               s.contains(QStringLiteral(" scans | scan 10 ms"));
    })) << status().toStdString();
    EXPECT_FALSE(view->inlineEditor()->isVisible()); // the key did not reach the ladder

    QTest::keyClick(view, Qt::Key_F11);
    EXPECT_EQ(sim()->runState(), State::Paused);
    // A scan under way when F11 came ends first.
    EXPECT_TRUE(statusComes([](const QString &s) {
        return s.startsWith(QStringLiteral("Paused | "));
    })) << status().toStdString();

    // F12: one scan, published at once; F12 again: exactly one more, Y1 following the parity.
    // (The scan under way at F11 may publish after the status said Paused: the first F12 is
    // seen as at least one more scan; the second, counted from a settled pause, exactly one.)
    const quint64 before = sim()->session()->snapshot()->statistics.scans;
    QTest::keyClick(view, Qt::Key_F12);
    ASSERT_NE(
        waitFor([before](const model::Snapshot &s) { return s.statistics.scans > before; }),
        nullptr);
    const quint64 scans = sim()->session()->snapshot()->statistics.scans;
    // That a paused session does not scan shows only over time: ten scan periods.
    QTest::qWait(100);
    EXPECT_EQ(sim()->session()->snapshot()->statistics.scans, scans) << "paused, yet scanning";
    QTest::keyClick(view, Qt::Key_F12);
    const auto stepped =
        waitFor([scans](const model::Snapshot &s) { return s.statistics.scans == scans + 1; });
    ASSERT_NE(stepped, nullptr) << sim()->session()->snapshot()->statistics.scans << " after "
                                << scans;
    EXPECT_EQ(stepped->bit(at("Y1")), (scans + 1) % 2 == 1);
    EXPECT_EQ(stepped->statistics.timeMs, static_cast<qint64>(scans + 1) * 10);
    EXPECT_TRUE(statusComes([scans](const QString &s) {
        return s.contains(QStringLiteral("| %1 scans |").arg(scans + 1));
    })) << status().toStdString();

    // Shift+F11: the power-on state.
    QTest::keyClick(view, Qt::Key_F11, Qt::ShiftModifier);
    EXPECT_EQ(sim()->runState(), State::Stopped);
    const auto stopped = waitFor([](const model::Snapshot &s) { return s.statistics.scans == 0; });
    ASSERT_NE(stopped, nullptr);
    EXPECT_FALSE(stopped->bit(at("Y1")));
    EXPECT_TRUE(statusComes([](const QString &s) {
        return s.startsWith(QStringLiteral("Stopped | 0:00:00.00 | 0 scans"));
    })) << status().toStdString();
}

TEST_F(Simulation, TheKeysWorkFromTheInstructionListToo) {
    load(kFlipFlop);
    window.setSideBySide(true);
    showActive();
    window.ilEditor()->setFocus();
    ASSERT_TRUE(window.ilEditor()->hasFocus());
    QTest::keyClick(window.ilEditor(), Qt::Key_F12);
    EXPECT_NE(sim()->session(), nullptr);
    QTest::keyClick(window.ilEditor(), Qt::Key_F10);
    EXPECT_EQ(sim()->runState(), State::Running);
    QTest::keyClick(window.ilEditor(), Qt::Key_F11);
    EXPECT_EQ(sim()->runState(), State::Paused);
    EXPECT_EQ(window.ilEditor()->text(), listing()); // nothing typed into the list
    window.setSideBySide(false);                     // the next test's (QSettings)
}

TEST_F(Simulation, SingleScansFromPowerOnCountOneEach) {
    load(kFlipFlop);
    ASSERT_TRUE(sim()->singleScan());
    auto s = waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; });
    ASSERT_NE(s, nullptr);
    EXPECT_TRUE(s->bit(at("Y1")));
    ASSERT_TRUE(sim()->singleScan());
    s = waitFor([](const model::Snapshot &s) { return s.statistics.scans == 2; });
    ASSERT_NE(s, nullptr);
    EXPECT_FALSE(s->bit(at("Y1")));
    // The session says Paused on this thread once the scan is done.
    EXPECT_TRUE(test::eventually([&] { return sim()->runState() == State::Paused; }));
}

TEST_F(Simulation, TheSpeedChosenInTheMenuGoesToTheSession) {
    load(kFlipFlop);
    QAction *fast = test::menuAction(window, QStringLiteral("As Fast as Possible"));
    ASSERT_NE(fast, nullptr);
    fast->trigger();
    ASSERT_TRUE(sim()->run());
    EXPECT_EQ(sim()->session()->speed(), 0.0);
    EXPECT_TRUE(statusComes([](const QString &s) {
        return s.startsWith(QStringLiteral("Running at full speed"));
    })) << status().toStdString();
    QAction *ten = test::menuAction(window, QStringLiteral("x10 Real Time"));
    ASSERT_NE(ten, nullptr);
    ten->trigger();
    EXPECT_EQ(sim()->session()->speed(), 10.0);
    sim()->setSpeed(1.0); // what the next test starts with (QSettings)
}

TEST_F(Simulation, TheScanPeriodChosenInTheMenuIsTheVirtualTimeOfAScan) {
    load(kFlipFlop);
    QAction *five = test::menuAction(window, QStringLiteral("5 ms"));
    ASSERT_NE(five, nullptr);
    five->trigger();
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    ASSERT_TRUE(sim()->singleScan());
    const auto s = waitFor([](const model::Snapshot &s) { return s.statistics.scans == 2; });
    ASSERT_NE(s, nullptr);
    EXPECT_EQ(s->statistics.periodMs, 5);
    EXPECT_EQ(s->statistics.timeMs, 10);
    EXPECT_TRUE(statusComes([](const QString &s) {
        return s.contains(QStringLiteral("| scan 5 ms"));
    })) << status().toStdString();
    test::menuAction(window, QStringLiteral("10 ms"))->trigger(); // the next test's (QSettings)
}

TEST_F(Simulation, ReleaseAllForcesEndsEveryForce) {
    load(kFlipFlop);
    ASSERT_TRUE(sim()->singleScan());
    sim()->session()->force(at("X0"), true);
    sim()->session()->force(at("M5"), true);
    ASSERT_NE(waitFor([this](const model::Snapshot &s) {
                  return s.forced(at("X0")) && s.forced(at("M5"));
              }),
              nullptr);
    QAction *release = test::menuAction(window, QStringLiteral("Release All Forces"));
    ASSERT_NE(release, nullptr);
    release->trigger();
    ASSERT_NE(waitFor([this](const model::Snapshot &s) {
                  return !s.forced(at("X0")) && !s.forced(at("M5"));
              }),
              nullptr);
}

TEST_F(Simulation, TheWatchListShowsTheRunningValues) {
    load(kFlipFlop);
    window.document()->setWatchLists({{QStringLiteral("W"), {QStringLiteral("Y1")}}},
                                     QStringLiteral("watch"));
    editor::WatchListView *watch = window.watchListView();
    EXPECT_EQ(watch->monitorSource(), nullptr);
    ASSERT_TRUE(sim()->singleScan());
    EXPECT_EQ(watch->monitorSource(), sim()->session());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    EXPECT_TRUE(test::eventually([&] {
        return test::watchText(watch, 0, 0, editor::WatchListView::ValueColumn) ==
               QStringLiteral("ON");
    })) << test::watchText(watch, 0, 0, editor::WatchListView::ValueColumn).toStdString();
    // Every monitoring view was handed the same source.
    EXPECT_EQ(window.ioPanel()->monitorSource(), sim()->session());
    EXPECT_EQ(window.timingChart()->monitorSource(), sim()->session());
}

// An edit while it runs is an online edit (test_simulation_debug.cpp has the rest); while
// stopped, an edit drops the simulation and Run starts the edited program.
TEST_F(Simulation, EditingWhileRunningIsAnOnlineEditAndWhileStoppedDropsTheSimulation) {
    load(kFlipFlop);
    ASSERT_TRUE(sim()->run());
    // A watch list is no part of what runs: the simulation goes on.
    window.document()->setWatchLists({{QStringLiteral("W"), {QStringLiteral("Y1")}}},
                                     QStringLiteral("watch"));
    EXPECT_EQ(sim()->runState(), State::Running);
    simulator::SimulatorSession *session = sim()->session();
    load("LD X1\nOUT Y0\nLDI Y1\nOUT Y1\nEND\n");
    EXPECT_EQ(sim()->session(), session);
    EXPECT_EQ(sim()->runState(), State::Running);
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith(
        QStringLiteral("Online edit: the edited program runs from the next scan on")))
        << window.statusBar()->currentMessage().toStdString();
    sim()->stop();
    load("LD X2\nOUT Y0\nEND\n");
    EXPECT_EQ(sim()->session(), nullptr);
    EXPECT_EQ(sim()->runState(), State::Offline);
    EXPECT_EQ(window.watchListView()->monitorSource(), nullptr);
    EXPECT_EQ(window.ioPanel()->monitorSource(), nullptr);
    EXPECT_EQ(window.timingChart()->monitorSource(), nullptr);
    // Run starts the edited program.
    ASSERT_TRUE(sim()->run());
    ASSERT_NE(sim()->session(), nullptr);
}

TEST_F(Simulation, AListAsTypedWithErrorsDoesNotStart) {
    load(kFlipFlop);
    window.show();
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nLD\nEND\n"));
    window.applyListing();
    EXPECT_FALSE(sim()->run());
    EXPECT_EQ(sim()->session(), nullptr);
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(
        QStringLiteral("The instruction list has errors")))
        << window.statusBar()->currentMessage().toStdString();
}

TEST_F(Simulation, AProgramWithErrorsDoesNotStartAndProblemsSaysWhy) {
    load(kFlipFlop);
    window.show();
    // A coil on an input (OP002): the ladder draws it, the checks refuse it.
    model::Rung rung = window.document()->ladder().rungs.front();
    ASSERT_TRUE(rung.outputs[0].has_value());
    rung.outputs[0]->operands[0].address = at("X1");
    window.document()->setRung(0, rung, QStringLiteral("bad"));
    // What cannot be listed first; else the checks' errors.
    std::vector<model::Diagnostic> errors = window.document()->listing().problems;
    if (errors.empty())
        for (const model::Diagnostic &d : window.document()->diagnostics())
            if (d.severity == model::Severity::Error)
                errors.push_back(d);
    ASSERT_FALSE(errors.empty()) << "the test needs a program with an error";

    EXPECT_FALSE(sim()->run());
    EXPECT_EQ(sim()->session(), nullptr);
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith(
        QStringLiteral("The program has %1 error").arg(errors.size())))
        << window.statusBar()->currentMessage().toStdString();
    EXPECT_GE(window.problemsView()->count(model::Severity::Error), 1);
    for (const model::Diagnostic &e : errors) {
        bool shown = false;
        for (int i = 0; window.problemsView()->diagnosticAt(i); ++i)
            shown = shown || window.problemsView()->diagnosticAt(i)->message == e.message;
        EXPECT_TRUE(shown) << e.message.toStdString();
    }
}

} // namespace
