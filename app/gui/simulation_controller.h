#pragma once

// The IDE's simulation: compiles the program the document shows, runs it in a
// SimulatorSession (the engine on its own thread) and says what it is doing. The controller
// never simulates a program other than the one shown: an edit of the program drops the
// session (and says so), and Run compiles the edited program anew.

#include "model/checks/diagnostic.h"
#include "model/image/monitor_source.h"
#include "model/listing/il.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <vector>

namespace rung::editor {
class Document;
}
namespace rung::simulator {
class SimulatorSession;
}

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
    model::MonitorSource::RunState runState() const;

    // Each compiles the program first when there is no session; false (with problems() or
    // message()) when it cannot run.
    bool run();
    void pause();
    void stop(); // back to the power-on state
    bool singleScan();
    bool powerCycle();
    // Times real time; 0: as fast as the engine goes. Kept for the next session too.
    void setSpeed(double factor);
    double speed() const { return m_speed; }
    // The virtual scan period (>= 1 ms; the engine's default is 10), kept like the speed.
    void setPeriodMs(qint64 periodMs);
    qint64 periodMs() const { return m_periodMs; }
    void releaseAll(); // every forced device

    // The status line: run state, simulated time, scans, scan time (the virtual period) and
    // the evaluation time current/min/max.
    QString statusText() const;
    static QString statusText(model::MonitorSource::RunState state, double speed,
                              const model::Snapshot *snapshot);

signals:
    void sessionChanged(rung::simulator::SimulatorSession *session); // null: none any more
    void statusChanged();
    // Why the program does not start: the errors to show in the problems list.
    void problems(const std::vector<rung::model::Diagnostic> &diagnostics);
    void message(const QString &text);

private:
    bool ensureSession();
    void dropSession();
    void programChanged();

    editor::Document *m_document;
    std::function<QString()> m_blocker;
    std::unique_ptr<simulator::SimulatorSession> m_session;
    std::vector<model::Instruction> m_running; // the instructions the session was built from
    double m_speed = 1.0;
    qint64 m_periodMs = 10;
};

} // namespace rung::app
