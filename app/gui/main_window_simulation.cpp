#include "main_window.h"

#include "debug_controller.h"
#include "eliding_label.h"
#include "listing_controller.h"
#include "simulation_controller.h"
#include "simulation_menu.h"

#include "editor/problems_view.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "simulator/session.h"

#include <QDockWidget>
#include <QLabel>
#include <QStatusBar>

#include <algorithm>

// The window's side of the simulation: its values handed to the views (live, or a past scan
// while the history is shown), its problems beside the program's, the chart's cursor scrubbing
// the history; the menu and the status (simulation_menu.h) and the debugging
// (debug_controller.h) are parts of their own.

namespace rung::app {

void MainWindow::setupSimulation() {
    m_simulation = new SimulationController(m_document, this);
    m_simulation->setBlocker([this]() -> QString {
        m_listing->flush(); // what was just typed is part of what the user sees
        if (m_listing->hasErrors())
            return tr("The instruction list has errors, so the ladder still shows the last "
                      "program without them: correct the list (or undo) before simulating");
        return {};
    });
    connect(m_simulation, &SimulationController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    // The live session, or a past scan while the history is shown (simulation_history.cpp).
    connect(m_simulation, &SimulationController::monitorSourceChanged, this,
            [this](model::MonitorSource *source) {
                setMonitorSource(source, m_simulation->historyShown() ? MonitorOrigin::History
                                                                      : MonitorOrigin::Simulation);
            });
    connect(m_simulation, &SimulationController::sessionChanged, this,
            [](simulator::SimulatorSession *session) {
                if (session)
                    session->setPowerFlowRecording(true); // the overlay draws it
            });
    connect(m_simulation, &SimulationController::sessionChanged, this,
            [this](simulator::SimulatorSession *session) { setPanelsSource(session); });
    // Scrubbing the chart's cursor A back shows that scan in the ladder, the list, the
    // watch table and the terminals (cursor B only measures); Return to Live ends it.
    connect(m_chart, &editor::TimingChart::cursorMoved, this,
            [this](int which, quint64, qint64 timeMs) {
                if (which == 0 && m_simulation->session())
                    m_simulation->showHistoryAt(timeMs);
            });

    connect(m_simulation, &SimulationController::problems, this,
            [this](const std::vector<model::Diagnostic> &errors) {
                std::vector<model::Diagnostic> all = m_document->diagnostics();
                for (const model::Diagnostic &e : errors)
                    if (std::none_of(all.begin(), all.end(), [&e](const model::Diagnostic &d) {
                            return d.code == e.code && d.message == e.message;
                        }))
                        all.push_back(e);
                m_problems->setDiagnostics(all);
                if (auto *dock = findChild<QDockWidget *>(QStringLiteral("problemsDock"))) {
                    dock->setWindowTitle(m_problems->summary());
                    dock->show();
                    dock->raise();
                }
            });
    m_debug =
        new DebugController(m_document, m_ladder, m_il, m_simulation, statusBar(), this, this);
    m_simulationMenu = new SimulationMenu(m_simulation, m_debug, this, this);
    statusBar()->addPermanentWidget(m_simulationMenu->historyLabel());
    updateMonitorLabel(); // the origin's label, left of the simulation's, hidden until values show
    statusBar()->addPermanentWidget(m_simulationMenu->statusLabel());
    m_simulationMenu->updateStatus();
}

} // namespace rung::app
