// What a new user tripped over (issue 31), offscreen with the real window and simulation: the
// window never says something that is no longer true (the history's label after Return to
// Live, a list's errors on the next file, a watch value nobody wrote, a constant preset read
// as 0), the UI changes nothing the user did not touch (the wheel over the connection
// settings, a right click on another rung), and the small things (a word after an export, a
// Remove that needs a choice, the connection's last words on another project, the ladder
// left where the user scrolled it, the history's window told truly).

#include "app/gui/connection_panel.h"
#include "app/gui/dock_layout.h"
#include "app/gui/language.h"
#include "app/gui/scan_debugger_view.h"
#include "app/gui/simulation_controller.h"
#include "editor/ladder_view.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"
#include "simulator/history_source.h"
#include "simulator/session.h"

#include <QApplication>
#include <QComboBox>
#include <QContextMenuEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QLineEdit>
#include <QMainWindow>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeWidget>
#include <QWheelEvent>

#include "tests/editor/watch_rows.h"
#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace rung;

namespace {

using RunState = model::MonitorSource::RunState;

struct TrueWindow : test::WindowFixture {
    app::SimulationController *sim() { return window.simulation(); }
    model::Address at(const char *device) {
        return std::get<model::Address>(
            model::parseAddress(window.document()->target(), QString::fromLatin1(device)));
    }
    bool paused() {
        return QTest::qWaitFor([&] { return sim()->runState() == RunState::Paused; }, 5000);
    }
    // The value cell of a device's row in the watch table.
    QPersistentModelIndex watchValue(const QString &device) {
        return test::watchRowOf(window.watchListView(), device)
            .siblingAtColumn(editor::WatchListView::ValueColumn);
    }
    QString originLabel() {
        auto *origin = window.statusBar()->findChild<QLabel *>(QStringLiteral("monitorOrigin"));
        return origin && origin->isVisible() ? origin->text() : QString();
    }
};

} // namespace

// Item 1: Return to Live names the simulation again, in the status bar and the title, and
// Run and Stop after it do not bring the history's name back.
TEST_F(TrueWindow, ReturnToLiveNamesTheSimulationAgain) {
    load("LD M9000\nADD D0 K1 D0\nEND\n");
    window.show();
    ASSERT_TRUE(sim()->runScans(20));
    ASSERT_TRUE(paused());
    sim()->showHistoryScan(5);
    const QString history = app::MainWindow::originText(app::MainWindow::MonitorOrigin::History);
    const QString simulation =
        app::MainWindow::originText(app::MainWindow::MonitorOrigin::Simulation);
    EXPECT_EQ(originLabel(), history);
    EXPECT_TRUE(window.windowTitle().contains(history));
    QAction *live = test::menuAction(window, QStringLiteral("Return to Live"));
    ASSERT_NE(live, nullptr);
    live->trigger();
    EXPECT_EQ(originLabel(), simulation);
    EXPECT_FALSE(window.windowTitle().contains(history)) << window.windowTitle().toStdString();
    EXPECT_TRUE(window.windowTitle().contains(simulation)) << window.windowTitle().toStdString();
    ASSERT_TRUE(sim()->run());
    sim()->stop();
    EXPECT_EQ(originLabel(), simulation);
    EXPECT_FALSE(window.windowTitle().contains(history)) << window.windowTitle().toStdString();
}

// Item 2: the ladder's banner about the list's errors belongs to the file that had them.
TEST_F(TrueWindow, TheBannerAboutAListsErrorsGoesWithItsFile) {
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.il"));
    const QString good = dir.filePath(QStringLiteral("good.il"));
    for (const auto &[path, text] : {std::pair{bad, "LD X0\nOUT Y0\nFOO X1\nLD\nBAR\nEND\n"},
                                     std::pair{good, "LD X0\nOUT Y0\nEND\n"}}) {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
    }
    ASSERT_TRUE(window.openFile(bad, QStringLiteral("vigor"), true));
    EXPECT_TRUE(view->notice().startsWith(QStringLiteral("The instruction list has ")))
        << view->notice().toStdString();
    ASSERT_TRUE(window.openFile(good, QStringLiteral("vigor"), true));
    EXPECT_TRUE(view->notice().isEmpty()) << view->notice().toStdString();
    // A new project too.
    ASSERT_TRUE(window.openFile(bad, QStringLiteral("vigor"), true));
    ASSERT_FALSE(view->notice().isEmpty());
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    EXPECT_TRUE(view->notice().isEmpty()) << view->notice().toStdString();
}

