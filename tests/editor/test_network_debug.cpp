// Debugging a station in the network window (network_debug_controller.h): a breakpoint set in
// one station's instruction list stops the whole network, the window shows that station, its
// list and ladder mark the place, the Scan Debugger follows it, the other stations wait at
// their scan boundary; a step moves the held station alone; Continue runs the network on.

#include "app/gui/debug_entries.h"
#include "app/gui/language.h"
#include "app/gui/network_chart.h"
#include "app/gui/network_debug_controller.h"
#include "app/gui/network_window.h"
#include "app/gui/scan_debugger_view.h"
#include "window_fixture.h"

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/timing_canvas.h"
#include "network/network_session.h"

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTreeWidget>

namespace rung::test {
namespace {

using RunState = model::MonitorSource::RunState;

const QString kCpuLink =
    QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/cpu-link/cpu-link.rungnet");

app::NetworkWindow *debuggedNetwork(app::MainWindow &window) {
    const auto windows = window.findChildren<app::NetworkWindow *>();
    return windows.isEmpty() ? nullptr : windows.back();
}

QAction *networkAction(app::NetworkWindow &net, const char *name) {
    return net.findChild<QAction *>(QString::fromLatin1(name));
}

// The 1-based line of the list that holds `text`; 0 for none.
int lineHolding(editor::IlEditor *il, const QString &text) {
    for (int line = 0; line < il->lines(); ++line)
        if (il->lineText(line).contains(text))
            return line + 1;
    return 0;
}

bool heldInside(const network::NetworkSession *session, const char *station) {
    const auto snapshot = session->station(QString::fromLatin1(station))->snapshot();
    return snapshot && snapshot->pause.has_value();
}

TEST(NetworkDebug, ABreakpointInOneStationStopsTheNetworkAndAStepMovesItAlone) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkDebugController *debug = net->debugger();
    network::NetworkSession *session = net->session();
    ASSERT_TRUE(session);

    // slave1's list is a tab beside the ladder: read-only, the program as its file has it.
    ASSERT_TRUE(net->selectStation(QStringLiteral("slave1")));
    editor::IlEditor *il = debug->listView(QStringLiteral("slave1"));
    ASSERT_NE(il, nullptr);
    EXPECT_TRUE(il->isReadOnly());
    auto *tabs = net->findChild<QTabWidget *>(QStringLiteral("networkTabs"));
    ASSERT_NE(tabs, nullptr);
    EXPECT_EQ(tabs->tabText(tabs->indexOf(debug->listPage())), QStringLiteral("Instruction List"));
    const int vrrd = lineHolding(il, QStringLiteral("VRRD"));
    ASSERT_GT(vrrd, 0);

    // A click in the list's margin sets the breakpoint: marked in the list and the ladder.
    emit il->breakpointToggleRequested(vrrd);
    ASSERT_EQ(debug->breakpoints(QStringLiteral("slave1")).size(), 1u);
    EXPECT_EQ(il->breakpointLines(), std::vector<int>{vrrd});
    EXPECT_EQ(debug->scanDebugger()->breakpointList()->topLevelItemCount(), 1);
    // The other stations have none.
    ASSERT_TRUE(net->selectStation(QStringLiteral("master")));
    EXPECT_EQ(debug->scanDebugger()->breakpointList()->topLevelItemCount(), 0);

