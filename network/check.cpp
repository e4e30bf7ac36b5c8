#include "network/check.h"

#include "network/devices.h"
#include "network/station.h"
#include "network/tr.h"

#include "model/comm/link_table.h"

#include <algorithm>
#include <map>
#include <set>

namespace rung::network {

namespace {

using Protocol = model::ProtocolId;

QString protocolName(Protocol p) {
    switch (p) {
    case Protocol::VigorLink:
        return NetworkCheckTr::tr("Computer Link");
    case Protocol::Modbus:
        return NetworkCheckTr::tr("MODBUS");
    case Protocol::HostLink:
        return NetworkCheckTr::tr("Host Link");
    }
    return {};
}

// What a port or device on a wire answers: its protocol and station number.
struct Answerer {
    Protocol protocol;
    int station;
    QString name;
};

std::vector<Answerer> answerers(const Wire &wire) {
    std::vector<Answerer> out;
    for (Endpoint *e : wire.ends) {
        if (auto *port = dynamic_cast<StationPort *>(e)) {
            const model::PortApplication &app = *port->config().application;
            if (model::answersAt(app, port->config().station))
                out.push_back({*app.answers, port->config().station, port->name});
        } else if (auto *device = dynamic_cast<ModbusSlaveDevice *>(e)) {
            out.push_back({Protocol::Modbus, device->station, device->name});
        }
    }
    return out;
}

QString statusText(model::LinkStatus s) {
    switch (s) {
    case model::LinkStatus::BadLength:
        return NetworkCheckTr::tr("status 2: the length is not 1..64");
    case model::LinkStatus::BadDeviceType:
        return NetworkCheckTr::tr("status 4: a wrong device type or command");
    case model::LinkStatus::BadDeviceNumber:
        return NetworkCheckTr::tr("status 5: a wrong device number");
    case model::LinkStatus::AttributesDiffer:
        return NetworkCheckTr::tr("status 6: the master's and the slave's devices differ (bits "
                                  "and words)");
    default:
        return {};
    }
}

void checkPl110Ports(Network &network, std::vector<NetworkFinding> *out);

} // namespace

std::vector<NetworkFinding> checkNetwork(Network &network) {
    std::vector<NetworkFinding> out;
    // Masters: the ports a LINK or MBUS drives, and the ports whose application is a master.
    std::map<const Endpoint *, QString> masters; // port -> what makes it one
    for (const auto &s : network.stations()) {
        const simulator::Program &program = s->engine().program();
        for (const simulator::CommStep &c : program.comms) {
            if (c.kind != simulator::CommKind::EasyLink &&
                c.kind != simulator::CommKind::ModbusMaster)
                continue;
            const QString where = NetworkCheckTr::tr("%1: line %2")
                                      .arg(s->name())
                                      .arg(program.lines[std::size_t(c.step)]);
            const StationPort *port = s->findPort(c.port);
            if (!port || !port->wire) {
                out.push_back({false, where,
                               NetworkCheckTr::tr("%1 drives %2, which is on no wire: every set "
                                                  "ends in a time-out (status A)")
                                   .arg(c.spec ? c.spec->mnemonic : QString(), c.port)});
                continue;
            }
            masters[port] = c.spec ? c.spec->mnemonic : QString();
        }
        for (const auto &[name, port] : s->ports())
            if (port->config().application->master && !masters.count(port.get()))
                masters[port.get()] = QCoreApplication::translate("rung::model::Target",
                                                                  port->config().application->name);
    }
    for (const auto &wire : network.wires()) {
        const QString where = NetworkCheckTr::tr("wire %1").arg(wire->name);
        QStringList onWire;
        for (const Endpoint *e : wire->ends)
            if (const auto it = masters.find(e); it != masters.end())
                onWire << QStringLiteral("%1 (%2)").arg(e->name, it->second);
        if (onWire.size() > 1)
            out.push_back({true, where,
                           NetworkCheckTr::tr("%1 masters on one wire: %2; their requests "
                                              "collide")
                               .arg(onWire.size())
                               .arg(onWire.join(QStringLiteral(", ")))});
        const std::vector<Answerer> all = answerers(*wire);
        for (std::size_t i = 0; i < all.size(); ++i)
            for (std::size_t j = i + 1; j < all.size(); ++j)
                if (all[i].protocol == all[j].protocol && all[i].station == all[j].station)
                    out.push_back({true, where,
                                   NetworkCheckTr::tr("%1 and %2 both answer %3 station %4")
                                       .arg(all[i].name, all[j].name, protocolName(all[i].protocol))
                                       .arg(all[i].station)});
    }
    // The tables as the first scan leaves them (a station's first scan ends at its period).
    qint64 firstScans = 0;
    for (const auto &s : network.stations())
        firstScans = std::max(firstScans, s->periodMs() * 1000);
    network.runUntil(firstScans);
    for (const auto &s : network.stations()) {
        const simulator::Program &program = s->engine().program();
        const auto words = s->engine().words();
        for (const simulator::CommStep &c : program.comms) {
            const bool link = c.kind == simulator::CommKind::EasyLink;
            if ((!link && c.kind != simulator::CommKind::ModbusMaster) || c.first < 0)
                continue;
            const StationPort *port = s->findPort(c.port);
            if (!port || !port->wire)
                continue;
            const QString where = NetworkCheckTr::tr("%1: line %2")
                                      .arg(s->name())
                                      .arg(program.lines[std::size_t(c.step)]);
            const std::int32_t sets = words[std::size_t(c.first)];
            if (sets < 1 || sets > model::kLinkMaxSets ||
                1 + model::kLinkSetRegisters * sets > c.firstWords) {
                out.push_back({true, where,
                               NetworkCheckTr::tr("%1's table holds %2 sets after the first "
                                                  "scan; it takes 1 to %3 within its area")
                                   .arg(c.spec->mnemonic)
                                   .arg(sets)
                                   .arg(model::kLinkMaxSets)});
                continue;
            }
            std::set<int> stations;
            const Protocol protocol = link ? Protocol::VigorLink : Protocol::Modbus;
            for (const Answerer &a : answerers(*port->wire))
                if (a.protocol == protocol)
                    stations.insert(a.station);
            for (int k = 0; k < sets; ++k) {
                const std::int32_t *r =
                    &words[std::size_t(c.first + 1 + model::kLinkSetRegisters * k)];
                const model::LinkSet set = model::readLinkSet(
                    s->target(),
                    link ? model::LinkTableKind::EasyLink : model::LinkTableKind::Modbus, r);
                if (set.status != model::LinkStatus::Normal) {
                    out.push_back({true, where,
                                   NetworkCheckTr::tr("%1 set %2: %3")
                                       .arg(c.spec->mnemonic)
                                       .arg(k + 1)
                                       .arg(statusText(set.status))});
                    continue;
                }
                if (!stations.count(set.station))
                    out.push_back(
                        {true, where,
                         NetworkCheckTr::tr("%1 set %2 names station %3, which no port or "
                                            "device on %4 answers with %5: the set ends in a "
                                            "time-out (status A)")
                             .arg(c.spec->mnemonic)
                             .arg(k + 1)
                             .arg(set.station)
                             .arg(port->wire->name, protocolName(protocol))});
            }
        }
    }
    checkPl110Ports(network, &out);
    return out;
}

namespace {

// The PL110's ports (PL110 manual 4.2.19, 4.2.21), the tables' first scan run: a COM / EXP query
// naming a slave that nothing on its wire answers, a port in NAIS MATSUSHITA-MASTER (no
// published frames: its queries never reach a wire), a SEND on a port that the first scan left
// out of free-port or that is on no wire.
void checkPl110Ports(Network &network, std::vector<NetworkFinding> *out) {
    for (const auto &s : network.stations()) {
        const simulator::Program &program = s->engine().program();
        const auto words = s->engine().words();
        for (const auto &[name, port] : s->ports()) {
            const model::PortApplication &app = *port->config().application;
            if (app.master && !app.published)
                out->push_back(
                    {false, port->name,
                     NetworkCheckTr::tr("%1 runs %2: the PL110 manual publishes no frames of it, "
                                        "so the simulation puts none on the wire and every COM / "
                                        "EXP query of the port times out")
                         .arg(port->name,
                              QCoreApplication::translate("rung::model::Target", app.name))});
        }
        for (const simulator::CommStep &c : program.comms) {
            if (c.kind != simulator::CommKind::MasterQuery &&
                c.kind != simulator::CommKind::FreePortSend)
                continue;
            const QString where = NetworkCheckTr::tr("%1: line %2")
                                      .arg(s->name())
                                      .arg(program.lines[std::size_t(c.step)]);
            const StationPort *port = s->findPort(c.port);
            const QString mnemonic = c.spec ? c.spec->mnemonic : QString();
            if (!port || !port->wire) {
                out->push_back({false, where,
                                c.kind == simulator::CommKind::FreePortSend
                                    ? NetworkCheckTr::tr("SEND sends on %1, which is on no wire: "
                                                         "the characters reach nobody")
                                          .arg(c.port)
                                    : NetworkCheckTr::tr("%1_%2 queries on %3, which is on no "
                                                         "wire: every query times out")
                                          .arg(mnemonic)
                                          .arg(c.index)
                                          .arg(c.port)});
                continue;
            }
            if (c.kind == simulator::CommKind::FreePortSend) {
                if (c.portIndex < 0)
                    continue;
                const simulator::PortDevices &d = program.ports[std::size_t(c.portIndex)];
                if (d.freePort >= 0 && !(words[std::size_t(d.freePort)] & 0x100))
                    out->push_back({false, where,
                                    NetworkCheckTr::tr("SEND on %1, which is not in free-port "
                                                       "after the first scan (%2 bit 8 is OFF): "
                                                       "the PLC ignores SEND until the program "
                                                       "sets it")
                                        .arg(c.port, QString::fromLatin1(d.markers->freePort))});
                continue;
            }
            if (!port->config().application->published || c.slave == 0)
                continue; // no frames; slave 0 is MODBUS's broadcast, which nobody answers
            std::set<int> stations;
            for (const Answerer &a : answerers(*port->wire))
                if (a.protocol == Protocol::Modbus)
                    stations.insert(a.station);
            if (!stations.count(c.slave))
                out->push_back({true, where,
                                NetworkCheckTr::tr("%1_%2 queries slave %3, which no port or "
                                                   "device on %4 answers with MODBUS: every "
                                                   "query times out and sets its status bit")
                                    .arg(mnemonic)
                                    .arg(c.index)
                                    .arg(c.slave)
                                    .arg(port->wire->name)});
        }
    }
}

} // namespace

} // namespace rung::network
