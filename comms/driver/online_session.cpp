#include "comms/driver/online_session.h"

#include "comms/driver/driver.h"
#include "model/target/target.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <algorithm>

namespace rung::comms {

namespace {

constexpr int kSignalIntervalMs = 200; // statistics and traffic: a few times a second

model::MonitorSource::RunState runStateOf(PlcMode mode) {
    switch (mode) {
    case PlcMode::Stop:
    case PlcMode::Program:
        return model::MonitorSource::RunState::Stopped;
    default:
        return model::MonitorSource::RunState::Running;
    }
}

} // namespace

OnlineSession::OnlineSession(const model::Target &target, ConnectionSettings settings,
                             QObject *parent, TransportFactory factory)
    : MonitorSource(parent)
    , m_target(target)
    , m_settings(std::move(settings))
    , m_factory(std::move(factory))
    , m_layout(std::make_shared<const model::MemoryLayout>(target))
    , m_history(m_layout) {
    setRunState(RunState::Offline);
    connect(this, &MonitorSource::watchedChanged, this, [this] {
        const std::vector<model::Address> devices = watched();
        control([&] {
            m_watched = devices;
            m_watchedDirty = true;
        });
    });
    m_worker = std::thread([this] { workerLoop(); });
}

OnlineSession::~OnlineSession() {
    control([this] { m_quit = true; });
    m_worker.join();
}

void OnlineSession::control(const std::function<void()> &change) {
    {
        std::lock_guard lock(m_mutex);
        change();
        // A read that waits for the PLC ends at once: the worker looks at the change.
        if (m_activeLink && (m_quit || !m_wanted))
            m_activeLink->cancel();
    }
    m_wake.notify_all();
}

void OnlineSession::connectToPlc() {
    if (m_state == ConnectionState::Disconnected || m_state == ConnectionState::Failed) {
        m_state = ConnectionState::Connecting;
        emit connectionStateChanged(m_state);
    }
    control([this] { m_wanted = true; });
}

void OnlineSession::disconnectFromPlc() {
    control([this] { m_wanted = false; });
}

QString OnlineSession::plcName() const {
    std::lock_guard lock(m_mutex);
    return m_plcName.isEmpty()
               ? QStringLiteral("%1 (%2)").arg(m_target.displayName, m_settings.where())
               : m_plcName;
}

OnlineSession::Abilities OnlineSession::abilities() const {
    std::lock_guard lock(m_mutex);
    return m_abilities;
}

QString OnlineSession::forceRefusal() const {
    QString name;
    {
        std::lock_guard lock(m_mutex);
        if (m_abilities.forces || m_plcName.isEmpty())
            return {}; // can force, or not known yet (a force then says why it was refused)
        name = m_plcName;
    }
    return QCoreApplication::translate("rung::comms::Driver",
                                       "%1 cannot force bits: its protocol has no force command. "
                                       "Set the bit instead (the program may overwrite it).")
        .arg(name);
}

LinkStatistics OnlineSession::statistics() const {
    std::lock_guard lock(m_mutex);
    return m_statistics;
}

std::vector<TrafficRecord> OnlineSession::traffic(quint64 from, quint64 *next) const {
    return m_traffic.records(from, next);
}

void OnlineSession::setTrafficTap(bool on) {
    m_traffic.setEnabled(on);
}

QString OnlineSession::notConnected() const {
    return QCoreApplication::translate("rung::comms::Driver",
                                       "%1 is not connected: nothing was sent")
        .arg(plcName());
}

void OnlineSession::startCommand(CommandId id, const model::DeviceCommand &command) {
    bool accepted = false;
    control([&] {
        accepted = m_wanted;
        if (accepted)
            m_pending.push_back({id, false, command, PlcMode::Unknown});
    });
    if (!accepted)
        finishCommand(id, false, notConnected());
}

model::MonitorSource::CommandId OnlineSession::setPlcMode(PlcMode mode) {
    const CommandId id = nextCommandId();
    bool accepted = false;
    control([&] {
        accepted = m_wanted;
        if (accepted)
            m_pending.push_back({id, true, {}, mode});
    });
    if (!accepted)
        finishCommand(id, false, notConnected());
    return id;
}

bool OnlineSession::waitFor(std::unique_lock<std::mutex> &lock, int ms) {
    // Wakes early for a command, a change of the watched devices, disconnect or quit.
    const auto due = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
    m_wake.wait_until(
        lock, due, [this] { return m_quit || !m_wanted || !m_pending.empty() || m_watchedDirty; });
    return !m_quit;
}

void OnlineSession::failPending(const QString &why) {
    std::deque<Pending> pending;
    {
        std::lock_guard lock(m_mutex);
        pending.swap(m_pending);
    }
    for (const Pending &p : pending)
        finishCommand(p.id, false, why);
}

void OnlineSession::publish(const std::vector<std::int32_t> &words, bool stale,
                            const std::map<model::Address, bool> &forced,
                            const model::ScanStatistics &statistics,
                            std::shared_ptr<const std::vector<bool>> wordsRead) {
    auto s = std::make_shared<model::Snapshot>();
    s->wordsRead = std::move(wordsRead);
    s->layout = m_layout;
    s->words = words;
    s->stale = stale;
    s->statistics = statistics;
    // The bits this session forced (Host Link has no command that lists them).
    if (!forced.empty()) {
        s->forceMask.assign(words.size(), 0);
        s->forceValue.assign(words.size(), 0);
        for (const auto &[address, on] : forced) {
            const model::BitRef ref = m_layout->bit(address);
            if (!ref.valid() || std::size_t(ref.word) >= words.size())
                continue;
            s->forceMask[std::size_t(ref.word)] |= ref.mask;
            if (on)
                s->forceValue[std::size_t(ref.word)] |= ref.mask;
        }
    }
    publishSnapshot(std::move(s));
}

bool OnlineSession::watchHistory(const model::Address &address) {
    std::lock_guard lock(m_historyMutex);
    if (m_history.wordOf(address) < 0)
        return false;
    if (std::find(m_historyPending.begin(), m_historyPending.end(), address) ==
        m_historyPending.end())
        m_historyPending.push_back(address);
    return true;
}

void OnlineSession::readHistory(
    const std::function<void(const model::HistoryRecorder &)> &read) const {
    std::lock_guard lock(m_historyMutex);
    read(m_history);
}

bool OnlineSession::setTrigger(std::optional<model::Trigger> trigger) {
    if (trigger)
        trigger->action = model::Trigger::Action::Mark; // a PLC does not stop for the chart
    std::lock_guard lock(m_historyMutex);
    return m_history.setTrigger(std::move(trigger));
}

void OnlineSession::recordHistory(const std::vector<std::int32_t> &words,
                                  const std::vector<bool> *wordsRead,
                                  const model::ScanStatistics &statistics) {
    bool fired = false;
    {
        std::lock_guard lock(m_historyMutex);
        std::erase_if(m_historyPending, [&](const model::Address &a) {
            const int word = m_history.wordOf(a);
            if (!wordsRead || word < 0 || std::size_t(word) >= wordsRead->size() ||
                !(*wordsRead)[std::size_t(word)])
                return false;
            m_history.watch(a);
            return true;
        });
        if (m_history.deviceCount() == 0)
            return;
        fired = m_history.record(statistics.scans, statistics.timeMs, words.data());
    }
    if (fired)
        postToOwner([this, scan = statistics.scans, time = statistics.timeMs] {
            emit triggered(scan, time);
        });
}

void OnlineSession::postState(ConnectionState state, const QString &error) {
    postToOwner([this, state, error] {
        setErrorText(error);
        if (state != ConnectionState::Online)
            setRunState(RunState::Offline);
        else
            setRunState(runStateOf(m_mode));
        if (state != m_state) {
            m_state = state;
            emit connectionStateChanged(state);
        }
    });
}

void OnlineSession::postMode(PlcMode mode) {
    postToOwner([this, mode] {
        if (m_state == ConnectionState::Online)
            setRunState(runStateOf(mode));
        if (mode != m_mode) {
            m_mode = mode;
            emit plcModeChanged(mode);
        }
    });
}

void OnlineSession::postStatistics() {
    postToOwner([this] { emit statisticsChanged(); });
}

namespace {

// After a refresh: the words its plan placed, but those of devices the PLC refused.
void markRead(const Driver::Plan &plan,
              const std::vector<std::pair<model::Address, QString>> &refused,
              std::shared_ptr<const std::vector<bool>> &wordsRead) {
    std::shared_ptr<std::vector<bool>> more;
    for (std::size_t d = 0; d < plan.devices.size(); ++d) {
        if (std::any_of(refused.begin(), refused.end(),
                        [&](const auto &r) { return r.first == plan.devices[d]; }))
            continue;
        for (const Driver::Placement &p : plan.placements[d]) {
            const auto word = std::size_t(p.word);
            if (p.word < 0 || word >= wordsRead->size() || (*wordsRead)[word])
                continue;
            if (!more)
                more = std::make_shared<std::vector<bool>>(*wordsRead);
            (*more)[word] = true;
        }
    }
    if (more)
        wordsRead = std::move(more);
}

} // namespace

void OnlineSession::workerLoop() {
    std::unique_ptr<Driver> driver;
    Driver::Plan plan;
    std::vector<std::int32_t> words(std::size_t(m_layout->wordCount()), 0);
    // The words the PLC answered for (Snapshot::wordsRead): shared by every snapshot until
    // a refresh reads one more.
    auto wordsRead = std::make_shared<const std::vector<bool>>(words.size(), false);
    std::vector<model::Address> refused; // devices the PLC refused: not asked for again
    QStringList problems;                // why some watched devices show nothing
    QString problemsPosted;              // what the owner was last told of them
    bool haveValues = false;
    bool everUp = false;
    bool up = false;
    int backoff = m_settings.reconnectMinMs;
    QElapsedTimer modeClock, signalClock, connectedClock;
    model::ScanStatistics figures;
    figures.periodMs = 0;
    quint64 trafficSeen = 0;
    PlcMode mode = PlcMode::Unknown;

    const auto problemText = [&problems] {
        return problems.isEmpty() ? QString() : problems.join(QLatin1Char('\n'));
    };
    const auto shareStatistics = [&](bool force) {
        if (!driver ||
            (!force && signalClock.isValid() && signalClock.elapsed() < kSignalIntervalMs))
            return;
        signalClock.restart();
        {
            std::lock_guard lock(m_mutex);
            m_statistics = driver->link().statistics();
        }
        postStatistics();
        quint64 next = 0;
        m_traffic.records(~quint64{0}, &next);
        if (next != trafficSeen) {
            trafficSeen = next;
            postToOwner([this] { emit trafficAvailable(); });
        }
    };
    // The link is down or silent: say so at once, keep the last values (stale), and wait
    // before trying again, longer each time.
    const auto lose = [&](const DriverError &e) -> bool {
        if (e.kind == DriverError::Kind::LinkDown)
            driver->link().close(); // opened again on the next try
        up = false;
        if (haveValues)
            publish(words, true, driver->forced(), figures, wordsRead);
        // Said once: a driver's message names the PLC already, a port's does not.
        const QString where = driver->plcName();
        const QString text =
            !everUp ? QCoreApplication::translate("rung::comms::Driver",
                                                  "Cannot reach %1: %2. Trying again.")
                          .arg(where, e.message)
            : e.message.contains(where)
                ? QCoreApplication::translate("rung::comms::Driver",
                                              "Connection lost: %1. Trying again.")
                      .arg(e.message)
                : QCoreApplication::translate("rung::comms::Driver",
                                              "Connection to %1 lost: %2. Trying again.")
                      .arg(where, e.message);
        postState(everUp ? ConnectionState::Lost : ConnectionState::Connecting, text);
        failPending(text);
        shareStatistics(true);
        std::unique_lock lock(m_mutex);
        const bool go = waitFor(lock, backoff);
        backoff = std::min(backoff * 2, std::max(m_settings.reconnectMaxMs, 1));
        return go;
    };

    for (;;) {
        bool wanted = false, dirty = false;
        std::vector<model::Address> watchedNow;
        {
            std::lock_guard lock(m_mutex);
            if (m_quit)
                break;
            wanted = m_wanted;
            if (m_watchedDirty) {
                dirty = true;
                watchedNow = m_watched;
                m_watchedDirty = false;
            }
        }
        if (!wanted) {
            if (driver) {
                shareStatistics(true);
                {
                    std::lock_guard lock(m_mutex);
                    m_activeLink = nullptr;
                }
                if (haveValues)
                    publish(words, true, driver->forced(), figures, wordsRead);
                driver->link().close();
                driver.reset();
                postState(ConnectionState::Disconnected, {});
            }
            up = everUp = false;
            failPending(notConnected());
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_quit || m_wanted || !m_pending.empty(); });
            continue;
        }
        if (!driver) {
            QString error;
            auto transport = m_factory ? m_factory() : makeTransport(m_settings);
            driver = Driver::create(m_target, m_settings.protocol, std::move(transport),
                                    m_settings.station, lineTiming(m_settings), &error);
            if (!driver) {
                const QString text =
                    QCoreApplication::translate("rung::comms::Driver", "Cannot connect to %1: %2")
                        .arg(m_target.displayName, error);
                postState(ConnectionState::Failed, text);
                failPending(text);
                std::lock_guard lock(m_mutex);
                m_wanted = false;
                continue;
            }
            driver->link().setTap(&m_traffic);
            figures = {};
            figures.periodMs = 0;
            connectedClock.invalidate();
            {
                std::lock_guard lock(m_mutex);
                m_activeLink = &driver->link();
                m_plcName = driver->plcName();
                m_abilities = {driver->canSetMode(), driver->hasMonitorMode(), driver->canForce()};
            }
            backoff = m_settings.reconnectMinMs;
            dirty = true;
            {
                std::lock_guard lock(m_mutex);
                watchedNow = m_watched;
                m_watchedDirty = false;
            }
        }
        if (dirty) {
            std::vector<model::Address> devices = watchedNow;
            if (driver->runStateDevice().valid())
                devices.push_back(driver->runStateDevice());
            std::sort(devices.begin(), devices.end());
            devices.erase(std::unique(devices.begin(), devices.end()), devices.end());
            refused.clear();
            plan = driver->plan(devices);
            problems.clear();
            for (const auto &[address, why] : plan.unmapped)
                problems << why;
        }
        if (!driver->link().isOpen()) {
            QString error;
            if (!driver->link().open(&error)) {
                if (!lose({DriverError::Kind::LinkDown, 0, error}))
                    break;
                continue;
            }
        }
        // First contact on this connection: who is there.
        if (!everUp && driver->protocol().identifies()) {
            PlcIdentity identity;
            DriverError e = driver->identify(&identity);
            if (e.kind == DriverError::Kind::Cancelled)
                continue;
            if (!e.ok() && e.kind != DriverError::Kind::Refused) {
                if (!lose(e))
                    break;
                continue;
            }
            postToOwner([this, identity] {
                m_identity = identity;
                emit identityChanged();
            });
        }
        // Commands first: the user waits for them.
        std::deque<Pending> pending;
        {
            std::lock_guard lock(m_mutex);
            pending.swap(m_pending);
        }
        bool lost = false;
        while (!pending.empty()) {
            const Pending p = pending.front();
            pending.pop_front();
            QString said;
            DriverError e = p.isMode ? driver->setMode(p.mode) : driver->execute(p.command, &said);
            if (!said.isEmpty())
                postToOwner([this, said] { emit notice(said); });
            if (p.isMode && e.ok())
                modeClock.invalidate(); // read the new mode now
            finishCommand(p.id, e.ok(), e.message);
            if (e.linkLost()) {
                for (const Pending &rest : pending)
                    finishCommand(rest.id, false, e.message);
                lost = !lose(e);
                break;
            }
        }
        if (lost)
            break;
        if (!driver->link().isOpen())
            continue;
        // The refresh.
        QElapsedTimer clock;
        clock.start();
        std::vector<std::pair<model::Address, QString>> newlyRefused;
        DriverError e = driver->refresh(plan, words, &newlyRefused);
        if (e.kind == DriverError::Kind::Cancelled)
            continue;
        if (!e.ok()) {
            if (!lose(e))
                break;
            continue;
        }
        driver->link().countRefresh(double(clock.nsecsElapsed()) / 1e6, int(plan.reads.size()),
                                    plan.bytes());
        markRead(plan, newlyRefused, wordsRead);
        if (!newlyRefused.empty()) {
            // Left out from now on (until the watched devices change): asking again would
            // only cost a refused frame every refresh.
            std::vector<model::Address> keep;
            for (const auto &[address, why] : newlyRefused) {
                refused.push_back(address);
                problems << why;
            }
            for (const model::Address &a : plan.devices)
                if (std::find(refused.begin(), refused.end(), a) == refused.end())
                    keep.push_back(a);
            plan = driver->plan(keep);
        }
        // The mode: its own command every modePollMs, or the bit read with the refresh.
        PlcMode now = mode;
        if (driver->readsModeByCommand()) {
            if (!modeClock.isValid() || modeClock.elapsed() >= m_settings.modePollMs) {
                DriverError me = driver->readMode(&now);
                if (me.kind == DriverError::Kind::Cancelled)
                    continue;
                if (!me.ok()) {
                    if (!lose(me))
                        break;
                    continue;
                }
                modeClock.restart();
            }
        } else if (driver->runStateDevice().valid()) {
            model::Snapshot image;
            image.layout = m_layout;
            image.words = words;
            now = image.bit(driver->runStateDevice()) ? PlcMode::Run : PlcMode::Stop;
        }
        haveValues = true;
        if (!connectedClock.isValid())
            connectedClock.start();
        ++figures.scans;
        figures.timeMs = connectedClock.elapsed();
        figures.periodMs = clock.elapsed();
        recordHistory(words, wordsRead.get(), figures);
        publish(words, false, driver->forced(), figures, wordsRead);
        if (now != mode || !up)
            postMode(now);
        mode = now;
        if (!up) {
            if (everUp)
                driver->link().countReconnect();
            up = everUp = true;
            backoff = m_settings.reconnectMinMs;
            problemsPosted = problemText();
            postState(ConnectionState::Online, problemsPosted);
        } else if (problemText() != problemsPosted) {
            // A device the PLC refused, or one with no address watched after the connection
            // was up: the warning changes without the state changing.
            problemsPosted = problemText();
            postToOwner([this, text = problemsPosted] { setErrorText(text); });
        }
        shareStatistics(false);
        // The interval runs from the start of this refresh, so a refresh that takes longer
        // than it (any serial line with more than a few frames) is followed by the next at
        // once: the wire, not a pause, sets the rate.
        std::unique_lock lock(m_mutex);
        if (!waitFor(lock, std::max(0, m_settings.pollIntervalMs - int(clock.elapsed()))))
            break;
    }
    std::lock_guard lock(m_mutex);
    m_activeLink = nullptr;
}

} // namespace rung::comms
