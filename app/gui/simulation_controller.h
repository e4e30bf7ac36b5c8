#pragma once

// The IDE's simulation: compiles the program the document shows, runs it in a
// SimulatorSession (the engine on its own thread) and says what it is doing. An edit of the
// program while it is simulated is an online edit: it takes over at the next scan boundary
// with the memory image kept; an edit that cannot keep the image or that changes the timers
// and counters used asks first (setAsker). Breakpoints and stepping (simulation_debug.cpp)
// and the history of past scans (simulation_history.cpp) live here too.

#include "model/checks/diagnostic.h"
#include "model/image/monitor_source.h"
#include "model/listing/il.h"
#include "simulator/engine.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace rung::editor {
class Document;
}
namespace rung::simulator {
class HistorySource;
class SimulatorSession;
struct EditImpact;
} // namespace rung::simulator

namespace rung::app {

class SimulationController : public QObject {
    Q_OBJECT

public:
    explicit SimulationController(editor::Document *document, QObject *parent = nullptr);
    ~SimulationController() override;

    // Says what stands in the way of simulating what the user sees (the list as typed has
    // errors the program did not take); empty when nothing does.
    void setBlocker(std::function<QString()> blocker) { m_blocker = std::move(blocker); }

    // Null until the program is compiled for a run, a scan or a power cycle.
    simulator::SimulatorSession *session() const { return m_session.get(); }
    // What the views show: the history while a past scan is shown, else the session (null:
    // none).
    model::MonitorSource *monitorSource() const;
    model::MonitorSource::RunState runState() const;

    // Each compiles the program first when there is no session; false (with problems() or
    // message()) when it cannot run.
    bool run();
    void pause();
    void stop(); // back to the power-on state
    bool singleScan();
    bool runScans(quint64 count);   // Stepping, then Paused
    bool runFor(qint64 durationMs); // virtual time: as many scans as fit in it
    bool powerCycle();
    // Times real time; 0: as fast as the engine goes. Kept for the next session too.
    void setSpeed(double factor);
    double speed() const { return m_speed; }
    // The virtual scan period (>= 1 ms; the engine's default is 10), kept like the speed.
    void setPeriodMs(qint64 periodMs);
    qint64 periodMs() const { return m_periodMs; }
    void releaseAll(); // every forced device

    // Breakpoints (simulation_debug.cpp). One sits on an instruction, kept as its rung and
    // place in the rung so an edit elsewhere does not move it; a rung's breakpoint is on its
    // first instruction. They outlive the session.
    struct BreakpointSpec {
        int rung = 0;
        int offset = 0; // instructions after the rung's first
        simulator::Breakpoint::When when = simulator::Breakpoint::When::Always;
        model::Address device;
        model::CompareOp op = model::CompareOp::Gt;
        qint64 value = 0;
        friend bool operator==(const BreakpointSpec &, const BreakpointSpec &) = default;
    };
    const std::vector<BreakpointSpec> &breakpoints() const { return m_breakpoints; }
    // The instruction (index in the listing) a breakpoint stands on; -1 when the program no
    // longer has it.
    int instructionOf(const BreakpointSpec &b) const;
    // The same against any program's rungs (ProgramListing::rungFirst); a network's stations
    // keep their breakpoints so too.
    static int instructionOf(const std::vector<int> &rungFirst, const BreakpointSpec &b);
    // The breakpoint on `instruction` of a program with these rungs, at its rung and place.
    static std::optional<BreakpointSpec> placeBreakpoint(const std::vector<int> &rungFirst,
                                                         int instruction,
                                                         const BreakpointSpec &condition);
    // The engine's breakpoints for these (those whose rung is too short now wait).
    static std::vector<simulator::Breakpoint>
    engineBreakpoints(const std::vector<int> &rungFirst, const std::vector<BreakpointSpec> &all);
    // Sets a plain breakpoint on the instruction, or clears the one there; true when set.
    bool toggleBreakpoint(int instruction);
    void setBreakpoint(int instruction, const BreakpointSpec &condition);
    void removeBreakpoint(int instruction);
    void clearBreakpoints();
    // The breakpoint on an instruction, if any.
    const BreakpointSpec *breakpointAt(int instruction) const;
    // "when Y0 rises", "when D10 > 100", "always" (translated), for lists and tooltips.
    QString conditionText(const BreakpointSpec &b) const;
    static QString conditionText(const model::Target &target, const BreakpointSpec &b);
    // Inside a scan: one instruction; the rest of the scan.
    bool stepInstruction();
    void finishScan();

    // History (simulation_history.cpp): shows the state after a past scan in place of the
    // live session (read-only, marked "History: scan N (time)") until returnToLive().
    bool historyShown() const { return m_historySource != nullptr; }
    simulator::HistorySource *historySource() const { return m_historySource.get(); }
    void showHistoryScan(quint64 scan);
    // "History: scan N (time)", empty while live.
    QString historyText() const;
    // The recorded window, for the user: "the last 1:00:00 of simulated time (scans
    // 12..360012, 2.1 MB)".
    QString historyWindowText() const;

    // Asks the user about an online edit that cannot keep things as they are; returns the
    // choice. The main window shows a dialog; tests answer directly.
    enum class EditChoice { KeepImage, Restart, StopSimulation };
    using Asker = std::function<EditChoice(const QString &question, bool canKeep)>;
    void setAsker(Asker asker) { m_asker = std::move(asker); }

public slots:
    // The chart's cursor on a past time (virtual ms): the views show the scan at that time.
    void showHistoryAt(qint64 timeMs);
    void returnToLive();
    // The status line: run state, simulated time, scans, scan time (the virtual period).
    QString statusText() const;
    static QString statusText(model::MonitorSource::RunState state, double speed,
                              const model::Snapshot *snapshot);
    // "Evaluation of a scan on this computer: 2.5 µs (1.0..9.9)"; empty without a snapshot.
    static QString evaluationText(const model::Snapshot *snapshot);
    // The status line and the evaluation, for its tooltip.
    QString statusToolTip() const;
    // Virtual time as h:mm:ss.cc, the same in every language.
    static QString clockText(qint64 ms);

signals:
    void sessionChanged(rung::simulator::SimulatorSession *session); // null: none any more
    // The source the views are to show changed (live session, history, or none).
    void monitorSourceChanged(rung::model::MonitorSource *source);
    void breakpointsChanged();
    // A stopped scan's position changed (or it ended: instruction -1).
    void stoppedAtChanged(int instruction);
    void statusChanged();
    // Why the program does not start: the errors to show in the problems list.
    void problems(const std::vector<rung::model::Diagnostic> &diagnostics);
    void message(const QString &text);

private:
    bool ensureSession();
    void dropSession();
    void programChanged();
    void sendBreakpoints();
    std::vector<simulator::Breakpoint> engineBreakpoints() const;
    void watchStoppedAt();
    QString editQuestion(const simulator::EditImpact &impact) const;

    editor::Document *m_document;
    std::function<QString()> m_blocker;
    std::unique_ptr<simulator::SimulatorSession> m_session;
    std::vector<model::Instruction> m_running; // the instructions the session was built from
    std::shared_ptr<const simulator::Program> m_runningProgram;
    // The shown program did not compile (an edit with errors): the session runs the one
    // before it.
    bool m_stale = false;
    double m_speed = 1.0;
    qint64 m_periodMs = 10;
    std::vector<BreakpointSpec> m_breakpoints;
    int m_stoppedAt = -1;
    std::unique_ptr<simulator::HistorySource> m_historySource;
    Asker m_asker;
};

} // namespace rung::app
