#include "cli_serve.h"

#include "cli_load_program.h"
#include "cli_network.h"
#include "cli_stop_signals.h"

#include "app/tr.h"
#include "app/virtual_plc/virtual_plc.h"
#include "comms/driver/connection.h"
#include "comms/driver/protocol_driver.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/serial_transport.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <ctime>
#include <mutex>
#include <optional>
#include <pthread.h>
#include <sys/stat.h>
#include <unistd.h>

namespace rung::app {

namespace {

using comms::SerialSettings;
using comms::slave::Fault;

QString serveUsageText() {
    return ServeTr::tr(
        "usage: rungstudio-cli serve FILE [--target T] [--model M] --protocol "
        "vigor|modbus|modbus-tcp|hostlink (--pty [--link PATH] | --port NAME | --tcp "
        "HOST:PORT) [--station N] [--baud B] [--frame 8N1|7E1|7E2|...] [--period MS] "
        "[--fault bad-checksum|silent|wrong-station|garbage|truncated|split]");
}

// What ended the serving: a signal, or the line failing.
struct Ending {
    std::mutex mutex;
    QString failure;
};

// The target of the symbolic link at path; empty when path is no symbolic link.
QString linkTarget(const QByteArray &path) {
    struct stat st {};
    if (::lstat(path.constData(), &st) != 0 || !S_ISLNK(st.st_mode))
        return {};
    QByteArray target(PATH_MAX, '\0');
    const ssize_t n = ::readlink(path.constData(), target.data(), std::size_t(target.size()));
    return n > 0 ? QString::fromLocal8Bit(target.left(n)) : QString();
}

// A stable name for the pseudo-terminal (--link): a symbolic link to it, made when serving
// starts and removed when it ends, so that a master (the IDE, mbpoll) finds the PLC at the
// same path after serve restarts. What is at the path already is replaced only when it is
// such a link, one into /dev/pts/ (left by a serve that was killed); anything else is the
// user's and is refused.
class PtyLink {
public:
    explicit PtyLink(QString path)
        : m_path(QFileInfo(path).absoluteFilePath()) {}
    ~PtyLink() { remove(); }
    PtyLink(const PtyLink &) = delete;
    PtyLink &operator=(const PtyLink &) = delete;

    const QString &path() const { return m_path; }

    // Whether the path may take the link; false with why.
    bool usable(QString *error) const {
        const QByteArray path = QFile::encodeName(m_path);
        struct stat st {};
        if (::lstat(path.constData(), &st) != 0) {
            if (errno == ENOENT)
                return true;
            *error =
                ServeTr::tr("--link %1: %2").arg(m_path, QString::fromLocal8Bit(strerror(errno)));
            return false;
        }
        if (S_ISLNK(st.st_mode) && linkTarget(path).startsWith(QLatin1String("/dev/pts/")))
            return true;
        *error =
            ServeTr::tr("--link %1: something that is not a link to a pseudo-terminal is there "
                        "already; it is left as it is: remove it or give another path")
                .arg(m_path);
        return false;
    }

    // Points the path at the pseudo-terminal (the old link replaced in one step).
    bool make(const QString &pty, QString *error) {
        const QByteArray path = QFile::encodeName(m_path);
        const QByteArray fresh = path + ".new-" + QByteArray::number(qint64(::getpid()));
        ::unlink(fresh.constData());
        if (::symlink(QFile::encodeName(pty).constData(), fresh.constData()) != 0 ||
            ::rename(fresh.constData(), path.constData()) != 0) {
            *error = ServeTr::tr("--link %1: the link cannot be made: %2")
                         .arg(m_path, QString::fromLocal8Bit(strerror(errno)));
            ::unlink(fresh.constData());
            return false;
        }
        m_pty = pty;
        return true;
    }

    // Removes the link if it is still this serve's (another may have taken the path since).
    void remove() {
        if (m_pty.isEmpty())
            return;
        const QByteArray path = QFile::encodeName(m_path);
        if (linkTarget(path) == m_pty)
            ::unlink(path.constData());
        m_pty.clear();
    }

private:
    QString m_path;
    QString m_pty; // what the link points to, once made
};

} // namespace

int runServeCommand(const QStringList &args, QTextStream &out, QTextStream &err) {
    // A network (docs/network.md): its bridges on real lines, in real time.
    for (qsizetype i = 0; i < args.size(); ++i)
        if (!args[i].startsWith(QLatin1String("--")) && isNetworkFile(args[i]))
            return runNetworkServe(args[i], args.mid(0, i) + args.mid(i + 1), out, err);
    ProgramOptions program;
    QString protocolName, portName, tcp, faultName, linkPath;
    bool pty = false;
    int station = -1, baud = 0;
    qint64 period = 0;
    QString format;
    auto fail = [&err](const QString &message) {
        err << message << '\n' << serveUsageText() << '\n';
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
        else if (a == QLatin1String("--link"))
            ok = value(&linkPath) && !linkPath.isEmpty();
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
    if (!linkPath.isEmpty() && !pty)
        return fail(ServeTr::tr("--link names the pseudo-terminal of --pty (a port keeps its own "
                                "name, a TCP address is given)"));
    std::optional<PtyLink> link;
    if (!linkPath.isEmpty()) {
        link.emplace(linkPath);
        QString why;
        if (!link->usable(&why)) {
            err << why << '\n';
            return 2;
        }
    }
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
                    ? ServeTr::tr("%1 has no published protocol to serve (its manual gives none)")
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
    QString linked; // the pseudo-terminal the link points to
    if (pty) {
        auto transport = comms::PtyTransport::createPair(&error);
        if (transport) {
            where = transport->peerPath();
            if (!plc.serve(std::move(transport), &error))
                where.clear();
        }
        if (!where.isEmpty() && link) {
            linked = where;
            where = link->make(linked, &error) ? link->path() : QString();
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
    // The first line says where the PLC is reached (with --link, the link); a script reads
    // it before anything else.
    out << where << Qt::endl;
    err << ServeTr::tr("%1 serves %2 (%3, %4, station %5) on %6; stop it with Ctrl+C")
               .arg(loaded.target->displayName, program.file,
                    QCoreApplication::translate("rung::model::Target", map->description),
                    protocolName)
               .arg(slave.station)
               .arg(linked.isEmpty()
                        ? where
                        : ServeTr::tr("%1 (a link to %2, removed at the end)").arg(where, linked))
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
    if (link)
        link->remove();
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
