#include "comms/driver/connection.h"

#include "comms/transport/pty_transport.h"
#include "comms/transport/serial_transport.h"
#include "comms/transport/tcp_transport.h"

#include <QFileInfo>

namespace rung::comms {

QString ConnectionSettings::where() const {
    return via == Via::Tcp ? QStringLiteral("%1:%2").arg(host).arg(tcpPort) : port;
}

ConnectionSettings defaultSettings(ProtocolKind protocol) {
    ConnectionSettings s;
    s.protocol = protocol;
    switch (protocol) {
    // CP1: 19200, 7 bits, even, 1 stop, station 0 (Vigor M/VB/VH communication manual, B-5-1)
    case ProtocolKind::VigorLink:
        s.serial = {19200, 7, SerialSettings::Parity::Even, 1, SerialSettings::Flow::None};
        s.station = 0;
        break;
    case ProtocolKind::HostLink: // the common PC Setup: 9600, 7 bits, even, 2 stop
        s.serial = {9600, 7, SerialSettings::Parity::Even, 2, SerialSettings::Flow::None};
        s.station = 0;
        break;
    case ProtocolKind::ModbusRtu: // PL110 COM1: 19200 8N1 (PL110 manual 2.1.2, 3.1)
    case ProtocolKind::ModbusTcp:
        s.serial = {19200, 8, SerialSettings::Parity::None, 1, SerialSettings::Flow::None};
        s.station = 1;
        break;
    }
    return s;
}

LinkSettings lineTiming(const ConnectionSettings &settings) {
    LinkSettings link = settings.link;
    if (settings.via == ConnectionSettings::Via::Serial)
        link.characterUs = settings.serial.characterMicroseconds();
    // A pseudo-terminal or a serial device server still ends at a real line somewhere; the
    // gap costs at most 1.75 ms above 19200 bps (less than a character below it).
    if (settings.protocol == ProtocolKind::ModbusRtu)
        link.gapUs = settings.serial.rtuGapMicroseconds();
    return link;
}

std::unique_ptr<Transport> makeTransport(const ConnectionSettings &settings) {
    switch (settings.via) {
    case ConnectionSettings::Via::Serial: // a pseudo-terminal named as a port works too
        return makePortTransport(settings.port, settings.serial);
    case ConnectionSettings::Via::Pty:
        return std::make_unique<PtyTransport>(settings.port);
    case ConnectionSettings::Via::Tcp: {
        auto tcp = std::make_unique<TcpTransport>(settings.host, settings.tcpPort);
        tcp->setOpenTimeout(std::max(settings.link.timeoutMs, 500));
        return tcp;
    }
    }
    return nullptr;
}

std::unique_ptr<Transport> makePortTransport(const QString &port, const SerialSettings &line) {
    // A socat link names its pseudo-terminal through a symbolic link, and so does
    // `serve --pty --link PATH`, whose link may lead nowhere for a moment while serve restarts:
    // still a pseudo-terminal, opened through the link when it leads to one again.
    const QFileInfo info(port);
    QString real = info.canonicalFilePath();
    if (real.isEmpty() && info.isSymLink())
        real = info.symLinkTarget();
    if ((real.isEmpty() ? port : real).startsWith(QLatin1String("/dev/pts/")))
        return std::make_unique<PtyTransport>(port);
    return std::make_unique<SerialTransport>(port, line);
}

namespace {

// The command line's names (rungstudio-cli read/write/serve --protocol).
const struct {
    const char *name;
    ProtocolKind kind;
} kCommandNames[] = {{"vigor", ProtocolKind::VigorLink},
                     {"modbus", ProtocolKind::ModbusRtu},
                     {"modbus-tcp", ProtocolKind::ModbusTcp},
                     {"hostlink", ProtocolKind::HostLink}};

} // namespace

bool parseProtocolKind(QStringView name, ProtocolKind *kind) {
    for (const auto &n : kCommandNames)
        if (name == QLatin1String(n.name)) {
            *kind = n.kind;
            return true;
        }
    return false;
}

QString protocolCommandName(ProtocolKind kind) {
    for (const auto &n : kCommandNames)
        if (n.kind == kind)
            return QLatin1String(n.name);
    return {};
}

StationRange stationRange(ProtocolKind protocol) {
    switch (protocol) {
    // CP2 stations 0..255 (Vigor M/VB/VH communication manual, B-5-1)
    case ProtocolKind::VigorLink:
        return {0, 255};
    case ProtocolKind::HostLink: // units 00..31 (W353 Host Link)
        return {0, 31};
    case ProtocolKind::ModbusRtu: // 1..247; 0 is broadcast
    case ProtocolKind::ModbusTcp:
        return {1, 247};
    }
    return {0, 0};
}

} // namespace rung::comms
