#pragma once

// Modbus, the master's side: a request's PDU and the decoder of its reply (modbus.h holds
// the frames and types both sides share).

#include "comms/protocol/modbus.h"

namespace rung::comms::modbus {

QByteArray encodeRequestPdu(const Request &request);

// Master side: the reply to one request, from bytes as they arrive. Over RTU the length comes
// from the function code and byte count, so no silence timer is needed to end a reply.
class ReplyDecoder : public ReplyDecoderBase {
public:
    ReplyDecoder(Framing framing, int unit, const Request &request, int transaction = 0);
    FrameStatus feed(QByteArrayView bytes);
    ProtocolError deadlinePassed(int waitedMs) const;
    const Response &response() const { return m_response; }
    // Bytes held: never more than one byte past the longest reply a header can announce
    // (ASCII: MaxAsciiBuffered, two characters a byte).
    qsizetype buffered() const { return m_buffer.size(); }
    static constexpr qsizetype MaxBuffered = 3 + 255 + 2 + 1;
    static constexpr qsizetype MaxAsciiBuffered = MaxAsciiFrame + 1;

private:
    FrameStatus decodePdu(QByteArrayView pdu, int unit);
    FrameStatus feedAscii();
    qsizetype expectedRtuLength() const; // 0 = not known yet

    Framing m_framing;
    int m_unit;
    Request m_request;
    int m_transaction;
    QByteArray m_buffer;
    qsizetype m_received = 0;
    Response m_response;
};

} // namespace rung::comms::modbus