    session->setSpeed(0);
    networkAction(*net, "networkRun")->trigger();
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    // The window shows the station that holds, where it holds.
    EXPECT_EQ(net->currentStation(), QStringLiteral("slave1"));
    EXPECT_TRUE(eventually([&] { return il->stoppedLine() == vrrd; }));
    EXPECT_TRUE(debug->scanDebugger()->positionText().contains(QStringLiteral("VRRD")))
        << debug->scanDebugger()->positionText().toStdString();
    EXPECT_TRUE(debug->scanDebugger()->positionText().contains(
        QStringLiteral("A breakpoint stopped the scan.")));
    EXPECT_TRUE(debug->scanDebuggerDock()->isVisible());
    auto *held = net->findChild<QLabel *>(QStringLiteral("networkHeld"));
    ASSERT_NE(held, nullptr);
    EXPECT_EQ(held->text(), QStringLiteral("slave1 stopped before line %1").arg(vrrd));
    EXPECT_TRUE(net->statusText().startsWith(QStringLiteral("Paused")));
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("slave1")));
    // The others wait at their scan boundary, and the clock stands.
    EXPECT_FALSE(heldInside(session, "master"));
    EXPECT_FALSE(heldInside(session, "slave2"));
    const qint64 at = session->nowUs();
    EXPECT_GT(at, 0);

    // Ctrl+F12: one instruction of slave1; the next is its END.
    networkAction(*net, "networkStepInstruction")->trigger();
    ASSERT_TRUE(eventually(
        [&] { return session->runState() == RunState::Paused && il->stoppedLine() > vrrd; }));
    EXPECT_TRUE(il->lineText(il->stoppedLine() - 1).contains(QStringLiteral("END")));
    EXPECT_TRUE(debug->scanDebugger()->positionText().contains(QStringLiteral("END")));
    EXPECT_EQ(session->nowUs(), at);
    EXPECT_FALSE(heldInside(session, "master"));
    EXPECT_FALSE(heldInside(session, "slave2"));

    // Continue runs the network on: slave1 stops again one scan (10 ms) later.
    QSignalSpy hits(session, &network::NetworkSession::breakpointHit);
    networkAction(*net, "networkRun")->trigger();
    ASSERT_TRUE(eventually([&] { return hits.count() == 1; }));
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    EXPECT_EQ(session->nowUs(), at + 10000);
    EXPECT_TRUE(eventually([&] { return il->stoppedLine() == vrrd; }));

    // Finish Scan (Shift+F12) ends the held scan; the marks go.
    networkAction(*net, "networkFinishScan")->trigger();
    ASSERT_TRUE(eventually([&] { return !heldInside(session, "slave1"); }));
    EXPECT_TRUE(eventually([&] { return il->stoppedLine() == 0 && held->text().isEmpty(); }));
    EXPECT_TRUE(debug->scanDebugger()->positionText().startsWith(
        QStringLiteral("Not stopped inside a scan")));

    // The breakpoint removed from the ladder's gutter (rung of VRRD): the network runs on.
    editor::LadderView *ladder = net->ladderView(QStringLiteral("slave1"));
    const auto &origin = net->document(QStringLiteral("slave1"))->listing().origin;
    const int instruction =
        net->document(QStringLiteral("slave1"))->printedListing().instructionAt(vrrd);
    ASSERT_GE(instruction, 0);
    const int rung = origin[std::size_t(instruction)].rung;
    emit ladder->breakpointToggleRequested(rung); // sets one on the rung's first instruction
    EXPECT_EQ(debug->breakpoints(QStringLiteral("slave1")).size(), 2u);
    debug->clearBreakpoints();
    EXPECT_TRUE(debug->breakpoints(QStringLiteral("slave1")).empty());
    EXPECT_TRUE(il->breakpointLines().empty());
    networkAction(*net, "networkRun")->trigger();
    EXPECT_TRUE(eventually([&] { return session->nowUs() > at + 200000; }));
    EXPECT_EQ(session->runState(), RunState::Running);
    networkAction(*net, "networkPause")->trigger();
}

