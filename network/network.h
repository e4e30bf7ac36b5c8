#pragma once

// A network of PLCs on one virtual clock (docs/network.md): stations (each a program on its
// engine, with its ports), simulated devices, wires between ports, CPU Link and Parallel Link
// groups, faults. Everything runs on the caller's thread, deterministically: the same network
// and stimulus give the same traces and the same traffic, byte for byte.
//
//   NetworkDescription d;                     // network_file.h
//   readNetworkFile("plant.rungnet", &d, &error);
//   auto net = Network::build(d, loader, &error);
//   net->runUntil(1'000'000);                 // one second of virtual time

#include "network/network_file.h"

#include "model/comm/port_config.h"
#include "simulator/program.h"

#include <QByteArray>
#include <QJsonObject>

#include <functional>
#include <memory>
#include <queue>
#include <vector>

namespace rung::simulator {
class Engine;
}

namespace rung::network {

class Network;
class Station;
class StationPort;

// A station's program as its file gives it.
struct LoadedStation {
    std::shared_ptr<const simulator::Program> program;
    const model::Target *target = nullptr;
    const model::ModelVariant *model = nullptr;
    QJsonObject ports; // a project's port settings ("ports"); empty for a listing
};
// Loads a station's program (the command line's loader, which `simulate` uses too, or a
// test's); false with the reasons in *error, a line each.
using ProgramLoader =
    std::function<bool(const StationDescription &station, LoadedStation *loaded, QString *error)>;

// What went over a wire, or what a group exchanged without frames.
// What an end on a wire keeps of what it received and nobody took yet (a program that never
// looks at its port, a device's log, a flood on the wire): the newest bytes, at most this many.
inline constexpr qsizetype kMaxReceivedKept = 64 * 1024;
inline void trimReceived(QByteArray &kept) {
    if (kept.size() > kMaxReceivedKept)
        kept.remove(0, kept.size() - kMaxReceivedKept);
}

struct TrafficRecord {
    qint64 startUs = 0;
    qint64 endUs = 0;
    QString wire;
    QString sender; // "master/CP2", a device's name
    QByteArray bytes;
    QString note; // translated; empty for a frame delivered as sent
    // The frame reached the other ends (garbled perhaps); false when a fault kept it from
    // the wire (silent, cut) or the port is on none.
    bool delivered = true;
};

// Anything with a port on a wire: a station's port, a device.
class Endpoint {
public:
    virtual ~Endpoint() = default;
    QString name;  // "master/CP2", "tc"
    QString owner; // the station's or device's name
    class Wire *wire = nullptr;
    qint64 txEndUs = 0; // when the last byte it sent left
    virtual const model::SerialSettings &lineSettings() const = 0;
    // Bytes the wire brings, read at this end's line (uart.h), at virtual time atUs.
    virtual void deliver(const QByteArray &bytes, int errors, qint64 atUs) = 0;
};

// Something the clock drives: a station's scans, a device's answers, a group's exchange.
class Actor {
public:
    virtual ~Actor() = default;
    // The next time it does something; INT64_MAX: nothing planned.
    virtual qint64 nextUs() const = 0;
    virtual void run(qint64 nowUs) = 0;
    // Stopped inside its work (a station's scan held at a breakpoint or a step): the network
    // goes no further until it is not.
    virtual bool holding() const { return false; }
};

class Wire {
public:
    QString name;
    std::vector<Endpoint *> ends;
    int frames = 0; // transmissions so far (the corrupt fault counts them)
    struct Transmission {
        Endpoint *sender = nullptr;
        qint64 startUs = 0;
        qint64 endUs = 0;
        bool collided = false;
    };
    std::vector<std::shared_ptr<Transmission>> active;
};

class Network {
public:
    // Loads every station's program, reads every port's settings, joins the wires; false (and
    // nullptr) with what, where and why.
    static std::unique_ptr<Network> build(const NetworkDescription &description,
                                          const ProgramLoader &loader, QString *error);
    ~Network();

