#pragma once

// Omron Host Link, C-mode commands (Omron CPM1/SRM1 programming manual W353, Host Link; the
// C200HS manual), both sides, no I/O.
//   command  "@" unit(2 decimal) header(2) text FCS(2 hex) "*" CR
//   response "@" unit header end-code(2 hex) text FCS "*" CR
// FCS = XOR of every character from "@" (or the frame's first character) to the end of the
// text. A frame over 131 characters is split: the first holds at most 131 characters, each
// later one at most 128; a frame that is not the last ends in FCS CR (no "*"), and the other
// side answers a lone CR (the delimiter) before the next part comes.

#include "comms/protocol/protocol_error.h"
#include "model/target/protocol_map.h"

#include <QByteArray>
#include <QList>

#include <cstdint>
#include <vector>

namespace rung::comms::hostlink {

inline constexpr char Cr = '\r';
inline constexpr int MaxFirstFrame = 131;
inline constexpr int MaxLaterFrame = 128;
// The longest legal text of a command or reply, all parts joined: a count is four decimal
// digits, so a write carries at most a begin word and 9999 words of four hex digits.
inline constexpr int MaxWords = 9999;
inline constexpr int MaxText = 4 + 4 * MaxWords;
// Characters the slave holds while looking for a part's CR: a part too long for the PLC
// (over 131) still gets its end code 18 up to this length; beyond it the bytes are noise.
inline constexpr int MaxPartBuffer = 4 * MaxFirstFrame;

// The word areas the read / write commands reach are the Host Link spaces of the protocol
// maps (model::ProtocolSpace::HostLinkIr .. HostLinkCompletion: RR/WR, RH/WH, RD/WD, RC/WC,
// RG), so a driver passes what the CPM1 map gives without a translation table of its own.
using model::ProtocolSpace;

enum class Mode : std::uint8_t { Program = 0x00, Monitor = 0x02, Run = 0x03 };

// End codes (W353, Host Link commands).
enum EndCode : std::uint8_t {
    Normal = 0x00,
    NotInRun = 0x01,
    NotInMonitor = 0x02,
    WriteProtected = 0x03,
    AddressOver = 0x04,
    NotInProgram = 0x0B,
    FcsError = 0x13,
    FormatError = 0x14,
    EntryNumberError = 0x15,
    NotSupported = 0x16,
    FrameLengthError = 0x18,
};

struct Frame {
    int unit = 0;
    QByteArray header; // "RD", "MS", ...
    int endCode = -1;  // responses only; -1 for a command
    QByteArray text;   // everything after the header (and end code), all parts joined
};

// The characters' XOR as two upper-case hex digits.
QByteArray fcs(QByteArrayView characters);

// A whole frame as it goes on the wire: one string per part (split over 131 characters;
// word data is split on whole words, as the PLC does: 30 words, then 31 per part).
QList<QByteArray> encode(const Frame &frame);

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
QString endCodeText(int code);

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
    FrameStatus finish();
    qsizetype maxReplyText() const;

    Frame m_command;
    QByteArray m_buffer;
    int m_parts = 0;
    bool m_delimiter = false;
    Reply m_reply;
};

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
    qsizetype buffered() const { return m_buffer.size() + m_command.text.size(); }
    static constexpr qsizetype MaxBuffered = MaxPartBuffer + MaxText;
    void next();

private:
    void keepPending();
    QByteArray m_buffer;
    int m_parts = 0;
    bool m_delimiter = false;
    FrameStatus m_status = FrameStatus::NeedMore;
    Frame m_command;
    int m_endCode = 0;
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
// Which space a read / write header reaches; false when it is neither.
bool spaceOfHeader(QByteArrayView header, ProtocolSpace &space, bool &write);

} // namespace rung::comms::hostlink
