// Breakpoints, stepping, history and the online edit in the IDE (issue 11), offscreen with
// the real session: a breakpoint set with a key stops the running scan before its
// instruction, the Scan Debugger shows the logic result and both stacks, the list and the
// ladder mark the place; a conditional breakpoint; the history shows an earlier scan in every
// view, marked, then returns to live; an edit while running keeps a counter's value; the new
// keys clash with nothing.

#include "app/gui/breakpoint_dialog.h"
#include "app/gui/scan_debugger_view.h"
#include "app/gui/simulation_controller.h"
#include "app/gui/simulation_panel.h"
#include "editor/il_editor.h"
#include "editor/io_panel.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "simulator/history_source.h"
#include "simulator/session.h"
#include "tests/eventually.h"

#include "model/target/address.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QTreeWidget>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

using namespace rung;
using State = model::MonitorSource::RunState;

namespace {

// Rung 1: 0 LD X0, 1 OR X1, 2 LD X2, 3 AND X3, 4 ORB, 5 MPS, 6 AND X4, 7 OUT Y0, 8 MPP,
// 9 OUT Y1; rung 2: 10 LD X5, 11 OUT Y2; 12 END.
constexpr const char *kBlocks = "LD X0\nOR X1\nLD X2\nAND X3\nORB\nMPS\nAND X4\nOUT Y0\nMPP\n"
                                "OUT Y1\nLD X5\nOUT Y2\nEND\n";

struct Debugging : test::WindowFixture {
    app::SimulationController *sim() { return window.simulation(); }
    model::Address at(const char *device) {
        return std::get<model::Address>(
            model::parseAddress(window.document()->target(), QString::fromLatin1(device)));
    }
    template <typename Condition> bool eventually(Condition condition) {
        return test::eventually(condition);
    }
    std::shared_ptr<const model::Snapshot> live() {
        return sim()->session() ? sim()->session()->snapshot() : nullptr;
    }
    // The line of the list pane that holds the instruction (1-based).
    int lineOf(int instruction) {
        return window.document()
            ->printedListing()
            .instructionLine[static_cast<std::size_t>(instruction)];
    }
    void showActive() {
        window.show();
        QApplication::setActiveWindow(&window);
        ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    }
};

} // namespace

