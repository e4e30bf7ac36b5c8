#pragma once

// Vigor link, the slave's side: the decoder of requests and a reply's frame (vigor_link.h
// holds the frames and types both sides share).

#include "comms/protocol/vigor_link.h"

namespace rung::comms::vigor {

QByteArray encodeReply(const Reply &reply);

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
