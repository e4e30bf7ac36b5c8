#pragma once

// A simulation as a MonitorSource: the engine scans on its own worker thread; device
// commands and power cycles go through the engine's command inbox (applied at the start of a
// scan, or at once while paused); snapshots are taken twice a beat of the readers'
// notifications (MonitorSource::kMinSnapshotIntervalMs / 2), after every step, and at once
// after the scan that follows a command (an answer: readers are told without waiting for
// the beat); all readers share them.
// The control calls (run, pause, stop, step, speed) return at once: the owner thread never
// waits for a scan. Chosen devices are recorded per scan in a HistoryRecorder.

#include "command_inbox.h"
#include "engine.h"
#include "scan_history.h"

#include "model/image/history.h"
#include "model/image/monitor_source.h"

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace rung::simulator {

class SimulatorSession : public model::MonitorSource {
    Q_OBJECT

public:
    explicit SimulatorSession(std::shared_ptr<const Program> program, QObject *parent = nullptr);
    ~SimulatorSession() override; // stops the worker and waits for it

    void run();   // scan continuously, paced by the speed factor
    void pause(); // keep the image, stop scanning
    void stop();  // back to the power-on state, not scanning, forces released
    void singleScan() { runScans(1); }
    void runScans(quint64 count); // Stepping, then Paused
    // As many scans as fit in the virtual duration at the period then in force (at least one).
    void runFor(qint64 durationMs);
    // Inside a scan (docs/simulator.md "Breakpoints"): one instruction (at a scan boundary:
    // start a scan and stop before its first instruction), Stepping then Paused.
    void stepInstruction();
    // The rest of a stopped scan, breakpoints ignored; then Paused.
    void finishScan();
    // Replaces the breakpoints; a scan running on stops at them (Paused, breakpointHit). A
    // breakpoint the program cannot take is said by errorText and changes nothing.
    void setBreakpoints(std::vector<Breakpoint> breakpoints);
    // Online edit: the program runs from the next scan boundary (of a stopped scan: its END)
    // on, with the image kept and these breakpoints (its own instructions).
    CommandId replaceProgram(std::shared_ptr<const Program> program,
                             std::vector<Breakpoint> breakpoints = {});
    // Times real time (2.0 = twice as fast); 0 or less: as fast as the engine goes.
    void setSpeed(double factor);
    double speed() const;
    void setPeriodMs(qint64 periodMs); // virtual scan period, >= 1
    void setPowerFlowRecording(bool on);
    // Power off and on at the next scan boundary: retentive areas survive.
    CommandId powerCycle();

    // History (MonitorSource): the worker records after every scan under m_historyMutex, so
    // read must be quick. A trigger with Action::Stop pauses the worker right after the scan
    // where it fired, publishes that scan and reports triggered().
    bool watchHistory(const model::Address &address) override;
    void
    readHistory(const std::function<void(const model::HistoryRecorder &)> &read) const override;
    bool setTrigger(std::optional<model::Trigger> trigger) override;
    // The record from which any scan of the recent past is rebuilt (HistorySource).
    std::shared_ptr<const ScanHistory> scanHistory() const { return m_scanHistory; }

signals:
    // A breakpoint stopped the scan before `instruction` (the run state is Paused).
    void breakpointHit(int instruction);

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    enum class Mode { Stopped, Paused, Running };
    enum class Work { None, Commands, Scan, Step, Finish };

    void control(const std::function<void()> &change); // under the lock, wakes the worker
    void wakeWorker();
    void workerLoop();
    void publish(const Engine &engine, bool answer = false);
    // Worker: Paused now, told to the owner unless a control call came after this.
    void pauseFromWorker(int breakpoint);
    void reportErrors(const Engine &engine, std::size_t &reported);
    struct Fired { // a trigger that fired after a scan
        bool stop = false;
        quint64 generation = 0; // the control generation its pause made
        quint64 scan = 0;
        qint64 timeMs = 0;
    };
    // After a scan: records the history; a stopping trigger pauses the worker here.
    std::optional<Fired> recordHistory(const Engine &engine);
    // After a completed scan: the scan record (ScanHistory) and the history above.
    std::optional<Fired> afterScan(const Engine &engine);
    void reportTrigger(const Fired &fired); // on the owner thread, after the snapshot

    std::shared_ptr<const Program> m_program;
    CommandInbox m_inbox;

    // Shared with the worker, under m_mutex.
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    Mode m_mode = Mode::Stopped;
    quint64 m_stepsLeft = 0;
    quint64 m_instructionSteps = 0;
    bool m_finishScan = false;
    std::vector<Breakpoint> m_breakpoints;
    bool m_breakpointsChanged = false;
    double m_speed = 1.0;
    qint64 m_periodMs = 0; // 0: the program's default
    bool m_recordFlow = false;
    bool m_quit = false;
    quint64 m_generation = 0; // bumped by every control change

    mutable std::mutex m_historyMutex;
    model::HistoryRecorder m_history;
    std::shared_ptr<ScanHistory> m_scanHistory = std::make_shared<ScanHistory>();

    std::thread m_worker; // last: starts after everything it reads exists
};

} // namespace rung::simulator
