#include "comms/protocol/vigor_link_master.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/vigor_link_detail.h"

namespace rung::comms::vigor {

namespace {

using Kind = ProtocolError::Kind;
using comms::detail::appendHex;
using comms::detail::hex2;
using comms::detail::hexValue;
using detail::closeFrame;

} // namespace

QByteArray encodeRequest(const Request &request) {
    QByteArray body;
    appendHex(body, request.station & 0xFF, 2);
    appendHex(body, int(request.command), 2);
    appendHex(body, request.address & 0xFFFF, 4);
    if (request.command == Command::Read) {
        appendHex(body, request.length & 0xFF, 2);
    } else if (request.command == Command::Write) {
        appendHex(body, int(request.data.size()) & 0xFF, 2);
        for (char byte : request.data)
            appendHex(body, static_cast<quint8>(byte), 2);
    }
    return closeFrame(Stx, body);
}

ReplyDecoder::ReplyDecoder(const Request &request)
    : m_request(request) {}

FrameStatus ReplyDecoder::feed(QByteArrayView bytes) {
    if (m_status != FrameStatus::NeedMore)
        return m_status;
    for (char c : bytes) {
        if (m_buffer.isEmpty() && c != Ack) {
            m_buffer += c;
            return fail(Kind::Garbage,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Vigor link: the reply starts with byte %1 instead of ACK "
                            "(06h): not a Computer Link answer")
                            .arg(hexDump(m_buffer)));
        }
        m_buffer += c;
        // ETX cannot occur inside the hex payload, so it marks the end: two sum digits follow.
        const qsizetype etx = m_buffer.indexOf(Etx);
        if (etx >= 0 && m_buffer.size() == etx + 3)
            return decode();
        // A reply as long as the longest legal one and still not ended is not going to end well.
        if (m_buffer.size() >= MaxReplyFrame)
            return fail(Kind::Garbage, QCoreApplication::translate(
                                           "rung::comms::Protocol",
                                           "Vigor link: %1 bytes without the end of a frame (ETX)")
                                           .arg(m_buffer.size()));
    }
    return m_status;
}

FrameStatus ReplyDecoder::decode() {
    const QByteArrayView frame(m_buffer);
    const qsizetype etx = frame.size() - 3;
    const QByteArrayView body = frame.sliced(1, etx); // station .. ETX
    const QByteArray expectedSum = sum(body);
    if (frame.sliced(etx + 1, 2) != QByteArrayView(expectedSum))
        return fail(
            Kind::BadChecksum,
            QCoreApplication::translate("rung::comms::Protocol",
                                        "Vigor link: wrong sum in the reply (received %1, computed "
                                        "%2): noise on the line or a wrong parity setting")
                .arg(QString::fromLatin1(frame.sliced(etx + 1, 2).toByteArray()),
                     QString::fromLatin1(expectedSum)));
    if (etx < 7 || (etx - 7) % 2 != 0)
        return fail(Kind::Malformed,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Vigor link: a reply of %1 bytes is too short or has an odd "
                        "number of hex digits: %2")
                        .arg(frame.size())
                        .arg(hexDump(frame)));
    const auto station = hexValue(frame, 1, 2);
    const auto command = hexValue(frame, 3, 2);
    const auto error = hexValue(frame, 5, 2);
    if (!station || !command || !error)
        return fail(Kind::Garbage, QCoreApplication::translate(
                                       "rung::comms::Protocol",
                                       "Vigor link: the reply holds characters that are not "
                                       "upper-case hexadecimal: %1")
                                       .arg(hexDump(frame)));
    QByteArray data;
    for (qsizetype at = 7; at < etx; at += 2) {
        const auto byte = hexValue(frame, at, 2);
        if (!byte)
            return fail(Kind::Garbage, QCoreApplication::translate(
                                           "rung::comms::Protocol",
                                           "Vigor link: the reply holds characters that are not "
                                           "upper-case hexadecimal: %1")
                                           .arg(hexDump(frame)));
        data += char(*byte);
    }
    if (*station != (m_request.station & 0xFF))
        return fail(Kind::WrongStation, QCoreApplication::translate(
                                            "rung::comms::Protocol",
                                            "Vigor link: station %1 answered, station %2 was asked")
                                            .arg(*station)
                                            .arg(m_request.station));
    if (*command != int(m_request.command))
        return fail(
            Kind::WrongReply,
            QCoreApplication::translate("rung::comms::Protocol",
                                        "Vigor link: the reply is for command %1h, the request was "
                                        "%2h")
                .arg(hex2(*command), hex2(int(m_request.command))));
    if (*error != 0)
        return fail(Kind::DeviceError,
                    QCoreApplication::translate("rung::comms::Protocol", "Vigor link: %1")
                        .arg(errorText(*error)),
                    *error);
    const int expected = m_request.command == Command::Read ? m_request.length : 0;
    if (data.size() != expected)
        return fail(Kind::Malformed, QCoreApplication::translate(
                                         "rung::comms::Protocol",
                                         "Vigor link: the reply carries %1 data bytes, %2 expected")
                                         .arg(data.size())
                                         .arg(expected));
    m_reply = Reply{*station, m_request.command, 0, data};
    return complete();
}

ProtocolError ReplyDecoder::deadlinePassed(int waitedMs) const {
    return truncated(
        m_buffer.isEmpty(),
        QCoreApplication::translate("rung::comms::Protocol",
                                    "Vigor link: no reply from station %1 within %2 ms")
            .arg(m_request.station)
            .arg(waitedMs),
        QCoreApplication::translate(
            "rung::comms::Protocol",
            "Vigor link: the reply stopped after %1 bytes (%2) within %3 ms")
            .arg(m_buffer.size())
            .arg(hexDump(m_buffer))
            .arg(waitedMs));
}

} // namespace rung::comms::vigor
