#include "main_window.h"

#include "debug_controller.h"
#include "dialogs.h"
#include "eliding_label.h"
#include "listing_controller.h"
#include "simulation_controller.h"
#include "simulation_panel.h"

#include "editor/problems_view.h"
#include "editor/timing_chart.h"
#include "editor/watch_list_view.h"
#include "simulator/session.h"

#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenuBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <algorithm>

// The Simulation menu, its toolbar buttons and the status bar's simulation section
// (simulation_controller.h does the work). The keys stay clear of the ladder's F5..F9 and
// Ctrl+F9/F10 (ladder_view_keys.cpp) and of the other menus (main_window_actions.cpp).

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
    m_statusHistory = new QLabel;
    m_statusHistory->setObjectName(QStringLiteral("historyStatus"));
    // A past scan is never taken for the live state: bold on amber, beside the run state.
    m_statusHistory->setStyleSheet(QStringLiteral(
        "QLabel { background: #ffd54f; color: #3e2700; font-weight: bold; padding: 0 6px; }"));
    m_statusHistory->hide();
    statusBar()->addPermanentWidget(m_statusHistory);
    updateMonitorLabel(); // the origin's label, left of the simulation's, hidden until values show
    m_statusSimulation = new ElidingLabel;
    m_statusSimulation->setObjectName(QStringLiteral("simulationStatus"));
    statusBar()->addPermanentWidget(m_statusSimulation);
    connect(m_simulation, &SimulationController::statusChanged, this,
            &MainWindow::updateSimulationStatus);
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
    connect(m_debug, &DebugController::stoppedAtShown, this, &MainWindow::updateSimulationStatus);
    updateSimulationStatus();
}

void MainWindow::buildSimulationMenu(QToolBar *bar) {
    QMenu *menu = menuBar()->addMenu(tr("&Simulation"));
    const auto add = [this, menu](const char *name, const QString &text,
                                  QStyle::StandardPixmap icon, const QKeySequence &key, auto slot) {
        QAction *a = menu->addAction(style()->standardIcon(icon), text, m_simulation, slot);
        a->setObjectName(QString::fromLatin1(name));
        a->setShortcut(key);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')),
                                                    key.toString(QKeySequence::NativeText)));
        return a;
    };
    QAction *run = add("simulationRun", tr("&Run"), QStyle::SP_MediaPlay, QKeySequence(Qt::Key_F10),
                       &SimulationController::run);
    QAction *pause = add("simulationPause", tr("&Pause"), QStyle::SP_MediaPause,
                         QKeySequence(Qt::Key_F11), &SimulationController::pause);
    QAction *stop = add("simulationStop", tr("&Stop (Back to Power-On)"), QStyle::SP_MediaStop,
                        QKeySequence(Qt::SHIFT | Qt::Key_F11), &SimulationController::stop);
    QAction *scan = add("simulationScan", tr("Single S&can"), QStyle::SP_MediaSkipForward,
                        QKeySequence(Qt::Key_F12), &SimulationController::singleScan);
    menu->addSeparator();
    add("simulationPowerCycle", tr("Po&wer Cycle"), QStyle::SP_BrowserReload,
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F12), &SimulationController::powerCycle);
    add("simulationRunScans", tr("Run Sc&ans..."), QStyle::SP_MediaSeekForward,
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F10), [this] {
            bool ok = false;
            const int count =
                askInt(this, tr("Run Scans"), tr("Scans to run:"),
                       m_debug->simulationPanel()->scansBox()->value(), 1, 100000000, &ok);
            if (ok) {
                m_debug->simulationPanel()->scansBox()->setValue(count);
                m_simulation->runScans(static_cast<quint64>(count));
            }
        });
    add("simulationRunFor", tr("R&un For..."), QStyle::SP_MediaSeekForward,
        QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F11), [this] {
            bool ok = false;
            const double seconds = askDouble(
                this, tr("Run For"), tr("Simulated time to run, in seconds:"),
                m_debug->simulationPanel()->durationBox()->value(), 0.01, 24.0 * 3600.0, 2, &ok);
            if (ok) {
                m_debug->simulationPanel()->durationBox()->setValue(seconds);
                m_simulation->runFor(static_cast<qint64>(seconds * 1000.0 + 0.5));
            }
        });
    QMenu *speed = menu->addMenu(tr("Spee&d"));
    auto *speeds = new QActionGroup(speed);
    for (const double factor : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0, 1000.0, 0.0}) {
        QAction *a = speed->addAction(factor > 0 ? tr("x%1 Real Time").arg(factor)
                                                 : tr("As &Fast as Possible"));
        a->setObjectName(QStringLiteral("simulationSpeedChoice"));
        a->setData(factor);
        a->setCheckable(true);
        a->setChecked(qFuzzyCompare(factor + 1, m_simulation->speed() + 1));
        speeds->addAction(a);
        connect(a, &QAction::triggered, m_simulation,
                [this, factor] { m_simulation->setSpeed(factor); });
    }
    QMenu *period = menu->addMenu(tr("Scan Peri&od"));
    auto *periods = new QActionGroup(period);
    for (const qint64 ms : {1, 2, 5, 10, 20, 50, 100}) {
        //: the virtual scan period, e.g. "10 ms"
        QAction *a = period->addAction(tr("%1 ms").arg(ms));
        a->setObjectName(QStringLiteral("simulationPeriodChoice"));
        a->setData(ms);
        a->setCheckable(true);
        a->setChecked(ms == m_simulation->periodMs());
        periods->addAction(a);
        connect(a, &QAction::triggered, m_simulation,
                [this, ms] { m_simulation->setPeriodMs(ms); });
    }
    menu->addSeparator();
    menu->addAction(tr("Release All &Forces"), m_simulation, &SimulationController::releaseAll);
    m_debug->addActions(menu); // debug_controller.cpp
    bar->addSeparator();
    for (QAction *a : {run, pause, stop, scan})
        bar->addAction(a);
    if (QAction *step = findChild<QAction *>(QStringLiteral("simulationStepInstruction")))
        bar->addAction(step);
    updateSimulationStatus();
}

