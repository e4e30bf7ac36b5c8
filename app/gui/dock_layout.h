#pragma once

// Where the window's docks go on a first start (a layout the user saved is restored as it
// was): what a user needs together is visible together (issue 31, docs/user-guide.md "The
// docks").
//  - Editing: Project and Cross Reference, tabs of the left column.
//  - Live values, from a simulation or a PLC: Inputs and Outputs, with Simulation (the Front
//    Panel a tab behind it; on a narrow screen behind Inputs and Outputs), Scan
//    Debugger and Connection as tabs below it (a simulation and a PLC never feed the views
//    together, so their docks share a place). On a wide screen this is a right-hand column;
//    on a narrow one (1024x600) there is room beside the ladder for one column only, so the
//    Simulation, Scan Debugger and Connection tabs join Project's and Inputs and Outputs
//    goes under them.
//  - Findings and records: Problems, Watch, Timing Chart and Tests, tabs below the ladder.
// The widths leave the ladder its readable width (a coil and a timer's box in view).

class QMainWindow;

namespace rung::app {

// The layout's version in the saved window state: a layout saved before these groups
// (six tabs on the left, 1), before the Tests dock (2) or before the Front Panel dock (3: an
// older layout restored left it alone where it was added, not a tab beside the run controls)
// is not restored.
inline constexpr int kDockLayoutVersion = 3;
// A screen at least this wide gets the right-hand column.
inline constexpr int kWideScreen = 1280;

// Places the docks by their object names (projectDock, crossReferenceDock, ioDock, frontPanelDock,
// simulationDock, scanDebuggerDock, connectionDock, problemsDock, watchDock, timingChartDock,
// testsDock).
void arrangeDocks(QMainWindow *window, bool wide);
// The first start's widths and heights of the columns, once the window is laid out.
void sizeDocks(QMainWindow *window, bool wide);

} // namespace rung::app
