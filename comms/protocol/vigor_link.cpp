#include "comms/protocol/vigor_link.h"

#include "comms/protocol/ascii_hex.h"

#include <optional>

namespace rung::comms::vigor {

namespace {

using Kind = ProtocolError::Kind;
using detail::appendHex;
using detail::hex2;
using detail::hexDigit;
using detail::hexValue;

// Body (station .. ETX) + sum; the caller puts the start byte in front.
QByteArray closeFrame(char start, QByteArray body) {
    body += Etx;
    QByteArray frame(1, start);
    frame += body;
    frame += sum(body);
    return frame;
}

bool knownCommand(int code) {
    return code == int(Command::Read) || code == int(Command::Write) ||
           code == int(Command::BitOn) || code == int(Command::BitOff);
}

} // namespace

QByteArray sum(QByteArrayView body) {
    unsigned total = 0;
    for (char c : body)
        total += static_cast<quint8>(c);
    QByteArray out;
    appendHex(out, int(total & 0xFF), 2);
    return out;
}

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

QByteArray encodeReply(const Reply &reply) {
    QByteArray body;
    appendHex(body, reply.station & 0xFF, 2);
    appendHex(body, int(reply.command), 2);
    appendHex(body, reply.error & 0xFF, 2);
    if (reply.error == 0)
        for (char byte : reply.data)
            appendHex(body, static_cast<quint8>(byte), 2);
    return closeFrame(Ack, body);
}

QString errorText(int code) {
    const QString hex = hex2(code);
    switch (ErrorCode(code)) {
    case ErrorCode::None:
        return QCoreApplication::translate("rung::comms::Protocol", "no error (error 00h)");
    case ErrorCode::AsciiConversion:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "the PLC could not read the request's characters as hexadecimal "
                   "(ASCII conversion error %1h)")
            .arg(hex);
    case ErrorCode::SumCheck:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "the PLC received the request with a wrong sum (sum check error "
                   "%1h): noise on the line or a wrong parity setting")
            .arg(hex);
    case ErrorCode::NoSuchCommand:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "the PLC does not know the command (error %1h)")
            .arg(hex);
    case ErrorCode::Communication:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "communication error (error %1h): the PLC may be in STOP or the "
                   "parity does not match")
            .arg(hex);
    case ErrorCode::AddressRange:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "address out of range (error %1h)")
            .arg(hex);
    }
    return QCoreApplication::translate("rung::comms::Protocol", "unknown error code %1h").arg(hex);
}

// ----- master side -----

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

// ----- slave side -----

void RequestDecoder::next() {
    m_buffer.remove(0, m_used);
    m_used = 0;
    m_status = FrameStatus::NeedMore;
    m_request = {};
    m_errorCode = 0;
    feed({});
}

FrameStatus RequestDecoder::feed(QByteArrayView bytes) {
    m_buffer += bytes;
    if (m_status == FrameStatus::NeedMore)
        parse();
    // While a request waits for next(), a master waits for its answer: more than one frame
    // after it is a stream gone wrong, and the excess is dropped.
    const qsizetype pending = m_buffer.size() - m_used;
    if (m_status == FrameStatus::Complete && pending > MaxRequestFrame) {
        m_discarded = {ProtocolError::Kind::Garbage, 0,
                       QCoreApplication::translate(
                           "rung::comms::Protocol",
                           "Vigor link: %1 bytes arrived before the request was answered; the "
                           "%2 beyond the first %3 were dropped")
                           .arg(pending)
                           .arg(pending - MaxRequestFrame)
                           .arg(MaxRequestFrame)};
        m_buffer.truncate(m_used + MaxRequestFrame);
    }
    return m_status;
}

void RequestDecoder::parse() {
    qsizetype etx = -1;
    while (true) {
        const qsizetype stx = m_buffer.indexOf(Stx);
        if (stx < 0) {
            m_buffer.clear(); // noise between frames
            return;
        }
        m_buffer.remove(0, stx);
        etx = m_buffer.indexOf(Etx);
        // STX cannot occur inside a frame (the payload is hex): a later one starts over.
        const qsizetype restart =
            etx < 0 ? m_buffer.lastIndexOf(Stx) : m_buffer.lastIndexOf(Stx, etx);
        if (restart > 0) {
            m_buffer.remove(0, restart);
            etx = m_buffer.indexOf(Etx);
        }
        if (etx >= 0 && etx + 3 <= MaxRequestFrame)
            break;
        if (etx < 0 && m_buffer.size() <= MaxRequestFrame)
            return; // the rest of the frame is on its way
        // Longer than any request without its ETX: noise, or a frame that lost its ETX.
        m_discarded = {ProtocolError::Kind::Garbage, 0,
                       QCoreApplication::translate(
                           "rung::comms::Protocol",
                           "Vigor link: %1 bytes from STX without ETX (a request holds at most "
                           "%2): dropped up to the next STX")
                           .arg(etx < 0 ? m_buffer.size() : etx + 1)
                           .arg(MaxRequestFrame)};
        const qsizetype again = m_buffer.indexOf(Stx, 1);
        m_buffer.remove(0, again < 0 ? m_buffer.size() : again);
    }
    if (m_buffer.size() < etx + 3)
        return;
    m_used = etx + 3;
    m_status = FrameStatus::Complete;
    const QByteArrayView frame = QByteArrayView(m_buffer).first(m_used);
    const QByteArrayView body = frame.sliced(1, etx);
    const auto station = hexValue(frame, 1, 2);
    const auto command = hexValue(frame, 3, 2);
    m_request.station = station.value_or(-1);
    m_request.command = Command(command.value_or(0));
    if (frame.sliced(etx + 1, 2) != QByteArrayView(sum(body))) {
        m_errorCode = int(ErrorCode::SumCheck);
        return;
    }
    for (qsizetype i = 1; i < etx; ++i)
        if (!hexDigit(frame[i])) {
            m_errorCode = int(ErrorCode::AsciiConversion);
            return;
        }
    if (etx < 5 || !knownCommand(*command)) {
        m_errorCode = int(ErrorCode::NoSuchCommand);
        return;
    }
    const auto address = hexValue(frame, 5, 4);
    m_request.address = address.value_or(0);
    const qsizetype dataDigits = etx - 9;
    bool sizeOk = address.has_value();
    switch (m_request.command) {
    case Command::Read:
        sizeOk = sizeOk && dataDigits == 2;
        m_request.length = hexValue(frame, 9, 2).value_or(0);
        break;
    case Command::Write: {
        m_request.length = hexValue(frame, 9, 2).value_or(-1);
        sizeOk = sizeOk && dataDigits == 2 + 2 * qsizetype(m_request.length);
        for (qsizetype at = 11; sizeOk && at < etx; at += 2)
            m_request.data += char(*hexValue(frame, at, 2));
        break;
    }
    case Command::BitOn:
    case Command::BitOff:
        sizeOk = sizeOk && dataDigits == 0;
        break;
    }
    if (!sizeOk)
        m_errorCode = int(ErrorCode::AsciiConversion);
    else if ((m_request.command == Command::Read || m_request.command == Command::Write) &&
             (m_request.length < 1 || m_request.length > MaxBytes))
        m_errorCode = int(ErrorCode::AddressRange);
}

} // namespace rung::comms::vigor