void MainWindow::updateSimulationStatus() {
    using State = model::MonitorSource::RunState;
    const State state = m_simulation->runState();
    m_statusSimulation->setFullText(m_simulation->statusText());
    m_statusSimulation->setToolTip(m_simulation->statusToolTip());
    const bool history = m_simulation->historyShown();
    if (m_statusHistory) {
        m_statusHistory->setVisible(history);
        // "(read-only)" is the framed origin label's beside it; a full status bar (a long
        // run state at x10) must not squeeze the scan's number out.
        m_statusHistory->setText(m_simulation->historyText());
        m_statusHistory->setMinimumWidth(m_statusHistory->sizeHint().width());
    }
    const bool scanning = state == State::Running || state == State::Stepping;
    for (QAction *a : findChildren<QAction *>()) {
        const QString name = a->objectName();
        if (name == QLatin1String("simulationRun"))
            a->setEnabled(state != State::Running);
        else if (name == QLatin1String("simulationPause"))
            a->setEnabled(scanning);
        else if (name == QLatin1String("simulationStop"))
            a->setEnabled(state != State::Offline && state != State::Stopped);
        else if (name == QLatin1String("simulationReturnToLive"))
            a->setEnabled(history);
        else if (name == QLatin1String("simulationFinishScan"))
            a->setEnabled(m_simulation->session() && m_simulation->session()->snapshot() &&
                          m_simulation->session()->snapshot()->pause.has_value());
        // The speed and period chosen in the dock check the menu's entry too.
        else if (name == QLatin1String("simulationSpeedChoice"))
            a->setChecked(qFuzzyCompare(a->data().toDouble() + 1, m_simulation->speed() + 1));
        else if (name == QLatin1String("simulationPeriodChoice"))
            a->setChecked(a->data().toLongLong() == m_simulation->periodMs());
    }
}

} // namespace rung::app
