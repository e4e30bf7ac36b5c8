#include "network/network.h"
#include "network/tr.h"

#include "network/devices.h"
#include "network/shared_link.h"
#include "network/station.h"
#include "network/uart.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>
#include <utility>

namespace rung::network {

namespace {

constexpr qint64 kNever = std::numeric_limits<qint64>::max();

} // namespace

Network::~Network() = default;

Station *Network::station(const QString &name) const {
    for (const auto &s : m_stations)
        if (s->name() == name)
            return s.get();
    return nullptr;
}

Endpoint *Network::endpoint(const QString &name) const {
    const qsizetype slash = name.indexOf(QLatin1Char('/'));
    if (slash < 0) {
        for (const auto &d : m_devices)
            if (d->name == name)
                return d.get();
        return nullptr;
    }
    const Station *s = station(name.left(slash));
    return s ? s->findPort(name.mid(slash + 1)) : nullptr;
}

std::unique_ptr<Network> Network::build(const NetworkDescription &d, const ProgramLoader &loader,
                                        QString *error) {
    std::unique_ptr<Network> net(new Network);
    net->m_description = d;
    const QString prefix = d.file + QStringLiteral(": ");
    auto fail = [&](const QString &why) {
        *error = prefix + why;
        return nullptr;
    };
    for (const StationDescription &sd : d.stations) {
        LoadedStation loaded;
        QString why;
        if (!loader(sd, &loaded, &why)) {
            *error = why;
            return nullptr;
        }
        const qint64 period = sd.periodMs > 0 ? sd.periodMs : d.periodMs;
        auto station = std::make_unique<Station>(net.get(), sd.name, loaded, period);
        // The project's port settings, then the network's over them, key by key.
        QStringList names = loaded.ports.keys();
        for (const QString &k : sd.ports.keys())
            if (!names.contains(k))
                names << k;
        for (const QString &port : names) {
            std::vector<model::PortLayer> layers;
            if (loaded.ports.contains(port))
                layers.push_back({loaded.ports.value(port).toObject(),
                                  sd.program + QStringLiteral(": ports.") + port});
            if (sd.ports.contains(port))
                layers.push_back(
                    {sd.ports.value(port).toObject(), sd.where + QStringLiteral(".ports.") + port});
            model::PortConfig config;
            if (!model::readPortConfig(*loaded.target, loaded.model, port, layers, &config, &why))
                return fail(why);
            if (station->findPort(config.port))
                return fail(
                    NetworkTr::tr("%1.ports: %2 is named twice").arg(sd.where, config.port));
            station->addPort(std::move(config));
        }
        net->m_stations.push_back(std::move(station));
    }
    for (const DeviceDescription &dd : d.devices) {
        QString why;
        std::unique_ptr<Endpoint> device = makeDevice(net.get(), dd, &why);
        if (!device)
            return fail(why);
        net->m_actors.push_back(dynamic_cast<Actor *>(device.get()));
        net->m_devices.push_back(std::move(device));
    }
    for (const WireDescription &wd : d.wires) {
        auto wire = std::make_unique<Wire>();
        wire->name = wd.name;
        for (qsizetype k = 0; k < wd.ends.size(); ++k) {
            const QString &end = wd.ends[k];
            const QString where = QStringLiteral("%1[%2]").arg(wd.where).arg(k);
            Endpoint *e = net->endpoint(end);
            const qsizetype slash = end.indexOf(QLatin1Char('/'));
            if (!e && slash > 0) {
                Station *s = net->station(end.left(slash));
                if (!s)
                    return fail(NetworkTr::tr("%1: no station \"%2\"").arg(where, end.left(slash)));
                // A port the settings do not name: the port's first application, as a new
                // PLC has it.
                model::PortConfig config;
                QString why;
                if (!model::readPortConfig(s->target(), s->model(), end.mid(slash + 1),
                                           {{QJsonObject(), where}}, &config, &why))
                    return fail(why);
                e = s->addPort(std::move(config));
            }
            if (!e)
                return fail(NetworkTr::tr("%1: no station or device \"%2\"").arg(where, end));
            if (e->wire)
                return fail(NetworkTr::tr("%1: %2 is on wire %3 already; a port has one wire")
                                .arg(where, e->name, e->wire->name));
            e->wire = wire.get();
            wire->ends.push_back(e);
        }
        net->m_wires.push_back(std::move(wire));
    }
    // A port named only by a bridge runs its first application, as one named only in a wire
    // (the Network view offers every port of the model for a bridge).
    for (const BridgeDescription &b : d.bridges) {
        const qsizetype slash = b.end.indexOf(QLatin1Char('/'));
        Station *s = slash > 0 ? net->station(b.end.left(slash)) : nullptr;
        if (!s || net->endpoint(b.end))
            continue; // bridge.h says why when it cannot be bridged
        model::PortConfig config;
        QString why;
        if (model::readPortConfig(s->target(), s->model(), b.end.mid(slash + 1),
                                  {{QJsonObject(), b.path}}, &config, &why))
            s->addPort(std::move(config));
    }
    for (const FaultDescription &f : d.faults) {
        if (!f.wire.isEmpty()) {
            bool found = false;
            for (const auto &w : net->m_wires)
                found = found || w->name == f.wire;
            if (!found)
                return fail(NetworkTr::tr("%1: no wire \"%2\"").arg(f.where, f.wire));
        }
        if (!f.station.isEmpty() && !net->station(f.station) && !net->endpoint(f.station))
            return fail(NetworkTr::tr("%1: no station or device \"%2\"").arg(f.where, f.station));
    }
    QString why;
    if (!makeSharedLinks(net.get(), &net->m_groups, &why))
        return fail(why);
    for (const auto &g : net->m_groups)
        net->m_actors.push_back(g.get());
    for (const auto &s : net->m_stations) {
        // An instruction on a port that runs another application would speak the wrong
        // protocol (LINK's Computer Link frames on a MODBUS port): the station does not start.
        const simulator::Program &program = s->engine().program();
        for (const simulator::CommStep &c : program.comms) {
            const StationPort *port = s->findPort(c.port);
            if (!port || !c.spec || c.spec->portApplications.empty())
                continue;
            const char *id = port->config().application->id;
            const auto &allowed = c.spec->portApplications;
            if (std::none_of(allowed.begin(), allowed.end(),
                             [id](const char *a) { return qstrcmp(a, id) == 0; })) {
                QStringList names;
                for (const char *a : allowed)
                    names << QString::fromLatin1(a);
                //: %1 station, %2 line, %3 instruction (LINK), %4 port (CP2), %5 what it runs, %6
                //: the applications %3 takes
                return fail(NetworkTr::tr("%1: line %2: %3 drives %4, which runs %5; %3 needs "
                                          "%6")
                                .arg(s->name())
                                .arg(program.lines[std::size_t(c.step)])
                                .arg(c.spec->mnemonic, port->name, QString::fromLatin1(id),
                                     names.join(QStringLiteral(" / "))));
            }
        }
        s->start();
        net->m_actors.push_back(s.get());
    }
    return net;
}

bool Network::silent(const QString &owner, qint64 us) const {
    for (const FaultDescription &f : m_description.faults)
        if (f.kind == FaultDescription::Kind::Silent && f.station == owner &&
            us >= f.fromMs * 1000 && (f.toMs < 0 || us < f.toMs * 1000))
            return true;
    return false;
}

void Network::endFaults(FaultDescription::Kind kind, const QString &target) {
    const qint64 nowMs = m_now / 1000;
    for (FaultDescription &f : m_description.faults) {
        const QString &on = kind == FaultDescription::Kind::Cut ? f.wire : f.station;
        if (f.kind == kind && on == target && (f.toMs < 0 || f.toMs > nowMs))
            f.toMs = std::max(f.fromMs, nowMs);
    }
}

bool Network::cut(const Wire &wire, qint64 us) const {
    for (const FaultDescription &f : m_description.faults)
        if (f.kind == FaultDescription::Kind::Cut && f.wire == wire.name && us >= f.fromMs * 1000 &&
            (f.toMs < 0 || us < f.toMs * 1000))
            return true;
    return false;
}

qint64 Network::transmit(Endpoint *from, const QByteArray &sent) {
    const qint64 start = std::max(m_now, from->txEndUs);
    const qint64 end = start + wireTimeUs(sent.size(), from->lineSettings());
    from->txEndUs = end;
    TrafficRecord r{start, end, from->wire ? from->wire->name : QString(), from->name, sent, {}};
    if (silent(from->owner, start)) {
        r.note = NetworkTr::tr("silent (fault): not sent");
        r.delivered = false;
        record(r);
        return end;
    }
    if (!from->wire) {
        r.note = NetworkTr::tr("the port is on no wire");
        r.delivered = false;
        record(r);
        return end;
    }
    Wire &w = *from->wire;
    const int frame = w.frames++;
    QByteArray bytes = sent;
    for (const FaultDescription &f : m_description.faults)
        if (f.kind == FaultDescription::Kind::Corrupt && f.wire == w.name && f.frame == frame &&
            f.byte < bytes.size()) {
            bytes[f.byte] = char(bytes[f.byte] ^ f.mask);
            r.bytes = bytes;
            r.note = NetworkTr::tr("byte %1 corrupted (fault): XOR %2h")
                         .arg(f.byte)
                         .arg(QString::number(f.mask, 16).toUpper());
        }
    if (cut(w, start)) {
        r.note = NetworkTr::tr("wire cut (fault): not delivered");
        r.delivered = false;
        record(r);
        return end;
    }
    // Two senders at once on a half-duplex line: both frames are lost as sent.
    auto transmission = std::make_shared<Wire::Transmission>(Wire::Transmission{from, start, end});
    std::erase_if(w.active, [&](const auto &t) { return t->endUs <= start; });
    for (const auto &t : w.active)
        if (t->sender != from) {
            t->collided = true;
            transmission->collided = true;
            r.note = NetworkTr::tr("collision with %1: both frames garbled").arg(t->sender->name);
        }
    w.active.push_back(transmission);
    record(r);
    for (Endpoint *e : w.ends)
        if (e != from)
            m_deliveries.push(
                Delivery{end, m_sequence++, e, bytes, from->lineSettings(), transmission});
    return end;
}

void Network::inject(Endpoint *at, const QByteArray &bytes) {
    transmit(at, bytes);
}

void Network::attach(std::unique_ptr<Endpoint> endpoint, Endpoint *beside) {
    if (!beside->wire) {
        auto wire = std::make_unique<Wire>();
        wire->name = endpoint->name;
        wire->ends.push_back(beside);
        beside->wire = wire.get();
        m_wires.push_back(std::move(wire));
    }
    endpoint->wire = beside->wire;
    beside->wire->ends.push_back(endpoint.get());
    m_devices.push_back(std::move(endpoint));
}

bool Network::runUntil(qint64 until) {
    m_interrupt = false; // only an actor run here interrupts it
    if (holdingStation())
        return false;
    if (m_resumeFrom > 0 && !runActors(std::exchange(m_resumeFrom, 0)))
        return false;
    while (true) {
        qint64 next = m_deliveries.empty() ? kNever : m_deliveries.top().atUs;
        for (const Actor *a : m_actors)
            next = std::min(next, a->nextUs());
        if (next > until || next == kNever)
            break;
        m_now = std::max(m_now, next);
        // What arrives at an instant is there for what runs at it.
        while (!m_deliveries.empty() && m_deliveries.top().atUs <= m_now) {
            Delivery d = m_deliveries.top();
            m_deliveries.pop();
            if (d.transmission->collided) {
                // Two drivers on a half-duplex line: the receivers read nothing sent; the
                // model's choice is every bit inverted, each character a framing error.
                QByteArray garbled = d.bytes;
                for (char &c : garbled)
                    c = char(~c);
                const Received got = acrossLine(garbled, d.line, d.to->lineSettings());
                d.to->deliver(got.bytes, int(got.bytes.size()), d.atUs);
            } else {
                const Received got = acrossLine(d.bytes, d.line, d.to->lineSettings());
                d.to->deliver(got.bytes, got.errors, d.atUs);
            }
        }
        if (!runActors(0))
            return false;
    }
    m_now = std::max(m_now, until);
    return true;
}

bool Network::runActors(std::size_t from) {
    for (std::size_t i = from; i < m_actors.size(); ++i) {
        Actor *a = m_actors[i];
        if (a->nextUs() > m_now)
            continue;
        a->run(m_now);
        if (a->holding() || std::exchange(m_interrupt, false)) {
            m_resumeFrom = i + 1;
            return false;
        }
    }
    return true;
}

Station *Network::holdingStation() const {
    for (const auto &s : m_stations)
        if (s->holding())
            return s.get();
    return nullptr;
}

} // namespace rung::network
