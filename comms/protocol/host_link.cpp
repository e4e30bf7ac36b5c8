#include "comms/protocol/host_link.h"

#include "comms/protocol/ascii_hex.h"

#include <optional>

namespace rung::comms::hostlink {

namespace {

using Kind = ProtocolError::Kind;
using detail::appendDecimal;
using detail::appendHex;
using detail::decimalValue;
using detail::hex2;
using detail::hexValue;

struct AreaHeaders {
    ProtocolSpace space;
    const char *read;
    const char *write; // nullptr: read only
};

constexpr AreaHeaders areaHeaders[] = {
    {ProtocolSpace::HostLinkIr, "RR", "WR"},
    {ProtocolSpace::HostLinkHr, "RH", "WH"},
    {ProtocolSpace::HostLinkDm, "RD", "WD"},
    {ProtocolSpace::HostLinkTimerPv, "RC", "WC"},
    {ProtocolSpace::HostLinkCompletion, "RG", nullptr},
};

const AreaHeaders *headersOf(ProtocolSpace space) {
    for (const auto &h : areaHeaders)
        if (h.space == space)
            return &h;
    return nullptr;
}

bool isWordHeader(QByteArrayView header) {
    for (const auto &h : areaHeaders)
        if (header == QByteArrayView(h.read) && h.space != ProtocolSpace::HostLinkCompletion)
            return true;
        else if (h.write && header == QByteArrayView(h.write))
            return true;
    return false;
}

// One received part (without its CR): checks the FCS, returns the text before it and whether
// it is the last part; nullopt when the FCS is wrong.
struct Part {
    QByteArrayView content;
    bool last = false;
    bool fcsOk = false;
    QByteArray received, computed;
};

Part splitPart(QByteArrayView frame) {
    Part p;
    p.last = frame.endsWith('*');
    const QByteArrayView body = p.last ? frame.chopped(1) : frame;
    if (body.size() < 2)
        return p;
    p.content = body.chopped(2);
    p.received = body.last(2).toByteArray();
    p.computed = fcs(p.content);
    p.fcsOk = p.received == p.computed;
    return p;
}

} // namespace

QByteArray fcs(QByteArrayView characters) {
    int value = 0;
    for (char c : characters)
        value ^= static_cast<quint8>(c);
    QByteArray out;
    appendHex(out, value, 2);
    return out;
}

QList<QByteArray> encode(const Frame &frame) {
    QByteArray content("@");
    appendDecimal(content, frame.unit, 2);
    content += frame.header;
    if (frame.endCode >= 0)
        appendHex(content, frame.endCode, 2);
    const qsizetype dataStart =
        content.size() + (frame.endCode < 0 && frame.header.startsWith('W') ? 4 : 0);
    const int unit = isWordHeader(frame.header) ? 4 : 1;
    content += frame.text;

    QList<QByteArray> parts;
    qsizetype pos = 0;
    bool first = true;
    while (true) {
        const qsizetype room = (first ? MaxFirstFrame : MaxLaterFrame) - 4; // FCS "*" CR
        if (content.size() - pos <= room) {
            const QByteArray chunk = content.mid(pos);
            parts << chunk + fcs(chunk) + "*" + Cr;
            return parts;
        }
        qsizetype end = pos + room;
        if (end > dataStart)
            end -= (end - dataStart) % unit;
        const QByteArray chunk = content.mid(pos, end - pos);
        parts << chunk + fcs(chunk) + Cr;
        pos = end;
        first = false;
    }
}

Frame readCommand(int unit, ProtocolSpace space, int begin, int count) {
    const AreaHeaders *h = headersOf(space);
    Frame f{unit, h ? h->read : "", -1, {}};
    appendDecimal(f.text, begin, 4);
    appendDecimal(f.text, count, 4);
    return f;
}

Frame writeCommand(int unit, ProtocolSpace space, int begin,
                   const std::vector<std::uint16_t> &words) {
    const AreaHeaders *h = headersOf(space);
    const char *header = h ? h->write : nullptr;
    Frame f{unit, header ? header : "", -1, {}};
    appendDecimal(f.text, begin, 4);
    for (auto w : words)
        appendHex(f.text, w, 4);
    return f;
}

Frame statusCommand(int unit) {
    return {unit, "MS", -1, {}};
}

Frame modeCommand(int unit, Mode mode) {
    Frame f{unit, "SC", -1, {}};
    appendHex(f.text, int(mode), 2);
    return f;
}

Frame forceCommand(int unit, bool set, int word, int bit) {
    Frame f{unit, set ? "KS" : "KR", -1, "CIO "};
    appendDecimal(f.text, word, 4);
    appendDecimal(f.text, bit, 2);
    return f;
}

Frame cancelForceCommand(int unit) {
    return {unit, "KC", -1, {}};
}
Frame modelCommand(int unit) {
    return {unit, "MM", -1, {}};
}

Mode modeOfStatus(int status) {
    switch ((status >> 8) & 3) {
    case 2:
        return Mode::Run;
    case 3:
        return Mode::Monitor;
    default:
        return Mode::Program;
    }
}

QString endCodeText(int code) {
    const QString hex = hex2(code);
    switch (code) {
    case Normal:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "normal completion (end code %1)")
            .arg(hex);
    case NotInRun:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "not executable in RUN mode (end code %1): switch the PLC to "
                   "MONITOR to write")
            .arg(hex);
    case NotInMonitor:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "not executable in MONITOR mode (end code %1)")
            .arg(hex);
    case WriteProtected:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC's memory is write-protected (end code %1)")
            .arg(hex);
    case AddressOver:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "address over: the area ends before the last word asked for "
                   "(end code %1)")
            .arg(hex);
    case NotInProgram:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "not executable in PROGRAM mode (end code %1)")
            .arg(hex);
    case FcsError:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "the PLC received the command with a wrong FCS (end code %1): noise "
                   "on the line or a wrong parity setting")
            .arg(hex);
    case FormatError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC found the command's format wrong (end code %1)")
            .arg(hex);
    case EntryNumberError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "a number in the command is out of range (end code %1)")
            .arg(hex);
    case NotSupported:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC does not support the command (end code %1)")
            .arg(hex);
    case FrameLengthError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the command's frame is too long (end code %1)")
            .arg(hex);
    }
    return QCoreApplication::translate("rung::comms::Protocol", "end code %1").arg(hex);
}