// Item 3: a write the history refuses leaves the row showing what the scan shown holds, not
// the value typed.
TEST_F(TrueWindow, AWatchValueTheHistoryRefusesIsNotShown) {
    load("LD M9000\nADD D0 K1 D0\nEND\n");
    window.watchListView()->addDevice(QStringLiteral("D0"));
    ASSERT_TRUE(sim()->runScans(20));
    ASSERT_TRUE(paused());
    sim()->showHistoryScan(5);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const auto s = sim()->historySource()->snapshot();
            return s && s->statistics.scans == 5;
        },
        5000));
    const QPersistentModelIndex row = watchValue(QStringLiteral("D0"));
    ASSERT_TRUE(row.isValid());
    ASSERT_TRUE(QTest::qWaitFor([&] { return row.data().toString() == QStringLiteral("5"); }, 5000))
        << row.data().toString().toStdString();
    // Typed in the value cell (F2) and committed with Return, as a user does.
    editor::WatchListView *watch = window.watchListView();
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    watch->setCurrentIndex(row);
    QTest::keyClick(watch, Qt::Key_F2);
    auto *editor = watch->viewport()->findChild<QLineEdit *>();
    ASSERT_NE(editor, nullptr);
    editor->setText(QStringLiteral("777"));
    QTest::keyClick(editor, Qt::Key_Return);
    QApplication::processEvents();
    EXPECT_EQ(row.data().toString(), QStringLiteral("5"));
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            return window.statusBar()->currentMessage().startsWith(
                QStringLiteral("history is read-only"));
        },
        5000))
        << window.statusBar()->currentMessage().toStdString();
    EXPECT_EQ(row.data().toString(), QStringLiteral("5"));
}

// Item 4: a K preset is the program's: after Stop the box, the list and the watch table show
// it, not the 0 of a memory the box has not run in yet.
TEST_F(TrueWindow, AConstantPresetIsShownWhenStopped) {
    load("LD X0\nTMR T0 K350\nLD X1\nCNT C0 K10\nEND\n");
    window.watchListView()->addDevice(QStringLiteral("T0"));
    window.watchListView()->addDevice(QStringLiteral("C0"));
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_TRUE(paused());
    sim()->stop();
    // The power-on state's snapshot: no scan yet, the boxes not run.
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
            const auto s = sim()->session() ? sim()->session()->snapshot() : nullptr;
            return sim()->runState() == RunState::Stopped && s && s->statistics.scans == 0;
        },
        5000));
    QApplication::processEvents();
    const auto value = [&](int rung) {
        const model::RungOverlay o = view->overlay(rung);
        return o.output(0) ? o.output(0)->value : QString();
    };
    EXPECT_TRUE(QTest::qWaitFor([&] { return value(0).startsWith(QStringLiteral("0/350")); }, 5000))
        << value(0).toStdString();
    EXPECT_EQ(value(1), QStringLiteral("0/10"));
    const QModelIndex timer = watchValue(QStringLiteral("T0"));
    const QModelIndex counter = watchValue(QStringLiteral("C0"));
    ASSERT_TRUE(timer.isValid() && counter.isValid());
    EXPECT_EQ(timer.data().toString(), QStringLiteral("0 of 350, OFF"));
    EXPECT_EQ(counter.data().toString(), QStringLiteral("0 of 10, OFF"));
}

// Item 6: the wheel over the connection dock scrolls it; the format and the station stay.
TEST_F(TrueWindow, TheWheelScrollsTheConnectionDockAndChangesNoSetting) {
    window.resize(1024, 600);
    window.show();
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("connectionDock"));
    ASSERT_NE(dock, nullptr);
    dock->show();
    dock->raise();
    QApplication::processEvents();
    app::ConnectionPanel *panel = window.connectionPanel();
    auto *frame = panel->findChild<QComboBox *>(QStringLiteral("connectionFrame"));
    auto *station = panel->findChild<QSpinBox *>(QStringLiteral("connectionStation"));
    auto *scroll = qobject_cast<QScrollArea *>(dock->widget());
    ASSERT_TRUE(frame && station && scroll);
    const int format = frame->currentIndex();
    const int number = station->value();
    const auto wheel = [](QWidget *over, int delta) {
        const QPointF at(over->width() / 2.0, over->height() / 2.0);
        QWheelEvent event(at, over->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(over, &event);
    };
    scroll->verticalScrollBar()->setValue(0);
    for (int turn = 0; turn < 3; ++turn) {
        wheel(frame, -120);
        wheel(station, -120);
        wheel(frame, 120);
        wheel(station, 120);
        wheel(station, 120);
    }
    EXPECT_EQ(frame->currentIndex(), format);
    EXPECT_EQ(station->value(), number);
    EXPECT_FALSE(frame->hasFocus());
    EXPECT_FALSE(station->hasFocus());
    // What the wheel meant: the dock scrolls.
    if (scroll->verticalScrollBar()->maximum() > 0) {
        scroll->verticalScrollBar()->setValue(0);
        wheel(frame, -120);
        EXPECT_GT(scroll->verticalScrollBar()->value(), 0);
    }
}

