#pragma once

// The Front Panel dock (issue 30): the PLC's front panel (editor/front_panel.h) of the
// document's PLC, fed by the simulation's source as the other monitoring docks are; or, for a
// while, any source of any PLC (a network station's), until the window goes back to its
// simulation.

#include "model/image/monitor_source.h"

#include <QObject>
#include <QPointer>

class QDockWidget;
class QMainWindow;

namespace rung::model {
class Target;
}

namespace rung::editor {
class Document;
class FrontPanel;
} // namespace rung::editor

namespace rung::app {

class FrontPanelController : public QObject {
    Q_OBJECT

public:
    // Adds the dock "frontPanelDock" to the window, hidden (dock_layout.h places it).
    FrontPanelController(editor::Document *document, QMainWindow *window);

    QDockWidget *dock() const { return m_dock; }
    editor::FrontPanel *panel() const { return m_panel; }

    // The window's simulation (null: none): the panel of the document's PLC shows it unless
    // showSource pointed it elsewhere.
    void setSimulationSource(model::MonitorSource *source);
    // Any source of any PLC (a network station's, with the station's table and model): the
    // panel shows it until showSimulation.
    void showSource(model::MonitorSource *source, const model::Target &target,
                    const QString &modelName);
    void showSimulation();
    void retranslate();

private:
    void followDocument();

    editor::Document *m_document;
    QDockWidget *m_dock;
    editor::FrontPanel *m_panel;
    QPointer<model::MonitorSource> m_simulation;
    bool m_pinned = false; // showSource's source, not the simulation's
};

} // namespace rung::app
