#include "network/network_session.h"

#include "network/station.h"
#include "network/tr.h"

#include <utility>

// Breakpoints, stepping and triggers of a simulated network (network_session.h; docs/network.md
// "Breakpoints"). The network runs its stations' scans one at a time on one clock, each scan
// at an instant: when a station's scan holds inside (Station::holding), the network's run
// returns at that instant (Network::runUntil), so every other station is at its scan boundary
// by construction, and the clock stands until the held scan ends. Everything here but the
// control calls runs on the worker thread.

namespace rung::network {

// ---- control calls (owner thread) ----------------------------------------------------------

void NetworkSession::setBreakpoints(const QString &station,
                                    std::vector<simulator::Breakpoint> breakpoints) {
    control([this, &station, &breakpoints] {
        m_breakpoints[station] = std::move(breakpoints);
        m_breakpointsChanged = true;
    });
}

void NetworkSession::stepInstruction(const QString &station) {
    control([this, &station] {
        if (m_mode == Mode::Running || m_mode == Mode::Stopped)
            m_mode = Mode::Paused;
        m_budgetUs = 0;
        m_finishScan = false;
        ++m_instructionSteps;
        m_stepStation = station;
    });
    setRunState(RunState::Stepping);
}

void NetworkSession::finishScan() {
    control([this] {
        m_mode = Mode::Paused;
        m_budgetUs = 0;
        m_instructionSteps = 0;
        m_finishScan = true;
    });
    setRunState(RunState::Stepping);
}

QString NetworkSession::heldStation() const {
    for (const StationSource *s : m_sources) {
        const auto snapshot = s->snapshot();
        if (snapshot && snapshot->pause)
            return s->stationName();
    }
    return {};
}

// ---- the worker ----------------------------------------------------------------------------

bool NetworkSession::takeDebugWork(DebugWork *work) {
    // Under m_mutex (workerLoop's look at its controls).
    if (m_breakpointsChanged) {
        m_breakpointsChanged = false;
        work->breakpoints = true;
    }
    if (m_instructionSteps > 0) {
        --m_instructionSteps;
        work->step = true;
        work->stepStation = m_stepStation;
        work->stepsDone = m_instructionSteps == 0;
        work->generation = m_generation;
    } else if (m_finishScan) {
        m_finishScan = false;
        work->finish = true;
        work->stepsDone = true;
        work->generation = m_generation;
    }
    return work->breakpoints || work->step || work->finish;
}

void NetworkSession::prepareNetwork(Network &network) {
    m_fired.clear();
    m_stopFired = false;
    for (std::size_t i = 0; i < m_sources.size() && i < network.stations().size(); ++i) {
        StationSource *source = m_sources[i];
        Network *net = &network;
        network.stations()[i]->setScanHook(
            [this, net, source](Station &station) { recordScan(*net, *source, station); });
    }
    applyBreakpoints(network);
}

void NetworkSession::applyBreakpoints(Network &network) {
    std::map<QString, std::vector<simulator::Breakpoint>> wanted;
    {
        std::lock_guard lock(m_mutex);
        wanted = m_breakpoints;
    }
    for (const auto &station : network.stations()) {
        const auto found = wanted.find(station->name());
        QString error;
        if (!station->engine().setBreakpoints(
                found != wanted.end() ? found->second : std::vector<simulator::Breakpoint>{},
                &error)) {
            //: %1 station, %2 why its breakpoints were not taken
            const QString text = NetworkSessionTr::tr("%1: %2").arg(station->name(), error);
            post([this, text] { setError(text); });
        }
    }
}

void NetworkSession::recordScan(Network &network, StationSource &source, const Station &station) {
    const simulator::Engine &engine = station.engine();
    const quint64 scan = engine.statistics().scans;
    const qint64 timeMs = engine.statistics().timeMs;
    source.m_scansRecorded = scan;
    bool stop = false;
    {
        std::lock_guard lock(source.m_historyMutex);
        if (source.m_history.deviceCount() == 0) {
            source.m_history.scannedUnrecorded();
            return;
        }
        if (!source.m_history.record(scan, timeMs, engine.words().data()))
            return;
        stop = source.m_history.trigger()->action == model::Trigger::Action::Stop;
    }
    m_fired.push_back({&source, scan, timeMs});
    if (stop) {
        m_stopFired = true;
        network.interrupt(); // the network stops right after this scan
    }
}

void NetworkSession::reportTriggers() {
    for (const Fired &f : std::exchange(m_fired, {})) {
        StationSource *source = f.source;
        post([source, f] { emit source->triggered(f.scan, f.timeMs); });
    }
}

void NetworkSession::pauseFromWorker(const QString &station, int breakpoint) {
    quint64 generation = 0;
    {
        std::lock_guard lock(m_mutex);
        m_mode = Mode::Paused;
        m_budgetUs = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
        generation = ++m_generation;
    }
    post([this, generation, station, breakpoint] {
        // Only when no later control call (run, stop, ...) has changed the state.
        std::unique_lock lock(m_mutex);
        const bool current = m_generation == generation;
        lock.unlock();
        if (!current)
            return;
        setRunState(RunState::Paused);
        if (breakpoint >= 0)
            emit breakpointHit(station, breakpoint);
    });
}

bool NetworkSession::runSlice(Network &network, qint64 until) {
    m_stopFired = false;
    bool reached = false;
    Station *held = network.holdingStation();
    if (held && held->continueScan() == simulator::ScanStop::Breakpoint) {
        reached = false;
    } else if (std::exchange(m_stopFired, false)) {
        held = nullptr; // the held scan ended and its trigger stops the network there
    } else {
        reached = network.runUntil(until);
        held = network.holdingStation();
    }
    if (reached)
        return true;
    // A breakpoint holds, or a trigger stopped the network after its scan. The snapshots go
    // first: a reader told "Paused" finds the held scan in them (ThreadSanitizer's slower
    // worker let a test read the station before they came).
    publish(network, false);
    pauseFromWorker(held ? held->name() : QString(),
                    held ? held->engine().pausePosition()->breakpoint : -1);
    return false;
}

void NetworkSession::doDebugWork(Network &network, const DebugWork &work) {
    if (work.breakpoints)
        applyBreakpoints(network);
    bool stopped = false; // the network stopped on its way to the step (a breakpoint, a trigger)
    if (work.step) {
        if (Station *held = network.holdingStation()) {
            held->stepInstruction();
        } else if (Station *station = network.station(work.stepStation)) {
            // The network runs up to the station's next scan, which holds before its first
            // instruction; another station's breakpoint or a trigger may stop it first.
            station->setHoldAtNextScan(true);
            network.runUntil(station->nextUs());
            station->setHoldAtNextScan(false);
            Station *now = network.holdingStation();
            stopped = now != station;
            if (stopped) {
                publish(network, false); // before "Paused", as in runSlice
                pauseFromWorker(now ? now->name() : QString(),
                                now ? now->engine().pausePosition()->breakpoint : -1);
            }
            afterSlice(network);
        }
    } else if (work.finish) {
        if (Station *held = network.holdingStation())
            held->finishScan();
    }
    publish(network, false);
    reportTriggers();
    if (stopped || !(work.step || work.finish) || !work.stepsDone)
        return;
    const quint64 generation = work.generation;
    post([this, generation] {
        std::unique_lock lock(m_mutex);
        const bool current = m_generation == generation;
        lock.unlock();
        if (current && m_runState == RunState::Stepping)
            setRunState(RunState::Paused);
    });
}

} // namespace rung::network