// Item 7: a right click on an element of another rung opens that element's menu, though the
// spare row leaves the cursor's rung and the drawing moves under the pointer.
TEST_F(TrueWindow, ARightClickOnAnotherRungOpensTheMenuOfItsElement) {
    load("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n");
    window.resize(1200, 800);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    ASSERT_TRUE(sim()->singleScan()); // the menu writes to a running source
    ASSERT_TRUE(paused());
    view->setCursor({0, 0, 0}); // the spare row under rung 1
    const editor::CellCursor target{2, 0, 0};
    const QPoint at = view->cellRectOnScreen(target).center();
    const QPoint global = view->viewport()->mapToGlobal(at);
    QMouseEvent press(QEvent::MouseButtonPress, at, global, Qt::RightButton, Qt::RightButton,
                      Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &press);
    QContextMenuEvent menuEvent(QContextMenuEvent::Mouse, at, global);
    QApplication::sendEvent(view->viewport(), &menuEvent);
    EXPECT_EQ(view->cursor().rung, target.rung);
    EXPECT_EQ(view->cursor().row, target.row);
    EXPECT_EQ(view->cursor().column, target.column);
    QMenu *menu = view->findChild<QMenu *>(QStringLiteral("monitorMenu"));
    ASSERT_NE(menu, nullptr);
    bool namesX2 = false;
    for (QAction *a : menu->actions())
        namesX2 = namesX2 || a->text().contains(QStringLiteral("X2"));
    EXPECT_TRUE(namesX2);
    menu->close();
}

// Item 15: the chart's export says where it went.
TEST_F(TrueWindow, ExportingTheTimingChartSaysWhereItWent) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("chart.csv"));
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, true);
    QTimer::singleShot(0, [&] {
        if (auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget())) {
            dialog->selectFile(path);
            QMetaObject::invokeMethod(dialog, "accept"); // a slot: what the Save button does
        }
    });
    emit window.timingChart()->exportRequested(QStringLiteral("csv"));
    QCoreApplication::setAttribute(Qt::AA_DontUseNativeDialogs, false);
    EXPECT_TRUE(QFile::exists(path));
    EXPECT_EQ(window.statusBar()->currentMessage(),
              QStringLiteral("Timing chart exported to %1").arg(QDir::toNativeSeparators(path)));
}

// Item 15: Remove needs a breakpoint chosen in the list, and says so while none is.
TEST_F(TrueWindow, RemoveNeedsABreakpointChosenAndSaysSo) {
    load("LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n");
    sim()->toggleBreakpoint(0);
    sim()->toggleBreakpoint(2);
    app::ScanDebuggerView *debugger = window.scanDebugger();
    QPushButton *remove = debugger->removeButton();
    ASSERT_EQ(debugger->breakpointList()->topLevelItemCount(), 2);
    debugger->breakpointList()->clearSelection();
    EXPECT_FALSE(remove->isEnabled());
    EXPECT_EQ(remove->toolTip(), QStringLiteral("Choose a breakpoint in the list first"));
    debugger->breakpointList()->setCurrentItem(debugger->breakpointList()->topLevelItem(1));
    EXPECT_TRUE(remove->isEnabled());
    EXPECT_TRUE(remove->toolTip().isEmpty());
    remove->click();
    ASSERT_EQ(sim()->breakpoints().size(), 1u);
    EXPECT_EQ(sim()->instructionOf(sim()->breakpoints().front()), 0);
}

