#include "simulation_menu.h"

#include "debug_controller.h"
#include "dialogs.h"
#include "eliding_label.h"
#include "simulation_controller.h"
#include "simulation_panel.h"

#include "simulator/session.h"

#include <QAction>
#include <QActionGroup>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSpinBox>
#include <QStyle>
#include <QToolBar>

namespace rung::app {

SimulationMenu::SimulationMenu(SimulationController *simulation, DebugController *debug,
                               QMainWindow *window, QObject *parent)
    : QObject(parent)
    , m_simulation(simulation)
    , m_debug(debug)
    , m_window(window)
    , m_history(new QLabel)
    , m_status(new ElidingLabel) {
    m_history->setObjectName(QStringLiteral("historyStatus"));
    // A past scan is never taken for the live state: bold on amber, beside the run state.
    m_history->setStyleSheet(QStringLiteral(
        "QLabel { background: #ffd54f; color: #3e2700; font-weight: bold; padding: 0 6px; }"));
    m_history->hide();
    m_status->setObjectName(QStringLiteral("simulationStatus"));
    connect(m_simulation, &SimulationController::statusChanged, this,
            &SimulationMenu::updateStatus);
    connect(m_debug, &DebugController::stoppedAtShown, this, &SimulationMenu::updateStatus);
}

SimulationMenu::~SimulationMenu() = default;

void SimulationMenu::addActions(QToolBar *bar) {
    QMenu *menu = m_window->menuBar()->addMenu(tr("&Simulation"));
    const auto add = [this, menu](const char *name, const QString &text,
                                  QStyle::StandardPixmap icon, const QKeySequence &key, auto slot) {
        QAction *a =
            menu->addAction(m_window->style()->standardIcon(icon), text, m_simulation, slot);
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
                askInt(m_window, tr("Run Scans"), tr("Scans to run:"),
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
                m_window, tr("Run For"), tr("Simulated time to run, in seconds:"),
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
    if (QAction *step = menu->findChild<QAction *>(QStringLiteral("simulationStepInstruction")))
        bar->addAction(step);
    updateStatus();
}

void SimulationMenu::updateStatus() {
    using State = model::MonitorSource::RunState;
    const State state = m_simulation->runState();
    m_status->setFullText(m_simulation->statusText());
    m_status->setToolTip(m_simulation->statusToolTip());
    const bool history = m_simulation->historyShown();
    {
        m_history->setVisible(history);
        // "(read-only)" is the framed origin label's beside it; a full status bar (a long
        // run state at x10) must not squeeze the scan's number out.
        m_history->setText(m_simulation->historyText());
        m_history->setMinimumWidth(m_history->sizeHint().width());
    }
    const bool scanning = state == State::Running || state == State::Stepping;
    for (QAction *a : m_window->menuBar()->findChildren<QAction *>()) {
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
