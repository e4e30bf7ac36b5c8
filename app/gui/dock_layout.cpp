#include "dock_layout.h"

#include <QDockWidget>
#include <QMainWindow>

namespace rung::app {

namespace {

QDockWidget *dock(QMainWindow *window, const char *name) {
    return window->findChild<QDockWidget *>(QLatin1String(name));
}

} // namespace

void arrangeDocks(QMainWindow *window, bool wide) {
    QDockWidget *project = dock(window, "projectDock");
    QDockWidget *crossReference = dock(window, "crossReferenceDock");
    QDockWidget *io = dock(window, "ioDock");
    QDockWidget *simulation = dock(window, "simulationDock");
    QDockWidget *debugger = dock(window, "scanDebuggerDock");
    QDockWidget *connection = dock(window, "connectionDock");
    QDockWidget *problems = dock(window, "problemsDock");
    QDockWidget *watch = dock(window, "watchDock");
    QDockWidget *chart = dock(window, "timingChartDock");
    if (!project || !crossReference || !io || !simulation || !debugger || !connection ||
        !problems || !watch || !chart)
        return;
    // A split before the tabs: Qt tabs a dock split beside one that is already tabbed.
    window->addDockWidget(Qt::LeftDockWidgetArea, project);
    // Narrow, the one column goes down to the status bar: stacked over the findings its
    // minimum height and theirs made the window taller than a 600 px screen.
    window->setCorner(Qt::BottomLeftCorner,
                      wide ? Qt::BottomDockWidgetArea : Qt::LeftDockWidgetArea);
    if (wide) {
        window->addDockWidget(Qt::RightDockWidgetArea, io);
        window->splitDockWidget(io, simulation, Qt::Vertical);
    } else {
        window->splitDockWidget(project, io, Qt::Vertical);
    }
    window->tabifyDockWidget(project, crossReference);
    if (!wide)
        window->tabifyDockWidget(crossReference, simulation);
    window->tabifyDockWidget(simulation, debugger);
    window->tabifyDockWidget(debugger, connection);
    // The front panel a tab behind the run controls (wide: the terminals' tab bar has no room
    // for a second title at 1366 px) or behind the terminals (narrow: the run controls' group
    // already holds the left column's tabs).
    if (QDockWidget *front = dock(window, "frontPanelDock")) {
        QDockWidget *beside = wide ? simulation : io;
        window->tabifyDockWidget(beside, front);
        beside->raise();
    }
    window->addDockWidget(Qt::BottomDockWidgetArea, problems);
    window->tabifyDockWidget(problems, watch);
    window->tabifyDockWidget(watch, chart);
    if (QDockWidget *tests = dock(window, "testsDock"))
        window->tabifyDockWidget(chart, tests);
    // Each tabbed dock shown and hidden again leaves another in front: the first start
    // shows the project and the problems.
    project->raise();
    problems->raise();
}

void sizeDocks(QMainWindow *window, bool wide) {
    QDockWidget *project = dock(window, "projectDock");
    QDockWidget *io = dock(window, "ioDock");
    QDockWidget *simulation = dock(window, "simulationDock");
    QDockWidget *problems = dock(window, "problemsDock");
    if (!project || !io || !simulation || !problems)
        return;
    // The ladder keeps about 850 px with its frame and scroll bar, the docks' frames and
    // handles take about 50: at its smallest readable zoom a full row's contacts, coil and
    // boxes fit (LadderMetrics::minReadableZoom). A wide screen's two columns share the rest;
    // a narrow one's single column takes what is left, at least a narrow symbol table.
    const int spare = window->width() - 900;
    if (wide) {
        const int column = std::clamp(spare / 2, 180, 300);
        window->resizeDocks({project, io}, {column, column}, Qt::Horizontal);
    } else {
        window->resizeDocks({project}, {std::clamp(spare + 20, 150, 300)}, Qt::Horizontal);
    }
    // The problems, the watch table and the timing chart share the bottom: tall enough for a
    // few signals of the chart, less on a low screen.
    window->resizeDocks({problems}, {std::clamp(window->height() / 4, 120, 190)}, Qt::Vertical);
    // The live column: the terminals above, the run controls or the connection below.
    if (wide)
        window->resizeDocks({io, simulation}, {window->height() / 3, window->height() / 2},
                            Qt::Vertical);
}

} // namespace rung::app
