#pragma once

// The Simulation menu, its toolbar buttons and the status bar's simulation section: what the
// user runs the simulation with (simulation_controller.h does the work). The keys stay clear
// of the ladder's F5..F9 and Ctrl+F9/F10 (ladder_view_keys.cpp) and of the other menus: F10
// run, F11 pause, Shift+F11 stop, F12 one scan, Ctrl+Shift+F12 power cycle, Ctrl+Shift+F10 /
// F11 run scans / run for. It needs the simulation, the debugging controller (whose entries
// join the menu) and a main window for the menu bar, not the Rung Studio window.

#include <QObject>

class QLabel;
class QMainWindow;
class QToolBar;

namespace rung::app {

class DebugController;
class ElidingLabel;
class SimulationController;

class SimulationMenu : public QObject {
    Q_OBJECT

public:
    SimulationMenu(SimulationController *simulation, DebugController *debug, QMainWindow *window,
                   QObject *parent = nullptr);
    ~SimulationMenu() override;

    // The status bar's two labels, for the window to place: the history's scan (shown while a
    // past scan is) and the run state.
    QLabel *historyLabel() const { return m_history; }
    ElidingLabel *statusLabel() const { return m_status; }

    // The Simulation menu (after the menus before it) and its buttons on the toolbar (built
    // again with the menus when the language changes).
    void addActions(QToolBar *bar);
    // The labels and the entries as the simulation's state allows.
    void updateStatus();

private:
    SimulationController *m_simulation;
    DebugController *m_debug;
    QMainWindow *m_window;
    QLabel *m_history;
    ElidingLabel *m_status;
};

} // namespace rung::app
