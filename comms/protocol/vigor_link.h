#pragma once

// Vigor M / VB / VH "Computer Link" (Vigor M/VB/VH communication manual, B-5): pure encoders
// and incremental decoders for both sides, no I/O. This file holds what both sides share; the
// master's side is vigor_link_master.h, the slave's vigor_link_slave.h.
//   request  <STX> station(2) command(2) data... <ETX> sum(2)
//   response <ACK> station(2) command(2) error(2) data... <ETX> sum(2)
// The sum adds the bytes from the first station digit up to and including ETX; its low byte is
// sent as two upper-case hex digits. Payload is upper-case ASCII hex.

#include "comms/protocol/protocol_error.h"
#include "model/target/protocol_map.h"

#include <QByteArray>

#include <cstdint>

namespace rung::comms::vigor {

inline constexpr char Stx = 0x02;
inline constexpr char Etx = 0x03;
inline constexpr char Ack = 0x06;
// 51h / 61h move at most 128 bytes (Vigor M/VB/VH communication manual, B-5-3): the model's,
// which the link map reads too.
inline constexpr int MaxBytes = model::VigorLinkMaxBytes;
// The longest frames: a 61h request of MaxBytes (STX, station, command, address, length, the
// bytes, ETX, sum) and a 51h reply of MaxBytes (ACK, station, command, error, the bytes, ETX,
// sum).
inline constexpr int MaxRequestFrame = 1 + 10 + 2 * MaxBytes + 3;
inline constexpr int MaxReplyFrame = 1 + 6 + 2 * MaxBytes + 3;

enum class Command : std::uint8_t { Read = 0x51, Write = 0x61, BitOn = 0x70, BitOff = 0x71 };

// The error byte of a response (Vigor M/VB/VH communication manual, B-5-2).
enum class ErrorCode : std::uint8_t {
    None = 0x00,
    AsciiConversion = 0x10,
    SumCheck = 0x11,
    NoSuchCommand = 0x12,
    Communication = 0x14, // PLC in STOP, parity
    AddressRange = 0x28,
};

struct Request {
    int station = 0;
    Command command = Command::Read;
    int address = 0; // byte address for 51h / 61h, bit address (byte << 3 | bit) for 70h / 71h
    int length = 0;  // bytes to read (51h); for 61h the size of data
    QByteArray data; // bytes to write (61h)
};

struct Reply {
    int station = 0;
    Command command = Command::Read;
    int error = 0;   // ErrorCode value
    QByteArray data; // bytes read (51h)
};

// The bit address of commands 70h / 71h: byte address << 3 | bit position (S20 -> 1814h).
constexpr int bitAddress(int byteAddress, int bit) {
    return byteAddress << 3 | bit;
}

// The sum of a frame body (from the first station digit through ETX) as two hex digits.
QByteArray sum(QByteArrayView body);

// Why the PLC refused, translated: "address out of range (error 28h)".
QString errorText(int code);

} // namespace rung::comms::vigor
