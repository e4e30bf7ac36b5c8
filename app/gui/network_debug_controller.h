#pragma once

// Debugging a station of a simulated network in the network window (docs/user-guide.md,
// "Networks of PLCs"): the selected station's instruction list (read-only, with live values,
// a tab beside its ladder), the Scan Debugger dock following the selected station, breakpoints
// set from the station's ladder or list (Ctrl+B, a click in the margin, Ctrl+Shift+B for a
// condition) and stepping with the main window's keys (Ctrl+F12 one instruction, Shift+F12 the
// rest of the scan). A breakpoint that holds stops the whole network (NetworkSession): the
// window is told to show that station, the place is marked in its ladder and list, and the
// status bar says which station holds. Breakpoints are kept by station, rung and place in the
// rung, so they outlive Stop (the network built again).

#include "app/gui/simulation_controller.h"

#include <QObject>

#include <map>
#include <vector>

class QDockWidget;
class QLabel;
class QMainWindow;
class QMenu;
class QStackedWidget;
class QTabWidget;

namespace rung::editor {
class Document;
class IlEditor;
class LadderView;
} // namespace rung::editor
namespace rung::network {
class NetworkSession;
class StationSource;
} // namespace rung::network

namespace rung::app {

class ScanDebuggerView;
class StationDebugSubject;

class NetworkDebugController : public QObject {
    Q_OBJECT

public:
    using BreakpointSpec = SimulationController::BreakpointSpec;
    struct StationParts {
        QString name;
        network::StationSource *source = nullptr;
        editor::Document *document = nullptr;
        editor::LadderView *ladder = nullptr;
    };
    // Adds the Instruction List tab to `tabs` and the Scan Debugger dock to `window`.
    NetworkDebugController(QMainWindow *window, QTabWidget *tabs, QObject *parent = nullptr);
    ~NetworkDebugController() override;

    // The session and its stations' views (null, {}: none); before they are destroyed.
    void setSession(network::NetworkSession *session, const std::vector<StationParts> &stations);
    // The station the list and the debugger show.
    void selectStation(const QString &name);
    QString station() const { return m_current; }
    // The Simulation menu's debugging part: stepping, breakpoints, the debugger dock.
    void addActions(QMenu *menu);
    void retranslate();

    ScanDebuggerView *scanDebugger() const { return m_debugger; }
    QDockWidget *scanDebuggerDock() const { return m_dock; }
    QWidget *listPage() const;
    editor::IlEditor *listView(const QString &station) const;
    // The station holding inside its scan, as the status bar says it ("" for none).
    QString heldText() const;

    // Breakpoints of a station by instruction (index in its program).
    bool toggleBreakpoint(const QString &station, int instruction);
    void setBreakpoint(const QString &station, int instruction, const BreakpointSpec &condition);
    void removeBreakpoint(const QString &station, int instruction);
    void clearBreakpoints(); // every station's
    std::vector<BreakpointSpec> breakpoints(const QString &station) const;
    // Where the user is in the selected station: its list's line when it has the focus, else
    // its ladder cursor's rung.
    void toggleBreakpointHere();
    void editBreakpointCondition(int instruction);
    void stepInstruction();
    void finishScan();
    // A condition on a station's device, written STATION/CONDITION ("s2/D10 > 100",
    // "master/X0 rises"): the station's trigger (model/image/trigger.h), which stops the whole
    // network right after the scan in which it becomes true. Kept over Stop. False with what
    // is wrong in *error; empty text: none.
    bool setStopCondition(const QString &text, QString *error);
    QString stopCondition() const { return m_stopCondition; }

signals:
    // A breakpoint held in this station: the window shows it.
    void stationWanted(const QString &name);
    void message(const QString &text);

private:
    friend class StationDebugSubject;
    struct Station {
        StationParts parts;
        editor::IlEditor *il = nullptr;
        int stoppedAt = -1;
    };
    const Station *find(const QString &name) const;
    int instructionHere(QString *where) const;
    void sendBreakpoints(const QString &station);
    void updateMarks(const Station &station);
    void snapshotArrived(Station &station);
    void showStoppedAt(const Station &station, int instruction);
    void updateHeld();
    void showDebugger(); // shown, raised, as wide as it needs
    bool armStopCondition(QString *error);

    QMainWindow *m_window;
    QTabWidget *m_tabs;
    QStackedWidget *m_lists;
    QDockWidget *m_dock;
    StationDebugSubject *m_subject;
    ScanDebuggerView *m_debugger;
    QLabel *m_held;
    network::NetworkSession *m_session = nullptr;
    std::vector<Station> m_stations;
    QString m_current;
    std::map<QString, std::vector<BreakpointSpec>> m_breakpoints; // by station
    std::vector<QMetaObject::Connection> m_connections;           // to the session's objects
    QString m_stopCondition;
    network::StationSource *m_stopSource = nullptr; // where it is armed
};

} // namespace rung::app
