#pragma once

// A serial port as a PLC's program drives it (Vigor RS, LINK, MBUS, FROM / TO of a VB-1COM;
// PL110 SEND, COM / EXP): bytes out and in on the virtual clock of a simulation. Below the
// simulator and comms: the engine's communication instructions talk to this interface, the
// network (network/) implements it for each port of a station, and the protocol a master
// instruction speaks is comms' codec behind MasterProtocol (master_protocol.h), so that one
// codec per protocol serves the IDE's master, the virtual PLC and the PLC-side master alike.

#include "model/comm/master_protocol.h"
#include "model/comm/port_config.h"

#include <QByteArray>

namespace rung::model {

class PlcPort {
public:
    virtual ~PlcPort() = default;
    PlcPort() = default;
    PlcPort(const PlcPort &) = delete;
    PlcPort &operator=(const PlcPort &) = delete;

    virtual const PortConfig &config() const = 0;
    // The line now: the configured one, or what the program set (a VB-1COM's BFM #0).
    virtual const SerialSettings &line() const = 0;
    virtual void setLine(const SerialSettings &line) = 0;
    // The virtual time, in microseconds.
    virtual qint64 nowUs() const = 0;
    // Starts sending the bytes (after what is still being sent); returns the virtual time the
    // last of them will have left the port.
    virtual qint64 send(QByteArrayView bytes) = 0;
    virtual bool sending() const = 0;
    // The bytes received since the last call, in order.
    virtual QByteArray receive() = 0;
    // When the last byte arrived (microseconds; -1: none yet), for time-outs between bytes.
    virtual qint64 lastReceivedUs() const = 0;
    // Characters received with a parity or framing error since the last call (a wrong baud
    // rate or format on the wire); their bytes are among receive()'s, as a UART hands them on.
    virtual int takeCharacterErrors() = 0;
    // The codec of the master protocol the port's application speaks (Computer Link for LINK,
    // MODBUS RTU / ASCII for MBUS and COM / EXP); nullptr when it has none.
    virtual MasterProtocol *master() = 0;
    // The program takes the port from its protocol (PL110 free-port, PL110 manual 4.2.19): while
    // on, the port answers no master and what arrives is the program's alone.
    virtual void setProgramDriven(bool on) = 0;
    // The slave's side (a port that answers its protocol): when the last request for this
    // station came whole and was answered (-1: none yet), for the PL110's link supervision
    // (PL110 manual 2.1.2, SM70 / SM80 / SM90 of a slave port).
    virtual qint64 lastAnsweredRequestUs() const { return -1; }
    // Requests for this station that came wrong (a wrong CRC or sum, a wrong length) so far;
    // other stations' frames on the bus are not counted (SM77 / SM87 of a slave port).
    virtual quint64 requestErrors() const { return 0; }
};

// A station's ports, by name (Target::ports: "CP2", "MODULE1", "COM1"); an engine asks once,
// when it is attached. nullptr: the PLC has no such port in this network.
class PlcPorts {
public:
    virtual ~PlcPorts() = default;
    virtual PlcPort *port(const QString &name) = 0;
};

} // namespace rung::model
