#include "main_window.h"

#include "connection_panel.h"
#include "file_controller.h"
#include "simulation_controller.h"

#include "comms/driver/online_session.h"
#include "comms/driver/protocol_driver.h"
#include "simulator/session.h"

#include <QAction>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

// The window's side of going online (issue 13): the connection dock, the Online menu and its
// toolbar button, and the hand-over of the session to every monitoring view. An online PLC
// and a simulation never feed the views together: going online pauses a running simulation
// (after asking), and a simulation started while online is paused again with the offer to go
// offline. Keys follow CX-Programmer's habits (Ctrl+W work online, Ctrl+1 / 3 / 4 PROGRAM /
// MONITOR / RUN) and stay clear of the ladder's F5..F9 and the simulation's F10..F12.

namespace rung::app {

namespace {
// As wide as the panel's fields and buttons as they are now (the texts wrap, the fields do
// not; online the settings are hidden and the dock may be narrower), but no wider than a
// column beside the ladder may be (dock_layout.h): past that the panel scrolls sideways.
void fitConnectionDock(QDockWidget *dock, ConnectionPanel *panel) {
    constexpr int kWidestColumn = 240;
    if (auto *scroll = qobject_cast<QScrollArea *>(dock->widget()))
        scroll->setMinimumWidth(std::min(
            kWidestColumn, panel->minimumSizeHint().width() +
                               scroll->verticalScrollBar()->sizeHint().width() +
                               2 * dock->style()->pixelMetric(QStyle::PM_LayoutRightMargin)));
}

bool scanning(model::MonitorSource::RunState state) {
    using State = model::MonitorSource::RunState;
    return state == State::Running || state == State::Stepping;
}
} // namespace

void MainWindow::setupOnline() {
    m_connectionPanel = new ConnectionPanel;
    auto *dock = new QDockWidget(this);
    dock->setObjectName(QStringLiteral("connectionDock"));
    // Scrolled: on a 1366x768 screen the settings, the figures and the traffic log must never
    // make the window taller than the screen.
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded); // in a narrow column
    scroll->setWidget(m_connectionPanel);
    dock->setWidget(scroll);
    addDockWidget(Qt::RightDockWidgetArea, dock); // with the live docks (dock_layout.h)
    dock->hide(); // View > Connection, or Online > Go Online, shows it
    const auto refreshTarget = [this] {
        const model::ModelVariant *variant = m_document->modelVariant();
        m_connectionPanel->setTarget(m_document->target(), variant ? variant->name : QString());
        updateOnlineActions();
    };
    refreshTarget();
    connect(m_document, &editor::Document::programChanged, this, refreshTarget);
    connect(m_document, &editor::Document::pathChanged, this, refreshTarget);
    connect(m_document, &editor::Document::projectReplaced, m_connectionPanel,
            &ConnectionPanel::forgetResults);
    connect(m_connectionPanel, &ConnectionPanel::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    connect(m_connectionPanel, &ConnectionPanel::sessionChanged, this,
            &MainWindow::onlineSessionChanged);
    connect(m_connectionPanel, &ConnectionPanel::saveTrafficRequested, this, [this] {
        const QString path = m_files->askSavePath(tr("Save Traffic Log"), tr("Text files (*.txt)"),
                                                  {QStringLiteral("txt")});
        QString error;
        if (!path.isEmpty() && !m_connectionPanel->saveTraffic(path, &error))
            QMessageBox::critical(this, tr("Cannot save"), error);
    });
    // Going online while the simulation runs: ask, then pause it (its image stays).
    m_connectionPanel->setConnectGuard([this] {
        if (!scanning(m_simulation->runState()))
            return true;
        if (!m_connectionPanel->confirm(
                tr("Go Online"),
                tr("The simulation is running. Going online pauses it: the views then show the "
                   "PLC's values. Go online?")))
            return false;
        m_simulation->pause();
        return true;
    });
    // A simulation started while online: the PLC keeps the views; offer to go offline.
    connect(m_simulation, &SimulationController::statusChanged, this, [this] {
        if (!m_connectionPanel->session() || !scanning(m_simulation->runState()))
            return;
        m_simulation->pause();
        if (m_connectionPanel->confirm(tr("Simulate"),
                                       tr("The IDE is online to %1. Go offline to simulate?")
                                           .arg(m_connectionPanel->session()->plcName()))) {
            m_connectionPanel->disconnectFromPlc();
            m_simulation->run();
        } else {
            statusBar()->showMessage(tr("The simulation stays paused while the IDE is online"),
                                     10000);
        }
    });
}

void MainWindow::buildOnlineMenu(QToolBar *bar, QMenu *view) {
    auto *dock = findChild<QDockWidget *>(QStringLiteral("connectionDock"));
    dock->setWindowTitle(tr("Connection"));
    fitConnectionDock(dock, m_connectionPanel);
    view->addAction(dock->toggleViewAction());
    QMenu *menu = menuBar()->addMenu(tr("&Online"));
    // A greyed entry says why when hovered (a status tip does not show for it).
    menu->setToolTipsVisible(true);
    const auto add = [this, menu](const char *name, const QString &text, const QKeySequence &key,
                                  auto slot) {
        QAction *a = menu->addAction(text, this, slot);
        a->setObjectName(QString::fromLatin1(name));
        if (!key.isEmpty()) {
            a->setShortcut(key);
            a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')),
                                                        key.toString(QKeySequence::NativeText)));
        }
        return a;
    };
    QAction *go =
        add("onlineConnect", tr("Go &Online"), QKeySequence(Qt::CTRL | Qt::Key_W), [this, dock] {
            if (m_connectionPanel->session()) {
                m_connectionPanel->disconnectFromPlc();
                return;
            }
            dock->show();
            dock->raise();
            m_connectionPanel->connectToPlc();
        });
    go->setIcon(style()->standardIcon(QStyle::SP_DriveNetIcon));
    add("onlineTest", tr("&Test Connection"), {}, [this, dock] {
        dock->show();
        dock->raise(); // its settings and its answer are in the panel
        m_connectionPanel->testConnection();
    });
    menu->addSeparator();
    add("onlineProgram", tr("PLC to &STOP / PROGRAM"), QKeySequence(Qt::CTRL | Qt::Key_1),
        [this] { m_connectionPanel->requestPlcMode(comms::PlcMode::Program); });
    add("onlineMonitor", tr("PLC to &MONITOR"), QKeySequence(Qt::CTRL | Qt::Key_3),
        [this] { m_connectionPanel->requestPlcMode(comms::PlcMode::Monitor); });
    add("onlineRun", tr("PLC to &RUN"), QKeySequence(Qt::CTRL | Qt::Key_4),
        [this] { m_connectionPanel->requestPlcMode(comms::PlcMode::Run); });
    menu->addSeparator();
    add("onlineReleaseAll", tr("Release All &Forces in the PLC"), {}, [this] {
        if (comms::OnlineSession *s = m_connectionPanel->session())
            s->releaseAll();
    });
    bar->addSeparator();
    bar->addAction(go);
    updateOnlineActions();
}