// ----- master side -----

ReplyDecoder::ReplyDecoder(const Frame &command)
    : m_command(command) {}

bool ReplyDecoder::takeDelimiterRequest() {
    return std::exchange(m_delimiter, false);
}

FrameStatus ReplyDecoder::feed(QByteArrayView bytes) {
    for (char c : bytes) {
        if (m_status != FrameStatus::NeedMore)
            return m_status;
        if (m_parts == 0 && m_buffer.isEmpty() && c != '@') {
            m_buffer += c;
            return fail(Kind::Garbage, QCoreApplication::translate(
                                           "rung::comms::Protocol",
                                           "Host Link: the reply starts with byte %1 instead of "
                                           "\"@\": not a Host Link answer")
                                           .arg(hexDump(m_buffer)));
        }
        if (c != Cr) {
            m_buffer += c;
            if (m_buffer.size() >= MaxFirstFrame) // a part is at most 130 before its CR
                return fail(Kind::Garbage,
                            QCoreApplication::translate(
                                "rung::comms::Protocol",
                                "Host Link: %1 characters without the end of a frame "
                                "(CR)")
                                .arg(m_buffer.size()));
            continue;
        }
        const QByteArray frame = std::exchange(m_buffer, {});
        part(frame);
    }
    return m_status;
}

