#pragma once

// A station of a network: a PLC's program on its engine, its ports, and the slaves' side of
// the protocols its ports answer (comms' responders over the engine's image).

#include "network/image_writes.h"
#include "network/network.h"

#include "comms/slave/responder.h"
#include "model/comm/plc_port.h"
#include "simulator/engine.h"

#include <algorithm>
#include <map>

namespace rung::network {

class EngineImage;

// A port of a station: an end of a wire for the network, a PlcPort for the engine.
class StationPort final : public Endpoint, public model::PlcPort {
public:
    StationPort(Network *network, Station *station, model::PortConfig config);
    ~StationPort() override;

    // Endpoint
    const model::SerialSettings &lineSettings() const override { return m_line; }
    void deliver(const QByteArray &bytes, int errors, qint64 atUs) override;

    // model::PlcPort
    const model::PortConfig &config() const override { return m_config; }
    const model::SerialSettings &line() const override { return m_line; }
    void setLine(const model::SerialSettings &line) override { m_line = line; }
    qint64 nowUs() const override;
    qint64 send(QByteArrayView bytes) override;
    bool sending() const override { return nowUs() < txEndUs; }
    QByteArray receive() override;
    qint64 lastReceivedUs() const override { return m_lastUs; }
    int takeCharacterErrors() override;
    model::MasterProtocol *master() override { return m_master.get(); }
    void setProgramDriven(bool on) override;
    qint64 lastAnsweredRequestUs() const override { return m_lastAnsweredUs; }
    quint64 requestErrors() const override { return m_requestErrors; }

    // The station's program drives the port (an instruction named it).
    void setUsedByProgram() { m_used = true; }
    bool usedByProgram() const { return m_used; }
    // The slave's side after the station's scan: the requests that came, answered.
    void answer(qint64 nowUs);
    comms::slave::Responder *responder() const { return m_responder.get(); }
    // The virtual time the port last received a byte or its last byte sent leaves; -1: never.
    qint64 communicatedUs() const { return std::max(m_lastUs, m_sentUs); }
    void makeResponder(const std::shared_ptr<EngineImage> &image);

private:
    Network *m_network;
    Station *m_station;
    model::PortConfig m_config;
    model::SerialSettings m_line;
    std::unique_ptr<model::MasterProtocol> m_master;
    std::unique_ptr<comms::slave::Responder> m_responder;
    bool m_used = false;
    bool m_programDriven = false; // free-port: the responder is off
    QByteArray m_forProgram;      // received, for the engine
    QByteArray m_forResponder;    // received, for the slave's side
    QByteArrayList m_replies;     // the slave's answers to frames ended by a silence, not sent yet
    qint64 m_lastAnsweredUs = -1; // the end of the last request answered
    quint64 m_requestErrors = 0;  // requests addressed to the station that did not read
    int m_frameAddress = -1;      // the first byte of the frame the responder is reading
    QByteArrayList feedResponder(QByteArray frame, bool silence);
    qint64 m_lastUs = -1;
    qint64 m_sentUs = -1; // when the last byte it sent leaves
    int m_errors = 0;
};

class Station final : public Actor, public model::PlcPorts {
public:
    Station(Network *network, QString name, const LoadedStation &loaded, qint64 periodMs);
    ~Station() override;

    const QString &name() const { return m_name; }
    const model::Target &target() const { return *m_target; }
    const model::ModelVariant *model() const { return m_model; }
    simulator::Engine &engine() { return *m_engine; }
    const simulator::Engine &engine() const { return *m_engine; }
    // What was written in the image between scans (image_writes.h): marked by the writers,
    // taken by the network's history.
    ImageWrites &written() { return m_written; }
    qint64 periodMs() const { return m_periodMs; }
    // The engine's snapshot with what its ports did (Snapshot::communicatedUs: the front
    // panel's COMM lamp).
    model::Snapshot snapshot() const;
    // The latest StationPort::communicatedUs of its ports (-1: none has carried a byte): what
    // the snapshot and the network's history say of its communication.
    qint64 communicatedUs() const;
    const std::map<QString, std::unique_ptr<StationPort>> &ports() const { return m_ports; }
    StationPort *findPort(const QString &name) const;
    StationPort *addPort(model::PortConfig config);
    // Attaches the ports to the engine and the slaves' sides to the image (after addPort).
    void start();

    // Actor
    qint64 nextUs() const override { return m_nextUs; }
    void run(qint64 nowUs) override;
    bool holding() const override { return m_engine->insideScan(); }

    // Debugging inside a scan (network_session_debug.cpp). With breakpoints set on the engine
    // a scan runs to the first that holds and the station holds there (the network with it);
    // these go on from a hold, and a scan they complete ends as run() ends one (the ports'
    // answers, the next scan planned, the scan hook).
    // Its next scan starts and holds before its first instruction.
    void setHoldAtNextScan(bool on) { m_holdAtStart = on; }
    // One instruction of the held scan.
    simulator::ScanStop stepInstruction();
    // The rest of the held scan, breakpoints ignored.
    void finishScan();
    // The rest of the held scan up to the next breakpoint that holds.
    simulator::ScanStop continueScan();
    // Called after each scan the station completes, on the network's thread.
    void setScanHook(std::function<void(Station &)> hook) { m_scanHook = std::move(hook); }

    // model::PlcPorts
    model::PlcPort *port(const QString &name) override;

private:
    Network *m_network;
    QString m_name;
    const model::Target *m_target;
    const model::ModelVariant *m_model;
    qint64 m_periodMs;
    qint64 m_nextUs = 0; // the end of the next scan
    std::unique_ptr<simulator::Engine> m_engine;
    std::shared_ptr<EngineImage> m_image;
    ImageWrites m_written;
    std::map<QString, std::unique_ptr<StationPort>> m_ports;
    bool m_holdAtStart = false;
    std::function<void(Station &)> m_scanHook;
    void scanEnded(qint64 nowUs);
};

} // namespace rung::network
