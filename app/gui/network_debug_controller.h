#pragma once

// Debugging a station of a simulated network in the network window (docs/user-guide.md,
// "Networks of PLCs"): the selected station's instruction list (read-only, with live values,
// a tab beside its ladder), the Scan Debugger dock following the selected station, breakpoints
// set from the station's ladder or list (Ctrl+B, a click in the margin, Ctrl+Shift+B for a
// condition) and stepping with the main window's entries and keys (debug_entries.h: Ctrl+F12
// one instruction, Shift+F12 the rest of the scan, Ctrl+Shift+L back from the history). A
// breakpoint that holds stops the whole network (NetworkSession): the window is told to show that
// station, the place is marked in its ladder and list, and the status bar says which station holds.
// Breakpoints are kept by station, rung and place in the rung, so they outlive Stop (the network
// built again).

#include "app/gui/debug_entries.h"
#include "app/gui/simulation_controller.h"
#include "model/image/trigger.h"

#include <QObject>
#include <QPointer>

#include <map>
#include <vector>

class QAction;
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

class NetworkHistoryController;
class ScanDebuggerView;
class StationDebugSubject;

class NetworkDebugController : public QObject, public DebugCommands {
    Q_OBJECT

public:
    using BreakpointSpec = SimulationController::BreakpointSpec;
    struct StationParts {
        QString name;
        network::StationSource *source = nullptr;
        editor::Document *document = nullptr;
        editor::LadderView *ladder = nullptr;
    };
    // Adds the Instruction List tab to `tabs` and the Scan Debugger dock to `window`; Return to
    // Live leaves `history`'s past.
    NetworkDebugController(QMainWindow *window, QTabWidget *tabs, NetworkHistoryController *history,
                           QObject *parent = nullptr);
    ~NetworkDebugController() override;

    // The session and its stations' views (null, {}: none); before they are destroyed.
    void setSession(network::NetworkSession *session, const std::vector<StationParts> &stations);
    // The station the list and the debugger show.
    void selectStation(const QString &name);
    QString station() const { return m_current; }
    // The Simulation menu's debugging part: stepping, breakpoints, return to live, the debugger
    // dock.
    void addActions(QMenu *menu);
    void retranslate();

    ScanDebuggerView *scanDebugger() const { return m_debugger; }
    QDockWidget *scanDebuggerDock() const { return m_dock; }
    QWidget *listPage() const;
    editor::IlEditor *listView(const QString &station) const;
    // The station holding inside its scan, or the trigger's condition that stopped the network
    // while it stays paused, as the status bar says it ("" for none).
    QString heldText() const;

    // Breakpoints of a station by instruction (index in its program).
    bool toggleBreakpoint(const QString &station, int instruction);
    void setBreakpoint(const QString &station, int instruction, const BreakpointSpec &condition);
    void removeBreakpoint(const QString &station, int instruction);
    void clearBreakpoints() override; // every station's
    std::vector<BreakpointSpec> breakpoints(const QString &station) const;
    // Where the user is in the selected station: its list's line when it has the focus, else
    // its ladder cursor's rung.
    void toggleBreakpointHere() override;
    void editBreakpointConditionHere() override;
    void editBreakpointCondition(int instruction);
    void stepInstruction() override;
    void finishScan() override;
    void returnToLive() override;
    // The network's trigger: a condition on a station's device, written STATION/CONDITION
    // ("s2/D10 > 100", "master/X0 rises"), armed as that station's trigger
    // (model/image/trigger.h). With Stop it stops the whole network right after the scan in
    // which it becomes true, shown as a breakpoint's stop is (the station selected, the status
    // bar and heldText() naming it and the condition); with Mark the moment is only noted
    // (the timing chart marks it). One at a time, kept over Stop; Stop When... and the timing
    // chart's trigger set the same one. False with what is wrong in *error (the one before
    // stays armed); empty text: none.
    bool setTrigger(const QString &text, model::Trigger::Action action, QString *error);
    bool setStopCondition(const QString &text, QString *error); // with Stop
    QString stopCondition() const { return m_stopCondition; }
    model::Trigger::Action triggerAction() const { return m_triggerAction; }

signals:
    // A breakpoint held in this station, or its condition stopped the network: the window
    // shows it.
    void stationWanted(const QString &name);
    void message(const QString &text);
    // The trigger was armed, changed or cleared (stopCondition(), triggerAction()).
    void triggerChanged();
    // The trigger became true after this scan of its station; `stopped`: the network paused.
    void triggerFired(quint64 scan, qint64 timeMs, bool stopped);

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
    void updateReturnAction(); // enabled while the history is shown

    QMainWindow *m_window;
    QTabWidget *m_tabs;
    QPointer<NetworkHistoryController> m_history;
    QPointer<QAction> m_returnAction; // the menu's, made again with the menu
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
    model::Trigger::Action m_triggerAction = model::Trigger::Action::Stop;
    network::StationSource *m_stopSource = nullptr; // where it is armed
    QString m_triggerStop; // the condition that stopped the network, while it stays paused
};

} // namespace rung::app
