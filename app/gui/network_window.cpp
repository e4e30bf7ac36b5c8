// The network window's docks and menus (network_window.h); the network it opens and runs, and
// the views of its stations, are network_window_session.cpp's.

#include "app/gui/network_window.h"

#include "app/gui/network_bridge_controller.h"
#include "app/gui/network_chart.h"
#include "app/gui/network_debug_controller.h"
#include "app/gui/network_document.h"
#include "app/gui/network_history_controller.h"
#include "app/gui/network_traffic_view.h"
#include "app/gui/network_view.h"
#include "app/gui/network_watch_model.h"

#include "editor/document.h"
#include "editor/front_panel.h"
#include "editor/io_panel.h"
#include "editor/keep_typed_delegate.h"
#include "editor/ladder_view.h"
#include "network/network_session.h"

#include <QActionGroup>
#include <QCloseEvent>
#include <QComboBox>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QKeySequence>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QTabWidget>
#include <QTableView>
#include <QToolBar>
#include <QUndoStack>
#include <QVBoxLayout>
#include <QWidgetAction>

namespace rung::app {

NetworkWindow::NetworkWindow(QWidget *parent)
    : QMainWindow(parent) {
    setObjectName(QStringLiteral("networkWindow"));
    setAttribute(Qt::WA_DeleteOnClose);
    buildWindow();
    buildMenus();
    retranslate();
    resize(1280, 720);
}

NetworkWindow::~NetworkWindow() {
    // Its children are hidden and deleted after this body, its members before: nothing of
    // theirs may call back into the window meanwhile.
    for (QObject *child : findChildren<QObject *>())
        disconnect(child, nullptr, this, nullptr);
    if (m_session)
        disconnect(m_session.get(), nullptr, this, nullptr);
    // The views first: they read the stations' sources, which the session owns.
    for (StationView &v : m_views) {
        v.ladder->setMonitorSource(nullptr);
        v.io->setMonitorSource(nullptr);
    }
    m_panel->setMonitorSource(nullptr);
    m_debug->setSession(nullptr, {});
    m_watch->setSession(nullptr);
    m_chart->setSession(nullptr);
}

void NetworkWindow::buildWindow() {
    m_doc = new NetworkDocument(this);
    m_view = new NetworkView(m_doc, this);
    m_view->setObjectName(QStringLiteral("networkView"));
    connect(m_doc, &NetworkDocument::changed, this, &NetworkWindow::documentChanged);
    connect(m_doc, &NetworkDocument::modifiedChanged, this, &NetworkWindow::updateTitle);
    connect(m_view, &NetworkView::stationSelected, this,
            [this](const QString &name) { selectStation(name); });
    connect(m_view, &NetworkView::stationActivated, this, [this](const QString &name) {
        if (const network::StationDescription *s = m_doc->station(name))
            emit openProgramRequested(s->path);
    });
    connect(m_view, &NetworkView::editRefused, this,
            [this](const QString &why) { statusBar()->showMessage(why, 10000); });
    m_ladders = new QStackedWidget(this);
    m_ladders->setObjectName(QStringLiteral("networkLadders"));
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("networkTabs"));
    m_tabs->addTab(m_view, QString());
    m_tabs->addTab(m_ladders, QString());
    setCentralWidget(m_tabs);

    m_stationList = new QListWidget(this);
    m_stationList->setObjectName(QStringLiteral("networkStations"));
    connect(m_stationList, &QListWidget::currentRowChanged, this, [this](int row) {
        // The station's program shows: as a ladder, or as the list when that is shown.
        if (row >= 0 && row < int(m_views.size()) &&
            selectStation(m_views[std::size_t(row)].name) &&
            m_tabs->currentWidget() != m_debug->listPage())
            m_tabs->setCurrentWidget(m_ladders);
    });
    connect(m_stationList, &QListWidget::itemActivated, this, [this](QListWidgetItem *item) {
        const int row = m_stationList->row(item);
        if (row >= 0 && row < int(m_views.size()))
            emit openProgramRequested(m_views[std::size_t(row)].source->programPath());
    });
    m_stationsDock = new QDockWidget(this);
    m_stationsDock->setObjectName(QStringLiteral("networkStationsDock"));
    m_stationsDock->setWidget(m_stationList);
    addDockWidget(Qt::LeftDockWidgetArea, m_stationsDock);

