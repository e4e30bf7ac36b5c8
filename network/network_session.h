#pragma once

// A network simulated in the IDE: the Network (network.h) runs on a worker thread, paced
// against the wall clock by a speed factor, as SimulatorSession runs one program. Each
// station is a MonitorSource of its own (StationSource), so every view the IDE has for one
// PLC (ladder overlay, instruction list values, inputs and outputs, watch table, timing chart,
// front panel) shows a station unchanged; device commands go to the station's engine between
// two slices of virtual time. The control calls return at once; the owner thread never waits
// for the network. Traffic (every frame) is collected for the owner in batches.
//
// Threads: the worker alone touches the Network and its engines. The owner thread (the UI)
// calls the controls and reads snapshots, history and traffic; everything between them goes
// through mutexes (the stations' inboxes, the history, the traffic queue, the controls).

#include "network/network.h"
#include "network/network_history.h"
#include "network/network_session_bridges.h"

#include "model/image/history.h"
#include "model/image/monitor_source.h"
#include "model/image/panel_view.h"
#include "simulator/command_inbox.h"
#include "simulator/engine.h"

#include <QObject>

#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace rung::network {

class NetworkSession;

// One station of a simulated network, as the views see a PLC.
class StationSource final : public model::MonitorSource {
    Q_OBJECT

public:
    ~StationSource() override;

    const QString &stationName() const { return m_name; }
    const model::Target &target() const { return *m_target; }
    const model::ModelVariant *model() const { return m_model; }
    // The file of the station's program (resolved against the network file).
    const QString &programPath() const { return m_programPath; }
    // What the station's PLC holds beside its memory (the front panel's PL110 system page 3):
    // its program's name (the file's, without its suffix) and each port's application as the
    // project's and the network's settings give it.
    const model::PanelContext &panelContext() const { return m_panelContext; }

    // History: the station's devices recorded after every scan it completes (MonitorSource). A
    // trigger is evaluated there: it reports triggered(), and with Trigger::Action::Stop the
    // whole network pauses right after that scan, every other station at its scan boundary.
    bool watchHistory(const model::Address &address) override;
    void
    readHistory(const std::function<void(const model::HistoryRecorder &)> &read) const override;
    bool setTrigger(std::optional<model::Trigger> trigger) override;

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    friend class NetworkSession;
    StationSource(NetworkSession *session, const Station &station, const QString &programPath);

    NetworkSession *m_session;
    QString m_name;
    const model::Target *m_target;
    const model::ModelVariant *m_model;
    QString m_programPath;
    model::PanelContext m_panelContext;
    simulator::CommandInbox m_inbox;
    mutable std::mutex m_historyMutex;
    model::HistoryRecorder m_history;
    std::size_t m_errorsReported = 0; // worker thread
    quint64 m_scansRecorded = 0;      // worker thread
};

class Station;

class NetworkSession : public QObject {
    Q_OBJECT

public:
    using RunState = model::MonitorSource::RunState;

    // Builds the network (its programs loaded by `loader`) and starts its worker, Stopped at
    // virtual time 0; null with what, where and why. `learn`, when given, reads the network
    // built, on the caller's thread, before the worker touches it (a traffic decoder learning
    // the wiring); it must keep no reference to it.
    static std::unique_ptr<NetworkSession>
    start(const NetworkDescription &description, ProgramLoader loader, QString *error,
          QObject *parent = nullptr, const std::function<void(const Network &)> &learn = {});
    ~NetworkSession() override; // stops the worker and waits for it

    const NetworkDescription &description() const { return m_description; }
    const std::vector<StationSource *> &stations() const { return m_sources; }
    StationSource *station(const QString &name) const;
    // The wires as the network joined them: name and ends ("master/CP2", "tc").
    struct WireInfo {
        QString name;
        QStringList ends;
    };
    const std::vector<WireInfo> &wires() const { return m_wires; }

