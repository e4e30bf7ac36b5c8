// A network in the IDE (network_window.h): File > Open of a .rungnet opens its window, the
// station selector chooses what the ladder shows, a value crosses from one station to another
// in the network's watch table, a wire cut from the Faults menu raises the master's error, and
// a station's program opens in the main window for editing.

#include "app/gui/language.h"
#include "app/gui/network_chart.h"
#include "app/gui/network_document.h"
#include "app/gui/network_traffic_model.h"
#include "app/gui/network_traffic_view.h"
#include "app/gui/network_view.h"
#include "app/gui/network_watch_model.h"
#include "app/gui/network_window.h"
#include "editor/timing_canvas.h"
#include "window_fixture.h"

#include "editor/document.h"
#include "model/target/address.h"
#include "network/network_session.h"
#include "network/traffic_decode.h"

#include <QComboBox>
#include <QListWidget>
#include <QMenu>
#include <QSignalSpy>
#include <QTabBar>
#include <QTableView>

#include <map>

namespace rung::test {
namespace {

using RunState = model::MonitorSource::RunState;

const QString kExamples = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/");

QString example(const char *name) {
    return kExamples + QLatin1String(name) + QLatin1Char('/') + QLatin1String(name) +
           QStringLiteral(".rungnet");
}

app::NetworkWindow *openedNetwork(app::MainWindow &window) {
    const auto windows = window.findChildren<app::NetworkWindow *>();
    return windows.isEmpty() ? nullptr : windows.back();
}

// The value of a watch row as the table shows it.
QString shown(app::NetworkWatchModel *model, int row) {
    return model->data(model->index(row, app::NetworkWatchModel::Value)).toString();
}

TEST(NetworkWindow, OpeningANetworkFileShowsItsStationsInAWindowOfItsOwn) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    EXPECT_TRUE(net->isWindow());
    EXPECT_TRUE(net->windowTitle().startsWith(QStringLiteral("easy-link.rungnet")));
    ASSERT_EQ(net->stationSelector()->count(), 3);
    EXPECT_EQ(net->stationSelector()->itemText(1), QStringLiteral("s5 (Vigor VB)"));
    EXPECT_EQ(net->currentStation(), QStringLiteral("master"));
    EXPECT_EQ(net->session()->runState(), RunState::Stopped);
    // The master's ladder is its listing drawn: the LINK of the manual's example.
    ASSERT_NE(net->document(QStringLiteral("master")), nullptr);
    EXPECT_TRUE(net->document(QStringLiteral("master"))
                    ->listingText()
                    .contains(QStringLiteral("LINK D1000 D100")));
    // The main window still shows its own program: nothing of it was replaced.
    EXPECT_FALSE(window.document()->listingText().contains(QStringLiteral("LINK")));
}

// The menus are made again in the new language: the old ones go, so no entry is there twice
// (two actions with one shortcut make it ambiguous, and Qt then runs neither).
TEST(NetworkWindow, ALanguageChangeLeavesOneOfEachMenuEntry) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    const auto entries = [net] {
        std::map<QString, int> count;
        for (const QAction *a : net->findChildren<QAction *>())
            if (!a->objectName().isEmpty())
                ++count[a->objectName()];
        return count;
    };
    const std::map<QString, int> before = entries();
    ASSERT_EQ(before.at(QStringLiteral("networkRun")), 1);
    for (const char *language : {"hu", "it", "en"}) {
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(language), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        QCoreApplication::processEvents();
    }
    EXPECT_EQ(entries(), before);
    EXPECT_EQ(net->menuBar()->findChildren<QMenu *>(Qt::FindDirectChildrenOnly).size(),
              net->menuBar()->actions().size());
    // The one Run there is runs the network.
    net->findChild<QAction *>(QStringLiteral("networkRun"))->trigger();
    EXPECT_TRUE(eventually([&] { return net->session()->runState() == RunState::Running; }));
}

