#pragma once

// Where a PLC is and how to speak to it: the protocol, the port (a serial port, a
// pseudo-terminal, a TCP host) with its line settings, the station, timeouts and retries.
// The defaults are each protocol's: Vigor CP1 19200 7E1 station 0 (Vigor M/VB/VH
// communication manual, B-5-1), PL110 19200 8N1 unit 1 (PL110 manual 2.1.2, 3.1), Host Link
// 9600 7E2 unit 0 (the common PC Setup; Omron CPM1/SRM1 programming manual W353, Host Link).

#include "comms/driver/link.h"
#include "comms/driver/protocol_driver.h"
#include "comms/transport/serial_settings.h"

#include <memory>

namespace rung::comms {

struct ConnectionSettings {
    enum class Via : std::uint8_t { Serial, Pty, Tcp };
    ProtocolKind protocol = ProtocolKind::ModbusRtu;
    Via via = Via::Serial;
    QString port; // serial port or pseudo-terminal path
    SerialSettings serial;
    QString host;
    quint16 tcpPort = 502;
    int station = 1;
    LinkSettings link;
    // The shortest time from the start of one refresh of the watched devices to the start of
    // the next (0: as fast as the PLC answers).
    int pollIntervalMs = 20;
    // How often a mode that needs its own command (Host Link MS) is read.
    int modePollMs = 1000;
    // Reconnecting after the link is lost: the first wait, doubled up to the last.
    int reconnectMinMs = 250;
    int reconnectMaxMs = 4000;

    // "/dev/ttyUSB0", "192.168.1.5:502": where, as a user would say it.
    QString where() const;
};

// Each protocol's usual line settings and station (see above), on the given port.
ConnectionSettings defaultSettings(ProtocolKind protocol);

// The link settings with the line's timing: on a serial port the time per character, and
// for Modbus RTU the 3.5-character silence before each request.
LinkSettings lineTiming(const ConnectionSettings &settings);

// A transport for the settings, not yet open. A TCP transport must be made and used on one
// thread (QTcpSocket): the session calls this on its worker.
std::unique_ptr<Transport> makeTransport(const ConnectionSettings &settings);
// A transport for a port the user names: a pseudo-terminal (a /dev/pts path, or a link to
// one) through termios, anything else through libserialport with the line settings.
std::unique_ptr<Transport> makePortTransport(const QString &port, const SerialSettings &line);

// "vigor", "modbus", "modbus-tcp", "hostlink" (the command line's names); false when unknown.
bool parseProtocolKind(QStringView name, ProtocolKind *kind);
// The command line's name of a protocol ("modbus-tcp").
QString protocolCommandName(ProtocolKind kind);

// The stations (units) a protocol numbers: Vigor 0..255, Modbus 1..247, Host Link 0..31.
struct StationRange {
    int first = 0;
    int last = 0;
};
StationRange stationRange(ProtocolKind protocol);

} // namespace rung::comms
