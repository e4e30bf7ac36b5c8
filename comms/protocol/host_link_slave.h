#pragma once

// Host Link, the slave's side: the decoder of commands and the operands of those it serves
// (host_link.h holds the frames and types both sides share).

#include "comms/protocol/host_link.h"

#include <cstdint>
#include <vector>

namespace rung::comms::hostlink {

// Slave side: one command over any number of parts. endCode() is the code a PLC answers a
// broken command with (13 FCS, 14 format, 18 frame length), 0 when the command is sound.
// Memory stays bounded whatever arrives: a command whose parts go on past MaxText ends
// Complete with end code 18 (its text dropped) and the decoder looks for the next "@"; bytes
// that arrive while a command waits for next() are kept up to MaxPartBuffer, the rest dropped.
// discarded() says what was thrown away last and why.
class CommandDecoder {
public:
    FrameStatus feed(QByteArrayView bytes);
    bool takeDelimiterRequest();
    FrameStatus status() const { return m_status; }
    const Frame &command() const { return m_command; }
    int endCode() const { return m_endCode; }
    const ProtocolError &discarded() const { return m_discarded; }
    // The FCS of the first part whose FCS is wrong (end code 13), as received and as computed
    // from the part's characters; both empty while every part's FCS is right.
    const QByteArray &receivedFcs() const { return m_receivedFcs; }
    const QByteArray &computedFcs() const { return m_computedFcs; }
    qsizetype buffered() const { return m_buffer.size() + m_command.text.size(); }
    static constexpr qsizetype MaxBuffered = MaxPartBuffer + MaxText;
    void next();

private:
    void keepPending();
    void forgetCommand(); // the command so far: its parts, text, end code and FCS
    QByteArray m_buffer;
    int m_parts = 0;
    bool m_delimiter = false;
    FrameStatus m_status = FrameStatus::NeedMore;
    Frame m_command;
    int m_endCode = 0;
    QByteArray m_receivedFcs, m_computedFcs;
    ProtocolError m_discarded;
};

// The text of a read / write / force command, as the slave reads it.
struct Operands {
    int begin = 0;
    int count = 0;
    std::vector<std::uint16_t> words;
    int bit = -1;
    bool valid = false;
};
Operands parseRead(QByteArrayView text);  // begin(4) count(4), decimal
Operands parseWrite(QByteArrayView text); // begin(4) words(4 hex each)
Operands parseForce(QByteArrayView text); // "CIO " word(4) bit(2)
} // namespace rung::comms::hostlink