    m_ioPanels = new QStackedWidget(this);
    m_ioDock = new QDockWidget(this);
    m_ioDock->setObjectName(QStringLiteral("networkIoDock"));
    m_ioDock->setWidget(m_ioPanels);
    addDockWidget(Qt::LeftDockWidgetArea, m_ioDock);

    // The selected station's front panel, as its manual draws it (editor/front_panel.h).
    m_panel = new editor::FrontPanel(this);
    m_panel->setObjectName(QStringLiteral("networkFrontPanel"));
    connect(m_panel, &editor::FrontPanel::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    m_panelDock = new QDockWidget(this);
    m_panelDock->setObjectName(QStringLiteral("networkFrontPanelDock"));
    m_panelDock->setWidget(m_panel);
    addDockWidget(Qt::LeftDockWidgetArea, m_panelDock);
    tabifyDockWidget(m_ioDock, m_panelDock);
    m_ioDock->raise();

    m_watch = new NetworkWatchModel(this);
    auto *watchBox = new QWidget(this);
    auto *watchLayout = new QVBoxLayout(watchBox);
    watchLayout->setContentsMargins(2, 2, 2, 2);
    auto *line = new QHBoxLayout;
    m_watchLine = new QLineEdit(watchBox);
    m_watchLine->setObjectName(QStringLiteral("networkWatchLine"));
    connect(m_watchLine, &QLineEdit::returnPressed, this, &NetworkWindow::addWatchedFromLine);
    auto *add = new QPushButton(watchBox);
    add->setObjectName(QStringLiteral("networkWatchAdd"));
    connect(add, &QPushButton::clicked, this, &NetworkWindow::addWatchedFromLine);
    line->addWidget(m_watchLine, 1);
    line->addWidget(add);
    watchLayout->addLayout(line);
    m_watchView = new QTableView(watchBox);
    m_watchView->setObjectName(QStringLiteral("networkWatchTable"));
    m_watchView->setModel(m_watch);
    m_watchView->setItemDelegate(new editor::KeepTypedDelegate(m_watchView));
    m_watchView->verticalHeader()->hide();
    m_watchView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_watchView->horizontalHeader()->setStretchLastSection(true);
    m_watchView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_watchView->setEditTriggers(QAbstractItemView::DoubleClicked |
                                 QAbstractItemView::EditKeyPressed |
                                 QAbstractItemView::AnyKeyPressed);
    watchLayout->addWidget(m_watchView, 1);
    m_removeWatch = new QAction(this);
    m_removeWatch->setShortcut(QKeySequence::Delete);
    m_removeWatch->setShortcutContext(Qt::WidgetShortcut);
    connect(m_removeWatch, &QAction::triggered, this, [this] {
        const QModelIndex i = m_watchView->currentIndex();
        if (i.isValid())
            m_watch->removeRow(i.row());
    });
    m_watchView->addAction(m_removeWatch);
    m_chartWatched = new QAction(this);
    connect(m_chartWatched, &QAction::triggered, this, [this] {
        const QModelIndex i = m_watchView->currentIndex();
        if (i.isValid())
            m_chart->addDevice(m_watch->devices().value(i.row()));
    });
    m_watchView->addAction(m_chartWatched);
    m_watchView->setContextMenuPolicy(Qt::ActionsContextMenu);
    m_watchDock = new QDockWidget(this);
    m_watchDock->setObjectName(QStringLiteral("networkWatchDock"));
    m_watchDock->setWidget(watchBox);
    addDockWidget(Qt::RightDockWidgetArea, m_watchDock);

    m_chart = new NetworkChart(this);
    m_chart->setObjectName(QStringLiteral("networkChart"));
    connect(m_chart, &NetworkChart::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    m_chartDock = new QDockWidget(this);
    m_chartDock->setObjectName(QStringLiteral("networkChartDock"));
    m_chartDock->setWidget(m_chart);
    addDockWidget(Qt::BottomDockWidgetArea, m_chartDock);

    m_traffic = new NetworkTrafficView(this);
    m_traffic->setObjectName(QStringLiteral("networkTraffic"));
    // A frame chosen: the chart shows that instant.
    connect(m_traffic, &NetworkTrafficView::frameChosen, this, [this](qint64 startUs) {
        m_chartDock->show();
        m_chart->placeCursor(startUs / 1000);
    });
    m_trafficDock = new QDockWidget(this);
    m_trafficDock->setObjectName(QStringLiteral("networkTrafficDock"));
    m_trafficDock->setWidget(m_traffic);
    addDockWidget(Qt::BottomDockWidgetArea, m_trafficDock);
    tabifyDockWidget(m_chartDock, m_trafficDock);
    m_chartDock->raise();

    // The bridges, live: where each is reached (a pseudo-terminal's path, to copy).
    m_bridges = new NetworkBridgeController(m_doc, m_view, this);
    connect(m_bridges, &NetworkBridgeController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    addDockWidget(Qt::RightDockWidgetArea, m_bridges->dock());
    m_bridges->dock()->hide(); // until the network has a bridge
    // History across the network: cursor A, or a frame chosen, shows every station then.
    m_history = new NetworkHistoryController(
        m_chart, m_traffic, m_watch,
        [this](network::StationSource *station, model::MonitorSource *source) {
            for (StationView &v : m_views)
                if (v.source == station) {
                    v.ladder->setMonitorSource(source);
                    v.io->setMonitorSource(source);
                }
            if (station->stationName() == currentStation())
                m_panel->setMonitorSource(source);
        },
        this);
    connect(m_history, &NetworkHistoryController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    statusBar()->addPermanentWidget(m_history->label());

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("networkStatus"));
    statusBar()->addPermanentWidget(m_status);

    m_debug = new NetworkDebugController(this, m_tabs, m_history, this);
    connect(m_debug, &NetworkDebugController::stationWanted, this,
            [this](const QString &name) { selectStation(name); });
    connect(m_debug, &NetworkDebugController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    // The chart's trigger is the network's one (Stop When... sets it too): armed there, shown
    // here.
    connect(m_chart, &NetworkChart::armRequested, this,
            [this](const QString &condition, model::Trigger::Action action) {
                QString error;
                if (!m_debug->setTrigger(condition, action, &error))
                    statusBar()->showMessage(error, 10000);
            });
    connect(m_chart, &NetworkChart::disarmRequested, this,
            [this] { m_debug->setTrigger(QString(), m_debug->triggerAction(), nullptr); });
    connect(m_debug, &NetworkDebugController::triggerChanged, this,
            [this] { m_chart->showTrigger(m_debug->stopCondition(), m_debug->triggerAction()); });
    connect(m_debug, &NetworkDebugController::triggerFired, m_chart,
            &NetworkChart::showTriggerFired);
}

void NetworkWindow::buildMenus() {
    // Made again on a language change: the old menus go with their entries (a stale entry
    // would double its shortcut, which Qt then runs for neither). The station selector lives
    // on: its action belongs to the window, not to the toolbar that shows it.
    for (QMenu *menu : menuBar()->findChildren<QMenu *>(Qt::FindDirectChildrenOnly))
        delete menu;
    menuBar()->clear();
    for (QToolBar *bar : findChildren<QToolBar *>())
        delete bar;
    auto *tools = addToolBar(tr("Network"));
    tools->setObjectName(QStringLiteral("networkToolBar"));

    QMenu *file = menuBar()->addMenu(tr("&Network"));
    m_editProgram = file->addAction(tr("&Edit Station Program"), this, [this] {
        for (const StationView &v : m_views)
            if (v.name == currentStation())
                emit openProgramRequested(v.source->programPath());
    });
    m_editProgram->setObjectName(QStringLiteral("networkEditProgram"));
    file->addSeparator();
    m_save = file->addAction(tr("&Save Network"), QKeySequence::Save, this, [this] { save(); });
    m_save->setObjectName(QStringLiteral("networkSave"));
    m_saveAs = file->addAction(tr("Save Network &As..."), QKeySequence::SaveAs, this,
                               [this] { save(true); });
    file->addSeparator();
    m_close = file->addAction(tr("&Close Network"), QKeySequence::Close, this, &QWidget::close);
    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    m_undo = m_doc->undoStack()->createUndoAction(edit, tr("&Undo"));
    m_undo->setShortcut(QKeySequence::Undo);
    edit->addAction(m_undo);
    m_redo = m_doc->undoStack()->createRedoAction(edit, tr("&Redo"));
    m_redo->setShortcut(QKeySequence::Redo);
    edit->addAction(m_redo);
    edit->addSeparator();
    edit->addAction(tr("Add Station From a &Program..."), m_view,
                    &NetworkView::addStationFromProgram);
    edit->addAction(tr("Add Station as a &New Project..."), m_view,
                    &NetworkView::addNewProjectStation);
    edit->addAction(tr("Network Peri&od..."), m_view, &NetworkView::editPeriod);

    m_simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    auto add = [&](const char *name, const QString &text, QStyle::StandardPixmap icon,
                   const QKeySequence &key, auto slot) {
        QAction *a = m_simulationMenu->addAction(style()->standardIcon(icon), text);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(key);
        //: a toolbar button's tooltip: its name and its key
        a->setToolTip(tr("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')),
                                        key.toString(QKeySequence::NativeText)));
        connect(a, &QAction::triggered, this, slot);
        tools->addAction(a);
        return a;
    };
    m_run = add("networkRun", tr("&Run"), QStyle::SP_MediaPlay, QKeySequence(Qt::Key_F10), [this] {
        if (m_session)
            m_session->run();
    });
    m_pause =
        add("networkPause", tr("&Pause"), QStyle::SP_MediaPause, QKeySequence(Qt::Key_F11), [this] {
            if (m_session)
                m_session->pause();
        });
    m_stop = add("networkStop", tr("&Stop"), QStyle::SP_MediaStop,
                 QKeySequence(Qt::SHIFT | Qt::Key_F11), [this] {
                     if (m_session)
                         m_session->stop();
                     if (m_stale) {
                         QString why;
                         if (!buildSession(&why))
                             statusBar()->showMessage(why, 15000);
                     }
                 });
    m_scan = add("networkSingleScan", tr("Single S&can"), QStyle::SP_MediaSeekForward,
                 QKeySequence(Qt::Key_F12), [this] {
                     if (m_session)
                         m_session->singleScan();
                 });
    QAction *runFor = m_simulationMenu->addAction(tr("Run &For..."));
    runFor->setObjectName(QStringLiteral("networkRunFor"));
    runFor->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F10));
    connect(runFor, &QAction::triggered, this, [this] {
        bool ok = false;
        //: the virtual time to run the network for, in seconds
        const double seconds = QInputDialog::getDouble(
            this, tr("Run For"), tr("Virtual time to run the network for (seconds):"), 1.0, 0.001,
            86400.0, 3, &ok);
        if (ok && m_session)
            m_session->runFor(static_cast<qint64>(seconds * 1000.0 + 0.5));
    });
    m_powerCycle = m_simulationMenu->addAction(tr("Power C&ycle"));
    m_powerCycle->setObjectName(QStringLiteral("networkPowerCycle"));
    m_powerCycle->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F12));
    connect(m_powerCycle, &QAction::triggered, this, [this] {
        if (m_session)
            m_session->powerCycle();
    });
    m_speedMenu = m_simulationMenu->addMenu(tr("Spee&d"));
    auto *speeds = new QActionGroup(m_speedMenu);
    for (const double factor : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0, 0.0}) {
        QAction *a = m_speedMenu->addAction(factor > 0 ? tr("x%1 Real Time").arg(factor)
                                                       : tr("As &Fast as Possible"));
        a->setData(factor);
        a->setCheckable(true);
        a->setChecked(m_session ? qFuzzyCompare(factor + 1, m_session->speed() + 1)
                                : factor == 1.0);
        speeds->addAction(a);
        connect(a, &QAction::triggered, this, [this, factor] {
            if (m_session)
                m_session->setSpeed(factor);
        });
    }
    m_debug->addActions(m_simulationMenu);
    tools->addSeparator();
    m_selectorLabel = new QLabel(tr("Station:"), tools);
    tools->addWidget(m_selectorLabel);
    if (!m_selector) {
        m_selector = new QComboBox(this);
        m_selector->setObjectName(QStringLiteral("networkStationSelector"));
        m_selector->setSizeAdjustPolicy(QComboBox::AdjustToContents);
        connect(m_selector, &QComboBox::currentIndexChanged, this, [this](int i) {
            if (i >= 0 && i < int(m_views.size()) && selectStation(m_views[std::size_t(i)].name) &&
                m_tabs->currentWidget() != m_debug->listPage())
                m_tabs->setCurrentWidget(m_ladders);
        });
        m_selectorAction = new QWidgetAction(this);
        m_selectorAction->setDefaultWidget(m_selector);
    }
    tools->addAction(m_selectorAction);

    m_faultsMenu = menuBar()->addMenu(tr("F&aults"));
    m_faultsMenu->setObjectName(QStringLiteral("networkFaultsMenu"));
    connect(m_faultsMenu, &QMenu::aboutToShow, this, &NetworkWindow::buildFaultsMenu);
    buildFaultsMenu();

    QMenu *view = menuBar()->addMenu(tr("&View"));
    view->addAction(m_stationsDock->toggleViewAction());
    view->addAction(m_ioDock->toggleViewAction());
    view->addAction(m_panelDock->toggleViewAction());
    view->addAction(m_watchDock->toggleViewAction());
    view->addAction(m_chartDock->toggleViewAction());
    view->addAction(m_trafficDock->toggleViewAction());
    view->addAction(m_bridges->dock()->toggleViewAction());
    updateActions();
}