FrameStatus ReplyDecoder::part(QByteArrayView frame) {
    const Part p = splitPart(frame);
    if (p.received.isEmpty())
        return fail(Kind::Malformed,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Host Link: a frame too short to hold an FCS: %1")
                        .arg(hexDump(frame)));
    if (!p.fcsOk)
        return fail(
            Kind::BadChecksum,
            QCoreApplication::translate("rung::comms::Protocol",
                                        "Host Link: wrong FCS in the reply (received %1, computed "
                                        "%2): noise on the line or a wrong parity setting")
                .arg(QString::fromLatin1(p.received), QString::fromLatin1(p.computed)));
    QByteArrayView text = p.content;
    if (m_parts++ == 0) {
        const auto unit = decimalValue(text, 1, 2);
        if (!unit || text.size() < 5)
            return fail(Kind::Malformed,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Host Link: the reply has no unit number and header: %1")
                            .arg(hexDump(frame)));
        m_reply.frame.unit = *unit;
        m_reply.frame.header = text.sliced(3, 2).toByteArray();
        if (m_reply.frame.header == "IC") {
            if (*unit != m_command.unit)
                return fail(
                    Kind::WrongStation,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Host Link: unit %1 answered, unit %2 was asked")
                        .arg(*unit)
                        .arg(m_command.unit));
            return fail(
                Kind::DeviceError,
                QCoreApplication::translate("rung::comms::Protocol",
                                            "Host Link: the PLC did not recognise the command %1 "
                                            "(IC)")
                    .arg(QString::fromLatin1(m_command.header)),
                NotSupported);
        }
        const auto endCode = hexValue(text, 5, 2);
        if (!endCode)
            return fail(Kind::Malformed,
                        QCoreApplication::translate("rung::comms::Protocol",
                                                    "Host Link: the reply has no end code: %1")
                            .arg(hexDump(frame)));
        m_reply.frame.endCode = *endCode;
        text = text.sliced(7);
    }
    if (m_reply.frame.text.size() + text.size() > maxReplyText())
        return fail(Kind::Malformed,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Host Link: the reply to %1 goes on past the %2 characters of data the "
                        "command asks for (part %3): not the answer to this command")
                        .arg(QString::fromLatin1(m_command.header))
                        .arg(maxReplyText())
                        .arg(m_parts));
    m_reply.frame.text += text;
    if (!p.last) {
        m_delimiter = true;
        return m_status;
    }
    return finish();
}

// The most data characters the reply to this command can hold, so that a stream of parts
// that never ends fails instead of growing: a read's words or flags; one frame for the rest.
qsizetype ReplyDecoder::maxReplyText() const {
    ProtocolSpace space;
    bool write = false;
    if (spaceOfHeader(m_command.header, space, write) && !write) {
        const int count = decimalValue(m_command.text, 4, 4).value_or(0);
        return space == ProtocolSpace::HostLinkCompletion ? count : 4 * count;
    }
    return MaxFirstFrame;
}

FrameStatus ReplyDecoder::finish() {
    const Frame &f = m_reply.frame;
    if (f.unit != m_command.unit)
        return fail(Kind::WrongStation,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Host Link: unit %1 answered, unit %2 was "
                                                "asked")
                        .arg(f.unit)
                        .arg(m_command.unit));
    if (f.header != m_command.header)
        return fail(
            Kind::WrongReply,
            QCoreApplication::translate("rung::comms::Protocol",
                                        "Host Link: the reply is for %1, the command was %2")
                .arg(QString::fromLatin1(f.header), QString::fromLatin1(m_command.header)));
    if (f.endCode != Normal)
        return fail(
            Kind::DeviceError,
            QCoreApplication::translate("rung::comms::Protocol", "Host Link: %1 refused: %2")
                .arg(QString::fromLatin1(f.header), endCodeText(f.endCode)),
            f.endCode);
    const auto malformed = [this, &f] {
        return fail(Kind::Malformed,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Host Link: the reply to %1 holds %2 characters of data that "
                        "do not fit the command")
                        .arg(QString::fromLatin1(f.header))
                        .arg(f.text.size()));
    };
    const QByteArrayView h(f.header);
    ProtocolSpace space;
    bool write = false;
    if (spaceOfHeader(h, space, write) && !write) {
        const int count = decimalValue(m_command.text, 4, 4).value_or(0);
        if (space == ProtocolSpace::HostLinkCompletion) {
            if (f.text.size() != count)
                return malformed();
            for (char c : f.text) {
                if (c != '0' && c != '1')
                    return malformed();
                m_reply.flags.push_back(c == '1');
            }
        } else {
            if (f.text.size() != 4 * count)
                return malformed();
            for (int i = 0; i < count; ++i) {
                const auto w = hexValue(f.text, 4 * i, 4);
                if (!w)
                    return malformed();
                m_reply.words.push_back(std::uint16_t(*w));
            }
        }
    } else if (h == "MS") {
        const auto s = hexValue(f.text, 0, 4);
        if (!s)
            return malformed();
        m_reply.status = *s;
    } else if (h == "MM") {
        const auto m = hexValue(f.text, 0, 2);
        if (!m || f.text.size() != 2)
            return malformed();
        m_reply.model = *m;
    } else if (!f.text.isEmpty()) {
        return malformed();
    }
    return complete();
}

