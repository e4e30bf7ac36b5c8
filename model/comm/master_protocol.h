#pragma once

// The protocol a PLC's master instruction speaks (LINK: Vigor Computer Link; MBUS, PL110 COM /
// EXP: MODBUS), as the engine uses it: a request in the units of a protocol space, the reply's
// units or why there are none. comms/protocol implements it over its codecs (plc_master.h);
// the engine knows only this interface (docs/architecture.md, "The network room").

#include "model/target/protocol_map.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <vector>

namespace rung::model {

struct MasterRequest {
    enum class Kind : std::uint8_t {
        Read,        // count units from first (link bytes, coils, registers)
        Write,       // values into count units from first
        WriteSingle, // MODBUS 05 / 06: one unit
        SetBit,      // Vigor 70h: one bit of a unit that packs bit devices
        ResetBit,    // Vigor 71h
    };
    int station = 0;
    Kind kind = Kind::Read;
    ProtocolSpace space = ProtocolSpace::HoldingRegisters;
    int first = 0;
    int count = 1;
    int bit = -1;                      // SetBit / ResetBit: the bit in the unit
    std::vector<std::uint16_t> values; // Write, WriteSingle: a unit each (a bit: 0 / 1)
};

enum class MasterStatus : std::uint8_t {
    NeedMore, // the reply is not complete yet
    Done,     // the reply answered the request; values() holds what was read
    Refused,  // the slave answered with its error (Vigor error code, MODBUS exception)
    Garbled,  // bytes that are not the reply: noise, a wrong sum or CRC, another station
};

class MasterProtocol {
public:
    virtual ~MasterProtocol() = default;
    // The most units one request may carry (Vigor: 128 link bytes; MODBUS: 125 registers to
    // read, 123 to write, 2000 / 1968 coils).
    virtual int maxUnits(ProtocolSpace space, bool write) const = 0;
    // The frame of a request; the decoder waits for its reply from now on.
    virtual QByteArray request(const MasterRequest &request) = 0;
    // Whether the request gets a reply (a MODBUS broadcast does not).
    virtual bool expectsReply() const = 0;
    virtual MasterStatus feed(QByteArrayView bytes) = 0;
    // After Done: the units read (Read), nothing else.
    virtual const std::vector<std::uint16_t> &values() const = 0;
    // After Refused or Garbled: what came and why (translated), and the slave's code (Vigor
    // error byte, MODBUS exception; 0 when Garbled).
    virtual QString problem() const = 0;
    virtual int errorCode() const = 0;
};

} // namespace rung::model
