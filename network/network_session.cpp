#include "network/network_session.h"

#include "network/station.h"
#include "network/tr.h"

#include <QFileInfo>

#include <chrono>
#include <utility>

namespace rung::network {

namespace {

using Clock = std::chrono::steady_clock;

// The most real-time pacing catches up in a burst after falling behind.
constexpr auto kMaxCatchUp = std::chrono::milliseconds(50);
// Snapshots twice a beat of the readers (MonitorSource), so the beat always finds a new one.
constexpr auto kPublishInterval =
    std::chrono::milliseconds(model::MonitorSource::kMinSnapshotIntervalMs / 2);

// The slice of virtual time the worker runs between two looks at its controls: the network's
// period, so every station scans about once a slice and commands apply within a scan.
qint64 sliceUs(const NetworkDescription &d) {
    return std::max<qint64>(1, d.periodMs) * 1000;
}

} // namespace

// ---- StationSource ------------------------------------------------------------------------

StationSource::StationSource(NetworkSession *session, const Station &station,
                             const QString &programPath)
    : MonitorSource(session)
    , m_session(session)
    , m_name(station.name())
    , m_target(&station.target())
    , m_model(station.model())
    , m_programPath(programPath)
    , m_inbox([this](quint64 id, bool ok, const QString &error) { finishCommand(id, ok, error); })
    , m_history(station.engine().program().layout) {
    std::map<QString, const model::PortApplication *> ports;
    for (const auto &[name, port] : station.ports())
        ports[port->config().port] = port->config().application;
    m_panelContext =
        model::panelContext(*m_target, m_model, QFileInfo(programPath).completeBaseName(), ports);
    setRunState(RunState::Stopped);
}

StationSource::~StationSource() = default;

bool StationSource::watchHistory(const model::Address &address) {
    std::lock_guard lock(m_historyMutex);
    return m_history.watch(address);
}

void StationSource::readHistory(
    const std::function<void(const model::HistoryRecorder &)> &read) const {
    std::lock_guard lock(m_historyMutex);
    read(m_history);
}

bool StationSource::setTrigger(std::optional<model::Trigger> trigger) {
    std::lock_guard lock(m_historyMutex);
    return m_history.setTrigger(std::move(trigger));
}

void StationSource::startCommand(CommandId id, const model::DeviceCommand &command) {
    m_inbox.post({id, command});
    // A paused worker applies it at once.
    m_session->control([] {});
}

// ---- NetworkSession -----------------------------------------------------------------------

std::unique_ptr<NetworkSession>
NetworkSession::start(const NetworkDescription &description, ProgramLoader loader, QString *error,
                      QObject *parent, const std::function<void(const Network &)> &learn) {
    std::unique_ptr<Network> network = Network::build(description, loader, error);
    if (!network)
        return nullptr;
    if (learn)
        learn(*network);
    return std::unique_ptr<NetworkSession>(
        new NetworkSession(description, std::move(loader), std::move(network), parent));
}

NetworkSession::NetworkSession(NetworkDescription description, ProgramLoader loader,
                               std::unique_ptr<Network> network, QObject *parent)
    : QObject(parent)
    , m_description(std::move(description))
    , m_loader(std::move(loader))
    , m_initial(std::move(network)) {
    for (std::size_t i = 0; i < m_initial->stations().size(); ++i) {
        const Station &s = *m_initial->stations()[i];
        const StationDescription *d = nullptr;
        for (const StationDescription &sd : m_description.stations)
            if (sd.name == s.name())
                d = &sd;
        m_sources.push_back(new StationSource(this, s, d ? d->path : QString()));
    }
    for (const auto &w : m_initial->wires()) {
        WireInfo info{w->name, {}};
        for (const Endpoint *e : w->ends)
            info.ends << e->name;
        m_wires.push_back(info);
    }
    attachTraffic(*m_initial);
    m_networkHistory->start(*m_initial);
    publish(*m_initial, false);
    m_worker = std::thread([this] { workerLoop(); });
}

NetworkSession::~NetworkSession() {
    if (m_bridgeLinesShown) // a bridge's connection being opened gives up: no wait for it
        m_bridgeLinesShown->cancelOpening();
    control([this] { m_quit = true; });
    m_worker.join();
}

StationSource *NetworkSession::station(const QString &name) const {
    for (StationSource *s : m_sources)
        if (s->stationName() == name)
            return s;
    return nullptr;
}

void NetworkSession::control(const std::function<void()> &change) {
    {
        std::lock_guard lock(m_mutex);
        change();
        ++m_generation;
    }
    m_wake.notify_all();
}

void NetworkSession::setRunState(RunState state) {
    if (m_runState == state)
        return;
    m_runState = state;
    for (StationSource *s : m_sources)
        s->setRunState(state);
    emit runStateChanged(state);
}

void NetworkSession::setError(const QString &text) {
    if (m_errorText == text)
        return;
    m_errorText = text;
    emit errorTextChanged(text);
}

void NetworkSession::run() {
    control([this] {
        m_mode = Mode::Running;
        m_budgetUs = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    setRunState(RunState::Running);
}

void NetworkSession::pause() {
    control([this] {
        if (m_mode == Mode::Running)
            m_mode = Mode::Paused;
        m_budgetUs = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    if (m_runState == RunState::Running || m_runState == RunState::Stepping)
        setRunState(RunState::Paused);
}

void NetworkSession::stop() {
    control([this] {
        m_mode = Mode::Stopped;
        m_budgetUs = 0;
        m_instructionSteps = 0;
        m_finishScan = false;
        m_reset = true;
        m_faults.clear();
    });
    m_faultsShown.clear();
    setRunState(RunState::Stopped);
}

void NetworkSession::singleScan() {
    runFor(std::max<qint64>(1, m_description.periodMs));
}

void NetworkSession::runFor(qint64 durationMs) {
    if (durationMs <= 0)
        return;
    control([this, durationMs] {
        m_mode = Mode::Paused;
        m_budgetUs = durationMs * 1000;
        m_instructionSteps = 0;
        m_finishScan = false;
    });
    setRunState(RunState::Stepping);
}

void NetworkSession::setPowerFlowStation(const QString &station) {
    control([this, station] { m_flowStation = station; });
}

void NetworkSession::setSpeed(double factor) {
    control([this, factor] { m_speed = factor; });
}

double NetworkSession::speed() const {
    std::lock_guard lock(m_mutex);
    return m_speed;
}

void NetworkSession::setWireCut(const QString &wire, bool cut) {
    const Fault f{Fault::Kind::Cut, wire, cut};
    std::erase_if(m_faultsShown,
                  [&](const Fault &o) { return o.kind == f.kind && o.target == wire; });
    if (cut)
        m_faultsShown.push_back(f);
    control([this, f] { m_faults.push_back(f); });
}

void NetworkSession::setSilent(const QString &stationOrDevice, bool silent) {
    const Fault f{Fault::Kind::Silent, stationOrDevice, silent};
    std::erase_if(m_faultsShown,
                  [&](const Fault &o) { return o.kind == f.kind && o.target == stationOrDevice; });
    if (silent)
        m_faultsShown.push_back(f);
    control([this, f] { m_faults.push_back(f); });
}

void NetworkSession::corruptNextFrame(const QString &wire, int byte, int mask) {
    control([this, wire, byte, mask] {
        m_faults.push_back(Fault{Fault::Kind::Corrupt, wire, true, byte, mask});
    });
}

void NetworkSession::setBaud(const QString &port, int baud) {
    const Fault f{Fault::Kind::Baud, port, true, 0, baud};
    std::erase_if(m_faultsShown,
                  [&](const Fault &o) { return o.kind == f.kind && o.target == port; });
    m_faultsShown.push_back(f);
    control([this, f] { m_faults.push_back(f); });
}

int NetworkSession::baudSet(const QString &port) const {
    for (const Fault &f : m_faultsShown)
        if (f.kind == Fault::Kind::Baud && f.target == port)
            return f.mask;
    return 0;
}

void NetworkSession::powerCycle() {
    for (StationSource *s : m_sources)
        s->m_inbox.post({0, simulator::PowerCycle{}});
    control([] {});
}

bool NetworkSession::wireCut(const QString &wire) const {
    return std::any_of(m_faultsShown.begin(), m_faultsShown.end(), [&](const Fault &f) {
        return f.kind == Fault::Kind::Cut && f.target == wire;
    });
}

bool NetworkSession::silent(const QString &stationOrDevice) const {
    return std::any_of(m_faultsShown.begin(), m_faultsShown.end(), [&](const Fault &f) {
        return f.kind == Fault::Kind::Silent && f.target == stationOrDevice;
    });
}

std::vector<TrafficRecord> NetworkSession::takeTraffic(bool *startedOver) {
    std::lock_guard lock(m_trafficMutex);
    m_trafficTold = false;
    if (startedOver)
        *startedOver = m_takenEpoch != m_trafficEpoch;
    m_takenEpoch = m_trafficEpoch;
    return std::exchange(m_traffic, {});
}

void NetworkSession::startBridges(std::shared_ptr<BridgeLines> lines) {
    m_bridgeLinesShown = lines;
    control([this, &lines] { m_bridgeLines = std::move(lines); });
}

void NetworkSession::postBridgeStatus(const std::vector<BridgeStatus> &status) {
    post([this, status] {
        m_bridgeStatus = status;
        emit bridgesChanged();
    });
}

void NetworkSession::post(std::function<void()> function) {
    bool first = false;
    {
        std::lock_guard lock(m_postMutex);
        first = m_posted.empty();
        m_posted.push_back(std::move(function));
    }
    if (first)
        QMetaObject::invokeMethod(this, "runPosted", Qt::QueuedConnection);
}

void NetworkSession::runPosted() {
    std::vector<std::function<void()>> posted;
    {
        std::lock_guard lock(m_postMutex);
        posted.swap(m_posted);
    }
    for (auto &f : posted)
        f();
}

void NetworkSession::attachTraffic(Network &network) {
    network.setTrafficSink([this](const TrafficRecord &r) {
        bool tell = false;
        {
            std::lock_guard lock(m_trafficMutex);
            m_traffic.push_back(r);
            tell = !std::exchange(m_trafficTold, true);
        }
        if (tell)
            post([this] { emit trafficAvailable(); });
    });
}

void NetworkSession::applyFaults(Network &network, std::vector<Fault> faults) {
    const qint64 nowMs = network.nowUs() / 1000;
    for (const Fault &f : faults) {
        FaultDescription d;
        d.fromMs = nowMs;
        d.where = NetworkSessionTr::tr("a fault made in the IDE");
        switch (f.kind) {
        case Fault::Kind::Cut:
        case Fault::Kind::Silent: {
            const auto kind = f.kind == Fault::Kind::Cut ? FaultDescription::Kind::Cut
                                                         : FaultDescription::Kind::Silent;
            network.endFaults(kind, f.target);
            if (f.on) {
                d.kind = kind;
                (kind == FaultDescription::Kind::Cut ? d.wire : d.station) = f.target;
                network.addFault(d);
            }
            break;
        }
        case Fault::Kind::Baud: {
            const qsizetype slash = f.target.indexOf(QLatin1Char('/'));
            Station *station = slash > 0 ? network.station(f.target.left(slash)) : nullptr;
            StationPort *port = station ? station->findPort(f.target.mid(slash + 1)) : nullptr;
            if (port) {
                model::SerialSettings line = port->line();
                line.baud = f.mask;
                port->setLine(line);
            }
            break;
        }
        case Fault::Kind::Corrupt:
            for (const auto &w : network.wires())
                if (w->name == f.target) {
                    d.kind = FaultDescription::Kind::Corrupt;
                    d.wire = f.target;
                    d.frame = w->frames; // the next transmission
                    d.byte = f.byte;
                    d.mask = f.mask;
                    network.addFault(d);
                }
            break;
        }
    }
}

void NetworkSession::publish(Network &network, bool answer) {
    for (std::size_t i = 0; i < m_sources.size() && i < network.stations().size(); ++i)
        m_sources[i]->publishSnapshot(
            std::make_shared<const model::Snapshot>(network.stations()[i]->snapshot()), answer);
    m_nowUs.store(network.nowUs(), std::memory_order_relaxed);
    const qint64 now = network.nowUs();
    post([this, now] { emit clockChanged(now); });
}

void NetworkSession::afterSlice(Network &network) {
    for (std::size_t i = 0; i < m_sources.size() && i < network.stations().size(); ++i) {
        StationSource &source = *m_sources[i];
        const simulator::Engine &engine = network.stations()[i]->engine();
        // The history is recorded after each scan (recordScan).
        const auto &errors = engine.runtimeErrors();
        if (errors.size() != source.m_errorsReported) {
            source.m_errorsReported = errors.size();
            const simulator::RuntimeError &e = errors.back();
            //: %1 station, %2 line, %3 what went wrong
            const QString text =
                e.line > 0 ? NetworkSessionTr::tr("%1: line %2: %3")
                                 .arg(source.stationName())
                                 .arg(e.line)
                                 .arg(e.message)
                           : NetworkSessionTr::tr("%1: %2").arg(source.stationName(), e.message);
            StationSource *s = &source;
            post([this, s, text] {
                s->setErrorText(text);
                setError(text);
            });
        }
    }
}

void NetworkSession::workerLoop() {
    std::unique_ptr<Network> network = std::move(m_initial);
    prepareNetwork(*network);
    const qint64 slice = sliceUs(m_description);
    quint64 seen = ~quint64{0};
    Clock::time_point paceWall;
    qint64 paceVirtualUs = 0;
    auto anchor = [&] {
        paceWall = Clock::now();
        paceVirtualUs = network->nowUs();
    };
    QString flowStation; // the worker's copy of m_flowStation, taken with the controls
    auto applyFlow = [&] {
        for (const auto &station : network->stations())
            station->engine().setPowerFlowRecording(station->name() == flowStation);
    };
    Clock::time_point lastPublish = Clock::now();
    bool unpublished = false;
    bool answerDue = false;
    for (;;) {
        bool reset = false;
        bool scan = false;
        bool stepsDone = false;
        quint64 generation = 0;
        DebugWork debug;
        std::vector<Fault> faults;
        qint64 until = 0;
        std::shared_ptr<BridgeLines> bridgeLines;
        {
            std::unique_lock lock(m_mutex);
            for (;;) {
                if (m_quit)
                    return;
                if (m_generation != seen) {
                    seen = m_generation;
                    anchor();
                    if (flowStation != m_flowStation) {
                        flowStation = m_flowStation;
                        applyFlow();
                    }
                }
                if (m_reset) {
                    m_reset = false;
                    reset = true;
                    break;
                }
                if (m_bridgeLines) {
                    bridgeLines = std::move(m_bridgeLines);
                    break;
                }
                if (takeDebugWork(&debug))
                    break;
                faults.swap(m_faults);
                bool commands = false;
                for (StationSource *s : m_sources)
                    commands = commands || s->m_inbox.pending();
                if (commands || !faults.empty())
                    break;
                if (m_mode == Mode::Running || m_budgetUs > 0) {
                    qint64 step = slice;
                    if (m_budgetUs > 0) {
                        step = std::min(step, m_budgetUs);
                        m_budgetUs -= step;
                        stepsDone = m_budgetUs == 0;
                    }
                    until = network->nowUs() + step;
                    if (m_speed > 0 && m_mode == Mode::Running) {
                        const double dueMs =
                            static_cast<double>(until - paceVirtualUs) / 1000.0 / m_speed;
                        const auto due =
                            paceWall + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double, std::milli>(dueMs));
                        const auto now = Clock::now();
                        if (now < due) {
                            m_wake.wait_until(lock, due);
                            continue;
                        }
                        if (now - due > kMaxCatchUp)
                            anchor();
                    }
                    scan = true;
                    generation = m_generation;
                    break;
                }
                if (unpublished)
                    break;
                m_wake.wait(lock);
            }
        }
        if (bridgeLines) {
            // Opened here, not on the owner thread: a port may take seconds to open.
            m_bridges =
                std::make_unique<SessionBridges>(std::move(bridgeLines), m_description.bridges);
            postBridgeStatus(m_bridges->attach(*network));
            continue;
        }
        if (reset) {
            QString error;
            std::unique_ptr<Network> fresh = Network::build(m_description, m_loader, &error);
            if (!fresh) {
                // The files changed under the network: it stays as it was, and says why.
                post([this, error] { setError(error); });
                continue;
            }
            network = std::move(fresh);
            applyFlow();
            {
                // What the old network sent is gone with it.
                std::lock_guard lock(m_trafficMutex);
                m_traffic.clear();
                ++m_trafficEpoch;
            }
            attachTraffic(*network);
            prepareNetwork(*network);
            if (m_bridges) // the same lines on the new network's wires
                postBridgeStatus(m_bridges->attach(*network));
            m_networkHistory->start(*network);
            for (StationSource *s : m_sources) {
                s->m_errorsReported = 0;
                s->m_scansRecorded = 0;
                std::lock_guard lock(s->m_historyMutex);
                s->m_history.clear();
            }
            for (StationSource *s : m_sources)
                post([s] { s->setErrorText({}); });
            post([this] { setError({}); });
            anchor();
            publish(*network, true);
            lastPublish = Clock::now();
            unpublished = false;
            continue;
        }
        if (debug.breakpoints || debug.step || debug.finish) {
            doDebugWork(*network, debug);
            lastPublish = Clock::now();
            unpublished = false;
            continue;
        }
        // Commands and faults take effect between two slices, at every station's scan
        // boundary.
        applyFaults(*network, std::move(faults));
        bool applied = false;
        for (std::size_t i = 0; i < m_sources.size() && i < network->stations().size(); ++i)
            if (m_sources[i]->m_inbox.pending()) {
                m_sources[i]->m_inbox.apply(network->stations()[i]->engine());
                applied = true;
            }
        if (applied) {
            m_networkHistory->record(*network, true);
            publish(*network, true);
            for (StationSource *s : m_sources)
                s->m_inbox.complete();
            lastPublish = Clock::now();
            unpublished = false;
            answerDue = true;
            continue;
        }
        if (!scan) {
            publish(*network, false);
            lastPublish = Clock::now();
            unpublished = false;
            continue;
        }
        const bool reached = runSlice(*network, until);
        if (m_bridges && m_bridges->poll(*network, [this] {
                std::lock_guard lock(m_mutex);
                return m_reset;
            }))
            postBridgeStatus(m_bridges->statuses());
        afterSlice(*network);
        // A station held inside its scan has a half-scanned image: the past is recorded when
        // the slice is whole.
        if (reached)
            m_networkHistory->record(*network, false);
        unpublished = true;
        const auto now = Clock::now();
        if (!reached || !m_fired.empty() || stepsDone || answerDue ||
            now - lastPublish >= kPublishInterval) {
            publish(*network, std::exchange(answerDue, false));
            lastPublish = now;
            unpublished = false;
        }
        reportTriggers(); // after the snapshot: a reader told finds that scan in it
        if (!reached)
            continue; // paused where it stopped (runSlice)
        if (stepsDone)
            post([this, generation] {
                std::unique_lock lock(m_mutex);
                const bool current = m_generation == generation;
                lock.unlock();
                if (current && m_runState == RunState::Stepping)
                    setRunState(RunState::Paused);
            });
    }
}

} // namespace rung::network