TEST(NetworkWindow, TheStationSelectorChoosesWhatTheLadderShows) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    QSignalSpy changed(net, &app::NetworkWindow::stationChanged);
    net->stationSelector()->setCurrentIndex(2);
    EXPECT_EQ(net->currentStation(), QStringLiteral("s2"));
    EXPECT_EQ(changed.count(), 1);
    auto *list = net->findChild<QListWidget *>(QStringLiteral("networkStations"));
    ASSERT_NE(list, nullptr);
    EXPECT_EQ(list->currentRow(), 2);
    list->setCurrentRow(1);
    EXPECT_EQ(net->currentStation(), QStringLiteral("s5"));
    EXPECT_EQ(net->stationSelector()->currentIndex(), 1);
    EXPECT_TRUE(net->ladderView(QStringLiteral("s5"))->isVisibleTo(net));
}

// The test: a value crossing from one station to another in the watch table.
TEST(NetworkWindow, AValueCrossesFromOneStationToAnotherInTheWatchTable) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkWatchModel *watch = net->watchModel();
    ASSERT_TRUE(net->watch(QStringLiteral("s5/D10")));
    ASSERT_TRUE(net->watch(QStringLiteral("master/D0")));
    EXPECT_TRUE(net->watch(QStringLiteral("master/D0"))); // listed once
    EXPECT_EQ(watch->rowCount(), 2);
    EXPECT_FALSE(net->watch(QStringLiteral("x/D0")));
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("master, s5, s2")))
        << net->statusBar()->currentMessage().toStdString();
    EXPECT_FALSE(net->watch(QStringLiteral("D0")));
    EXPECT_TRUE(watch->setData(watch->index(0, app::NetworkWatchModel::Value), 4321));
    ASSERT_TRUE(eventually([&] { return shown(watch, 0) == QStringLiteral("4321"); }));
    EXPECT_EQ(shown(watch, 1), QStringLiteral("0"));
    net->session()->setSpeed(0);
    toolbarAction(*net, QStringLiteral("Run"))->trigger();
    EXPECT_EQ(net->session()->runState(), RunState::Running);
    EXPECT_TRUE(eventually([&] { return shown(watch, 1) == QStringLiteral("4321"); }));
    EXPECT_TRUE(net->statusText().startsWith(QStringLiteral("Running")));
}

// The test: a cut wire raising the master's error. LINK's working area (S2 = D100 in
// the example) holds in its high byte the status: A, "communication normal but no response
// from the slave" (Vigor M/VB/VH communication manual, B-3-3).
TEST(NetworkWindow, AWireCutFromTheFaultsMenuRaisesTheMastersError) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    ASSERT_TRUE(net->watch(QStringLiteral("master/D100")));
    net->session()->setSpeed(0);
    net->session()->runFor(300);
    ASSERT_TRUE(eventually([&] { return net->session()->runState() == RunState::Paused; }));
    const auto status = [&] {
        return net->watchModel()->data(net->watchModel()->index(0, 1), Qt::EditRole).toLongLong() >>
               8;
    };
    EXPECT_EQ(status(), 0);
    auto *faults = net->findChild<QMenu *>(QStringLiteral("networkFaultsMenu"));
    ASSERT_NE(faults, nullptr);
    QAction *cut = nullptr;
    for (QAction *a : faults->actions())
        if (a->objectName() == QStringLiteral("faultCut_w1"))
            cut = a;
    ASSERT_NE(cut, nullptr);
    EXPECT_TRUE(cut->text().contains(QStringLiteral("master/CP2")));
    // Every station's port on a wire can be set to another baud rate; what was set shows.
    QStringList baud;
    for (QAction *a : faults->actions())
        if (a->objectName().startsWith(QStringLiteral("faultBaud_")))
            baud << a->objectName().mid(10);
    EXPECT_EQ(baud, (QStringList{QStringLiteral("master/CP2"), QStringLiteral("s5/CP2"),
                                 QStringLiteral("s2/CP2")}));
    net->session()->setBaud(QStringLiteral("s2/CP2"), 4800);
    emit faults->aboutToShow();
    for (QAction *a : faults->actions()) {
        if (a->objectName() == QStringLiteral("faultBaud_s2/CP2")) {
            EXPECT_TRUE(a->text().contains(QStringLiteral("4800"))) << a->text().toStdString();
        }
    }
    cut = nullptr;
    for (QAction *a : faults->actions())
        if (a->objectName() == QStringLiteral("faultCut_w1"))
            cut = a;
    ASSERT_NE(cut, nullptr);
    cut->trigger();
    EXPECT_TRUE(net->session()->wireCut(QStringLiteral("w1")));
    net->session()->runFor(1000);
    ASSERT_TRUE(eventually([&] { return net->session()->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] { return status() == 0x0A; })) << status();
    // Stop: the network as its file describes it, the fault gone.
    toolbarAction(*net, QStringLiteral("Stop"))->trigger();
    EXPECT_FALSE(net->session()->wireCut(QStringLiteral("w1")));
    EXPECT_TRUE(eventually([&] { return status() == 0 && net->session()->nowUs() == 0; }));
}