TEST_F(Debugging, ABreakpointSetWithCtrlBInTheListStopsTheRunWithTheStacks) {
    load(kBlocks);
    ASSERT_EQ(window.document()->listing().list.instructions.size(), 13u)
        << listing().toStdString();
    showActive();
    editor::IlEditor *il = window.ilEditor();
    window.setSideBySide(true);
    il->setFocus();
    // The inputs first (X0 and X2 ON: the block below ORB holds X0 OR X1), then the breakpoint.
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
    sim()->session()->writeBit(at("X0"), true);
    sim()->session()->writeBit(at("X2"), true);
    const int orb = lineOf(4);
    ASSERT_EQ(il->lineText(orb - 1).trimmed(), QStringLiteral("ORB"));
    il->setCursorPosition(orb - 1, 0);
    QTest::keyClick(il, Qt::Key_B, Qt::ControlModifier);
    ASSERT_EQ(sim()->breakpoints().size(), 1u);
    EXPECT_EQ(sim()->instructionOf(sim()->breakpoints()[0]), 4);
    EXPECT_EQ(il->breakpointLines(), std::vector<int>{orb});
    EXPECT_EQ(il->text(), listing()); // Ctrl+B typed nothing

    QTest::keyClick(il, Qt::Key_F10); // Run
    ASSERT_TRUE(
        eventually([&] { return sim()->runState() == State::Paused && live() && live()->pause; }));
    const model::ScanPause pause = *live()->pause;
    EXPECT_EQ(pause.instruction, 4);
    EXPECT_EQ(pause.breakpoint, 4);
    app::ScanDebuggerView *debugger = window.scanDebugger();
    ASSERT_TRUE(eventually([&] {
        return debugger->positionText().contains(QStringLiteral("ORB"));
    })) << debugger->positionText().toStdString();
    EXPECT_TRUE(debugger->positionText().contains(QStringLiteral("A breakpoint stopped")));
    // X2 AND X3 is OFF or ON depending on whether X2 had been read; X3 is OFF: OFF.
    EXPECT_EQ(debugger->resultText(), QStringLiteral("OFF"));
    EXPECT_EQ(debugger->blockStack().size(), 1);
    EXPECT_TRUE(debugger->blockStack()[0].contains(QStringLiteral("(top)")));
    EXPECT_EQ(debugger->memoryStack(), QStringList{QStringLiteral("(empty)")});
    EXPECT_EQ(il->stoppedLine(), orb);
    EXPECT_EQ(window.ladderView()->stoppedAt().rung, 0);
    EXPECT_EQ(window.ladderView()->stoppedAt().row, -1); // ORB: the rung as a whole

    // Ctrl+F12: ORB then MPS run; the MPS stack holds the block's result.
    QTest::keyClick(il, Qt::Key_F12, Qt::ControlModifier);
    ASSERT_TRUE(eventually([&] { return live()->pause && live()->pause->instruction == 5; }));
    QTest::keyClick(il, Qt::Key_F12, Qt::ControlModifier);
    ASSERT_TRUE(eventually([&] { return live()->pause && live()->pause->instruction == 6; }));
    ASSERT_TRUE(eventually([&] {
        return debugger->memoryStack().size() == 1 &&
               debugger->memoryStack()[0].contains(QStringLiteral("ON"));
    }));
    EXPECT_EQ(il->stoppedLine(), lineOf(6));
    EXPECT_EQ(window.ladderView()->stoppedAt().rung, 0);
    EXPECT_GE(window.ladderView()->stoppedAt().row, 0); // AND X4: its cell
    EXPECT_EQ(il->text(), listing());

    // Shift+F12 ends the scan: nothing stopped inside any more.
    const quint64 scans = live()->statistics.scans;
    QTest::keyClick(il, Qt::Key_F12, Qt::ShiftModifier);
    ASSERT_TRUE(
        eventually([&] { return !live()->pause && live()->statistics.scans == scans + 1; }));
    ASSERT_TRUE(eventually([&] { return il->stoppedLine() == 0; }));
    EXPECT_EQ(window.ladderView()->stoppedAt().rung, -1);
    EXPECT_TRUE(live()->bit(at("Y1")));
}

TEST_F(Debugging, AClickInTheLaddersGutterSetsARungBreakpoint) {
    load(kBlocks);
    showActive();
    editor::LadderView *ladder = window.ladderView();
    const QRect cell = ladder->cellRectOnScreen({1, 0, 0}); // rung 2's first cell
    QTest::mouseClick(ladder->viewport(), Qt::LeftButton, {}, QPoint(5, cell.center().y()));
    ASSERT_EQ(sim()->breakpoints().size(), 1u);
    EXPECT_EQ(sim()->instructionOf(sim()->breakpoints()[0]), 10);
    EXPECT_EQ(ladder->breakpointRungs(), (std::map<int, bool>{{1, false}}));
    // The key does the same on the cursor's rung: clears it again.
    ladder->setFocus();
    QTest::keyClick(ladder, Qt::Key_B, Qt::ControlModifier);
    EXPECT_TRUE(sim()->breakpoints().empty());
    EXPECT_TRUE(ladder->breakpointRungs().empty());
}

TEST_F(Debugging, AConditionalBreakpointStopsWhenTheWordPassesItsValue) {
    load("LD M9000\nINC D10\nLD X0\nOUT Y0\nEND\n");
    app::SimulationController::BreakpointSpec b;
    b.when = simulator::Breakpoint::When::Compare;
    b.device = at("D10");
    b.op = model::CompareOp::Gt;
    b.value = 100;
    sim()->setBreakpoint(2, b);
    EXPECT_EQ(sim()->conditionText(sim()->breakpoints()[0]), QStringLiteral("when D10 > 100"));
    EXPECT_EQ(window.ladderView()->breakpointRungs(), (std::map<int, bool>{{1, true}}));
    sim()->setSpeed(0);
    ASSERT_TRUE(sim()->run());
    ASSERT_TRUE(eventually([&] { return live() && live()->pause.has_value(); }));
    EXPECT_EQ(live()->value(at("D10")), 101);
    EXPECT_EQ(live()->pause->instruction, 2);
    QTreeWidget *list = window.scanDebugger()->breakpointList();
    ASSERT_EQ(list->topLevelItemCount(), 1);
    EXPECT_EQ(list->topLevelItem(0)->text(1), QStringLiteral("when D10 > 100"));
    sim()->setSpeed(1);
}

