#pragma once

// Modbus, the slave's side: the decoder of requests and a response's PDU (modbus.h holds the
// frames and types both sides share).

#include "comms/protocol/modbus.h"

namespace rung::comms::modbus {

QByteArray encodeResponsePdu(const Response &response);

// A request PDU as the slave reads it. Failure carries the exception to answer with.
struct ParsedRequest {
    Request request;
    int exception = 0;
};
ParsedRequest parseRequestPdu(QByteArrayView pdu);

// Slave side: requests, one after another, from bytes as they arrive.
//  RTU: length from the function code; an unknown function ends at silence() (the 3.5
//  character gap); a frame with a bad CRC is dropped, as the RTU spec says (no reply).
//  TCP: the MBAP length field.
//  ASCII: ':' to CR LF; a frame with a wrong LRC is dropped without a reply.
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
    static constexpr qsizetype MaxAsciiBuffered = 2 * MaxAsciiFrame;
    void next();

private:
    FrameStatus take(qsizetype length);
    void feedAscii();
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
