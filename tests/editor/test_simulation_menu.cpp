// The Simulation menu, its buttons and the status bar's simulation section
// (app/gui/simulation_menu.h) without the Rung Studio window: the simulation, the debugging
// controller and a plain main window.

#include "app/gui/debug_controller.h"
#include "app/gui/eliding_label.h"
#include "app/gui/simulation_controller.h"
#include "app/gui/simulation_menu.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "tests/eventually.h"

#include <QAction>
#include <QLabel>
#include <QMainWindow>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>

using namespace rung;
using rung::waits::kPatienceMs;

namespace {

// The simulation's speed and period are remembered in the settings: what a test here chooses
// is put back when it ends, so that no later test of the binary starts at 20 ms scans.
struct RememberedSimulation {
    QVariant speed = QSettings().value(QStringLiteral("simulation/speed"));
    QVariant period = QSettings().value(QStringLiteral("simulation/periodMs"));
    ~RememberedSimulation() {
        QSettings settings;
        for (const auto &[key, value] : {std::pair{QStringLiteral("simulation/speed"), speed},
                                         std::pair{QStringLiteral("simulation/periodMs"), period}})
            if (value.isValid())
                settings.setValue(key, value);
            else
                settings.remove(key);
    }
};

struct MenuAlone {
    RememberedSimulation remembered; // first: restored after the controller has gone
    QMainWindow window;              // the menu bar's place: no Rung Studio window
    editor::Document document;
    editor::LadderView ladder{&document};
    editor::IlEditor il{model::Target::get(model::Family::Vigor)};
    app::SimulationController simulation{&document};
    app::DebugController debug{&document, &ladder, &il, &simulation, window.statusBar(), &window};
    app::SimulationMenu menu{&simulation, &debug, &window};
    QToolBar bar;

    MenuAlone() {
        document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        EXPECT_TRUE(document.setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), nullptr));
        menu.addActions(&bar);
    }
    QAction *action(const char *name) const {
        return window.menuBar()->findChild<QAction *>(QString::fromLatin1(name));
    }
    QString state() const { return menu.statusLabel()->fullText(); }
};

} // namespace

TEST(SimulationMenuAlone, TheKeysAndButtonsAreTheVendorsAndFollowTheRunState) {
    using RunState = model::MonitorSource::RunState;
    MenuAlone f;
    QAction *run = f.action("simulationRun");
    QAction *pause = f.action("simulationPause");
    QAction *stop = f.action("simulationStop");
    QAction *scan = f.action("simulationScan");
    ASSERT_TRUE(run && pause && stop && scan);
    EXPECT_EQ(run->shortcut(), QKeySequence(Qt::Key_F10));
    EXPECT_EQ(pause->shortcut(), QKeySequence(Qt::Key_F11));
    EXPECT_EQ(stop->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F11));
    EXPECT_EQ(scan->shortcut(), QKeySequence(Qt::Key_F12));
    // Run, pause, stop, one scan and one instruction on the toolbar, in that order.
    QStringList buttons;
    for (QAction *a : f.bar.actions())
        if (!a->isSeparator())
            buttons << a->objectName();
    EXPECT_EQ(buttons,
              QStringList({QStringLiteral("simulationRun"), QStringLiteral("simulationPause"),
                           QStringLiteral("simulationStop"), QStringLiteral("simulationScan"),
                           QStringLiteral("simulationStepInstruction")}));
    // Before a run: only what starts one.
    EXPECT_TRUE(run->isEnabled());
    EXPECT_FALSE(pause->isEnabled());
    EXPECT_FALSE(stop->isEnabled());
    // Running: pause and stop, and the state in the status bar.
    run->trigger();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return f.simulation.runState() == RunState::Running; }, kPatienceMs));
    EXPECT_FALSE(run->isEnabled());
    EXPECT_TRUE(pause->isEnabled());
    EXPECT_TRUE(stop->isEnabled());
    EXPECT_TRUE(f.state().startsWith(QStringLiteral("Running"))) << f.state().toStdString();
    // Paused: run again or stop.
    pause->trigger();
    ASSERT_TRUE(
        QTest::qWaitFor([&] { return f.simulation.runState() == RunState::Paused; }, kPatienceMs));
    EXPECT_TRUE(run->isEnabled());
    EXPECT_FALSE(pause->isEnabled());
    EXPECT_TRUE(f.state().startsWith(QStringLiteral("Paused"))) << f.state().toStdString();
    stop->trigger();
    EXPECT_FALSE(stop->isEnabled());
    EXPECT_TRUE(f.menu.historyLabel()->isHidden()); // no past scan shown
}

TEST(SimulationMenuAlone, ASpeedOrPeriodChosenElsewhereIsCheckedInTheMenu) {
    MenuAlone f;
    const auto checked = [&](const char *name) {
        QVariant data;
        for (QAction *a : f.window.menuBar()->findChildren<QAction *>(QString::fromLatin1(name)))
            if (a->isChecked())
                data = a->data();
        return data;
    };
    f.simulation.setSpeed(10.0); // as the Simulation dock's box sets it
    EXPECT_EQ(checked("simulationSpeedChoice").toDouble(), 10.0);
    f.simulation.setPeriodMs(20);
    EXPECT_EQ(checked("simulationPeriodChoice").toLongLong(), 20);
}