TEST(NetworkDebug, StepInstructionAtABoundaryStartsTheShownStationsScanAndStopKeepsBreakpoints) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkDebugController *debug = net->debugger();
    network::NetworkSession *session = net->session();
    ASSERT_TRUE(net->selectStation(QStringLiteral("slave2")));
    // Ctrl+F12 with nothing held: slave2's first scan starts and stops before its first
    // instruction; the stations before it in that instant have scanned.
    networkAction(*net, "networkStepInstruction")->trigger();
    ASSERT_TRUE(eventually(
        [&] { return session->runState() == RunState::Paused && heldInside(session, "slave2"); }));
    EXPECT_EQ(session->nowUs(), 10000);
    EXPECT_EQ(session->heldStation(), QStringLiteral("slave2"));
    EXPECT_TRUE(debug->scanDebugger()->positionText().contains(
        QStringLiteral("Stepping one instruction at a time.")));

    // A breakpoint set by Ctrl+B on the ladder's cursor (rung 1) outlives Stop.
    net->ladderView(QStringLiteral("slave2"))->setCursor({0, 0, 0});
    networkAction(*net, "networkToggleBreakpoint")->trigger();
    EXPECT_EQ(debug->breakpoints(QStringLiteral("slave2")).size(), 1u);
    networkAction(*net, "networkStop")->trigger();
    ASSERT_TRUE(
        eventually([&] { return session->nowUs() == 0 && !heldInside(session, "slave2"); }));
    session->setSpeed(0);
    networkAction(*net, "networkRun")->trigger();
    ASSERT_TRUE(eventually(
        [&] { return session->runState() == RunState::Paused && heldInside(session, "slave2"); }));
    EXPECT_EQ(session->nowUs(), 10000);
    EXPECT_EQ(session->station(QStringLiteral("slave2"))->snapshot()->pause->instruction, 0);
}

TEST(NetworkDebug, AStopConditionOnAStationsDeviceStopsTheNetworkAfterThatScan) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkDebugController *debug = net->debugger();
    network::NetworkSession *session = net->session();
    QString error;
    EXPECT_FALSE(debug->setStopCondition(QStringLiteral("nobody/D0 > 1"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("master, slave1, slave2"))) << error.toStdString();
    EXPECT_FALSE(debug->setStopCondition(QStringLiteral("slave1/D0 >"), &error));
    EXPECT_TRUE(debug->stopCondition().isEmpty());
    // slave1's first scan moves K3 into D9080 (its display mode).
    ASSERT_TRUE(debug->setStopCondition(QStringLiteral("slave1/D9080 = 3"), &error))
        << error.toStdString();
    QSignalSpy fired(session->station(QStringLiteral("slave1")), &model::MonitorSource::triggered);
    session->setSpeed(0);
    networkAction(*net, "networkRun")->trigger();
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    EXPECT_EQ(session->nowUs(), 10000);
    EXPECT_EQ(net->currentStation(), QStringLiteral("slave1"));
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("slave1/D9080 = 3")))
        << net->statusBar()->currentMessage().toStdString();
    EXPECT_FALSE(heldInside(session, "master"));
    EXPECT_FALSE(heldInside(session, "slave2"));
    // Run goes on: the condition stays true, so it does not fire again.
    networkAction(*net, "networkRun")->trigger();
    EXPECT_TRUE(eventually([&] { return session->nowUs() > 100000; }));
    EXPECT_EQ(fired.count(), 1);
    networkAction(*net, "networkPause")->trigger();
}