TEST_F(Debugging, TheConditionDialogAcceptsOnlyAConditionThatCanHold) {
    const model::Target &t = window.document()->target();
    app::BreakpointDialog dialog(t, QStringLiteral("line 3"), {});
    auto *ok = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
    EXPECT_TRUE(ok->isEnabled()); // always
    dialog.kindBox()->setCurrentIndex(
        dialog.kindBox()->findData(static_cast<int>(simulator::Breakpoint::When::Compare)));
    EXPECT_FALSE(ok->isEnabled());
    dialog.deviceEdit()->setText(QStringLiteral("Y0"));
    EXPECT_FALSE(ok->isEnabled());
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("Y0 is a bit")))
        << dialog.problem().toStdString();
    dialog.deviceEdit()->setText(QStringLiteral("Q7"));
    EXPECT_TRUE(dialog.problem().contains(QStringLiteral("Q7"))) << dialog.problem().toStdString();
    dialog.deviceEdit()->setText(QStringLiteral("D10"));
    dialog.operatorBox()->setCurrentIndex(dialog.operatorBox()->findText(QStringLiteral(">=")));
    dialog.valueBox()->setValue(250);
    EXPECT_TRUE(ok->isEnabled());
    const auto b = dialog.breakpoint();
    EXPECT_EQ(b.when, simulator::Breakpoint::When::Compare);
    EXPECT_EQ(b.device, at("D10"));
    EXPECT_EQ(b.op, model::CompareOp::Ge);
    EXPECT_EQ(b.value, 250);
    dialog.kindBox()->setCurrentIndex(
        dialog.kindBox()->findData(static_cast<int>(simulator::Breakpoint::When::Rises)));
    dialog.deviceEdit()->setText(QStringLiteral("Y0"));
    EXPECT_TRUE(ok->isEnabled());
}

TEST_F(Debugging, TheHistoryShowsAnEarlierScanInTheViewsMarkedThenReturnsToLive) {
    load("LD X0\nCNT C0 K100\nLD M9000\nADD D0 K1 D0\nEND\n");
    window.watchListView(); // the watch list is a view that follows the source
    ASSERT_TRUE(sim()->runScans(10));
    ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
    ASSERT_TRUE(sim()->runScans(40));
    ASSERT_TRUE(eventually(
        [&] { return sim()->runState() == State::Paused && live()->statistics.scans == 50; }));
    EXPECT_EQ(live()->value(at("D0")), 50);
    app::SimulationPanel *panel = window.simulationPanel();
    ASSERT_TRUE(eventually([&] { return panel->historySlider()->maximum() == 50; }));
    // The slider to scan 10: every view reads the history, marked as such.
    panel->historySlider()->setValue(10);
    ASSERT_TRUE(sim()->historyShown());
    ASSERT_TRUE(eventually([&] {
        const auto s = sim()->historySource()->snapshot();
        return s && s->statistics.scans == 10;
    }));
    EXPECT_EQ(sim()->historySource()->snapshot()->value(at("D0")), 10);
    EXPECT_EQ(window.watchListView()->monitorSource(), sim()->historySource());
    ASSERT_TRUE(eventually([&] {
        return test::statusText(window).contains(
            QStringLiteral("History: scan 10 (0:00:00.10)|History (read-only)"));
    })) << test::statusText(window).toStdString();
    // The panel and the status bar read the history source at different moments (on
    // statusChanged, the status bar also on the debugger's stop mark) while its worker
    // publishes the rebuilt scan; its shown() then refreshes both once more.
    ASSERT_TRUE(eventually([&] {
        return panel->historyLabel() == QStringLiteral("History: scan 10 (0:00:00.10)");
    })) << panel->historyLabel().toStdString();
    // A write is refused and said.
    sim()->historySource()->writeWord(at("D0"), 5);
    ASSERT_TRUE(eventually([&] {
        return window.statusBar()->currentMessage().startsWith(
            QStringLiteral("history is read-only"));
    })) << window.statusBar()->currentMessage().toStdString();
    // Scrubbing the timing chart's cursor A: 255 ms sits on scan 25's end (250 ms). The
    // chart itself stays live (it is what one scrubs along); the terminals show the past
    // with the ladder.
    editor::TimingChart *chart = window.timingChart();
    chart->placeCursor(0, 255);
    ASSERT_TRUE(eventually([&] {
        const auto s = sim()->historySource()->snapshot();
        return s && s->statistics.scans == 25;
    }));
    EXPECT_EQ(sim()->historySource()->snapshot()->value(at("D0")), 25);
    EXPECT_EQ(window.ioPanel()->monitorSource(), sim()->historySource());
    EXPECT_EQ(chart->monitorSource(), sim()->session());
    // Cursor B measures; it does not move the history.
    chart->placeCursor(1, 405);
    QApplication::processEvents();
    EXPECT_EQ(sim()->historySource()->snapshot()->statistics.scans, 25u);
    QAction *live = test::menuAction(window, QStringLiteral("Return to Live"));
    ASSERT_NE(live, nullptr);
    EXPECT_EQ(live->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L));
    live->trigger();
    EXPECT_FALSE(sim()->historyShown());
    EXPECT_EQ(window.watchListView()->monitorSource(), sim()->session());
    EXPECT_EQ(window.ioPanel()->monitorSource(), sim()->session());
    EXPECT_FALSE(test::statusText(window).contains(QStringLiteral("History:")));
    EXPECT_TRUE(panel->historyLabel().isEmpty());
}

