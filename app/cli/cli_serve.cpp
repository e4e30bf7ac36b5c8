#include "cli_serve.h"

#include "cli_load_program.h"
#include "cli_stop_signals.h"

#include "app/tr.h"
#include "app/virtual_plc/virtual_plc.h"
#include "comms/driver/connection.h"
#include "comms/driver/protocol_driver.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/serial_transport.h"

#include <QCoreApplication>

#include <mutex>

namespace rung::app {

namespace {

using comms::SerialSettings;
using comms::slave::Fault;

QString usage() {
    return ServeTr::tr("usage: rungstudio-cli serve FILE [--target T] [--model M] --protocol "
                       "vigor|modbus|modbus-tcp|hostlink (--pty | --port NAME | --tcp HOST:PORT) "
                       "[--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] "
                       "[--fault bad-checksum|silent|wrong-station|garbage|truncated|split]");
}

// What ended the serving: a signal, or the line failing.
struct Ending {
    std::mutex mutex;
    QString failure;
};

} // namespace

int runServeCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    ProgramOptions program;
    QString protocolName, portName, tcp, faultName;
    bool pty = false;
    int station = -1, baud = 0;
    qint64 period = 0;
    QString format;
    auto fail = [&err](const QString &message) {
        err << message << '\n' << usage() << '\n';
        return 2;
    };
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        const auto value = [&](QString *into) {
            if (i + 1 >= args.size())
                return false;
            *into = args[++i];
            return true;
        };
        const auto number = [&](auto *into, qint64 low, qint64 high) {
            QString text;
            bool ok = value(&text);
            const qint64 n = text.toLongLong(&ok);
            if (!ok || n < low || n > high)
                return false;
            *into = static_cast<std::remove_pointer_t<decltype(into)>>(n);
            return true;
        };
        bool ok = true;
        if (a == QLatin1String("--target"))
            ok = value(&program.target);
        else if (a == QLatin1String("--model"))
            ok = value(&program.model);
        else if (a == QLatin1String("--protocol"))
            ok = value(&protocolName);
        else if (a == QLatin1String("--pty"))
            pty = true;
        else if (a == QLatin1String("--port"))
            ok = value(&portName);
        else if (a == QLatin1String("--tcp"))
            ok = value(&tcp);
        else if (a == QLatin1String("--station"))
            ok = number(&station, 0, 255);
        else if (a == QLatin1String("--baud"))
            ok = number(&baud, 50, 4'000'000);
        else if (a == QLatin1String("--frame") || a == QLatin1String("--format"))
            ok = value(&format);
        else if (a == QLatin1String("--period"))
            ok = number(&period, 1, 60'000);
        else if (a == QLatin1String("--fault"))
            ok = value(&faultName);
        else if (!a.startsWith(QLatin1String("--")) && program.file.isEmpty())
            program.file = a;
        else
            return fail(ServeTr::tr("unexpected argument %1").arg(a));
        if (!ok)
            return fail(ServeTr::tr("%1 needs a valid value").arg(a));
    }
    if (program.file.isEmpty())
        return fail(ServeTr::tr("no FILE given"));
    // One table of the protocols' line defaults and stations, the connection panel's too.
    comms::ProtocolKind kind{};
    if (!comms::parseProtocolKind(protocolName, &kind))
        return fail(protocolName.isEmpty()
                        ? ServeTr::tr("--protocol is required")
                        : ServeTr::tr("unknown protocol %1 (vigor, modbus, modbus-tcp, hostlink)")
                              .arg(protocolName));
    const comms::ConnectionSettings defaults = comms::defaultSettings(kind);
    const comms::StationRange stations = comms::stationRange(kind);
    const auto framing = kind == comms::ProtocolKind::ModbusTcp ? comms::modbus::Framing::Tcp
                                                                : comms::modbus::Framing::Rtu;
    if (int(pty) + int(!portName.isEmpty()) + int(!tcp.isEmpty()) != 1)
        return fail(ServeTr::tr("give one of --pty, --port NAME and --tcp HOST:PORT"));
    if (framing == comms::modbus::Framing::Tcp && tcp.isEmpty())
        return fail(ServeTr::tr("--protocol modbus-tcp is served over --tcp HOST:PORT"));
    QHostAddress host;
    quint16 tcpPort = 0;
    if (!tcp.isEmpty()) {
        const qsizetype colon = tcp.lastIndexOf(u':');
        bool ok = colon > 0;
        const uint port = ok ? tcp.mid(colon + 1).toUInt(&ok) : 0;
        const QString name = tcp.left(colon);
        host = name == QLatin1String("localhost") ? QHostAddress(QHostAddress::LocalHost)
                                                  : QHostAddress(name);
        if (!ok || port > 65535 || host.isNull())
            return fail(ServeTr::tr("--tcp needs HOST:PORT with a numeric address, e.g. "
                                    "127.0.0.1:1502, not %1")
                            .arg(tcp));
        tcpPort = quint16(port);
    }
    comms::slave::SlaveOptions slave;
    slave.protocol = comms::protocolIdOf(kind);
    slave.framing = framing;
    slave.line = defaults.serial;
    if (baud > 0)
        slave.line.baud = baud;
    if (!format.isEmpty() && !comms::parseFrameFormat(format, &slave.line))
        return fail(ServeTr::tr("--frame needs data bits, parity and stop bits, e.g. 8N1 or 7E2, "
                                "not %1")
                        .arg(format));
    slave.station = station >= 0 ? station : defaults.station;
    if (slave.station < stations.first || slave.station > stations.last)
        return fail(ServeTr::tr("--station %1 is outside %2..%3, the stations of %4")
                        .arg(slave.station)
                        .arg(stations.first)
                        .arg(stations.last)
                        .arg(protocolName));
    if (!faultName.isEmpty()) {
        const auto fault = comms::slave::faultFromName(faultName);
        if (!fault)
            return fail(ServeTr::tr("unknown fault %1 (%2)")
                            .arg(faultName, comms::slave::faultNames().join(QLatin1String(", "))));
        slave.fault = *fault;
    }