// The chart takes devices of any station on one time axis: the value written in s5 shows in
// its row, and later, after the LINK's read, in the master's.
TEST(NetworkWindow, TheTimingChartDrawsDevicesOfTwoStationsOnOneClock) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkChart *chart = net->chart();
    ASSERT_TRUE(chart->addDevice(QStringLiteral("s5/D10")));
    ASSERT_TRUE(chart->addDevice(QStringLiteral("master/D0")));
    EXPECT_TRUE(chart->addDevice(QStringLiteral("master/D0"))); // drawn once
    QSignalSpy said(chart, &app::NetworkChart::message);
    EXPECT_FALSE(chart->addDevice(QStringLiteral("nowhere/D0")));
    EXPECT_EQ(said.count(), 1);
    EXPECT_EQ(chart->devices(),
              (QStringList{QStringLiteral("s5/D10"), QStringLiteral("master/D0")}));
    network::StationSource *s5 = net->session()->station(QStringLiteral("s5"));
    const auto d10 =
        std::get<model::Address>(model::parseAddress(s5->target(), QStringLiteral("D10")));
    s5->writeWord(d10, 99);
    net->session()->setSpeed(0);
    net->session()->runFor(500);
    ASSERT_TRUE(eventually([&] { return net->session()->runState() == RunState::Paused; }));
    // The chart refreshes on the clock's signals; the last one follows the last slice.
    const auto lastValue = [&](int row) -> qint64 {
        const auto &changes = chart->window().changes;
        return row < int(changes.size()) && !changes[std::size_t(row)].empty()
                   ? changes[std::size_t(row)].back().value
                   : -1;
    };
    EXPECT_TRUE(eventually([&] { return lastValue(0) == 99 && lastValue(1) == 99; }));
    // The value arrived in the master after it was in s5.
    const auto &master = chart->window().changes[1];
    ASSERT_FALSE(master.empty());
    EXPECT_GT(master.back().timeMs, 0);
}