void NetworkWindow::buildFaultsMenu() {
    m_faultsMenu->clear();
    if (!m_session) {
        m_faultsMenu->addAction(tr("No network is open"))->setEnabled(false);
        return;
    }
    for (const auto &w : m_session->wires()) {
        //: %1 a wire's name, %2 its ends ("master/CP2, s5/CP2")
        QAction *cut = m_faultsMenu->addAction(
            tr("Cut Wire %1 (%2)").arg(w.name, w.ends.join(QStringLiteral(", "))));
        cut->setObjectName(QStringLiteral("faultCut_") + w.name);
        cut->setCheckable(true);
        cut->setChecked(m_session->wireCut(w.name));
        connect(cut, &QAction::toggled, this, [this, name = w.name](bool on) {
            m_session->setWireCut(name, on);
            statusBar()->showMessage(on ? tr("Wire %1 is cut: nothing it carries arrives").arg(name)
                                        : tr("Wire %1 is joined again").arg(name),
                                     5000);
        });
        QAction *corrupt = m_faultsMenu->addAction(tr("Corrupt the Next Frame on %1").arg(w.name));
        corrupt->setObjectName(QStringLiteral("faultCorrupt_") + w.name);
        connect(corrupt, &QAction::triggered, this, [this, name = w.name] {
            m_session->corruptNextFrame(name, 1, 0x01);
            statusBar()->showMessage(
                tr("The next frame on %1 will arrive with its second byte changed").arg(name),
                5000);
        });
    }
    m_faultsMenu->addSeparator();
    for (const auto &w : m_session->wires())
        for (const QString &end : w.ends) {
            const qsizetype slash = end.indexOf(QLatin1Char('/'));
            if (slash <= 0 || !m_session->station(end.left(slash)))
                continue; // a simulated device's line is its own
            const int set = m_session->baudSet(end);
            //: %1 a station's port ("s5/CP2"); %2 the rate set by hand, if any
            QAction *baud = m_faultsMenu->addAction(
                set ? tr("Baud Rate of %1: %2 (changed)...").arg(end).arg(set)
                    : tr("Change the Baud Rate of %1...").arg(end));
            baud->setObjectName(QStringLiteral("faultBaud_") + end);
            connect(baud, &QAction::triggered, this, [this, end] {
                QStringList rates;
                for (const int b : {1200, 2400, 4800, 9600, 19200, 38400, 57600, 115200})
                    rates << QString::number(b);
                bool ok = false;
                const QString chosen = QInputDialog::getItem(
                    this, tr("Baud Rate"),
                    tr("%1 sends and reads at (the other ends keep theirs):").arg(end), rates,
                    rates.indexOf(QStringLiteral("9600")), false, &ok);
                if (ok)
                    m_session->setBaud(end, chosen.toInt());
            });
        }
    m_faultsMenu->addSeparator();
    QStringList owners;
    for (const auto &s : m_session->description().stations)
        owners << s.name;
    for (const auto &d : m_session->description().devices)
        owners << d.name;
    for (const QString &owner : owners) {
        QAction *silence = m_faultsMenu->addAction(tr("Silence %1").arg(owner));
        silence->setObjectName(QStringLiteral("faultSilent_") + owner);
        silence->setCheckable(true);
        silence->setChecked(m_session->silent(owner));
        connect(silence, &QAction::toggled, this,
                [this, owner](bool on) { m_session->setSilent(owner, on); });
    }
    m_faultsMenu->addSeparator();
    QAction *note = m_faultsMenu->addAction(tr("Stop ends every fault made here"));
    note->setEnabled(false);
}

