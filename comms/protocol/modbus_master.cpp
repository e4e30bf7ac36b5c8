#include "comms/protocol/modbus_master.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/modbus_detail.h"

namespace rung::comms::modbus {

namespace {

using Kind = ProtocolError::Kind;
using comms::detail::hex2;
using detail::byte;
using detail::get16;
using detail::getBits;
using detail::isBitRead;
using detail::isRead;
using detail::put16;
using detail::putBits;

} // namespace

QByteArray encodeRequestPdu(const Request &r) {
    QByteArray pdu(1, char(r.function));
    put16(pdu, r.address);
    switch (r.function) {
    case WriteSingleCoil:
        put16(pdu, !r.bits.empty() && r.bits.front() ? 0xFF00 : 0x0000);
        break;
    case WriteSingleRegister:
        put16(pdu, r.registers.empty() ? 0 : r.registers.front());
        break;
    case WriteMultipleCoils:
        put16(pdu, int(r.bits.size()));
        putBits(pdu, r.bits);
        break;
    case WriteMultipleRegisters:
        put16(pdu, int(r.registers.size()));
        pdu += char((r.registers.size() * 2) & 0xFF);
        for (auto value : r.registers)
            put16(pdu, value);
        break;
    default:
        put16(pdu, r.count);
        break;
    }
    return pdu;
}

ReplyDecoder::ReplyDecoder(Framing framing, int unit, const Request &request, int transaction)
    : m_framing(framing)
    , m_unit(unit)
    , m_request(request)
    , m_transaction(transaction) {}

qsizetype ReplyDecoder::expectedRtuLength() const {
    if (m_buffer.size() < 2)
        return 0;
    const int function = byte(m_buffer, 1);
    if (function == (m_request.function | 0x80))
        return 5;
    if (function != m_request.function)
        return -1;
    if (isRead(function))
        return m_buffer.size() < 3 ? 0 : 3 + byte(m_buffer, 2) + 2;
    return 8;
}

FrameStatus ReplyDecoder::feed(QByteArrayView bytes) {
    if (m_status != FrameStatus::NeedMore)
        return m_status;
    // Whatever the peer sends, one byte past the longest reply is enough to know it is wrong.
    m_received += bytes.size();
    if (m_framing == Framing::Ascii) {
        m_buffer += bytes.first(std::min(bytes.size(), MaxAsciiBuffered - m_buffer.size()));
        return feedAscii();
    }
    m_buffer += bytes.first(std::min(bytes.size(), MaxBuffered - m_buffer.size()));
    if (m_framing == Framing::Rtu) {
        const qsizetype length = expectedRtuLength();
        if (length < 0)
            return fail(Kind::Garbage,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Modbus RTU: the reply starts %1, not an answer to function "
                            "%2h")
                            .arg(hexDump(m_buffer), hex2(m_request.function)));
        if (length == 0 || m_buffer.size() < length)
            return m_status;
        if (m_buffer.size() > length)
            return fail(Kind::Garbage, QCoreApplication::translate(
                                           "rung::comms::Protocol",
                                           "Modbus RTU: %1 bytes more than the %2-byte reply: %3")
                                           .arg(m_received - length)
                                           .arg(length)
                                           .arg(hexDump(m_buffer)));
        const QByteArrayView frame(m_buffer);
        const auto crc = crc16(frame.first(length - 2));
        const int received = byte(frame, length - 2) | byte(frame, length - 1) << 8;
        if (crc != received)
            return fail(Kind::BadChecksum,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Modbus RTU: wrong CRC in the reply (received %1, computed "
                            "%2): noise on the line or a wrong baud rate or parity")
                            .arg(QString::number(received, 16).toUpper().rightJustified(4, u'0'),
                                 QString::number(crc, 16).toUpper().rightJustified(4, u'0')));
        return decodePdu(frame.sliced(1, length - 3), byte(frame, 0));
    }
    if (m_buffer.size() < 7)
        return m_status;
    const int transaction = get16(m_buffer, 0);
    const int protocol = get16(m_buffer, 2);
    const int length = get16(m_buffer, 4);
    if (protocol != 0 || length < 3 || length > 254)
        return fail(Kind::Garbage,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Modbus TCP: not a Modbus header (protocol %1, length %2): %3")
                        .arg(protocol)
                        .arg(length)
                        .arg(hexDump(m_buffer)));
    if (m_buffer.size() < 6 + length)
        return m_status;
    if (m_buffer.size() > 6 + length)
        return fail(Kind::Garbage,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Modbus TCP: %1 bytes more than the reply's length")
                        .arg(m_received - 6 - length));
    if (transaction != (m_transaction & 0xFFFF))
        return fail(Kind::WrongReply,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Modbus TCP: the reply is for transaction %1, the request was "
                        "%2")
                        .arg(transaction)
                        .arg(m_transaction));
    return decodePdu(QByteArrayView(m_buffer).sliced(7), byte(m_buffer, 6));
}