// A value typed into the network's watch table while the network runs is not overwritten by
// the snapshots that come meanwhile.
TEST(NetworkWindow, TypingAValueWhileTheNetworkRunsKeepsWhatIsTyped) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    ASSERT_TRUE(net->watch(QStringLiteral("master/D1001")));
    auto *table = net->findChild<QTableView *>(QStringLiteral("networkWatchTable"));
    ASSERT_NE(table, nullptr);
    net->session()->run();
    const QModelIndex value = net->watchModel()->index(0, app::NetworkWatchModel::Value);
    table->setCurrentIndex(value);
    table->edit(value);
    QWidget *editor = table->indexWidget(value);
    if (!editor)
        editor = table->viewport()->findChild<QWidget *>();
    ASSERT_NE(editor, nullptr);
    auto *line = qobject_cast<QLineEdit *>(editor);
    if (!line)
        line = editor->findChild<QLineEdit *>();
    ASSERT_NE(line, nullptr) << editor->metaObject()->className();
    line->setText(QStringLiteral("1234"));
    // Several beats of snapshots while the editor is open.
    const qint64 start = net->session()->nowUs();
    EXPECT_TRUE(eventually([&] { return net->session()->nowUs() > start + 200'000; }));
    QCoreApplication::processEvents();
    EXPECT_EQ(line->text(), QStringLiteral("1234"));
}

// The test: the Traffic view decoding a frame of the running network; a frame chosen
// puts the chart's cursor at its time; Stop starts the traffic over with the new network's.
TEST(NetworkWindow, TheTrafficViewDecodesTheFramesOfTheRunningNetwork) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    app::NetworkTrafficModel *traffic = net->traffic()->model();
    net->session()->setSpeed(0);
    net->session()->runFor(300);
    ASSERT_TRUE(eventually([&] { return net->session()->runState() == RunState::Paused; }));
    ASSERT_TRUE(eventually([&] { return traffic->rowCount() >= 4; }));
    // The master's first request of set 1 (read D10.. of station 5) and station 5's reply.
    const network::DecodedFrame &request = traffic->decoded(0);
    EXPECT_EQ(traffic->record(0).sender, QStringLiteral("master/CP2"));
    EXPECT_EQ(request.kind, network::DecodedFrame::Kind::Request);
    EXPECT_EQ(request.protocol, QStringLiteral("Computer Link"));
    EXPECT_EQ(request.station, 5);
    EXPECT_TRUE(request.address.startsWith(QStringLiteral("D10"))) << request.address.toStdString();
    EXPECT_TRUE(request.problem.isEmpty()) << request.problem.toStdString();
    EXPECT_EQ(traffic->decoded(1).kind, network::DecodedFrame::Kind::Reply);
    EXPECT_EQ(traffic->decoded(1).receiver, QStringLiteral("master/CP2"));

    QTableView *table = net->traffic()->table();
    table->selectionModel()->setCurrentIndex(table->model()->index(2, 0),
                                             QItemSelectionModel::ClearAndSelect |
                                                 QItemSelectionModel::Rows);
    const auto cursor = net->chart()->canvas()->cursorTime(0);
    ASSERT_TRUE(cursor.has_value());
    EXPECT_EQ(*cursor, traffic->record(2).startUs / 1000);

    toolbarAction(*net, QStringLiteral("Stop"))->trigger();
    net->session()->runFor(50);
    ASSERT_TRUE(eventually([&] { return net->session()->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] {
        return traffic->rowCount() > 0 &&
               traffic->record(traffic->rowCount() - 1).startUs <= 50'000;
    }));
    EXPECT_LE(traffic->record(0).startUs, 50'000);
}

// The Network view edits what the window simulates: an edit of a stopped network builds it
// again at once; a running one goes on as built until Stop, which takes the edit.
TEST(NetworkWindow, AnEditInTheNetworkViewIsSimulatedFromTheNextStop) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    ASSERT_TRUE(net->watch(QStringLiteral("master/D0")));
    app::NetworkDocument *doc = net->networkDocument();
    QString error;
    net->session()->setSpeed(0);
    net->session()->run();
    ASSERT_TRUE(doc->removeStation(QStringLiteral("s2"), &error)) << error.toStdString();
    EXPECT_TRUE(net->windowTitle().startsWith(QStringLiteral("easy-link.rungnet*")));
    EXPECT_EQ(net->stationSelector()->count(), 3); // still running as built
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("Stop")));
    toolbarAction(*net, QStringLiteral("Stop"))->trigger();
    ASSERT_EQ(net->stationSelector()->count(), 2);
    EXPECT_EQ(net->session()->stations().size(), 2u);
    EXPECT_EQ(net->watchModel()->devices(), QStringList{QStringLiteral("master/D0")}); // kept
    // Stopped: an edit is built at once; undo gives the station back.
    doc->undoStack()->undo();
    EXPECT_EQ(net->session()->stations().size(), 3u);
    EXPECT_FALSE(doc->isModified());
}