void NetworkWindow::retranslate() {
    m_stationsDock->setWindowTitle(tr("Stations"));
    m_ioDock->setWindowTitle(tr("Inputs and Outputs"));
    m_panelDock->setWindowTitle(tr("Front Panel"));
    m_watchDock->setWindowTitle(tr("Network Watch"));
    m_watchLine->setPlaceholderText(
        tr("Station/device, e.g. %1").arg(exampleStationDevice(m_session.get())));
    if (auto *add = findChild<QPushButton *>(QStringLiteral("networkWatchAdd")))
        add->setText(tr("&Watch"));
    m_removeWatch->setText(tr("Remove From Watch"));
    m_chartWatched->setText(tr("Add to the Timing Chart"));
    m_chartDock->setWindowTitle(tr("Timing Chart"));
    m_trafficDock->setWindowTitle(tr("Traffic"));
    m_stationList->setToolTip(tr("Double-click a station to edit its program"));
    m_tabs->setTabText(m_tabs->indexOf(m_view), tr("Network"));
    m_tabs->setTabText(m_tabs->indexOf(m_ladders), tr("Ladder"));
    m_debug->retranslate();
    updateTitle();
    updateStatus();
}

void NetworkWindow::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        buildMenus();
        retranslate();
    }
    QMainWindow::changeEvent(event);
}

void NetworkWindow::closeEvent(QCloseEvent *event) {
    if (m_doc->isModified()) {
        const auto answer = QMessageBox::question(
            this, tr("Close Network"),
            tr("%1 has edits that are not saved. Save them?").arg(m_doc->displayName()),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        if (answer == QMessageBox::Cancel || (answer == QMessageBox::Save && !save())) {
            event->ignore();
            return;
        }
    }
    if (m_session)
        m_session->pause();
    event->accept();
}

} // namespace rung::app