    LoadedProgram loaded;
    if (const int status = loadProgram(program, &loaded, err); status != 0)
        return status;
    const model::ProtocolMap *map = model::findProtocolMap(*loaded.target, slave.protocol);
    if (!map) {
        QStringList spoken;
        for (const comms::ProtocolKind k : comms::protocolsOf(*loaded.target))
            spoken << comms::protocolCommandName(k);
        err << (spoken.isEmpty()
                    ? ServeTr::tr("%1 has no published protocol to serve (protocols.md)")
                          .arg(loaded.target->displayName)
                    : ServeTr::tr("%1 does not speak %2; it speaks %3")
                          .arg(loaded.target->displayName, protocolName,
                               spoken.join(QLatin1String(", "))))
            << '\n';
        return 2;
    }

    StopSignals stopSignals; // before any thread of the virtual PLC starts

    auto ending = std::make_shared<Ending>();
    slave.onFailure = [ending](const QString &message) {
        std::lock_guard lock(ending->mutex);
        ending->failure = message;
    };
    VirtualPlc::Options options;
    options.slave = slave;
    options.periodMs = period;
    VirtualPlc plc(loaded.program, options);
    QString error;
    QString where;
    if (pty) {
        auto transport = comms::PtyTransport::createPair(&error);
        if (transport) {
            where = transport->peerPath();
            if (!plc.serve(std::move(transport), &error))
                where.clear();
        }
    } else if (!portName.isEmpty()) {
        if (plc.serve(std::make_unique<comms::SerialTransport>(portName, slave.line), &error))
            where = portName;
    } else if (plc.listen(host, tcpPort, &error)) {
        where = QStringLiteral("%1:%2").arg(host.toString()).arg(plc.port());
    }
    if (where.isEmpty()) {
        err << error << '\n';
        return 2;
    }
    // The first line says where the PLC is reached; a script reads it before anything else.
    out << where << Qt::endl;
    err << ServeTr::tr("%1 serves %2 (%3, %4, station %5) on %6; stop it with Ctrl+C")
               .arg(loaded.target->displayName, program.file,
                    QCoreApplication::translate("rung::model::Target", map->description),
                    protocolName)
               .arg(slave.station)
               .arg(where)
        << Qt::endl;

    QString failure;
    while (true) {
        if (stopSignals.wait(200))
            break;
        std::lock_guard lock(ending->mutex);
        if (!ending->failure.isEmpty()) {
            failure = ending->failure;
            break;
        }
    }
    plc.stop();
    const comms::slave::SlaveStatistics s = plc.statistics();
    err << ServeTr::tr("%1 requests answered, %2 refused with an error, %3 for other stations or "
                       "broadcast, %4 frames dropped; %5 writes")
               .arg(s.answered)
               .arg(s.refused)
               .arg(s.ignored)
               .arg(s.dropped)
               .arg(s.writes)
        << '\n';
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return 2;
    }
    return 0;
}

} // namespace rung::app
