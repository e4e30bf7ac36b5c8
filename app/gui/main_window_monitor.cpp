// Live values in the window: the one function that hands the active MonitorSource to every
// monitoring view, the label that says which origin is shown, and the instruction list's
// line map for its values. A view added later (I/O panel, timing chart, online dock) is one
// more line in setMonitorSource.

#include "main_window.h"

#include "connection_panel.h"
#include "file_controller.h"
#include "online_controller.h"
#include "simulation_controller.h"
#include "simulation_menu.h"
#include "tests_panel.h"

#include "editor/il_editor.h"
#include "editor/io_panel.h"
#include "editor/ladder_view.h"
#include "editor/watch_list_view.h"

#include "model/image/monitor_source.h"
#include "simulator/session.h"

#include <QLabel>
#include <QMessageBox>
#include <QStatusBar>

namespace rung::app {

// Online, the PLC's values go to the views; offline, the simulation's again. The traffic log
// is saved where the window's files propose.
void MainWindow::setupOnline() {
    m_online = new OnlineController(m_document, m_simulation, statusBar(), this, this);
    connect(m_online, &OnlineController::sessionChanged, this,
            [this](comms::OnlineSession *session) {
                if (session) {
                    setMonitorSource(session, MonitorOrigin::Online);
                    setPanelsSource(session);
                    return;
                }
                // A recording of the PLC keeps what it has: the session goes next.
                if (auto *tests = findChild<TestsPanel *>())
                    tests->keepOnlineRecording();
                // Offline: the simulation's values again (or none).
                setMonitorSource(m_simulation->monitorSource(), m_simulation->historyShown()
                                                                    ? MonitorOrigin::History
                                                                    : MonitorOrigin::Simulation);
                setPanelsSource(m_simulation->session());
            });
    connect(m_online->panel(), &ConnectionPanel::saveTrafficRequested, this, [this] {
        const QString path = m_files->askSavePath(tr("Save Traffic Log"), tr("Text files (*.txt)"),
                                                  {QStringLiteral("txt")});
        QString error;
        if (!path.isEmpty() && !m_online->panel()->saveTraffic(path, &error))
            QMessageBox::critical(this, tr("Cannot save"), error);
    });
}

void MainWindow::setMonitorSource(model::MonitorSource *source, MonitorOrigin origin) {
    // Online, the PLC keeps the views: the simulation's source waits until the IDE is offline.
    if (origin != MonitorOrigin::Online && m_online && m_online->session())
        return;
    m_monitorSource = source;
    m_monitorOrigin = origin;
    m_ladder->setMonitorSource(source);
    m_il->setMonitorSource(source);
    m_watch->setMonitorSource(source);
    // The terminals show what the ladder shows (a past scan too, where a toggle is refused
    // as read-only); the chart keeps the live source it is scrubbed along (setPanelsSource).
    m_ioPanel->setMonitorSource(source);
    updateMonitorLabel();
    updateTitle();
    if (m_simulationMenu)
        m_simulationMenu->updateStatus();
}

QString MainWindow::originText(MonitorOrigin origin) {
    switch (origin) {
    case MonitorOrigin::Simulation:
        return tr("Simulation");
    case MonitorOrigin::Online:
        return tr("Online PLC");
    case MonitorOrigin::History:
        return tr("History (read-only)");
    }
    return {};
}

void MainWindow::updateMonitorLabel() {
    if (!m_statusOrigin) {
        m_statusOrigin = new QLabel;
        m_statusOrigin->setObjectName(QStringLiteral("monitorOrigin"));
        // Framed and bold: which values these are must not be missed.
        m_statusOrigin->setFrameShape(QFrame::Box);
        m_statusOrigin->setStyleSheet(
            QStringLiteral("QLabel { font-weight: bold; padding: 0 6px; }"));
        statusBar()->addPermanentWidget(m_statusOrigin);
    }
    m_statusOrigin->setVisible(m_monitorSource != nullptr);
    m_statusOrigin->setText(m_monitorSource ? originText(m_monitorOrigin) : QString());
    m_statusOrigin->setToolTip(m_monitorSource
                                   ? tr("The ladder, the instruction list and the watch lists "
                                        "show the values of: %1")
                                         .arg(originText(m_monitorOrigin))
                                   : QString());
}

} // namespace rung::app
