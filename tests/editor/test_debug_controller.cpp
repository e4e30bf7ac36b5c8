// Breakpoints, stepping and the simulation's docks (app/gui/debug_controller.h) without the
// Rung Studio window: the document, the two views, the simulation and a plain main window.

#include "app/gui/debug_controller.h"
#include "app/gui/scan_debugger_view.h"
#include "app/gui/simulation_controller.h"
#include "app/gui/simulation_panel.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "tests/eventually.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTest>

#include <gtest/gtest.h>

using namespace rung;
using rung::waits::kPatienceMs;

namespace {

// Two rungs: X0 -> Y0 (instructions 0, 1), X1 -> Y1 (2, 3).
struct DebugAlone {
    QMainWindow window; // the docks' place: no Rung Studio window
    editor::Document document;
    editor::LadderView ladder{&document};
    editor::IlEditor il{model::Target::get(model::Family::Vigor)};
    app::SimulationController simulation{&document};
    app::DebugController debug{&document, &ladder, &il, &simulation, window.statusBar(), &window};
    QMenu menu;

    DebugAlone() {
        document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        EXPECT_TRUE(
            document.setListing(QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n"), nullptr));
        il.setListing(document.listingText()); // the list pane shows the program
        debug.addActions(&menu);
    }
    QAction *action(const char *name) const {
        return menu.findChild<QAction *>(QString::fromLatin1(name));
    }
    QString status() const { return window.statusBar()->currentMessage(); }
};

} // namespace

TEST(DebugControllerAlone, ABreakpointOnTheCursorsRungIsMarkedAndSaid) {
    DebugAlone f;
    f.ladder.setCursor({1, 0, 0});
    f.debug.toggleBreakpointHere();
    ASSERT_EQ(f.simulation.breakpoints().size(), 1u);
    EXPECT_EQ(f.simulation.instructionOf(f.simulation.breakpoints().front()), 2);
    EXPECT_EQ(f.ladder.breakpointRungs(), (std::map<int, bool>{{1, false}}));
    EXPECT_EQ(f.status(), QStringLiteral("Breakpoint set at rung 2"));
    // The list's margin marks the same instruction's line.
    EXPECT_EQ(f.il.breakpointLines(), std::vector<int>{3});
    // Ctrl+B again: gone, and said.
    f.action("simulationToggleBreakpoint")->trigger();
    EXPECT_TRUE(f.simulation.breakpoints().empty());
    EXPECT_TRUE(f.ladder.breakpointRungs().empty());
    EXPECT_EQ(f.status(), QStringLiteral("Breakpoint at rung 2 removed"));
    // A click in the list's margin beside a line with no instruction: nothing set, and said.
    emit f.il.breakpointToggleRequested(6);
    EXPECT_TRUE(f.simulation.breakpoints().empty());
    EXPECT_EQ(f.status(), QStringLiteral("No instruction on line 6 to stop at"));
    // Beside an instruction's line: set there.
    emit f.il.breakpointToggleRequested(2);
    ASSERT_EQ(f.simulation.breakpoints().size(), 1u);
    EXPECT_EQ(f.simulation.instructionOf(f.simulation.breakpoints().front()), 1);
}

TEST(DebugControllerAlone, TheFirstRunShowsTheSimulationDockAndAStopShowsWhereInBothViews) {
    DebugAlone f;
    auto *simulationDock = f.window.findChild<QDockWidget *>(QStringLiteral("simulationDock"));
    auto *debuggerDock = f.window.findChild<QDockWidget *>(QStringLiteral("scanDebuggerDock"));
    ASSERT_NE(simulationDock, nullptr);
    ASSERT_NE(debuggerDock, nullptr);
    EXPECT_TRUE(simulationDock->isHidden());
    EXPECT_TRUE(debuggerDock->isHidden());
    QSignalSpy shown(&f.debug, &app::DebugController::stoppedAtShown);
    ASSERT_TRUE(f.simulation.toggleBreakpoint(2)); // before LD X1, rung 2, line 3
    ASSERT_TRUE(f.simulation.run());
    EXPECT_FALSE(simulationDock->isHidden());
    ASSERT_TRUE(QTest::qWaitFor([&] { return !shown.isEmpty(); }, kPatienceMs));
    EXPECT_EQ(shown.last()[0].toInt(), 2);
    EXPECT_FALSE(debuggerDock->isHidden());
    EXPECT_EQ(f.ladder.stoppedAt().rung, 1);
    EXPECT_EQ(f.il.stoppedLine(), 3);
    // Stepped on: LD X1 done, stopped before OUT Y1 (line 4).
    f.action("simulationStepInstruction")->trigger();
    EXPECT_TRUE(QTest::qWaitFor([&] { return f.il.stoppedLine() == 4; }, kPatienceMs))
        << f.il.stoppedLine();
    f.simulation.stop();
}