    void run();
    void pause();
    // Back to power-on: the network is built again from its description (the programs read
    // again from their files), virtual time 0, the traffic and the faults made by hand gone.
    void stop();
    // One period of the network's virtual time (every station scans once at the default
    // period), then Paused.
    void singleScan();
    // As much virtual time, then Paused.
    void runFor(qint64 durationMs);
    // Every station powered off and on at the next slice: retentive areas survive, the rest
    // clears (simulator::PowerCycle); the network's clock goes on.
    void powerCycle();
    // Times real time; 0 or less: as fast as it goes.
    // The station whose ladder is on screen records power flow for the overlay; the others
    // pay nothing for it. Empty: none.
    void setPowerFlowStation(const QString &station);
    void setSpeed(double factor);
    double speed() const;
    RunState runState() const { return m_runState; }
    // Virtual time of the latest slice (any thread).
    qint64 nowUs() const { return m_nowUs.load(std::memory_order_relaxed); }
    // Why the network could not be built again at stop, or a station's runtime error; empty
    // when nothing is wrong.
    QString errorText() const { return m_errorText; }

    // Faults from now on (virtual time), as the network file's faults section has them
    // (docs/network-format.md): a cut wire delivers nothing, a silent station or device
    // sends nothing, the next frame on a wire has a byte changed. Each returns at once.
    void setWireCut(const QString &wire, bool cut);
    void setSilent(const QString &stationOrDevice, bool silent);
    void corruptNextFrame(const QString &wire, int byte = 0, int mask = 0x01);
    // A station's port ("s5/CP2") sends and reads at another rate from now on, as a port set
    // wrongly would: the other ends read its characters garbled (uart.h). Stop restores it.
    void setBaud(const QString &port, int baud);
    // The rate set by setBaud, or 0 while the port runs at its own.
    int baudSet(const QString &port) const;
    bool wireCut(const QString &wire) const;
    bool silent(const QString &stationOrDevice) const;

    // Debugging inside a station's scan (network_session_debug.cpp; docs/network.md,
    // "Breakpoints"). A breakpoint that holds stops its station before the instruction and the
    // whole network with it: every other station stays at its scan boundary (no scan is left
    // half run), the virtual clock stands, the run state is Paused and breakpointHit follows.
    // run(), singleScan() and runFor() go on from there: the held scan first (up to its next
    // breakpoint), then the network.
    // A station's breakpoints (instructions of its program), replacing its others; kept over
    // Stop. One the program cannot take is said by errorText and changes nothing.
    void setBreakpoints(const QString &station, std::vector<simulator::Breakpoint> breakpoints);
    // One instruction of the held scan; with no scan held, `station`'s next scan starts and
    // holds before its first instruction (the network runs up to it). Stepping, then Paused.
    void stepInstruction(const QString &station);
    // The rest of the held scan, breakpoints ignored; then Paused at that instant, the
    // stations after it not yet run.
    void finishScan();
    // The station whose scan holds as its latest snapshot shows; empty when none (owner
    // thread).
    QString heldStation() const;

    // The frames sent since the last call, oldest first (owner thread). *startedOver: the
    // network was built again (Stop) since the last call, and these are the new network's: a
    // reader drops what it kept of the old one first.
    std::vector<TrafficRecord> takeTraffic(bool *startedOver = nullptr);

    // Puts the description's bridges on real lines from now on (network_session_bridges.h):
    // the worker opens them (or takes them from `lines`, where they stay open across Stop and
    // sessions) and carries their bytes while the network runs. bridgeStatus() says where
    // each is reached or why it did not open (bridgesChanged). Owner thread.
    void startBridges(std::shared_ptr<BridgeLines> lines);
    const std::vector<BridgeStatus> &bridgeStatus() const { return m_bridgeStatus; }
    // Every station's past (network_history.h): recorded after every slice of virtual time
    // and every command, started again at Stop. Any thread reads it.
    std::shared_ptr<const NetworkHistory> history() const { return m_networkHistory; }

signals:
    void runStateChanged(rung::model::MonitorSource::RunState state);
    void errorTextChanged(const QString &text);
    // Frames are waiting for takeTraffic() (once per batch, not per frame).
    void trafficAvailable();
    // The virtual clock moved (on the readers' beat).
    void clockChanged(qint64 nowUs);
    // bridgeStatus() changed: a bridge opened, failed or was opened again.
    void bridgesChanged();
    // A breakpoint stopped `station`'s scan before `instruction` (the run state is Paused).
    void breakpointHit(const QString &station, int instruction);

private:
    friend class StationSource;
    NetworkSession(NetworkDescription description, ProgramLoader loader,
                   std::unique_ptr<Network> network, QObject *parent);
    enum class Mode { Stopped, Paused, Running };
    struct Fault {
        enum class Kind { Cut, Silent, Corrupt, Baud } kind;
        QString target;
        bool on = true;
        int byte = 0;
        int mask = 1;
    };