TEST_F(Debugging, AFullStatusBarElidesTheRunStateAndKeepsTheHistoryMarksApart) {
    // The run state with its statistics is long; in Hungarian at 1366x768 it once pushed the
    // amber history label and the framed origin label over each other.
    load("LD X0\nCNT C0 K100\nLD M9000\nADD D0 K1 D0\nEND\n");
    window.resize(800, 600);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    sim()->setSpeed(10);
    ASSERT_TRUE(sim()->runScans(30));
    ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
    window.simulationPanel()->historySlider()->setValue(10);
    ASSERT_TRUE(sim()->historyShown());
    auto *history = window.statusBar()->findChild<QLabel *>(QStringLiteral("historyStatus"));
    auto *origin = window.statusBar()->findChild<QLabel *>(QStringLiteral("monitorOrigin"));
    auto *state =
        window.statusBar()->findChild<app::ElidingLabel *>(QStringLiteral("simulationStatus"));
    ASSERT_TRUE(history && origin && state);
    ASSERT_TRUE(eventually([&] { return history->isVisible() && origin->isVisible(); }));
    // The status bar lays out over a few posted events; then the labels sit side by side.
    const auto apart = [&] {
        return !history->geometry().intersects(origin->geometry()) &&
               !origin->geometry().intersects(state->geometry()) &&
               !history->geometry().intersects(state->geometry());
    };
    EXPECT_TRUE(eventually(apart));
    const QString full = state->fullText();
    EXPECT_TRUE(full.startsWith(QStringLiteral("Paused | 0:00:00.30 | 30 scans")))
        << full.toStdString();
    EXPECT_GE(history->width(), history->sizeHint().width()); // the scan's number is whole
    EXPECT_LE(state->geometry().right(), window.statusBar()->width());
    // What did not fit is elided, and the whole run state is its tooltip.
    EXPECT_TRUE(state->text().endsWith(QChar(0x2026))) << state->text().toStdString();
    EXPECT_TRUE(state->toolTip().startsWith(full)) << state->toolTip().toStdString();
    sim()->setSpeed(1);
}

