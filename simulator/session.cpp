#include "simulator/session.h"
#include "simulator/tr.h"

#include <QCoreApplication>

#include <chrono>
#include <utility>

namespace rung::simulator {

namespace {

using Clock = std::chrono::steady_clock;

// The most real-time pacing catches up in a burst after falling behind (see workerLoop).
constexpr auto kMaxCatchUp = std::chrono::milliseconds(50);

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
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    setRunState(RunState::Running);
}

void SimulatorSession::pause() {
    control([this] {
        if (m_mode == Mode::Running)
            m_mode = Mode::Paused;
        m_stepsLeft = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    if (runState() == RunState::Running || runState() == RunState::Stepping)
        setRunState(RunState::Paused);
}

void SimulatorSession::stop() {
    control([this] {
        m_mode = Mode::Stopped;
        m_stepsLeft = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
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
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    setRunState(RunState::Stepping);
}

void SimulatorSession::runFor(qint64 durationMs) {
    if (durationMs <= 0)
        return;
    control([this, durationMs] {
        const qint64 period = m_periodMs > 0 ? m_periodMs : 10;
        m_mode = Mode::Paused;
        m_stepsLeft = static_cast<quint64>(std::max<qint64>(1, durationMs / period));
    });
    setRunState(RunState::Stepping);
}

void SimulatorSession::stepInstruction() {
    control([this] {
        if (m_mode == Mode::Running || m_mode == Mode::Stopped)
            m_mode = Mode::Paused;
        m_stepsLeft = 0;
        ++m_instructionSteps;
    });
    setRunState(RunState::Stepping);
}

void SimulatorSession::finishScan() {
    control([this] {
        m_mode = Mode::Paused;
        m_stepsLeft = 0;
        m_instructionSteps = 0;
        m_finishScan = true;
    });
    setRunState(RunState::Stepping);
}

void SimulatorSession::setBreakpoints(std::vector<Breakpoint> breakpoints) {
    control([this, &breakpoints] {
        m_breakpoints = std::move(breakpoints);
        m_breakpointsChanged = true;
    });
}

model::MonitorSource::CommandId
SimulatorSession::replaceProgram(std::shared_ptr<const Program> program,
                                 std::vector<Breakpoint> breakpoints) {
    const CommandId id = nextCommandId();
    {
        // The breakpoints the worker sets from now on are the new program's.
        std::lock_guard lock(m_mutex);
        m_breakpoints = breakpoints;
        m_breakpointsChanged = false;
    }
    m_inbox.post({id, ReplaceProgram{std::move(program), std::move(breakpoints)}});
    wakeWorker();
    return id;
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
        if (m_history.deviceCount() == 0) {
            m_history.scannedUnrecorded();
            return std::nullopt;
        }
        if (!m_history.record(engine.statistics().scans, engine.statistics().timeMs,
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

void SimulatorSession::publish(const Engine &engine, bool answer) {
    publishSnapshot(std::make_shared<const Snapshot>(engine.snapshot()), answer);
}

void SimulatorSession::reportErrors(const Engine &engine, std::size_t &reported) {
    const auto &errors = engine.runtimeErrors();
    if (errors.size() == reported)
        return;
    reported = errors.size();
    const RuntimeError &e = errors.back();
    const QString text =
        e.line > 0 ? SimulatorSessionTr::tr("Line %1: %2").arg(e.line).arg(e.message) : e.message;
    postToOwner([this, text] { setErrorText(text); });
}

std::optional<SimulatorSession::Fired> SimulatorSession::afterScan(const Engine &engine) {
    m_scanHistory->afterScan(engine, engine.statistics().execNsCurrent);
    return recordHistory(engine);
}

void SimulatorSession::pauseFromWorker(int breakpoint) {
    quint64 generation = 0;
    {
        std::lock_guard lock(m_mutex);
        m_mode = Mode::Paused;
        m_stepsLeft = 0;
        m_instructionSteps = 0;
        generation = ++m_generation;
    }
    postToOwner([this, generation, breakpoint] {
        // Only when no later control call (run, stop, ...) has changed the state.
        std::unique_lock lock(m_mutex);
        const bool current = m_generation == generation;
        lock.unlock();
        if (!current)
            return;
        setRunState(RunState::Paused);
        if (breakpoint >= 0)
            emit breakpointHit(breakpoint);
    });
}

void SimulatorSession::workerLoop() {
    Engine engine(m_program);
    m_scanHistory->start(engine);
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
    // Commands were applied and no scan has run since: the next scan's snapshot answers them
    // (the coil an input drives) and is told at once.
    bool answerDue = false;
    auto publishNow = [&](bool answer = false) {
        publish(engine, answer);
        lastPublish = Clock::now();
        unpublished = false;
    };
    // Twice a beat: the readers' beat (MonitorSource) then always finds a snapshot newer
    // than the last it told, and keeps its 30 a second.
    constexpr auto kPublishInterval = std::chrono::milliseconds(kMinSnapshotIntervalMs / 2);
    publishNow();
    for (;;) {
        Work work = Work::None;
        bool stepsDone = false;
        quint64 generation = 0;
        QString breakpointError;
        {
            std::unique_lock lock(m_mutex);
            for (;;) {
                if (m_quit)
                    return;
                if (m_generation != seen) {
                    // A control change: take the new settings, pace from here.
                    seen = m_generation;
                    if (m_periodMs > 0 && engine.periodMs() != m_periodMs) {
                        m_scanHistory->record(engine, ScanHistory::SetPeriod{m_periodMs});
                        engine.setPeriodMs(m_periodMs);
                    }
                    engine.setPowerFlowRecording(m_recordFlow);
                    if (m_breakpointsChanged) {
                        m_breakpointsChanged = false;
                        if (!engine.setBreakpoints(m_breakpoints, &breakpointError))
                            break;
                    }
                    anchor();
                }
                if (m_inbox.pending()) {
                    work = Work::Commands; // stop's reset among them, before any scan
                    break;
                }
                if (m_instructionSteps > 0) {
                    --m_instructionSteps;
                    work = Work::Step;
                    stepsDone = m_instructionSteps == 0;
                    generation = m_generation;
                    break;
                }
                if (m_finishScan) {
                    m_finishScan = false;
                    work = Work::Finish;
                    generation = m_generation;
                    break;
                }
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
                    work = Work::Scan;
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
        if (!breakpointError.isEmpty()) {
            postToOwner([this, breakpointError] { setErrorText(breakpointError); });
            continue;
        }
        switch (work) {
        case Work::None:
            publishNow();
            continue;
        case Work::Commands: {
            // Applied, published, then answered: a reader told that a command finished finds
            // its effect in the latest snapshot. The history records each as it comes (a
            // stop's reset starts it again: the past before it is another run).
            bool restart = false;
            const auto applied = m_inbox.apply(engine, [&](const EngineCommand &c) {
                if (restart)
                    m_scanHistory->start(engine);
                restart = std::holds_alternative<Reset>(c.what);
                if (!restart)
                    m_scanHistory->record(engine, c);
            });
            if (restart)
                m_scanHistory->start(engine);
            if (applied.reset) {
                errorsReported = 0;
                {
                    std::lock_guard lock(m_historyMutex);
                    m_history.clear();
                }
                postToOwner([this] { setErrorText({}); });
                anchor(); // the fresh engine's clock starts at 0
            }
            publishNow(true); // the input's own state shows at once too
            m_inbox.complete();
            answerDue = true;
            continue;
        }
        case Work::Step:
        case Work::Finish: {
            const bool completed = work == Work::Step
                                       ? engine.stepInstruction() == ScanStop::Completed
                                       : engine.insideScan() && (engine.scan(), true);
            const std::optional<Fired> fired =
                completed ? afterScan(engine) : std::optional<Fired>{};
            reportErrors(engine, errorsReported);
            publishNow();
            if (fired)
                reportTrigger(*fired);
            if (work == Work::Finish || stepsDone)
                postToOwner([this, generation] {
                    std::unique_lock lock(m_mutex);
                    const bool current = m_generation == generation;
                    lock.unlock();
                    if (current && runState() == RunState::Stepping)
                        setRunState(RunState::Paused);
                });
            continue;
        }
        case Work::Scan:
            break;
        }
        if (engine.scanToBreakpoint() == ScanStop::Breakpoint) {
            publishNow();
            pauseFromWorker(engine.stoppedAt());
            continue;
        }
        const std::optional<Fired> fired = afterScan(engine);
        reportErrors(engine, errorsReported);
        unpublished = true;
        const auto now = Clock::now();
        if (fired || stepsDone || answerDue || now - lastPublish >= kPublishInterval)
            publishNow(std::exchange(answerDue, false));
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