TEST(NetworkDebug, PausedAtABreakpointFitsTheScreenInEveryLanguage) {
    // At 1366 x 768 the network window held at a breakpoint in slave1 of the CPU Link example,
    // its list shown, in English, Hungarian and Italian: the Scan Debugger's buttons and the
    // status bar's texts as wide as they need. RUNG_SCREENSHOT_DIR set: the pictures are saved
    // there (docs/screenshots/).
    const QString shots = qEnvironmentVariable("RUNG_SCREENSHOT_DIR");
    for (const char *language : {"en", "hu", "it"}) {
        SCOPED_TRACE(language);
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(language), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        app::MainWindow window;
        ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
        app::NetworkWindow *net = debuggedNetwork(window);
        ASSERT_NE(net, nullptr);
        net->resize(1366, 768);
        net->show();
        app::NetworkDebugController *debug = net->debugger();
        network::NetworkSession *session = net->session();
        ASSERT_TRUE(net->selectStation(QStringLiteral("slave1")));
        auto *tabs = net->findChild<QTabWidget *>(QStringLiteral("networkTabs"));
        tabs->setCurrentWidget(debug->listPage());
        editor::IlEditor *il = debug->listView(QStringLiteral("slave1"));
        const int vrrd = lineHolding(il, QStringLiteral("VRRD"));
        ASSERT_GT(vrrd, 0);
        emit il->breakpointToggleRequested(vrrd);
        session->setSpeed(0);
        networkAction(*net, "networkRun")->trigger();
        ASSERT_TRUE(eventually(
            [&] { return session->runState() == RunState::Paused && il->stoppedLine() == vrrd; }));
        ASSERT_TRUE(eventually([&] {
            return debug->scanDebugger()->positionText().contains(QStringLiteral("VRRD"));
        }));
        // The docks' layout settles over a few posted events.
        for (int k = 0; k < 5; ++k)
            QCoreApplication::processEvents();
        EXPECT_LE(net->minimumSizeHint().width(), 1366);
        EXPECT_LE(net->minimumSizeHint().height(), 768);
        for (QPushButton *b : debug->scanDebugger()->findChildren<QPushButton *>())
            EXPECT_GE(b->width(), b->sizeHint().width()) << b->text().toStdString();
        // In sight: the debugger's dock is as wide as its buttons and stacks need (its scroll
        // area scrolls only up and down).
        EXPECT_GE(debug->scanDebugger()->parentWidget()->width(),
                  debug->scanDebugger()->minimumSizeHint().width());
        EXPECT_GE(debug->scanDebugger()->parentWidget()->height(),
                  debug->scanDebugger()->minimumSizeHint().height());
        auto *held = net->findChild<QLabel *>(QStringLiteral("networkHeld"));
        ASSERT_NE(held, nullptr);
        EXPECT_TRUE(held->isVisible());
        EXPECT_GE(held->width(), held->sizeHint().width()) << held->text().toStdString();
        if (!shots.isEmpty()) {
            net->grab().save(
                QStringLiteral("%1/network-breakpoint-%2.png").arg(shots, QLatin1String(language)));
            tabs->setCurrentIndex(
                tabs->indexOf(net->ladderView(QStringLiteral("slave1"))->parentWidget()));
            QCoreApplication::processEvents();
            net->grab().save(QStringLiteral("%1/network-breakpoint-ladder-%2.png")
                                 .arg(shots, QLatin1String(language)));
        }
        session->pause();
    }
    ASSERT_TRUE(app::setLanguage(QStringLiteral("en"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

// The timing chart's trigger in the network window is the network's trigger: "Stop the
// network" pauses every station right after the scan in which the condition becomes true (the
// others at their scan boundary), shown as a breakpoint's stop is (the station selected, the
// status bar and the held mark naming the condition), cursor A on that moment; Stop When...
// shows in the chart's field; "Only mark" lets the network run on and marks the moment.
// The trigger's action box grows with its text in the language chosen while the window is open
// ("Stop the network" -> "A hálózat megállítása"), not clipped at the width of the first one.
TEST(NetworkDebug, TheTriggerActionFitsItsTextAfterALanguageChange) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    QComboBox *box = net->chart()->triggerAction();
    const int first = box->sizeHint().width();
    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
    const QString text = box->itemText(0);
    EXPECT_NE(text, QStringLiteral("Stop the network"));
    EXPECT_GT(box->sizeHint().width(), first) << text.toStdString();
    app::setLanguage(QStringLiteral("en"), false);
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

TEST(NetworkDebug, TheTimingChartsTriggerStopsTheWholeNetworkAndSaysWhichStationAndCondition) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkDebugController *debug = net->debugger();
    network::NetworkSession *session = net->session();
    app::NetworkChart *chart = net->chart();
    ASSERT_TRUE(net->selectStation(QStringLiteral("master")));

    // A station that is not there: not armed, why in the status bar.
    chart->triggerField()->setText(QStringLiteral("nobody/D0 > 1"));
    chart->armButton()->click();
    EXPECT_FALSE(chart->armButton()->isChecked());
    EXPECT_TRUE(debug->stopCondition().isEmpty());
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("master, slave1")))
        << net->statusBar()->currentMessage().toStdString();

    // slave1's first scan moves K3 into D9080 (its display mode).
    chart->triggerField()->setText(QStringLiteral("slave1/D9080 = 3"));
    EXPECT_EQ(chart->triggerAction()->currentIndex(), 0); // Stop the network
    EXPECT_EQ(chart->triggerAction()->currentText(), QStringLiteral("Stop the network"));
    chart->armButton()->click();
    EXPECT_TRUE(chart->armButton()->isChecked());
    EXPECT_EQ(debug->stopCondition(), QStringLiteral("slave1/D9080 = 3"));
    EXPECT_EQ(debug->triggerAction(), model::Trigger::Action::Stop);
    EXPECT_TRUE(chart->readoutText().contains(QStringLiteral("Armed")));

    QSignalSpy fired(session->station(QStringLiteral("slave1")), &model::MonitorSource::triggered);
    session->setSpeed(0);
    networkAction(*net, "networkRun")->trigger();
    ASSERT_TRUE(eventually([&] { return fired.count() == 1; }));
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    // At the scan boundary: slave1's first scan (10 ms), no station inside a scan.
    EXPECT_EQ(session->nowUs(), 10000);
    EXPECT_FALSE(heldInside(session, "master"));
    EXPECT_FALSE(heldInside(session, "slave1"));
    EXPECT_FALSE(heldInside(session, "slave2"));
    // Shown as a breakpoint's stop: the station, the condition.
    EXPECT_EQ(net->currentStation(), QStringLiteral("slave1"));
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("slave1/D9080 = 3")))
        << net->statusBar()->currentMessage().toStdString();
    auto *held = net->findChild<QLabel *>(QStringLiteral("networkHeld"));
    ASSERT_NE(held, nullptr);
    EXPECT_TRUE(held->isVisibleTo(net));
    EXPECT_EQ(held->text(), QStringLiteral("Stopped: slave1/D9080 = 3 became true"));
    // The chart: cursor A on the moment, and what fired.
    EXPECT_EQ(chart->canvas()->cursorTime(0), std::optional<qint64>(10));
    EXPECT_TRUE(chart->readoutText().contains(QStringLiteral("slave1/D9080 = 3 at")))
        << chart->readoutText().toStdString();
    EXPECT_TRUE(chart->readoutText().contains(QStringLiteral("(scan 1)")))
        << chart->readoutText().toStdString();

    // Run goes on (the condition stays true: no second stop); the held mark goes.
    networkAction(*net, "networkRun")->trigger();
    EXPECT_TRUE(eventually([&] { return session->nowUs() > 100000; }));
    EXPECT_FALSE(held->isVisibleTo(net));
    networkAction(*net, "networkPause")->trigger();
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));

    // Stop When... sets the same trigger: the chart shows it.
    QString error;
    ASSERT_TRUE(debug->setStopCondition(QStringLiteral("master/D0 > 1000"), &error))
        << error.toStdString();
    EXPECT_EQ(chart->triggerField()->text(), QStringLiteral("master/D0 > 1000"));
    EXPECT_TRUE(chart->armButton()->isChecked());
    // Disarmed from the chart: none.
    chart->armButton()->click();
    EXPECT_TRUE(debug->stopCondition().isEmpty());
    EXPECT_FALSE(chart->armButton()->isChecked());

    // Only mark: the network runs on past the moment, which the chart marks.
    networkAction(*net, "networkStop")->trigger();
    ASSERT_TRUE(eventually([&] { return net->session() && net->session()->nowUs() == 0; }));
    session = net->session();
    chart->triggerField()->setText(QStringLiteral("slave1/D9080 = 3"));
    chart->triggerAction()->setCurrentIndex(1);
    chart->armButton()->click();
    ASSERT_EQ(debug->triggerAction(), model::Trigger::Action::Mark);
    QSignalSpy marked(session->station(QStringLiteral("slave1")), &model::MonitorSource::triggered);
    session->setSpeed(0);
    session->runFor(200);
    ASSERT_TRUE(eventually([&] { return marked.count() == 1; }));
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    EXPECT_GT(session->nowUs(), 10000);
    EXPECT_TRUE(eventually([&] { return chart->window().marks.size() == 1; }));
    EXPECT_FALSE(held->isVisibleTo(net));
}

