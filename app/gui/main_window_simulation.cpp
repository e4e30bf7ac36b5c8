#include "main_window.h"

#include "simulation_controller.h"

#include "editor/problems_view.h"
#include "editor/watch_list_view.h"
#include "simulator/session.h"

#include <QAction>
#include <QActionGroup>

#include <QDockWidget>
#include <QLabel>
#include <QMenuBar>
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
        if (m_ilTimer.isActive())
            applyListing(); // what was just typed is part of what the user sees
        if (model::hasErrors(m_listingErrors))
            return tr("The instruction list has errors, so the ladder still shows the last "
                      "program without them: correct the list (or undo) before simulating");
        return {};
    });
    m_statusSimulation = new QLabel;
    m_statusSimulation->setObjectName(QStringLiteral("simulationStatus"));
    statusBar()->addPermanentWidget(m_statusSimulation);
    connect(m_simulation, &SimulationController::statusChanged, this,
            &MainWindow::updateSimulationStatus);
    connect(m_simulation, &SimulationController::message, this,
            [this](const QString &text) { statusBar()->showMessage(text, 10000); });
    connect(m_simulation, &SimulationController::sessionChanged, this,
            [this](simulator::SimulatorSession *session) { setPanelsSource(session); });
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
    QMenu *speed = menu->addMenu(tr("Spee&d"));
    auto *speeds = new QActionGroup(speed);
    for (const double factor : {0.1, 0.5, 1.0, 2.0, 5.0, 10.0, 100.0, 1000.0, 0.0}) {
        QAction *a = speed->addAction(factor > 0 ? tr("x%1 Real Time").arg(factor)
                                                 : tr("As &Fast as Possible"));
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
        a->setCheckable(true);
        a->setChecked(ms == m_simulation->periodMs());
        periods->addAction(a);
        connect(a, &QAction::triggered, m_simulation,
                [this, ms] { m_simulation->setPeriodMs(ms); });
    }
    menu->addSeparator();
    menu->addAction(tr("Release All &Forces"), m_simulation, &SimulationController::releaseAll);
    bar->addSeparator();
    for (QAction *a : {run, pause, stop, scan})
        bar->addAction(a);
    updateSimulationStatus();
}

void MainWindow::updateSimulationStatus() {
    using State = model::MonitorSource::RunState;
    const State state = m_simulation->runState();
    m_statusSimulation->setText(m_simulation->statusText());
    const bool scanning = state == State::Running || state == State::Stepping;
    for (QAction *a : findChildren<QAction *>()) {
        if (a->objectName() == QLatin1String("simulationRun"))
            a->setEnabled(state != State::Running);
        else if (a->objectName() == QLatin1String("simulationPause"))
            a->setEnabled(scanning);
        else if (a->objectName() == QLatin1String("simulationStop"))
            a->setEnabled(state != State::Offline && state != State::Stopped);
    }
}

} // namespace rung::app
