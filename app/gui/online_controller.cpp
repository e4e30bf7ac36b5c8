#include "online_controller.h"

#include "connection_panel.h"
#include "keyed_action.h"
#include "simulation_controller.h"

#include "editor/document.h"

#include "comms/driver/online_session.h"
#include "comms/driver/protocol_driver.h"

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>

#include <algorithm>

namespace rung::app {

namespace {

bool scanning(model::MonitorSource::RunState state) {
    using State = model::MonitorSource::RunState;
    return state == State::Running || state == State::Stepping;
}

} // namespace

OnlineController::OnlineController(editor::Document *document, SimulationController *simulation,
                                   QStatusBar *status, QMainWindow *window, QObject *parent)
    : QObject(parent)
    , m_document(document)
    , m_simulation(simulation)
    , m_status(status)
    , m_window(window) {
    m_panel = new ConnectionPanel;
    m_dock = new QDockWidget(window);
    m_dock->setObjectName(QStringLiteral("connectionDock"));
    // Scrolled: on a 1366x768 screen the settings, the figures and the traffic log must never
    // make the window taller than the screen.
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded); // in a narrow column
    scroll->setWidget(m_panel);
    m_dock->setWidget(scroll);
    window->addDockWidget(Qt::RightDockWidgetArea, m_dock); // with the live docks (dock_layout.h)
    m_dock->hide(); // View > Connection, or Online > Go Online, shows it
    const auto refreshTarget = [this] {
        const model::ModelVariant *variant = m_document->modelVariant();
        m_panel->setTarget(m_document->target(), variant ? variant->name : QString());
        updateActions();
    };
    refreshTarget();
    connect(m_document, &editor::Document::programChanged, this, refreshTarget);
    connect(m_document, &editor::Document::pathChanged, this, refreshTarget);
    connect(m_document, &editor::Document::projectReplaced, m_panel,
            &ConnectionPanel::forgetResults);
    connect(m_panel, &ConnectionPanel::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    connect(m_panel, &ConnectionPanel::sessionChanged, this, &OnlineController::onSessionChanged);
    // Going online while the simulation runs: ask, then pause it (its image stays).
    m_panel->setConnectGuard([this] {
        if (!scanning(m_simulation->runState()))
            return true;
        if (!m_panel->confirm(
                tr("Go Online"),
                tr("The simulation is running. Going online pauses it: the views then show the "
                   "PLC's values. Go online?")))
            return false;
        m_simulation->pause();
        return true;
    });
    // A simulation started while online: the PLC keeps the views; offer to go offline.
    connect(m_simulation, &SimulationController::statusChanged, this, [this] {
        if (!m_panel->session() || !scanning(m_simulation->runState()))
            return;
        m_simulation->pause();
        if (m_panel->confirm(tr("Simulate"), tr("The IDE is online to %1. Go offline to simulate?")
                                                 .arg(m_panel->session()->plcName()))) {
            m_panel->disconnectFromPlc();
            m_simulation->run();
        } else {
            statusBar()->showMessage(tr("The simulation stays paused while the IDE is online"),
                                     10000);
        }
    });
}

OnlineController::~OnlineController() = default;

comms::OnlineSession *OnlineController::session() const {
    return m_panel->session();
}

void OnlineController::fitDock() {
    // As wide as the panel's fields and buttons as they are now (the texts wrap, the fields do
    // not; online the settings are hidden and the dock may be narrower), but no wider than a
    // column beside the ladder may be (dock_layout.h): past that the panel scrolls sideways.
    constexpr int kWidestColumn = 240;
    if (auto *scroll = qobject_cast<QScrollArea *>(m_dock->widget()))
        scroll->setMinimumWidth(std::min(
            kWidestColumn, m_panel->minimumSizeHint().width() +
                               scroll->verticalScrollBar()->sizeHint().width() +
                               2 * m_dock->style()->pixelMetric(QStyle::PM_LayoutRightMargin)));
}

void OnlineController::addActions(QToolBar *bar, QMenu *view) {
    m_dock->setWindowTitle(tr("Connection"));
    fitDock();
    view->addAction(m_dock->toggleViewAction());
    QMenu *menu = m_window->menuBar()->addMenu(tr("&Online"));
    // A greyed entry says why when hovered (a status tip does not show for it).
    menu->setToolTipsVisible(true);
    const auto add = [this, menu](const char *name, const QString &text, const QKeySequence &key,
                                  auto slot) {
        return addKeyedAction(menu, this, name, text, key, slot);
    };
    m_go = add("onlineConnect", tr("Go &Online"), QKeySequence(Qt::CTRL | Qt::Key_W), [this] {
        if (m_panel->session()) {
            m_panel->disconnectFromPlc();
            return;
        }
        m_dock->show();
        m_dock->raise();
        m_panel->connectToPlc();
    });
    m_go->setIcon(m_window->style()->standardIcon(QStyle::SP_DriveNetIcon));
    m_test = add("onlineTest", tr("&Test Connection"), {}, [this] {
        m_dock->show();
        m_dock->raise(); // its settings and its answer are in the panel
        m_panel->testConnection();
    });
    menu->addSeparator();
    m_program =
        add("onlineProgram", tr("PLC to &STOP / PROGRAM"), QKeySequence(Qt::CTRL | Qt::Key_1),
            [this] { m_panel->requestPlcMode(comms::PlcMode::Program); });
    m_monitor = add("onlineMonitor", tr("PLC to &MONITOR"), QKeySequence(Qt::CTRL | Qt::Key_3),
                    [this] { m_panel->requestPlcMode(comms::PlcMode::Monitor); });
    m_run = add("onlineRun", tr("PLC to &RUN"), QKeySequence(Qt::CTRL | Qt::Key_4),
                [this] { m_panel->requestPlcMode(comms::PlcMode::Run); });
    menu->addSeparator();
    m_releaseAll = add("onlineReleaseAll", tr("Release All &Forces in the PLC"), {}, [this] {
        if (comms::OnlineSession *s = m_panel->session())
            s->releaseAll();
    });
    bar->addSeparator();
    bar->addAction(m_go);
    updateActions();
}

void OnlineController::onSessionChanged(comms::OnlineSession *session) {
    emit sessionChanged(session);
    if (session) {
        // The panels' first showing may put the inputs and outputs over the connection tab.
        if (m_dock->isVisible())
            m_dock->raise();
        connect(session, &comms::OnlineSession::connectionStateChanged, this,
                [this, session](comms::OnlineSession::ConnectionState state) {
                    using State = comms::OnlineSession::ConnectionState;
                    if (state == State::Lost || state == State::Failed)
                        statusBar()->showMessage(m_panel->stateText(), 10000);
                    else if (state == State::Online)
                        statusBar()->showMessage(tr("Online: %1").arg(session->plcName()), 5000);
                    updateActions();
                });
        connect(session, &comms::OnlineSession::notice, this,
                [this](const QString &text) { statusBar()->showMessage(text, 10000); });
        statusBar()->showMessage(
            tr("Going online. The IDE cannot know whether the PLC runs the program shown: "
               "compare by reading devices"),
            10000);
    } else {
        statusBar()->showMessage(tr("Offline"), 5000);
    }
    fitDock();
    updateActions();
}

void OnlineController::updateActions() {
    if (!m_go) // no menu yet
        return;
    comms::OnlineSession *session = m_panel->session();
    // What the protocol can command (Vigor's Computer Link reads the mode but cannot set it).
    const comms::OnlineSession::Abilities can =
        session ? session->abilities() : comms::OnlineSession::Abilities{};
    const QString noMode =
        session && !can.setsMode
            ? tr("%1 cannot switch the PLC between RUN and STOP: use the switch on the PLC")
                  .arg(comms::protocolName(session->settings().protocol))
            : QString();
    m_go->setText(session ? tr("Go &Offline") : tr("Go &Online"));
    m_go->setToolTip(
        QStringLiteral("%1 (%2)").arg(m_go->text().remove(QLatin1Char('&')),
                                      m_go->shortcut().toString(QKeySequence::NativeText)));
    m_go->setEnabled(m_panel->canConnect() || session);
    if (!session && !m_panel->canConnect())
        m_go->setToolTip(m_panel->cannotConnectReason()); // a VPC: why not
    m_test->setEnabled(m_panel->canConnect() && !session);
    m_test->setToolTip(m_panel->cannotConnectReason());
    for (QAction *a : {m_program.data(), m_run.data()}) {
        a->setEnabled(session && can.setsMode);
        a->setToolTip(noMode);
    }
    m_releaseAll->setEnabled(session && can.forces);
    m_monitor->setEnabled(session && can.monitorMode);
    m_monitor->setToolTip(noMode);
}

} // namespace rung::app