    void control(const std::function<void()> &change);
    void setRunState(RunState state);
    void setError(const QString &text);
    void post(std::function<void()> function); // any thread -> owner thread
    Q_INVOKABLE void runPosted();
    void workerLoop();
    void attachTraffic(Network &network);
    void applyFaults(Network &network, std::vector<Fault> faults);
    void publish(Network &network, bool answer);
    void afterSlice(Network &network);
    // network_session_debug.cpp, on the worker thread.
    struct DebugWork {
        bool breakpoints = false; // the stations' breakpoints changed
        bool step = false;
        QString stepStation;
        bool finish = false;
        quint64 generation = 0;
        bool stepsDone = false;
    };
    bool takeDebugWork(DebugWork *work);   // under m_mutex: true when there is some
    void prepareNetwork(Network &network); // the scan hooks and breakpoints of a network built
    void applyBreakpoints(Network &network);
    void doDebugWork(Network &network, const DebugWork &work);
    // Runs the network to `until`: the held scan first; false when it stopped on the way (a
    // breakpoint, a stopping trigger), the session then Paused.
    bool runSlice(Network &network, qint64 until);
    void pauseFromWorker(const QString &station, int breakpoint);
    void recordScan(Network &network, StationSource &source, const Station &station);
    void reportTriggers();

    NetworkDescription m_description;
    ProgramLoader m_loader;
    std::unique_ptr<Network> m_initial; // built on the owner thread, handed to the worker
    std::vector<StationSource *> m_sources;
    std::vector<WireInfo> m_wires;
    RunState m_runState = RunState::Stopped; // owner thread
    QString m_errorText;                     // owner thread
    std::atomic<qint64> m_nowUs{0};

    // Controls, under m_mutex.
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    Mode m_mode = Mode::Stopped;
    qint64 m_budgetUs = 0; // Paused: virtual time still to run (single scan, run for)
    bool m_reset = false;
    bool m_quit = false;
    double m_speed = 1.0;
    QString m_flowStation;
    quint64 m_generation = 0;
    std::vector<Fault> m_faults;      // to apply at the next slice
    std::vector<Fault> m_faultsShown; // as the user set them (owner's view)
    // Debugging (network_session_debug.cpp).
    std::map<QString, std::vector<simulator::Breakpoint>> m_breakpoints; // by station
    bool m_breakpointsChanged = false;
    int m_instructionSteps = 0;
    QString m_stepStation;
    bool m_finishScan = false;
    struct Fired { // a trigger that fired, to report after the snapshot (worker thread)
        StationSource *source = nullptr;
        quint64 scan = 0;
        qint64 timeMs = 0;
    };
    std::vector<Fired> m_fired;
    bool m_stopFired = false; // a stopping trigger fired since the worker last looked

    std::mutex m_trafficMutex;
    std::vector<TrafficRecord> m_traffic;
    bool m_trafficTold = false;
    quint64 m_trafficEpoch = 0; // under m_trafficMutex: networks built so far
    quint64 m_takenEpoch = 0;   // owner thread: the epoch takeTraffic last handed out

    std::mutex m_postMutex;
    std::vector<std::function<void()>> m_posted;

    // Bridges: lines handed by startBridges under m_mutex; the worker's bridges; their
    // statuses as the owner thread last heard them.
    std::shared_ptr<BridgeLines> m_bridgeLines;
    std::shared_ptr<BridgeLines> m_bridgeLinesShown; // owner thread: to cancel an opening
    std::unique_ptr<SessionBridges> m_bridges;       // worker thread
    std::vector<BridgeStatus> m_bridgeStatus;        // owner thread
    void postBridgeStatus(const std::vector<BridgeStatus> &status);
    // Worker records; readers under its own lock. Before m_worker, which uses it.
    std::shared_ptr<NetworkHistory> m_networkHistory = std::make_shared<NetworkHistory>();

    std::thread m_worker;
};

} // namespace rung::network
