#pragma once

// Byte transports to a PLC. libserialport serves real ports and the port list; pseudo-
// terminals and TCP get their own backends (architecture.md). Filled in by the connection
// issue; the interface is here so the room exists and builds.

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace rung::comms {

// The serial ports the system offers, by name ("/dev/ttyUSB0"), via libserialport.
QStringList availableSerialPorts();

} // namespace rung::comms