// Item 15: the connection panel's last words are of this project, in this language.
TEST_F(TrueWindow, TheConnectionsLastWordsAreOfThisProjectInThisLanguage) {
    app::ConnectionPanel *panel = window.connectionPanel();
    auto *result = panel->findChild<QLabel *>(QStringLiteral("connectionTestResult"));
    ASSERT_NE(result, nullptr);
    comms::ConnectionSettings s = panel->settings();
    s.port.clear();
    panel->setSettings(s);
    EXPECT_FALSE(panel->testConnection()); // no port: it says so in the panel
    const QString english =
        QStringLiteral("Choose the serial port the PLC is on (or type its path)");
    EXPECT_EQ(result->text(), english);
    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
    const QString hungarian =
        QCoreApplication::translate("rung::app::ConnectionPanel", english.toLatin1().constData());
    EXPECT_NE(hungarian, english);
    EXPECT_EQ(result->text(), hungarian);
    app::setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
    EXPECT_EQ(result->text(), english);
    // Another project: the panel's words of the last one go.
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    EXPECT_TRUE(result->text().isEmpty()) << result->text().toStdString();
}

// Item 15: a row added to the watch table leaves the ladder where the user scrolled it.
TEST_F(TrueWindow, AddingAWatchRowLeavesTheLadderWhereItWasScrolled) {
    QString listing;
    for (int i = 0; i < 40; ++i)
        listing += QStringLiteral("LD X%1\nOUT Y%1\n").arg(i % 8);
    load(listing + QStringLiteral("END\n"));
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    view->setCursor({0, 0, 0});
    QScrollBar *bar = view->verticalScrollBar();
    ASSERT_GT(bar->maximum(), 0);
    bar->setValue(bar->maximum());
    window.watchListView()->addDevice(QStringLiteral("D5"));
    EXPECT_TRUE(watchValue(QStringLiteral("D5")).isValid());
    EXPECT_EQ(bar->value(), bar->maximum());
    // An edit of the rungs still shows where it was made.
    window.document()->insertRung(0, window.document()->ladder().rungs.front());
    EXPECT_LT(bar->value(), bar->maximum());
}

// Item 15: the history's window as the record keeps it: at least the last hour, never "at
// most" when it holds more.
TEST_F(TrueWindow, TheHistorysWindowIsToldAsTheRecordKeepsIt) {
    load("LD M9000\nADD D0 K1 D0\nEND\n");
    ASSERT_TRUE(sim()->runScans(10));
    ASSERT_TRUE(paused());
    const QString text = sim()->historyWindowText();
    EXPECT_TRUE(text.endsWith(QStringLiteral("; at least the last hour is kept")))
        << text.toStdString();
    EXPECT_FALSE(text.contains(QStringLiteral("at most"))) << text.toStdString();
}

namespace {

// A window with the docks the main window has, by name, for the layout alone.
struct DockedWindow {
    QMainWindow window;
    std::map<QString, QDockWidget *> docks;
    DockedWindow() {
        window.setCentralWidget(new QWidget);
        for (const char *name :
             {"projectDock", "crossReferenceDock", "ioDock", "simulationDock", "scanDebuggerDock",
              "connectionDock", "problemsDock", "watchDock", "timingChartDock"}) {
            auto *d = new QDockWidget(QString::fromLatin1(name), &window);
            d->setObjectName(QString::fromLatin1(name));
            d->setWidget(new QWidget);
            window.addDockWidget(Qt::LeftDockWidgetArea, d);
            docks[QString::fromLatin1(name)] = d;
        }
    }
    QDockWidget *operator[](const char *name) { return docks.at(QString::fromLatin1(name)); }
    // The docks tabbed with `name` (itself included), by name.
    std::set<QString> group(const char *name) {
        std::set<QString> names{QString::fromLatin1(name)};
        for (QDockWidget *d : window.tabifiedDockWidgets((*this)[name]))
            names.insert(d->objectName());
        return names;
    }
};

std::set<QString> names(std::initializer_list<const char *> list) {
    std::set<QString> out;
    for (const char *n : list)
        out.insert(QString::fromLatin1(n));
    return out;
}

} // namespace