ProtocolError ReplyDecoder::deadlinePassed(int waitedMs) const {
    return truncated(m_buffer.isEmpty() && m_parts == 0,
                     QCoreApplication::translate("rung::comms::Protocol",
                                                 "Host Link: no reply from unit %1 within %2 ms")
                         .arg(m_command.unit)
                         .arg(waitedMs),
                     QCoreApplication::translate(
                         "rung::comms::Protocol",
                         "Host Link: the reply stopped after %1 parts and %2 characters (%3) "
                         "within %4 ms")
                         .arg(m_parts)
                         .arg(m_buffer.size())
                         .arg(hexDump(m_buffer))
                         .arg(waitedMs));
}

// ----- slave side -----

bool CommandDecoder::takeDelimiterRequest() {
    return std::exchange(m_delimiter, false);
}

void CommandDecoder::next() {
    m_parts = 0;
    m_delimiter = false;
    m_status = FrameStatus::NeedMore;
    m_command = {};
    m_endCode = 0;
    feed({});
}

// While a command waits for next(), what follows it is the next command's start at most (a
// master waits for the answer); more than a part's worth is a stream gone wrong: dropped.
void CommandDecoder::keepPending() {
    if (m_buffer.size() <= MaxPartBuffer)
        return;
    m_discarded = {Kind::Garbage, 0,
                   QCoreApplication::translate(
                       "rung::comms::Protocol",
                       "Host Link: %1 characters arrived before the command was answered; "
                       "the %2 beyond the first %3 were dropped")
                       .arg(m_buffer.size())
                       .arg(m_buffer.size() - MaxPartBuffer)
                       .arg(MaxPartBuffer)};
    m_buffer.truncate(MaxPartBuffer);
}

