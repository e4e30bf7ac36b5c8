#pragma once

// A simulation as a MonitorSource: the engine scans on its own worker thread; device
// commands and power cycles go through the engine's command inbox (applied at the start of a
// scan, or at once while paused); snapshots are taken at most every
// MonitorSource::kMinSnapshotIntervalMs and after every step, and shared by all readers.
// The control calls (run, pause, stop, step, speed) return at once: the owner thread never
// waits for a scan. Chosen devices are recorded per scan in a HistoryRecorder.

#include "command_inbox.h"
#include "engine.h"

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

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    enum class Mode { Stopped, Paused, Running };

    void control(const std::function<void()> &change); // under the lock, wakes the worker
    void wakeWorker();
    void workerLoop();
    void publish(const Engine &engine);
    void reportErrors(const Engine &engine, std::size_t &reported);
    struct Fired { // a trigger that fired after a scan
        bool stop = false;
        quint64 generation = 0; // the control generation its pause made
        quint64 scan = 0;
        qint64 timeMs = 0;
    };
    // After a scan: records the history; a stopping trigger pauses the worker here.
    std::optional<Fired> recordHistory(const Engine &engine);
    void reportTrigger(const Fired &fired); // on the owner thread, after the snapshot

    std::shared_ptr<const Program> m_program;
    CommandInbox m_inbox;

    // Shared with the worker, under m_mutex.
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    Mode m_mode = Mode::Stopped;
    quint64 m_stepsLeft = 0;
    double m_speed = 1.0;
    qint64 m_periodMs = 0; // 0: the program's default
    bool m_recordFlow = false;
    bool m_quit = false;
    quint64 m_generation = 0; // bumped by every control change

    mutable std::mutex m_historyMutex;
    model::HistoryRecorder m_history;

    std::thread m_worker; // last: starts after everything it reads exists
};

} // namespace rung::simulator