// Item 13: what is used together is visible together. Wide: editing left; the terminals over
// the simulation's and the connection's tabs on the right; findings below.
TEST(DockGroups, AWideScreenHasAnEditingAndALiveColumn) {
    DockedWindow w;
    app::arrangeDocks(&w.window, true);
    EXPECT_EQ(w.group("projectDock"), names({"projectDock", "crossReferenceDock"}));
    EXPECT_EQ(w.group("simulationDock"),
              names({"simulationDock", "scanDebuggerDock", "connectionDock"}));
    EXPECT_EQ(w.group("ioDock"), names({"ioDock"})); // never behind the simulation's tab
    EXPECT_EQ(w.group("problemsDock"), names({"problemsDock", "watchDock", "timingChartDock"}));
    EXPECT_EQ(w.window.dockWidgetArea(w["projectDock"]), Qt::LeftDockWidgetArea);
    EXPECT_EQ(w.window.dockWidgetArea(w["ioDock"]), Qt::RightDockWidgetArea);
    EXPECT_EQ(w.window.dockWidgetArea(w["simulationDock"]), Qt::RightDockWidgetArea);
    EXPECT_EQ(w.window.dockWidgetArea(w["problemsDock"]), Qt::BottomDockWidgetArea);
}

// Item 13, narrow: one column beside the ladder; the terminals under the tabs, never behind
// one of them.
TEST(DockGroups, ANarrowScreenHasOneColumnWithTheTerminalsApart) {
    DockedWindow w;
    app::arrangeDocks(&w.window, false);
    EXPECT_EQ(w.group("projectDock"), names({"projectDock", "crossReferenceDock", "simulationDock",
                                             "scanDebuggerDock", "connectionDock"}));
    EXPECT_EQ(w.group("ioDock"), names({"ioDock"}));
    EXPECT_EQ(w.window.dockWidgetArea(w["ioDock"]), Qt::LeftDockWidgetArea);
    EXPECT_EQ(w.group("problemsDock"), names({"problemsDock", "watchDock", "timingChartDock"}));
}

// Item 12: on a 1024x600 screen (a title bar of it taken) the window with every dock shown
// is no taller than the screen, and the ladder shows a whole row with its coil and a timer's
// box without scrolling sideways, while simulating too.
TEST(SmallScreen, TheWindowFitsA1024x600ScreenAndTheLadderItsCoils) {
    test::OwnRecoveryFolder recoveryFolder;
    QSettings().remove(QStringLiteral("window")); // fresh settings: the first start's layout
    app::MainWindow window;
    editor::LadderView *view = window.ladderView();
    app::SimulationController *sim = window.simulation();
    const auto paused = [&] {
        return QTest::qWaitFor([&] { return sim->runState() == RunState::Paused; }, 5000);
    };
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nAND X1\nAND X2\nAND X3\nAND X4\nAND X5\nAND X6\nAND X7\n"
                       "AND X10\nAND X11\nAND X12\nOUT Y0\nLD X0\nTMR T0 K350\nEND\n"),
        &errors));
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    const QSize screen(1024, 600 - 32);
    window.resize(screen);
    app::sizeDocks(&window, false); // as the first start does
    for (int i = 0; i < 5; ++i)
        QApplication::processEvents();
    // The coil and the box are drawn in the output column's left 85 % (its right end is the
    // wire to the rail).
    const auto coilsInView = [&] {
        const QRect coil = view->cellRectOnScreen({0, 0, view->metrics().gridColumns});
        const QRect box = view->cellRectOnScreen({1, 0, view->metrics().gridColumns});
        const auto drawn = [](const QRect &r) { return r.left() + r.width() * 85 / 100; };
        return view->horizontalScrollBar()->value() == 0 &&
               drawn(coil) <= view->viewport()->width() && drawn(box) <= view->viewport()->width();
    };
    EXPECT_TRUE(QTest::qWaitFor(coilsInView, 2000))
        << view->viewport()->width() << " px for the ladder";
    ASSERT_TRUE(sim->singleScan()); // the terminals and the simulation's dock come
    ASSERT_TRUE(paused());
    for (const char *name : {"scanDebuggerDock", "timingChartDock"})
        window.findChild<QDockWidget *>(QString::fromLatin1(name))->show();
    for (int i = 0; i < 5; ++i)
        QApplication::processEvents();
    EXPECT_LE(window.minimumSizeHint().height(), screen.height());
    EXPECT_LE(window.minimumSizeHint().width(), screen.width());
    window.resize(screen);
    QApplication::processEvents();
    EXPECT_EQ(window.size(), screen);
    EXPECT_TRUE(QTest::qWaitFor(coilsInView, 2000))
        << view->viewport()->width() << " px for the ladder";
}
