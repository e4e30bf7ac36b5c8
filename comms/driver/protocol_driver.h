#pragma once

// One PLC protocol spoken as a master, in the units of its address spaces (protocol_map.h):
// read and write runs of units, a bit, force, RUN/STOP and identification where the protocol
// has them, and what a read costs on the wire, for the request planner. The device layer
// (driver.h) turns devices into units and back; these classes know frames only.

#include "comms/driver/link.h"
#include "model/target/protocol_map.h"

#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace rung::model {
class Target;
}

namespace rung::comms {

// The protocols a driver speaks, as a user picks them (`--protocol vigor|modbus|modbus-tcp|
// hostlink`). Modbus RTU may travel over TCP too (a serial device server); modbus-tcp is
// Modbus TCP with the MBAP header.
enum class ProtocolKind : std::uint8_t { VigorLink, ModbusRtu, ModbusTcp, HostLink };

model::ProtocolId protocolIdOf(ProtocolKind kind);
// The protocols a target can be reached by: those whose map its table has (a VPC: none).
std::vector<ProtocolKind> protocolsOf(const model::Target &target);
QString protocolName(ProtocolKind kind); // "Vigor Computer Link", "Modbus RTU", ...

// Stop: a PLC that has RUN and STOP only (its RUN bit is off); Program / Monitor / Run: Host Link.
enum class PlcMode : std::uint8_t { Unknown, Stop, Program, Monitor, Run };
QString modeName(PlcMode mode); // translated: "PROGRAM", "MONITOR", "RUN"

struct PlcIdentity {
    QString model;   // as the PLC reports it, with a word on what it is
    QString version; // empty when the protocol has none
};

class ProtocolDriver {
public:
    ProtocolDriver(Link &link, const model::Target &target, const model::ProtocolMap &map,
                   int station);
    virtual ~ProtocolDriver();
    ProtocolDriver(const ProtocolDriver &) = delete;
    ProtocolDriver &operator=(const ProtocolDriver &) = delete;

    Link &link() { return m_link; }
    const model::ProtocolMap &map() const { return m_map; }
    const model::Target &target() const { return m_target; }
    int station() const { return m_station; }
    // "Vigor station 0 on /dev/ttyUSB0": the PLC as messages name it.
    virtual QString plcName() const = 0;

    // --- the planner's cost model ---
    // The most units one read may ask for in the space.
    virtual int maxReadUnits(model::ProtocolSpace space) const = 0;
    // Bytes on the wire (request and reply, every part and delimiter) to read `units` units.
    virtual int readFrameBytes(model::ProtocolSpace space, int units) const = 0;
    // Whether the space carries values as BCD digits (Host Link RC / WC).
    virtual bool bcdUnits(model::ProtocolSpace) const { return false; }

    // --- I/O; `what` says what it is for ("reading D100 ..."), messages start with it ---
    // Units as numbers: a link byte, a register or word (16 bits), a bit 0/1.
    virtual DriverError readUnits(model::ProtocolSpace space, int start, int count,
                                  std::vector<std::uint32_t> *units, const QString &what) = 0;
    virtual DriverError writeUnits(model::ProtocolSpace space, int start,
                                   const std::vector<std::uint32_t> &units,
                                   const QString &what) = 0;
    // One bit: a bit inside a unit (address.bit >= 0) or a 1-bit unit.
    virtual DriverError writeBit(const model::ProtocolAddress &address, bool on,
                                 const QString &what) = 0;

    virtual bool canForce() const { return false; }
    virtual DriverError forceBit(const model::ProtocolAddress &address, bool on,
                                 const QString &what);
    virtual DriverError releaseAllForces(const QString &what);

    // A status command for the mode (Host Link MS); false: the device layer looks at the
    // target's RUN bit instead, if it has one in the map.
    virtual bool readsMode() const { return false; }
    virtual DriverError readMode(PlcMode *mode);
    virtual bool setsMode() const { return false; }
    // PROGRAM / MONITOR / RUN (Host Link) rather than STOP / RUN.
    virtual bool hasMonitorMode() const { return false; }
    virtual DriverError setMode(PlcMode mode);
    // Before a write: Host Link switches a PLC in RUN to MONITOR (writes answer end code 01
    // in RUN) and says so in *notice.
    virtual DriverError prepareWrite(QString *notice);
    virtual bool identifies() const { return false; }
    virtual DriverError identify(PlcIdentity *identity);

protected:
    DriverError unsupported(const QString &what, const QString &why) const;
    // A bit inside a word (address.bit >= 0) for a protocol with no command that writes one:
    // the word is read, the bit changed and the word written back. Not atomic: a bit of the
    // same word that the PLC's program changes in between is overwritten.
    DriverError writeBitOfWord(const model::ProtocolAddress &address, bool on, const QString &what);

    Link &m_link;
    const model::Target &m_target;
    const model::ProtocolMap &m_map;
    int m_station;
};

// The driver of a protocol for a target; nullptr with *error when the target has no map for
// that protocol.
std::unique_ptr<ProtocolDriver> makeProtocolDriver(ProtocolKind kind, Link &link,
                                                   const model::Target &target, int station,
                                                   QString *error);

} // namespace rung::comms
