#pragma once

// Vigor M / VB / VH "Computer Link" (Vigor M/VB/VH communication manual, B-5): pure encoders
// and incremental decoders for both sides, no I/O.
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

QByteArray encodeRequest(const Request &request);
QByteArray encodeReply(const Reply &reply);

// The sum of a frame body (from the first station digit through ETX) as two hex digits.
QByteArray sum(QByteArrayView body);

// Why the PLC refused, translated: "address out of range (error 28h)".
QString errorText(int code);

// Master side: collects the reply to one request from bytes as they arrive (in any split).
class ReplyDecoder : public ReplyDecoderBase {
public:
    explicit ReplyDecoder(const Request &request);
    // Feed the next bytes; after Complete or Failed further bytes are ignored.
    FrameStatus feed(QByteArrayView bytes);
    // The caller's deadline passed: a truncated frame or silence, as an error.
    ProtocolError deadlinePassed(int waitedMs) const;
    const Reply &reply() const { return m_reply; }
    qsizetype buffered() const { return m_buffer.size(); }
    static constexpr qsizetype MaxBuffered = MaxReplyFrame; // longer fails

private:
    FrameStatus decode();

    Request m_request;
    QByteArray m_buffer;
    Reply m_reply;
};

// Slave side: one request, parsed from bytes as they arrive. Bytes before STX are dropped
// (line noise between frames). A frame that is complete but wrong carries the error code the
// PLC answers with (sum 11h, ASCII 10h, command 12h); the caller still checks the station.
// Memory stays bounded whatever arrives: a frame that runs past MaxRequestFrame without its
// ETX is dropped up to the next STX; bytes that arrive while a request waits for next() are
// kept up to one frame, the rest dropped. discarded() says what was thrown away last and why.
class RequestDecoder {
public:
    FrameStatus feed(QByteArrayView bytes);
    FrameStatus status() const { return m_status; }
    const Request &request() const { return m_request; }
    int errorCode() const { return m_errorCode; } // 0, or the ErrorCode to answer with
    const ProtocolError &discarded() const { return m_discarded; }
    qsizetype buffered() const { return m_buffer.size(); }
    static constexpr qsizetype MaxBuffered = 2 * MaxRequestFrame; // a request and the next
    // Start over for the next frame, keeping bytes already received after this one.
    void next();

private:
    void parse();
    ProtocolError m_discarded;
    QByteArray m_buffer;
    qsizetype m_used = 0;
    FrameStatus m_status = FrameStatus::NeedMore;
    Request m_request;
    int m_errorCode = 0;
};

} // namespace rung::comms::vigor
