#pragma once

// Modbus (Modbus Application Protocol V1.1b3; RTU over serial line V1.02; for the PLC maps
// the Vigor M/VB/VH communication manual, B-3-6, and the PL110 manual, chapter 3): the PDU,
// RTU framing with CRC-16 and TCP framing with the MBAP header, no I/O. This file holds what
// both sides share; the master's side is modbus_master.h, the slave's modbus_slave.h.

#include "comms/protocol/protocol_error.h"

#include <QByteArray>

#include <cstdint>
#include <optional>
#include <vector>

namespace rung::comms::modbus {

enum Function : std::uint8_t {
    ReadCoils = 0x01,
    ReadDiscreteInputs = 0x02,
    ReadHoldingRegisters = 0x03,
    ReadInputRegisters = 0x04,
    WriteSingleCoil = 0x05,
    WriteSingleRegister = 0x06,
    WriteMultipleCoils = 0x0F,
    WriteMultipleRegisters = 0x10,
};

enum Exception : std::uint8_t {
    IllegalFunction = 0x01,
    IllegalDataAddress = 0x02,
    IllegalDataValue = 0x03,
    ServerDeviceFailure = 0x04,
    Acknowledge = 0x05,
    ServerDeviceBusy = 0x06,
    MemoryParityError = 0x08,
    GatewayPathUnavailable = 0x0A,
    GatewayTargetNoResponse = 0x0B,
};

// The protocol's own limits per request (Application Protocol 6.1..6.12).
inline constexpr int MaxReadBits = 2000;
inline constexpr int MaxReadRegisters = 125;
inline constexpr int MaxWriteBits = 1968;
inline constexpr int MaxWriteRegisters = 123;
inline constexpr int BroadcastUnit = 0;
// The longest frames: an RTU frame holds at most 256 bytes (serial line V1.02, 2.5.1.1); a
// TCP frame the 7-byte MBAP header and a PDU of at most 253 (Application Protocol 4.1).
inline constexpr int MaxRtuFrame = 256;
inline constexpr int MaxTcpFrame = 7 + 253;
// ASCII (serial line V1.02, 2.5.2): ':', the RTU frame's address and PDU as hex digits, the
// LRC as two more, CR LF: at most 513 characters.
inline constexpr int MaxAsciiFrame = 1 + 2 * (1 + 253 + 1) + 2;

struct Request {
    std::uint8_t function = ReadHoldingRegisters;
    int address = 0;                      // 0-based, as on the wire
    int count = 1;                        // bits or registers (1 for 05 / 06)
    std::vector<std::uint16_t> registers; // 06, 10
    std::vector<bool> bits;               // 05, 0F
};

struct Response {
    std::uint8_t function = ReadHoldingRegisters; // without the exception bit
    int exception = 0;                    // 0, or the exception code (function | 80h on the wire)
    int address = 0;                      // echoed by 05, 06, 0F, 10
    int count = 0;                        // echoed by 0F, 10; value for 06; 05: FF00h / 0000h
    std::vector<std::uint16_t> registers; // 03, 04
    std::vector<bool> bits;               // 01, 02 (padded to whole bytes by the wire)
};

std::uint16_t crc16(QByteArrayView bytes);
QByteArray rtuFrame(int unit, QByteArrayView pdu);                  // unit, PDU, CRC low first
QByteArray tcpFrame(int transaction, int unit, QByteArrayView pdu); // MBAP + PDU
// ':' address PDU LRC CR LF, upper-case hex (serial line V1.02, 2.5.2, 6.2.1).
QByteArray asciiFrame(int unit, QByteArrayView pdu);
// The LRC of the address and the PDU: the two's complement of their 8-bit sum.
std::uint8_t lrc(QByteArrayView bytes);

QString exceptionText(int code);

enum class Framing : std::uint8_t { Rtu, Tcp, Ascii };

namespace detail {
// The address, the PDU and the LRC of an ASCII frame between ':' and CR LF, the LRC checked
// and removed; nullopt with the reason when the characters are not a frame.
std::optional<QByteArray> asciiBody(QByteArrayView text, QString *why);
} // namespace detail

} // namespace rung::comms::modbus
