#pragma once

// Host Link, the master's side: the commands the product sends and the decoder of their
// replies (host_link.h holds the frames and types both sides share).

#include "comms/protocol/host_link.h"

#include <cstdint>
#include <vector>

namespace rung::comms::hostlink {

// Commands the product sends. begin / count in words (or timers for RC / RG). A space that is
// not a Host Link one gives a frame without a header, which the PLC refuses (IC).
Frame readCommand(int unit, ProtocolSpace space, int begin, int count);
Frame writeCommand(int unit, ProtocolSpace space, int begin,
                   const std::vector<std::uint16_t> &words);
Frame statusCommand(int unit);                             // MS
Frame modeCommand(int unit, Mode mode);                    // SC
Frame forceCommand(int unit, bool set, int word, int bit); // KS / KR on "CIO "
Frame cancelForceCommand(int unit);                        // KC
Frame modelCommand(int unit);                              // MM

// What the reply to a command holds.
struct Reply {
    Frame frame;
    std::vector<std::uint16_t> words; // RR RH RD RC: raw words (RC: BCD digits as written)
    std::vector<bool> flags;          // RG
    int status = 0;                   // MS: the status word; mode in bits 9-8
    int model = 0;                    // MM: model code
};

// MS status bits 9-8: 00 PROGRAM, 10 RUN, 11 MONITOR.
Mode modeOfStatus(int status);

// Master side: the reply to one command, from bytes as they arrive, over any number of parts.
class ReplyDecoder : public ReplyDecoderBase {
public:
    explicit ReplyDecoder(const Frame &command);
    FrameStatus feed(QByteArrayView bytes);
    // True once after each part that is not the last: the caller sends a lone CR.
    bool takeDelimiterRequest();
    ProtocolError deadlinePassed(int waitedMs) const;
    const Reply &reply() const { return m_reply; }
    // Characters held: the part being received and the text of the parts before it. Never
    // more than MaxBuffered: a reply longer than its command asks for fails.
    qsizetype buffered() const { return m_buffer.size() + m_reply.frame.text.size(); }
    static constexpr qsizetype MaxBuffered = MaxFirstFrame + MaxText;

private:
    FrameStatus part(QByteArrayView frame);
    FrameStatus appendText(QByteArrayView text, bool last);
    FrameStatus finish();
    qsizetype maxReplyText() const;

    Frame m_command;
    QByteArray m_buffer;
    int m_parts = 0;
    bool m_delimiter = false;
    Reply m_reply;
};

} // namespace rung::comms::hostlink