void MainWindow::onlineSessionChanged(comms::OnlineSession *session) {
    if (session) {
        setMonitorSource(session, MonitorOrigin::Online);
        setPanelsSource(session);
        // The panels' first showing may put the inputs and outputs over the connection tab.
        if (auto *dock = findChild<QDockWidget *>(QStringLiteral("connectionDock")))
            if (dock->isVisible())
                dock->raise();
        connect(session, &comms::OnlineSession::connectionStateChanged, this,
                [this, session](comms::OnlineSession::ConnectionState state) {
                    using State = comms::OnlineSession::ConnectionState;
                    if (state == State::Lost || state == State::Failed)
                        statusBar()->showMessage(m_connectionPanel->stateText(), 10000);
                    else if (state == State::Online)
                        statusBar()->showMessage(tr("Online: %1").arg(session->plcName()), 5000);
                    updateOnlineActions();
                });
        connect(session, &comms::OnlineSession::notice, this,
                [this](const QString &text) { statusBar()->showMessage(text, 10000); });
        statusBar()->showMessage(
            tr("Going online. The IDE cannot know whether the PLC runs the program shown: "
               "compare by reading devices"),
            10000);
    } else {
        // Offline: the simulation's values again (or none).
        setMonitorSource(m_simulation->monitorSource(), m_simulation->historyShown()
                                                            ? MonitorOrigin::History
                                                            : MonitorOrigin::Simulation);
        setPanelsSource(m_simulation->session());
        statusBar()->showMessage(tr("Offline"), 5000);
    }
    if (auto *dock = findChild<QDockWidget *>(QStringLiteral("connectionDock")))
        fitConnectionDock(dock, m_connectionPanel);
    updateOnlineActions();
}

void MainWindow::updateOnlineActions() {
    comms::OnlineSession *session = m_connectionPanel ? m_connectionPanel->session() : nullptr;
    // What the protocol can command (Vigor's Computer Link reads the mode but cannot set it).
    const comms::OnlineSession::Abilities can =
        session ? session->abilities() : comms::OnlineSession::Abilities{};
    const QString noMode =
        session && !can.setsMode
            ? tr("%1 cannot switch the PLC between RUN and STOP: use the switch on the PLC")
                  .arg(comms::protocolName(session->settings().protocol))
            : QString();
    for (QAction *a : findChildren<QAction *>()) {
        const QString name = a->objectName();
        if (name == QLatin1String("onlineConnect")) {
            a->setText(session ? tr("Go &Offline") : tr("Go &Online"));
            a->setToolTip(
                QStringLiteral("%1 (%2)").arg(a->text().remove(QLatin1Char('&')),
                                              a->shortcut().toString(QKeySequence::NativeText)));
            a->setEnabled(m_connectionPanel->canConnect() || session);
            if (!session && !m_connectionPanel->canConnect())
                a->setToolTip(m_connectionPanel->cannotConnectReason()); // a VPC: why not
        } else if (name == QLatin1String("onlineTest")) {
            a->setEnabled(m_connectionPanel->canConnect() && !session);
            a->setToolTip(m_connectionPanel->cannotConnectReason());
        } else if (name == QLatin1String("onlineProgram") || name == QLatin1String("onlineRun")) {
            a->setEnabled(session && can.setsMode);
            a->setToolTip(noMode);
        } else if (name == QLatin1String("onlineReleaseAll")) {
            a->setEnabled(session && can.forces);
        } else if (name == QLatin1String("onlineMonitor")) {
            a->setEnabled(session && can.monitorMode);
            a->setToolTip(noMode);
        }
    }
}

} // namespace rung::app