FrameStatus CommandDecoder::feed(QByteArrayView bytes) {
    m_buffer += bytes;
    while (m_status == FrameStatus::NeedMore) {
        if (m_parts > 0 && m_buffer.startsWith('@')) {
            // A later part holds data, never "@": a master that starts a command afresh
            // (after a time-out, or noise that looked like a first part) is served from here.
            m_discarded = {Kind::Garbage, 0,
                           QCoreApplication::translate(
                               "rung::comms::Protocol",
                               "Host Link: a new command began where part %1 of the %2 command "
                               "was due; the unfinished command was dropped")
                               .arg(m_parts + 1)
                               .arg(QString::fromLatin1(m_command.header))};
            m_parts = 0;
            m_command = {};
            m_endCode = 0;
        }
        if (m_parts == 0) {
            const qsizetype at = m_buffer.indexOf('@');
            m_buffer.remove(0, at < 0 ? m_buffer.size() : at); // noise between commands
        }
        const qsizetype cr = m_buffer.indexOf(Cr);
        if (cr < 0 || cr > MaxPartBuffer) {
            if (m_buffer.size() <= MaxPartBuffer)
                return m_status;
            // No CR in sight: neither a part nor one the PLC would answer 18 to. Resynchronise
            // at the next "@" (the command so far is dropped with it).
            m_discarded = {Kind::Garbage, 0,
                           QCoreApplication::translate(
                               "rung::comms::Protocol",
                               "Host Link: %1 characters without a CR (a part holds at most "
                               "%2): dropped, waiting for the next \"@\"")
                               .arg(cr < 0 ? m_buffer.size() : cr)
                               .arg(MaxFirstFrame)};
            const qsizetype again = m_buffer.indexOf('@', 1);
            m_buffer.remove(0, again < 0 ? m_buffer.size() : again);
            m_parts = 0;
            m_command = {};
            m_endCode = 0;
            continue;
        }
        const QByteArray frame = m_buffer.left(cr);
        m_buffer.remove(0, cr + 1);
        const Part p = splitPart(frame);
        QByteArrayView text = p.content;
        const bool first = m_parts++ == 0;
        if (first) {
            const auto unit = decimalValue(text, 1, 2);
            if (!unit || text.size() < 5) {
                m_parts = 0; // cannot be answered without a unit and a header: dropped
                continue;
            }
            m_command.unit = *unit;
            m_command.header = text.sliced(3, 2).toByteArray();
            text = text.sliced(5);
        }
        if (m_command.text.size() + text.size() > MaxText) {
            // Longer than any command can be (a count has four digits): answer 18 now and
            // take what follows as noise until the next "@".
            m_discarded = {Kind::Malformed, FrameLengthError,
                           QCoreApplication::translate(
                               "rung::comms::Protocol",
                               "Host Link: the %1 command goes on past %2 characters in %3 "
                               "parts, longer than any command; answered with end code 18")
                               .arg(QString::fromLatin1(m_command.header))
                               .arg(MaxText)
                               .arg(m_parts)};
            m_command.text.clear();
            m_endCode = FrameLengthError;
            m_status = FrameStatus::Complete;
            break;
        }
        m_command.text += text;
        if (!p.fcsOk && !m_endCode)
            m_endCode = FcsError;
        if (frame.size() + 1 > (first ? MaxFirstFrame : MaxLaterFrame) && !m_endCode)
            m_endCode = FrameLengthError;
        if (p.last)
            m_status = FrameStatus::Complete;
        else
            m_delimiter = true; // a master waits for it; parts already here are read on
    }
    keepPending();
    return m_status;
}

Operands parseRead(QByteArrayView text) {
    Operands o;
    const auto begin = decimalValue(text, 0, 4);
    const auto count = decimalValue(text, 4, 4);
    if (!begin || !count || text.size() != 8)
        return o;
    o.begin = *begin;
    o.count = *count;
    o.valid = true;
    return o;
}

Operands parseWrite(QByteArrayView text) {
    Operands o;
    const auto begin = decimalValue(text, 0, 4);
    if (!begin || text.size() < 8 || (text.size() - 4) % 4 != 0)
        return o;
    o.begin = *begin;
    for (qsizetype at = 4; at < text.size(); at += 4) {
        const auto w = hexValue(text, at, 4);
        if (!w)
            return o;
        o.words.push_back(std::uint16_t(*w));
    }
    o.count = int(o.words.size());
    o.valid = true;
    return o;
}

Operands parseForce(QByteArrayView text) {
    Operands o;
    if (text.size() != 10 || !text.startsWith("CIO "))
        return o;
    const auto word = decimalValue(text, 4, 4);
    const auto bit = decimalValue(text, 8, 2);
    if (!word || !bit || *bit > 15)
        return o;
    o.begin = *word;
    o.bit = *bit;
    o.count = 1;
    o.valid = true;
    return o;
}

bool spaceOfHeader(QByteArrayView header, ProtocolSpace &space, bool &write) {
    for (const auto &h : areaHeaders) {
        if (header == QByteArrayView(h.read)) {
            space = h.space;
            write = false;
            return true;
        }
        if (h.write && header == QByteArrayView(h.write)) {
            space = h.space;
            write = true;
            return true;
        }
    }
    return false;
}

} // namespace rung::comms::hostlink
