#pragma once

// Networks for the tests: listings given as texts (or read from files), loaded as the command
// line loads a listing (the checks, then the compiler), and the trace and traffic of a run as
// text.

#include "network/net_trace.h"
#include "network/network.h"
#include "network/station.h"
#include "network/traffic.h"

#include "model/listing/il.h"
#include "simulator/compiler.h"

#include <QFile>

#include <gtest/gtest.h>

#include <map>

namespace rung::network::test {

// Programs by the name a station's "program" gives; a name not here is read as a file.
inline ProgramLoader listingLoader(std::map<QString, QString> programs = {}) {
    return [programs](const StationDescription &s, LoadedStation *loaded, QString *error) {
        QString text;
        if (const auto it = programs.find(s.program); it != programs.end()) {
            text = it->second;
        } else {
            QFile f(s.path);
            if (!f.open(QIODevice::ReadOnly)) {
                *error = QStringLiteral("cannot read %1").arg(s.path);
                return false;
            }
            text = QString::fromUtf8(f.readAll());
        }
        const QString id = s.target.isEmpty() ? model::declaredTarget(text) : s.target;
        const model::Target *target =
            model::Target::byId(id.isEmpty() ? QStringLiteral("vigor") : id);
        const model::ModelVariant *variant =
            s.model.isEmpty() ? &target->defaultModel() : target->model(s.model);
        const model::ParseResult parsed = model::parseInstructionList(*target, text, variant);
        if (!parsed.ok()) {
            *error = s.name + QStringLiteral(": ") + parsed.errors.front().message;
            return false;
        }
        model::CheckOptions checks;
        checks.model = variant;
        const simulator::CompileResult compiled = simulator::prepareProgram(parsed.list, checks);
        if (!compiled.ok()) {
            *error = s.name + QStringLiteral(": ") + compiled.diagnostics.front().message;
            return false;
        }
        loaded->program = compiled.program;
        loaded->target = target;
        loaded->model = variant;
        return true;
    };
}

// The traffic the network's sink records lives apart from the NetRun, so that moving a
// NetRun (returning it without copy elision, assigning it) leaves the sink writing where
// records and traffic still read.
struct NetRunLog {
    QString traffic;
    std::vector<TrafficRecord> records;
};

struct NetRun {
    std::unique_ptr<Network> net;
    QString error;
    QString trace;
    std::shared_ptr<NetRunLog> log = std::make_shared<NetRunLog>();
    QString &traffic = log->traffic;
    std::vector<TrafficRecord> &records = log->records;
};

// Builds the network from its JSON (or reads `file` when json is empty) and, when args are
// given, runs a trace with them; the traffic is recorded from the start.
inline NetRun runNetwork(const QByteArray &json, const std::map<QString, QString> &programs,
                         const QStringList &args = {},
                         const QString &file = QStringLiteral("t.rungnet")) {
    NetRun r;
    NetworkDescription d;
    const bool read = json.isEmpty() ? readNetworkFile(file, &d, &r.error)
                                     : parseNetwork(json, file, &d, &r.error);
    if (!read)
        return r;
    r.net = Network::build(d, listingLoader(programs), &r.error);
    if (!r.net)
        return r;
    r.net->setTrafficSink([log = r.log](const TrafficRecord &t) {
        log->records.push_back(t);
        log->traffic += formatTraffic(t) + QLatin1Char('\n');
    });
    if (args.isEmpty())
        return r;
    NetTraceRequest request;
    if (!parseNetworkTraceOptions(*r.net, args, &request, &r.error))
        return r;
    QTextStream out(&r.trace);
    runNetworkTrace(*r.net, request, out);
    out.flush();
    return r;
}

inline std::int32_t value(const Network &net, const QString &station, const QString &device) {
    Station *s = net.station(station);
    const auto parsed = model::parseAddress(s->target(), device);
    return s->engine().value(std::get<model::Address>(parsed));
}

inline bool bit(const Network &net, const QString &station, const QString &device) {
    Station *s = net.station(station);
    const auto parsed = model::parseAddress(s->target(), device);
    return s->engine().bit(std::get<model::Address>(parsed));
}

inline QByteArray hex(const char *text) {
    return QByteArray::fromHex(QByteArray(text).replace(' ', ""));
}

} // namespace rung::network::test