// A trigger armed after the fact marks what already happened too: the moments the network's
// history saw the condition become true (the 1 s clock M9013 rising after the first scan and
// each second: 10 ms, 1.01 s, 2.01 s, 3.01 s in 3.2 s), and from then on those its station's
// recorder marks (4.01 s), none twice, and not the clock already ON when it was armed.
TEST(NetworkDebug, OnlyMarkArmedAfterTheFactMarksThePastMomentsToo) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(kCpuLink, QString(), true));
    app::NetworkWindow *net = debuggedNetwork(window);
    ASSERT_NE(net, nullptr);
    network::NetworkSession *session = net->session();
    app::NetworkChart *chart = net->chart();
    session->setSpeed(0);
    session->runFor(3200);
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    ASSERT_EQ(session->nowUs(), 3'200'000);
    chart->triggerField()->setText(QStringLiteral("master/M9013 rises"));
    chart->triggerAction()->setCurrentIndex(1); // Only mark
    chart->armButton()->click();
    ASSERT_TRUE(chart->armButton()->isChecked());
    EXPECT_TRUE(eventually([&] { return chart->window().marks.size() == 4; }))
        << chart->window().marks.size();
    for (const auto &m : chart->window().marks)
        EXPECT_LT(m.timeMs, 3200);
    // Run on a second: the recorder's one more, the past ones not again.
    session->runFor(1000);
    ASSERT_TRUE(eventually([&] { return session->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] { return chart->window().marks.size() == 5; }))
        << chart->window().marks.size();
    // Disarmed: no marks of a condition no longer watched from the past either.
    chart->armButton()->click();
    EXPECT_FALSE(chart->armButton()->isChecked());
    EXPECT_TRUE(eventually([&] { return chart->window().marks.empty(); }));
}

