#pragma once

// The window's side of going online: the connection dock, the Online menu and its toolbar
// button (enabled as the protocol can), and the simulation's give and take with the PLC. An
// online PLC and a simulation never feed the views together: going online pauses a running
// simulation (after asking), and a simulation started while online is paused again with the
// offer to go offline. Keys follow CX-Programmer's habits (Ctrl+W work online, Ctrl+1 / 3 / 4
// PROGRAM / MONITOR / RUN) and stay clear of the ladder's F5..F9 and the simulation's
// F10..F12. It needs the document, the simulation and a main window to dock into, not the
// Rung Studio window: the window hands the session to its views (sessionChanged).

#include <QObject>
#include <QPointer>

class QAction;
class QDockWidget;
class QMainWindow;
class QMenu;
class QStatusBar;
class QToolBar;

namespace rung::comms {
class OnlineSession;
}
namespace rung::editor {
class Document;
}

namespace rung::app {

class ConnectionPanel;
class SimulationController;

class OnlineController : public QObject {
    Q_OBJECT

public:
    // `window`: where the connection dock goes and the Online menu is added; `status`: its
    // messages.
    OnlineController(editor::Document *document, SimulationController *simulation,
                     QStatusBar *status, QMainWindow *window, QObject *parent = nullptr);
    ~OnlineController() override;

    ConnectionPanel *panel() const { return m_panel; }
    QDockWidget *dock() const { return m_dock; }
    // The session while online, else null.
    comms::OnlineSession *session() const;

    // The Online menu (after the menus before it), its button on the toolbar and the dock's
    // entry in View (built again with the menus when the language changes).
    void addActions(QToolBar *bar, QMenu *view);
    // The Online menu's entries as the session and its protocol allow.
    void updateActions();

signals:
    // Online (the session) or offline (null): the window hands the views their source.
    void sessionChanged(comms::OnlineSession *session);

private:
    QStatusBar *statusBar() const { return m_status; }
    void onSessionChanged(comms::OnlineSession *session);
    void fitDock();

    editor::Document *m_document;
    SimulationController *m_simulation;
    QStatusBar *m_status;
    QMainWindow *m_window;
    ConnectionPanel *m_panel = nullptr;
    QDockWidget *m_dock = nullptr;
    QPointer<QAction> m_go;
    QPointer<QAction> m_test;
    QPointer<QAction> m_program;
    QPointer<QAction> m_monitor;
    QPointer<QAction> m_run;
    QPointer<QAction> m_releaseAll;
};

} // namespace rung::app
