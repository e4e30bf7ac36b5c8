#pragma once

// Vigor link, the master's side: a request's frame and the decoder of its reply (vigor_link.h
// holds the frames and types both sides share).

#include "comms/protocol/vigor_link.h"

namespace rung::comms::vigor {

QByteArray encodeRequest(const Request &request);

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

} // namespace rung::comms::vigor