// The debugging entries of both Simulation menus come from one table (debug_entries.h): the
// same text, access key, key and tooltip in the main window and the network window, in every
// language, each translated once.
TEST(NetworkDebug, BothWindowsMakeTheirDebugEntriesFromOneTable) {
    for (const char *language : {"en", "hu", "it"}) {
        SCOPED_TRACE(language);
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(language), false));
        app::MainWindow window;
        app::NetworkWindow network;
        ASSERT_EQ(app::debugEntries().size(), 6u);
        for (const app::DebugEntry &e : app::debugEntries()) {
            SCOPED_TRACE(e.name);
            auto *single =
                window.findChild<QAction *>(QStringLiteral("simulation") + QLatin1String(e.name));
            auto *net =
                network.findChild<QAction *>(QStringLiteral("network") + QLatin1String(e.name));
            ASSERT_NE(single, nullptr);
            ASSERT_NE(net, nullptr);
            const QString text = QCoreApplication::translate("rung::app::DebugEntries", e.text);
            EXPECT_EQ(single->text(), text);
            EXPECT_EQ(net->text(), text);
            EXPECT_TRUE(text.contains(QLatin1Char('&'))) << text.toStdString();
            if (QLatin1String(language) != QLatin1String("en"))
                EXPECT_NE(text, QString::fromLatin1(e.text)) << "not translated";
            EXPECT_EQ(single->shortcut(), QKeySequence(e.key));
            EXPECT_EQ(net->shortcut(), QKeySequence(e.key));
            EXPECT_EQ(single->toolTip(), net->toolTip());
        }
    }
    ASSERT_TRUE(app::setLanguage(QStringLiteral("en"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

} // namespace
} // namespace rung::test
