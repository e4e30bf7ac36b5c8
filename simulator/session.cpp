#include "simulator/session.h"

#include <QCoreApplication>

#include <chrono>

namespace rung::simulator {

namespace {

using Clock = std::chrono::steady_clock;

// The most real-time pacing catches up in a burst after falling behind (see workerLoop).
constexpr auto kMaxCatchUp = std::chrono::milliseconds(50);

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::SimulatorSession)
};

} // namespace

SimulatorSession::SimulatorSession(std::shared_ptr<const Program> program, QObject *parent)
    : MonitorSource(parent)
    , m_program(std::move(program))
    , m_inbox([this](quint64 id, bool ok, const QString &error) { finishCommand(id, ok, error); })
    , m_history(m_program->layout) {
    setRunState(RunState::Stopped);
    m_worker = std::thread([this] { workerLoop(); });
}

SimulatorSession::~SimulatorSession() {
    control([this] { m_quit = true; });
    m_worker.join();
}

void SimulatorSession::control(const std::function<void()> &change) {
    {
        std::lock_guard lock(m_mutex);
        change();
        ++m_generation;
    }
    m_wake.notify_all();
}

void SimulatorSession::wakeWorker() {
    // Taking the lock orders the post before the worker's check of pending(): no lost wake-up.
    { std::lock_guard lock(m_mutex); }
    m_wake.notify_all();
}

void SimulatorSession::run() {
    control([this] {
        m_mode = Mode::Running;
        m_stepsLeft = 0;
    });
    setRunState(RunState::Running);
}

void SimulatorSession::pause() {
    control([this] {
        if (m_mode == Mode::Running)
            m_mode = Mode::Paused;
        m_stepsLeft = 0;
    });
    if (runState() == RunState::Running || runState() == RunState::Stepping)
        setRunState(RunState::Paused);
}

void SimulatorSession::stop() {
    control([this] {
        m_mode = Mode::Stopped;
        m_stepsLeft = 0;
        // Through the inbox, so a command submitted before stop() is applied before the reset
        // (a force is then released by it) and one submitted after it applies to the fresh
        // image.
        m_inbox.post({0, Reset{}});
    });
    setRunState(RunState::Stopped);
}

void SimulatorSession::runScans(quint64 count) {
    if (count == 0)
        return;
    control([this, count] {
        m_mode = Mode::Paused;
        m_stepsLeft = count;
    });
    setRunState(RunState::Stepping);
}

void SimulatorSession::setSpeed(double factor) {
    control([this, factor] { m_speed = factor; });
}

double SimulatorSession::speed() const {
    std::lock_guard lock(m_mutex);
    return m_speed;
}

void SimulatorSession::setPeriodMs(qint64 periodMs) {
    control([this, periodMs] { m_periodMs = std::max<qint64>(1, periodMs); });
}

void SimulatorSession::setPowerFlowRecording(bool on) {
    control([this, on] { m_recordFlow = on; });
}

model::MonitorSource::CommandId SimulatorSession::powerCycle() {
    const CommandId id = nextCommandId();
    m_inbox.post({id, PowerCycle{}});
    wakeWorker();
    return id;
}

void SimulatorSession::startCommand(CommandId id, const model::DeviceCommand &command) {
    m_inbox.post({id, command});
    wakeWorker(); // a paused worker applies it at once
}

bool SimulatorSession::watchHistory(const model::Address &address) {
    std::lock_guard lock(m_historyMutex);
    return m_history.watch(address);
}

void SimulatorSession::readHistory(
    const std::function<void(const model::HistoryRecorder &)> &read) const {
    std::lock_guard lock(m_historyMutex);
    read(m_history);
}

bool SimulatorSession::setTrigger(std::optional<model::Trigger> trigger) {
    std::lock_guard lock(m_historyMutex);
    return m_history.setTrigger(std::move(trigger));
}

std::optional<SimulatorSession::Fired> SimulatorSession::recordHistory(const Engine &engine) {
    Fired fired;
    {
        std::lock_guard lock(m_historyMutex);
        if (m_history.deviceCount() == 0 ||
            !m_history.record(engine.statistics().scans, engine.statistics().timeMs,
                              engine.words().data()))
            return std::nullopt;
        fired.stop = m_history.trigger()->action == model::Trigger::Action::Stop;
    }
    fired.scan = engine.statistics().scans;
    fired.timeMs = engine.statistics().timeMs;
    if (fired.stop) {
        // Paused here, at the scan where the condition became true: the worker scans no
        // further, as a breakpoint would stop it. A control call made since (run again) wins.
        std::lock_guard lock(m_mutex);
        if (m_mode == Mode::Running)
            m_mode = Mode::Paused;
        m_stepsLeft = 0;
        fired.generation = ++m_generation;
    }
    return fired;
}