// File > New Network: an empty network in the view; a station added there can be run.
TEST(NetworkWindow, ANewNetworkRunsOnceAStationIsAdded) {
    app::MainWindow window;
    QAction *newNetwork = window.findChild<QAction *>(QStringLiteral("fileNewNetwork"));
    ASSERT_NE(newNetwork, nullptr);
    newNetwork->trigger();
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    EXPECT_EQ(net->session(), nullptr);
    EXPECT_FALSE(toolbarAction(*net, QStringLiteral("Run"))->isEnabled());
    QString error;
    ASSERT_TRUE(net->networkDocument()->addExistingProgram(
        QStringLiteral("a"), kExamples + QStringLiteral("easy-link/master.il"), QString(),
        QString(), &error))
        << error.toStdString();
    ASSERT_NE(net->session(), nullptr);
    EXPECT_EQ(net->stationSelector()->count(), 1);
    EXPECT_TRUE(toolbarAction(*net, QStringLiteral("Run"))->isEnabled());
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("mine.rungnet"));
    QStringList notKept;
    ASSERT_TRUE(net->networkDocument()->saveAs(file, &notKept, &error)) << error.toStdString();
    network::NetworkDescription read;
    ASSERT_TRUE(network::readNetworkFile(file, &read, &error)) << error.toStdString();
    ASSERT_EQ(read.stations.size(), 1u);
    EXPECT_EQ(read.stations[0].name, QStringLiteral("a"));
}

TEST(NetworkWindow, AStationsProgramOpensInTheMainWindowForEditing) {
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(example("easy-link"), QString(), true));
    app::NetworkWindow *net = openedNetwork(window);
    ASSERT_NE(net, nullptr);
    // The station's ladder here refuses edits and says where they are made.
    editor::Document *doc = net->document(QStringLiteral("master"));
    const QString before = doc->listingText();
    doc->replaceRungs(0, 1, {}, QStringLiteral("delete"));
    EXPECT_EQ(doc->listingText(), before);
    EXPECT_TRUE(net->statusBar()->currentMessage().contains(QStringLiteral("main window")));
    emit net->openProgramRequested(
        net->session()->station(QStringLiteral("master"))->programPath());
    EXPECT_TRUE(window.document()->listingText().contains(QStringLiteral("LINK D1000 D100")));
}

// The docks' tabs read whole in every language on a 1366 x 768 screen (the window as it opens
// there, 1280 x 740): Italian's "Osservazione della rete" and "Debugger della scansione" were
// cut to "Osservazione dell..." beside each other.
TEST(NetworkWindow, TheDocksTabsReadWholeInEveryLanguage) {
    for (const char *language : {"en", "hu", "it"}) {
        SCOPED_TRACE(language);
        ASSERT_TRUE(app::setLanguage(QString::fromLatin1(language), false));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
        app::MainWindow window;
        ASSERT_TRUE(window.openFile(example("cpm1-host-link"), QString(), true));
        app::NetworkWindow *net = openedNetwork(window);
        ASSERT_NE(net, nullptr);
        net->resize(1280, 740);
        net->show();
        QCoreApplication::processEvents();
        int tabs = 0;
        for (const QTabBar *bar : net->findChildren<QTabBar *>()) {
            if (!bar->isVisible())
                continue;
            for (int i = 0; i < bar->count(); ++i, ++tabs) {
                const int text = bar->fontMetrics().horizontalAdvance(bar->tabText(i));
                EXPECT_GE(bar->tabRect(i).width(), text + 8) << bar->tabText(i).toStdString();
            }
        }
        EXPECT_GE(tabs, 4) << "the dock tabs were found";
    }
    ASSERT_TRUE(app::setLanguage(QStringLiteral("en"), false));
}

} // namespace
} // namespace rung::test
