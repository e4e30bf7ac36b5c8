#include "comms/protocol/host_link_master.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/host_link_detail.h"

#include <utility>

namespace rung::comms::hostlink {

namespace {

using Kind = ProtocolError::Kind;
using comms::detail::appendDecimal;
using comms::detail::appendHex;
using comms::detail::decimalValue;
using comms::detail::hexValue;
using detail::AreaHeaders;
using detail::headersOf;
using detail::Part;
using detail::splitPart;

} // namespace

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
        if (m_reply.frame.header == "TS") {
            // TEST has no end code: the characters sent come back as they were (W353,
            // Host Link commands, TEST).
            m_reply.frame.endCode = -1;
            text = text.sliced(5);
            return appendText(text, p.last);
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
    return appendText(text, p.last);
}

FrameStatus ReplyDecoder::appendText(QByteArrayView text, bool last) {
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
    if (!last) {
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
    const QByteArrayView h(f.header);
    if (h == "TS") {
        if (f.text != m_command.text)
            return fail(Kind::WrongReply,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Host Link: TEST returned \"%1\", not the \"%2\" that was sent")
                            .arg(QString::fromLatin1(f.text), QString::fromLatin1(m_command.text)));
        return complete();
    }
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

} // namespace rung::comms::hostlink
