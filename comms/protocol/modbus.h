#pragma once

// Modbus (Modbus Application Protocol V1.1b3; RTU over serial line V1.02; for the PLC maps
// the Vigor M/VB/VH communication manual, B-3-6, and the PL110 manual, chapter 3): the PDU,
// RTU framing with CRC-16 and TCP framing with the MBAP header, master and slave side, no I/O.

#include "comms/protocol/protocol_error.h"

#include <QByteArray>

#include <cstdint>
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

QByteArray encodeRequestPdu(const Request &request);
QByteArray encodeResponsePdu(const Response &response);

std::uint16_t crc16(QByteArrayView bytes);
QByteArray rtuFrame(int unit, QByteArrayView pdu);                  // unit, PDU, CRC low first
QByteArray tcpFrame(int transaction, int unit, QByteArrayView pdu); // MBAP + PDU

QString exceptionText(int code);

// A request PDU as the slave reads it. Failure carries the exception to answer with.
struct ParsedRequest {
    Request request;
    int exception = 0;
};
ParsedRequest parseRequestPdu(QByteArrayView pdu);

enum class Framing : std::uint8_t { Rtu, Tcp };

// Master side: the reply to one request, from bytes as they arrive. Over RTU the length comes
// from the function code and byte count, so no silence timer is needed to end a reply.
class ReplyDecoder : public ReplyDecoderBase {
public:
    ReplyDecoder(Framing framing, int unit, const Request &request, int transaction = 0);
    FrameStatus feed(QByteArrayView bytes);
    ProtocolError deadlinePassed(int waitedMs) const;
    const Response &response() const { return m_response; }
    // Bytes held: never more than one byte past the longest reply a header can announce.
    qsizetype buffered() const { return m_buffer.size(); }
    static constexpr qsizetype MaxBuffered = 3 + 255 + 2 + 1;

private:
    FrameStatus decodePdu(QByteArrayView pdu, int unit);
    qsizetype expectedRtuLength() const; // 0 = not known yet

    Framing m_framing;
    int m_unit;
    Request m_request;
    int m_transaction;
    QByteArray m_buffer;
    qsizetype m_received = 0;
    Response m_response;
};

// Slave side: requests, one after another, from bytes as they arrive.
//  RTU: length from the function code; an unknown function ends at silence() (the 3.5
//  character gap); a frame with a bad CRC is dropped, as the RTU spec says (no reply).
//  TCP: the MBAP length field.
// Memory stays bounded whatever arrives: an RTU frame that grows past 256 bytes (an unknown
// function on a line without gaps, or a byte count no request can have) is dropped with all
// that follows until silence(); bytes that arrive while a request waits for next() are kept
// up to one frame, the rest dropped. discarded() says what was thrown away last and why.
class RequestDecoder {
public:
    explicit RequestDecoder(Framing framing)
        : m_framing(framing) {}
    FrameStatus feed(QByteArrayView bytes);
    // The line was quiet for 3.5 characters: what is buffered is one whole RTU frame.
    FrameStatus silence();
    FrameStatus status() const { return m_status; }
    int unit() const { return m_unit; }
    int transaction() const { return m_transaction; }
    const ParsedRequest &parsed() const { return m_parsed; }
    int droppedFrames() const { return m_dropped; } // wrong CRC, too long, not Modbus
    const ProtocolError &discarded() const { return m_discarded; }
    qsizetype buffered() const { return m_buffer.size(); }
    static constexpr qsizetype MaxBuffered = 2 * MaxTcpFrame; // a request and the next one
    void next();

private:
    FrameStatus take(qsizetype length);
    void drop(QString why);
    void keepPending();
    Framing m_framing;
    QByteArray m_buffer;
    qsizetype m_used = 0;
    FrameStatus m_status = FrameStatus::NeedMore;
    int m_unit = 0;
    int m_transaction = 0;
    ParsedRequest m_parsed;
    int m_dropped = 0;
    bool m_skipToSilence = false;
    ProtocolError m_discarded;
};

} // namespace rung::comms::modbus