    qint64 nowUs() const { return m_now; }
    // Runs every event up to and including virtual time `us`; true when it got there. False
    // when a station holds inside its scan (a breakpoint, a step) or interrupt() was called:
    // the clock stays at that instant, every other station at its scan boundary, and the next
    // call goes on from there exactly as an uninterrupted run would have (the actors due at
    // that instant after the one that stopped run first). While a station holds it runs nothing.
    bool runUntil(qint64 us);
    // Stops runUntil after the actor running now (a trigger that stops the network after the
    // scan in which it fired). From an actor's run, on the network's thread; outside a run it
    // does nothing.
    void interrupt() { m_interrupt = true; }
    // A station holding inside its scan, or null.
    Station *holdingStation() const;

    const NetworkDescription &description() const { return m_description; }
    const std::vector<std::unique_ptr<Station>> &stations() const { return m_stations; }
    Station *station(const QString &name) const;
    Endpoint *endpoint(const QString &name) const; // "master/CP2", "tc"
    const std::vector<std::unique_ptr<Wire>> &wires() const { return m_wires; }

    // Every transmission and exchange from now on; null: not recorded (the default).
    void setTrafficSink(std::function<void(const TrafficRecord &)> sink) {
        m_traffic = std::move(sink);
    }
    void record(TrafficRecord record) const {
        if (m_traffic)
            m_traffic(record);
    }
    bool recording() const { return bool(m_traffic); }

    // A port's bytes onto its wire from now (after what it is still sending); returns when the
    // last byte will have left. Faults (cut, silent, corrupt) and collisions apply here.
    qint64 transmit(Endpoint *from, const QByteArray &bytes);
    // A station or device the faults keep silent at time t.
    bool silent(const QString &owner, qint64 us) const;
    bool cut(const Wire &wire, qint64 us) const;

    // A fault from the network's present on (the IDE's Faults menu): as the file's faults
    // section, fromMs at or before now.
    void addFault(FaultDescription fault) { m_description.faults.push_back(std::move(fault)); }
    // Ends now every cut of a wire (Kind::Cut) or silence of a station or device
    // (Kind::Silent) that lasts past now.
    void endFaults(FaultDescription::Kind kind, const QString &target);

    // Bytes a bridge (a real port) puts on the endpoint's wire as if that port sent them.
    void inject(Endpoint *at, const QByteArray &bytes);
    // An endpoint joined to the wire of `beside` (a bridge's real line beside a station's
    // port; bridge.h); a wire of their own when the port is on none. The network keeps it.
    void attach(std::unique_ptr<Endpoint> endpoint, Endpoint *beside);

private:
    Network() = default;
    struct Delivery {
        qint64 atUs = 0;
        quint64 sequence = 0;
        Endpoint *to = nullptr;
        QByteArray bytes;
        model::SerialSettings line; // the sender's
        std::shared_ptr<Wire::Transmission> transmission;
        bool operator>(const Delivery &o) const {
            return atUs != o.atUs ? atUs > o.atUs : sequence > o.sequence;
        }
    };
    friend class NetworkBuilder;

    NetworkDescription m_description;
    std::vector<std::unique_ptr<Station>> m_stations;
    std::vector<std::unique_ptr<Endpoint>> m_devices; // also in m_actors
    std::vector<std::unique_ptr<Actor>> m_groups;     // CPU Link, Parallel Link
    std::vector<Actor *> m_actors;                    // devices, groups, stations: this order
    std::vector<std::unique_ptr<Wire>> m_wires;
    std::priority_queue<Delivery, std::vector<Delivery>, std::greater<>> m_deliveries;
    quint64 m_sequence = 0;
    qint64 m_now = 0;
    std::function<void(const TrafficRecord &)> m_traffic;
    // The actors of the instant runUntil stopped at: m_actors from this index still to run
    // (0: none).
    std::size_t m_resumeFrom = 0;
    bool m_interrupt = false;
    // Runs the actors due now from index `from`; false when one held or interrupted.
    bool runActors(std::size_t from);
};

} // namespace rung::network
