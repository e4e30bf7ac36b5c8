#pragma once

// A PLC online as a MonitorSource (model/image/monitor_source.h): the same snapshot shape as
// the simulator's (words in MemoryLayout order), so the ladder overlay, the watch table and
// the chart draw a real PLC as they draw a simulation.
//
// A worker thread owns the port and the driver. It polls only the watched devices (the
// union MonitorSource::watched()), planned again whenever that set changes; commands
// (write a bit, a word, a set value; force and release where the protocol can) go to the
// PLC between two refreshes and are reported done only when the PLC acknowledged them.
// The run state comes from the PLC (Host Link MS; the RUN bit or the "ON while running" bit).
//
// Losing the link (a cable pulled, the PLC off, the port gone) shows at once: runState()
// Offline, errorText() saying why, the last values kept and marked stale; the worker tries
// again in the background, waiting longer each time up to reconnectMaxMs, and resumes
// without the user doing anything. Nothing here blocks the owner (UI) thread: connect and
// disconnect return at once, the destructor only waits for the worker to see its cancel.
//
// For the connection panel: connectionState(), statistics() (errors, retries, round trip),
// identity() (Host Link MM, PL110 words 0-1), and traffic(): a tap of every byte both ways,
// time-stamped, announced by trafficAvailable().

#include "comms/driver/connection.h"
#include "comms/driver/traffic.h"
#include "model/image/history.h"
#include "model/image/monitor_source.h"

#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace rung::comms {

class Driver;

class OnlineSession : public model::MonitorSource {
    Q_OBJECT

public:
    enum class ConnectionState {
        Disconnected, // not asked to connect
        Connecting,   // opening the port, first contact
        Online,       // the PLC answers
        Lost,         // it answered before and does not now: trying again
        Failed,       // the settings cannot work (no map for the protocol, a bad station)
    };
    Q_ENUM(ConnectionState)

    // Makes the transport on the worker thread; the default is makeTransport(settings).
    using TransportFactory = std::function<std::unique_ptr<Transport>()>;

    OnlineSession(const model::Target &target, ConnectionSettings settings,
                  QObject *parent = nullptr, TransportFactory factory = {});
    ~OnlineSession() override;

    const model::Target &target() const { return m_target; }
    const ConnectionSettings &settings() const { return m_settings; }
    std::shared_ptr<const model::MemoryLayout> layout() const { return m_layout; }

    // Owner thread; both return at once.
    void connectToPlc();
    void disconnectFromPlc();
    ConnectionState connectionState() const { return m_state; }

    // RUN / STOP / MONITOR where the protocol has it; commandFinished() carries the answer.
    CommandId setPlcMode(PlcMode mode);
    PlcMode plcMode() const { return m_mode; }
    PlcIdentity identity() const { return m_identity; }
    // "CPM1 unit 0 on /dev/ttyUSB0".
    QString plcName() const;
    // What the protocol can command, known once its driver exists (before the session is
    // first Online); all false before.
    struct Abilities {
        bool setsMode = false;    // RUN / STOP (or PROGRAM / RUN)
        bool monitorMode = false; // PROGRAM / MONITOR / RUN
        bool forces = false;      // forces bits (else a force is refused and says so)
    };
    Abilities abilities() const;
    // Once the protocol is known to have no force command: says so and what to do instead.
    QString forceRefusal() const override;

    // History (MonitorSource), refresh by refresh: "scans" are refreshes, the time is since the
    // connection. A device is recorded from the first refresh that read it (before that its
    // word holds a 0 the PLC never said); a reader that wants it recorded also watches it
    // (setWatched), or it is never read. A trigger only marks: the PLC does not stop for it.
    bool watchHistory(const model::Address &address) override;
    void
    readHistory(const std::function<void(const model::HistoryRecorder &)> &read) const override;
    bool setTrigger(std::optional<model::Trigger> trigger) override;

    // Any thread.
    LinkStatistics statistics() const;
    // The bytes both ways since sequence `from` (see TrafficTap::records).
    std::vector<TrafficRecord> traffic(quint64 from, quint64 *next = nullptr) const;
    void setTrafficTap(bool on);
    // The wall-clock time the tap's timeUs counts from, to print a record's time of day.
    QDateTime trafficStart() const { return m_traffic.start(); }

signals:
    void connectionStateChanged(rung::comms::OnlineSession::ConnectionState state);
    void plcModeChanged(rung::comms::PlcMode mode);
    void identityChanged();
    // Something the session did besides what was asked (switched RUN to MONITOR to write).
    void notice(const QString &text);
    void statisticsChanged(); // at most a few times a second
    void trafficAvailable();  // new bytes in the tap, at most a few times a second

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    struct Pending {
        CommandId id = 0;
        bool isMode = false;
        model::DeviceCommand command;
        PlcMode mode = PlcMode::Unknown;
    };
    enum class Link { Down, Up, Lost };

    void workerLoop();
    void control(const std::function<void()> &change);
    bool waitFor(std::unique_lock<std::mutex> &lock, int ms); // false: quit
    void failPending(const QString &why);
    // statistics: scans = refreshes so far, timeMs = since the connection, periodMs = the
    // last refresh's time (the online counterparts of the simulator's scan figures).
    void publish(const std::vector<std::int32_t> &words, bool stale,
                 const std::map<model::Address, bool> &forced,
                 const model::ScanStatistics &statistics,
                 std::shared_ptr<const std::vector<bool>> wordsRead);
    // Worker: the refresh's values into the history (devices read by now start recording).
    void recordHistory(const std::vector<std::int32_t> &words, const std::vector<bool> *wordsRead,
                       const model::ScanStatistics &statistics);
    void postState(ConnectionState state, const QString &error);
    void postMode(PlcMode mode);
    void postStatistics();
    QString notConnected() const;

    const model::Target &m_target;
    const ConnectionSettings m_settings;
    const TransportFactory m_factory;
    std::shared_ptr<const model::MemoryLayout> m_layout;
    TrafficTap m_traffic; // the driver's tap forwards here so it outlives reconnects

    // The history: the owner asks and reads, the worker records, under m_historyMutex.
    mutable std::mutex m_historyMutex;
    model::HistoryRecorder m_history;
    std::vector<model::Address> m_historyPending; // asked for, not read from the PLC yet

    // Owner thread.
    ConnectionState m_state = ConnectionState::Disconnected;
    PlcMode m_mode = PlcMode::Unknown;
    PlcIdentity m_identity;

    // Shared with the worker, under m_mutex.
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    bool m_quit = false;
    bool m_wanted = false;
    bool m_watchedDirty = true;
    std::vector<model::Address> m_watched;
    std::deque<Pending> m_pending;
    comms::Link *m_activeLink = nullptr; // cancel() target while the worker uses it
    LinkStatistics m_statistics;
    QString m_plcName;
    Abilities m_abilities;

    std::thread m_worker; // last: starts after everything it reads exists
};

} // namespace rung::comms