TEST_F(Debugging, AnEditWhileRunningKeepsTheCounterValueAndSaysSo) {
    load("LD X0\nCNT C0 K100\nEND\n");
    ASSERT_TRUE(sim()->singleScan());
    for (int k = 0; k < 4; ++k) {
        sim()->session()->writeBit(at("X0"), true);
        sim()->singleScan();
        ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
        sim()->session()->writeBit(at("X0"), false);
        sim()->singleScan();
        ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
    }
    ASSERT_TRUE(eventually([&] { return live()->value(at("C0")) == 4; }));
    simulator::SimulatorSession *session = sim()->session();
    sim()->setSpeed(10);
    ASSERT_TRUE(sim()->run());
    QString said;
    QObject::connect(sim(), &app::SimulationController::message, &window,
                     [&](const QString &text) { said = text; });
    load("LD X0\nCNT C0 K100\nLD C0\nOUT Y0\nLD M9000\nOUT Y1\nEND\n");
    EXPECT_EQ(sim()->session(), session); // not dropped: edited online
    EXPECT_EQ(said, QStringLiteral("Online edit: the edited program runs from the next scan on; "
                                   "the memory is kept"));
    ASSERT_TRUE(eventually([&] { return live()->bit(at("Y1")); }));
    EXPECT_EQ(live()->value(at("C0")), 4);
    EXPECT_EQ(sim()->runState(), State::Running);
    sim()->setSpeed(1);
    sim()->pause();
}

TEST_F(Debugging, AnEditThatRenumbersATimerAsksFirst) {
    load("LD X0\nTMR T0 K50\nEND\n");
    ASSERT_TRUE(sim()->run());
    QString asked;
    sim()->setAsker([&](const QString &question, bool canKeep) {
        asked = question;
        EXPECT_TRUE(canKeep);
        return app::SimulationController::EditChoice::Restart;
    });
    QSignalSpy sessions(sim(), &app::SimulationController::sessionChanged);
    load("LD X0\nTMR T5 K50\nEND\n");
    EXPECT_TRUE(asked.contains(QStringLiteral("no longer uses T0"))) << asked.toStdString();
    EXPECT_TRUE(asked.contains(QStringLiteral("now uses T5"))) << asked.toStdString();
    // Restarted from power-on: a new session, running.
    EXPECT_NE(sim()->session(), nullptr);
    EXPECT_EQ(sessions.count(), 2); // dropped, then made anew
    EXPECT_EQ(sim()->runState(), State::Running);
    sim()->pause();
    // Stop the simulation: none left.
    sim()->setAsker([](const QString &, bool) {
        return app::SimulationController::EditChoice::StopSimulation;
    });
    sim()->run();
    load("LD X0\nTMR T6 K50\nEND\n");
    EXPECT_EQ(sim()->session(), nullptr);
}

TEST_F(Debugging, AnEditWithErrorsGoesOnWithTheProgramBeforeItAndSaysSo) {
    load("LD X0\nOUT Y0\nEND\n");
    ASSERT_TRUE(sim()->run());
    simulator::SimulatorSession *session = sim()->session();
    // A coil on an input (OP002): the ladder draws it, the checks refuse it.
    model::Rung rung = window.document()->ladder().rungs.front();
    ASSERT_TRUE(rung.outputs[0].has_value());
    rung.outputs[0]->operands[0].address = at("X1");
    window.document()->setRung(0, rung, QStringLiteral("bad"));
    EXPECT_EQ(sim()->session(), session);
    EXPECT_TRUE(sim()->statusText().contains(QStringLiteral("the program before the edit")))
        << sim()->statusText().toStdString();
    sim()->stop();
}

