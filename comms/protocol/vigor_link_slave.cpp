#include "comms/protocol/vigor_link_slave.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/vigor_link_detail.h"

#include <optional>

namespace rung::comms::vigor {

namespace {

using comms::detail::appendHex;
using comms::detail::hexDigit;
using comms::detail::hexValue;
using detail::closeFrame;

bool knownCommand(int code) {
    return code == int(Command::Read) || code == int(Command::Write) ||
           code == int(Command::BitOn) || code == int(Command::BitOff);
}

} // namespace

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