FrameStatus ReplyDecoder::feedAscii() {
    // Noise before the colon is dropped, as a slave does (serial line 2.5.2.1).
    const qsizetype colon = m_buffer.indexOf(':');
    if (colon < 0) {
        m_buffer.clear();
        return m_status;
    }
    m_buffer.remove(0, colon);
    const qsizetype end = m_buffer.indexOf("\r\n");
    if (end < 0) {
        if (m_buffer.size() >= MaxAsciiBuffered)
            return fail(Kind::Garbage,
                        QCoreApplication::translate(
                            "rung::comms::Protocol",
                            "Modbus ASCII: no CR LF within %1 characters of the colon")
                            .arg(MaxAsciiFrame));
        return m_status;
    }
    QString why;
    const auto body = detail::asciiBody(QByteArrayView(m_buffer).sliced(1, end - 1), &why);
    if (!body)
        return fail(Kind::BadChecksum, why);
    if (m_buffer.size() > end + 2)
        return fail(Kind::Garbage, QCoreApplication::translate(
                                       "rung::comms::Protocol",
                                       "Modbus ASCII: %1 characters after the reply's CR LF")
                                       .arg(m_buffer.size() - end - 2));
    if (body->size() < 2)
        return fail(Kind::Malformed,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Modbus ASCII: a reply without a function code"));
    return decodePdu(QByteArrayView(*body).sliced(1), byte(*body, 0));
}

FrameStatus ReplyDecoder::decodePdu(QByteArrayView pdu, int unit) {
    if (unit != (m_unit & 0xFF))
        return fail(Kind::WrongStation,
                    QCoreApplication::translate("rung::comms::Protocol",
                                                "Modbus: unit %1 answered, unit %2 was asked")
                        .arg(unit)
                        .arg(m_unit));
    Response &r = m_response;
    const int function = byte(pdu, 0);
    r.function = m_request.function;
    if (function == (m_request.function | 0x80)) {
        if (pdu.size() != 2)
            return fail(Kind::Malformed,
                        QCoreApplication::translate("rung::comms::Protocol",
                                                    "Modbus: an exception reply of %1 bytes")
                            .arg(pdu.size()));
        r.exception = byte(pdu, 1);
        return fail(
            Kind::DeviceError,
            QCoreApplication::translate("rung::comms::Protocol", "Modbus: function %1h refused: %2")
                .arg(hex2(m_request.function), exceptionText(r.exception)),
            r.exception);
    }
    if (function != m_request.function)
        return fail(Kind::WrongReply,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Modbus: the reply is for function %1h, the request was %2h")
                        .arg(hex2(function), hex2(m_request.function)));
    const auto mismatch = [this, &pdu] {
        return fail(Kind::WrongReply,
                    QCoreApplication::translate(
                        "rung::comms::Protocol",
                        "Modbus: the reply to function %1h does not match the request: "
                        "%2")
                        .arg(hex2(m_request.function), hexDump(pdu)));
    };
    if (isRead(function)) {
        const int bytes = pdu.size() >= 2 ? byte(pdu, 1) : -1;
        const int needed = isBitRead(function) ? (m_request.count + 7) / 8 : 2 * m_request.count;
        if (bytes != needed || pdu.size() != 2 + bytes)
            return mismatch();
        if (isBitRead(function))
            r.bits = getBits(pdu, 2, m_request.count);
        else
            for (int i = 0; i < m_request.count; ++i)
                r.registers.push_back(std::uint16_t(get16(pdu, 2 + 2 * i)));
    } else {
        if (pdu.size() != 5)
            return mismatch();
        r.address = get16(pdu, 1);
        r.count = get16(pdu, 3);
        const QByteArray sent = encodeRequestPdu(m_request);
        if (r.address != m_request.address || QByteArrayView(sent).sliced(3, 2) != pdu.sliced(3, 2))
            return mismatch();
    }
    return complete();
}

ProtocolError ReplyDecoder::deadlinePassed(int waitedMs) const {
    return truncated(
        m_buffer.isEmpty(),
        QCoreApplication::translate("rung::comms::Protocol",
                                    "Modbus: no reply from unit %1 within %2 ms")
            .arg(m_unit)
            .arg(waitedMs),
        QCoreApplication::translate("rung::comms::Protocol",
                                    "Modbus: the reply stopped after %1 bytes (%2) within %3 ms")
            .arg(m_buffer.size())
            .arg(hexDump(m_buffer))
            .arg(waitedMs));
}

} // namespace rung::comms::modbus
