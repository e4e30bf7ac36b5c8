#pragma once

// The simulation's docks (Simulation: run N scans, run for, speed, period, statistics,
// history; Scan Debugger: the stopped scan and the breakpoints), breakpoints in the list's
// margin and on the ladder's rungs, the stopped instruction shown in both views, and the
// question an online edit asks. The menu's debugging entries and their keys are the table
// both windows share (debug_entries.h). It needs the document, the two views, the simulation
// and a main window to dock into, not the Rung Studio window.

#include "app/gui/debug_entries.h"

#include <QObject>

class QDockWidget;
class QMainWindow;
class QMenu;
class QStatusBar;

namespace rung::editor {
class Document;
class IlEditor;
class LadderView;
} // namespace rung::editor

namespace rung::app {

class ScanDebuggerView;
class SimulationController;
class SimulationPanel;

class DebugController : public QObject, public DebugCommands {
    Q_OBJECT

public:
    // `window`: where the two docks go and the parent of its dialogs; `status`: its messages.
    DebugController(editor::Document *document, editor::LadderView *ladder, editor::IlEditor *il,
                    SimulationController *simulation, QStatusBar *status, QMainWindow *window,
                    QObject *parent = nullptr);
    ~DebugController() override;

    SimulationPanel *simulationPanel() const { return m_panel; }
    ScanDebuggerView *scanDebugger() const { return m_debugger; }

    // The Simulation menu's debugging part: stepping, breakpoints, return to live, the docks.
    void addActions(QMenu *menu);
    // The docks' titles and panels in the language now installed.
    void retranslate();
    // The menu's entries (DebugCommands), for the simulation.
    void stepInstruction() override;
    void finishScan() override;
    // Sets or clears a breakpoint where the user is: the instruction list's line when it has
    // the focus, else the ladder cursor's rung (its first instruction).
    void toggleBreakpointHere() override;
    void editBreakpointConditionHere() override;
    void clearBreakpoints() override;
    void returnToLive() override;
    // Opens the condition of the breakpoint on an instruction (setting one if none).
    void editBreakpointCondition(int instruction);

signals:
    // The simulation stopped at an instruction (or -1: runs on) and both views show it.
    void stoppedAtShown(int instruction);

private:
    QStatusBar *statusBar() const { return m_status; }
    // The instruction at a 1-based line of the instruction list, -1 for none.
    int instructionAtLine(int line) const;
    // The instruction where the user is (as toggleBreakpointHere says), -1 for none; `where`
    // names the place ("line 3", "rung 2").
    int instructionHere(QString *where) const;
    void updateBreakpointMarks();
    void showStoppedAt(int instruction);

    editor::Document *m_document;
    editor::LadderView *m_ladder;
    editor::IlEditor *m_il;
    SimulationController *m_simulation;
    QStatusBar *m_status;
    QMainWindow *m_window;
    SimulationPanel *m_panel = nullptr;
    ScanDebuggerView *m_debugger = nullptr;
    QDockWidget *m_panelDock = nullptr;
    QDockWidget *m_debugDock = nullptr;
    bool m_docksShown = false; // shown once, when a simulation first starts
};

} // namespace rung::app