void SimulatorSession::reportTrigger(const Fired &fired) {
    postToOwner([this, fired] {
        if (fired.stop) {
            std::unique_lock lock(m_mutex);
            const bool current = m_generation == fired.generation;
            lock.unlock();
            if (current && (runState() == RunState::Running || runState() == RunState::Stepping))
                setRunState(RunState::Paused);
        }
        emit triggered(fired.scan, fired.timeMs);
    });
}

void SimulatorSession::publish(const Engine &engine) {
    publishSnapshot(std::make_shared<const Snapshot>(engine.snapshot()));
}

void SimulatorSession::reportErrors(const Engine &engine, std::size_t &reported) {
    const auto &errors = engine.runtimeErrors();
    if (errors.size() == reported)
        return;
    reported = errors.size();
    const RuntimeError &e = errors.back();
    const QString text = e.line > 0 ? Tr::tr("Line %1: %2").arg(e.line).arg(e.message) : e.message;
    postToOwner([this, text] { setErrorText(text); });
}

void SimulatorSession::workerLoop() {
    Engine engine(m_program);
    std::size_t errorsReported = 0;
    quint64 seen = ~quint64{0};
    // Real-time pacing: scan k is due when the wall clock has moved (virtual time - anchor's
    // virtual time) / speed past the anchor. Anchored again on every control change and every
    // reset, so a new mode never paces from an old engine clock.
    Clock::time_point paceWall;
    qint64 paceVirtualMs = 0;
    auto anchor = [&] {
        paceWall = Clock::now();
        paceVirtualMs = engine.statistics().timeMs;
    };
    Clock::time_point lastPublish;
    bool unpublished = false; // scans since the last snapshot
    auto publishNow = [&] {
        publish(engine);
        lastPublish = Clock::now();
        unpublished = false;
    };
    publishNow();
    for (;;) {
        bool scan = false, stepsDone = false;
        quint64 generation = 0;
        {
            std::unique_lock lock(m_mutex);
            for (;;) {
                if (m_quit)
                    return;
                if (m_generation != seen) {
                    // A control change: take the new settings, pace from here.
                    seen = m_generation;
                    if (m_periodMs > 0)
                        engine.setPeriodMs(m_periodMs);
                    engine.setPowerFlowRecording(m_recordFlow);
                    anchor();
                }
                if (m_inbox.pending())
                    break; // commands (stop's reset among them) before any scan, in every mode
                if (m_mode == Mode::Running || m_stepsLeft > 0) {
                    if (m_speed > 0) {
                        const double dueMs =
                            static_cast<double>(engine.statistics().timeMs - paceVirtualMs) /
                            m_speed;
                        const auto due =
                            paceWall + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double, std::milli>(dueMs));
                        const auto now = Clock::now();
                        if (now < due) {
                            m_wake.wait_until(lock, due);
                            continue;
                        }
                        // Behind by more than kMaxCatchUp (the machine stalled, or the engine
                        // cannot keep up with the speed factor): virtual time goes on from
                        // now instead of catching up in a burst of scans that would leave
                        // snapshots and history stale and peg a core. The burst is thus at
                        // most kMaxCatchUp's worth of scans.
                        if (now - due > kMaxCatchUp)
                            anchor();
                    }
                    scan = true;
                    if (m_stepsLeft > 0 && --m_stepsLeft == 0)
                        stepsDone = true;
                    generation = m_generation;
                    break;
                }
                if (unpublished)
                    break; // going idle: readers see the last scan
                m_wake.wait(lock);
            }
        }
        if (!scan && !m_inbox.pending()) {
            publishNow();
            continue;
        }
        if (!scan) {
            // Applied, published, then answered: a reader told that a command finished finds
            // its effect in the latest snapshot.
            if (m_inbox.apply(engine).reset) {
                errorsReported = 0;
                {
                    std::lock_guard lock(m_historyMutex);
                    m_history.clear();
                }
                postToOwner([this] { setErrorText({}); });
                anchor(); // the fresh engine's clock starts at 0
            }
            publishNow();
            m_inbox.complete();
            continue;
        }
        engine.scan();
        const std::optional<Fired> fired = recordHistory(engine);
        reportErrors(engine, errorsReported);
        unpublished = true;
        const auto now = Clock::now();
        if (fired || stepsDone ||
            now - lastPublish >= std::chrono::milliseconds(kMinSnapshotIntervalMs))
            publishNow();
        if (fired) // after the snapshot: a reader told finds that scan in it
            reportTrigger(*fired);
        if (stepsDone)
            postToOwner([this, generation] {
                // Only when no later control call (run, stop, ...) has changed the state.
                std::unique_lock lock(m_mutex);
                const bool current = m_generation == generation;
                lock.unlock();
                if (current && runState() == RunState::Stepping)
                    setRunState(RunState::Paused);
            });
    }
}

} // namespace rung::simulator
