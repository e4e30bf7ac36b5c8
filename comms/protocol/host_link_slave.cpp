#include "comms/protocol/host_link_slave.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/host_link_detail.h"

#include <utility>

namespace rung::comms::hostlink {

namespace {

using Kind = ProtocolError::Kind;
using comms::detail::decimalValue;
using comms::detail::hexValue;
using detail::Part;
using detail::splitPart;

} // namespace

bool CommandDecoder::takeDelimiterRequest() {
    return std::exchange(m_delimiter, false);
}

void CommandDecoder::forgetCommand() {
    m_parts = 0;
    m_command = {};
    m_endCode = 0;
    m_receivedFcs.clear();
    m_computedFcs.clear();
}

void CommandDecoder::next() {
    forgetCommand();
    m_delimiter = false;
    m_status = FrameStatus::NeedMore;
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
            forgetCommand();
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
            forgetCommand();
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
        if (!p.fcsOk && !m_endCode) {
            m_endCode = FcsError;
            m_receivedFcs = p.received;
            m_computedFcs = p.computed;
        }
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

} // namespace rung::comms::hostlink