TEST_F(Debugging, TheNewKeysAreInTheMenuAndClashWithNothing) {
    std::map<QString, QKeySequence> keys;
    for (const auto &[name, key] : std::map<QString, QKeySequence>{
             {QStringLiteral("Step Instruction"), QKeySequence(Qt::CTRL | Qt::Key_F12)},
             {QStringLiteral("Finish Scan"), QKeySequence(Qt::SHIFT | Qt::Key_F12)},
             {QStringLiteral("Toggle Breakpoint"), QKeySequence(Qt::CTRL | Qt::Key_B)},
             {QStringLiteral("Breakpoint Condition..."),
              QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B)},
             {QStringLiteral("Run Scans..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F10)},
             {QStringLiteral("Run For..."), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F11)},
             {QStringLiteral("Return to Live"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_L)}}) {
        QAction *a = test::menuAction(window, name);
        ASSERT_NE(a, nullptr) << name.toStdString();
        EXPECT_EQ(a->shortcut(), key) << name.toStdString();
        EXPECT_TRUE(a->toolTip().contains(key.toString(QKeySequence::NativeText)))
            << name.toStdString();
        keys[name] = key;
    }
    std::set<QAction *> seen;
    for (QAction *a : window.findChildren<QAction *>()) {
        if (!seen.insert(a).second)
            continue;
        for (const QKeySequence &other : a->shortcuts())
            for (const auto &[name, key] : keys) {
                if (QString(a->text()).remove(QLatin1Char('&')) != name) {
                    EXPECT_NE(other, key)
                        << name.toStdString() << " and " << a->text().toStdString();
                }
            }
    }
    for (const auto &[name, key] : keys) {
        const int k = key[0].key();
        EXPECT_FALSE(k >= Qt::Key_F5 && k <= Qt::Key_F9) << name.toStdString();
        EXPECT_NE(key, QKeySequence(Qt::CTRL | Qt::Key_F10)) << name.toStdString();
        EXPECT_NE(key, QKeySequence(Qt::CTRL | Qt::Key_F9)) << name.toStdString();
    }
}

TEST_F(Debugging, TheDockRunsScansAndForASimulatedTime) {
    load("LD X0\nOUT Y0\nEND\n");
    app::SimulationPanel *panel = window.simulationPanel();
    panel->scansBox()->setValue(25);
    panel->findChild<QPushButton *>(); // the panel is built
    for (QPushButton *b : panel->findChildren<QPushButton *>())
        if (b->text() == QStringLiteral("Run Scans"))
            b->click();
    ASSERT_TRUE(eventually([&] { return live() && live()->statistics.scans == 25; }));
    ASSERT_TRUE(eventually([&] { return sim()->runState() == State::Paused; }));
    panel->durationBox()->setValue(1.5); // 150 scans of 10 ms
    for (QPushButton *b : panel->findChildren<QPushButton *>())
        if (b->text() == QStringLiteral("Run For"))
            b->click();
    ASSERT_TRUE(eventually([&] { return live()->statistics.scans == 175; }));
    EXPECT_EQ(live()->statistics.timeMs, 1750);
    ASSERT_TRUE(eventually([&] {
        return panel->statisticsText().contains(QStringLiteral("Scans: 175"));
    })) << panel->statisticsText().toStdString();
    EXPECT_TRUE(panel->statisticsText().contains(QStringLiteral("Simulated time: 0:00:01.75")));
    // The period from the dock.
    panel->periodBox()->setValue(5);
    EXPECT_EQ(sim()->periodMs(), 5);
    sim()->setPeriodMs(10);
}

// The Scan Debugger names the stacks as the family writes them: ANB / ORB and MPS on a Vigor;
// AND LD / OR LD on a CPM1, which has no branch stack (it branches through TR bits) to show.
TEST_F(Debugging, TheStacksAreNamedInTheFamilysWords) {
    app::ScanDebuggerView *debugger = window.scanDebugger();
    ASSERT_NE(debugger, nullptr);
    const auto captions = [debugger] {
        QStringList texts;
        for (const QLabel *label : debugger->findChildren<QLabel *>())
            if (!label->isHidden())
                texts << label->text();
        return texts;
    };
    auto *branchStack = debugger->findChild<QWidget *>(QStringLiteral("debuggerMpsStack"));
    ASSERT_NE(branchStack, nullptr);
    load(kBlocks);
    debugger->refresh();
    EXPECT_TRUE(captions().contains(QStringLiteral("Block stack (ANB / ORB):")))
        << captions().join(u'|').toStdString();
    EXPECT_TRUE(captions().contains(QStringLiteral("MPS stack:")))
        << captions().join(u'|').toStdString();
    EXPECT_FALSE(branchStack->isHidden());
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    debugger->refresh();
    EXPECT_TRUE(captions().contains(QStringLiteral("Block stack (AND LD / OR LD):")))
        << captions().join(u'|').toStdString();
    EXPECT_FALSE(captions().join(u'|').contains(QStringLiteral("MPS")))
        << captions().join(u'|').toStdString();
    EXPECT_TRUE(branchStack->isHidden());
}
