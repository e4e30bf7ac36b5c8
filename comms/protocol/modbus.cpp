#include "comms/protocol/modbus.h"

#include "comms/protocol/ascii_hex.h"

namespace rung::comms::modbus {

namespace {

using Kind = ProtocolError::Kind;
using detail::hex2;

void put16(QByteArray &out, int value) {
    out += char((value >> 8) & 0xFF);
    out += char(value & 0xFF);
}

int get16(QByteArrayView bytes, qsizetype at) {
    return static_cast<quint8>(bytes[at]) << 8 | static_cast<quint8>(bytes[at + 1]);
}

int byte(QByteArrayView bytes, qsizetype at) {
    return static_cast<quint8>(bytes[at]);
}

void putBits(QByteArray &out, const std::vector<bool> &bits) {
    const auto bytes = (bits.size() + 7) / 8;
    out += char(bytes & 0xFF);
    for (std::size_t b = 0; b < bytes; ++b) {
        int value = 0;
        for (std::size_t i = 0; i < 8 && b * 8 + i < bits.size(); ++i)
            if (bits[b * 8 + i])
                value |= 1 << i;
        out += char(value);
    }
}

std::vector<bool> getBits(QByteArrayView bytes, qsizetype at, int count) {
    std::vector<bool> bits(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        bits[std::size_t(i)] = (byte(bytes, at + i / 8) >> (i % 8)) & 1;
    return bits;
}

bool isRead(int function) {
    return function >= ReadCoils && function <= ReadInputRegisters;
}

bool isBitRead(int function) {
    return function == ReadCoils || function == ReadDiscreteInputs;
}

bool known(int function) {
    return isRead(function) || function == WriteSingleCoil || function == WriteSingleRegister ||
           function == WriteMultipleCoils || function == WriteMultipleRegisters;
}

} // namespace

std::uint16_t crc16(QByteArrayView bytes) {
    // Modbus over serial line V1.02, 6.2.2: polynomial A001h (reflected 8005h), start FFFFh.
    std::uint16_t crc = 0xFFFF;
    for (char c : bytes) {
        crc ^= static_cast<quint8>(c);
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1) ? std::uint16_t((crc >> 1) ^ 0xA001) : std::uint16_t(crc >> 1);
    }
    return crc;
}

QByteArray rtuFrame(int unit, QByteArrayView pdu) {
    QByteArray frame(1, char(unit & 0xFF));
    frame += pdu;
    const auto crc = crc16(frame);
    frame += char(crc & 0xFF); // the CRC travels low byte first, unlike the PDU's fields
    frame += char(crc >> 8);
    return frame;
}

QByteArray tcpFrame(int transaction, int unit, QByteArrayView pdu) {
    QByteArray frame;
    put16(frame, transaction);
    put16(frame, 0); // protocol identifier: Modbus
    put16(frame, int(pdu.size()) + 1);
    frame += char(unit & 0xFF);
    frame += pdu;
    return frame;
}

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

QByteArray encodeResponsePdu(const Response &r) {
    if (r.exception) {
        QByteArray pdu(1, char(r.function | 0x80));
        pdu += char(r.exception);
        return pdu;
    }
    QByteArray pdu(1, char(r.function));
    if (isBitRead(r.function)) {
        putBits(pdu, r.bits);
    } else if (isRead(r.function)) {
        pdu += char((r.registers.size() * 2) & 0xFF);
        for (auto value : r.registers)
            put16(pdu, value);
    } else {
        put16(pdu, r.address);
        put16(pdu, r.count);
    }
    return pdu;
}

QString exceptionText(int code) {
    const QString hex = hex2(code);
    switch (code) {
    case IllegalFunction:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "illegal function (exception %1h): the device does not support "
                   "this function code")
            .arg(hex);
    case IllegalDataAddress:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "illegal data address (exception %1h): the address or the count "
                   "is outside the device's map")
            .arg(hex);
    case IllegalDataValue:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "illegal data value (exception %1h)")
            .arg(hex);
    case ServerDeviceFailure:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "server device failure (exception %1h); the PL110 manual uses this "
                   "code for an illegal data value")
            .arg(hex);
    case Acknowledge:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "acknowledge (exception %1h): the device accepted a long task")
            .arg(hex);
    case ServerDeviceBusy:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "server device busy (exception %1h)")
            .arg(hex);
    case MemoryParityError:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "memory parity error (exception %1h)")
            .arg(hex);
    case GatewayPathUnavailable:
        return QCoreApplication::translate("rung::comms::Protocol",
                                           "gateway path unavailable (exception %1h)")
            .arg(hex);
    case GatewayTargetNoResponse:
        return QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "gateway target device failed to respond (exception %1h)")
            .arg(hex);
    }
    return QCoreApplication::translate("rung::comms::Protocol", "unknown exception code %1h")
        .arg(hex);
}

ParsedRequest parseRequestPdu(QByteArrayView pdu) {
    ParsedRequest out;
    if (pdu.isEmpty()) {
        out.exception = IllegalFunction;
        return out;
    }
    Request &r = out.request;
    r.function = std::uint8_t(byte(pdu, 0));
    if (!known(r.function)) {
        out.exception = IllegalFunction;
        return out;
    }
    if (pdu.size() < 5) {
        out.exception = IllegalDataValue;
        return out;
    }
    r.address = get16(pdu, 1);
    const int value = get16(pdu, 3);
    switch (r.function) {
    case WriteSingleCoil:
        if ((value != 0xFF00 && value != 0x0000) || pdu.size() != 5)
            out.exception = IllegalDataValue;
        r.count = 1;
        r.bits = {value == 0xFF00};
        return out;
    case WriteSingleRegister:
        r.count = 1;
        r.registers = {std::uint16_t(value)};
        if (pdu.size() != 5)
            out.exception = IllegalDataValue;
        return out;
    case WriteMultipleCoils:
    case WriteMultipleRegisters: {
        r.count = value;
        const bool coils = r.function == WriteMultipleCoils;
        const int bytes = pdu.size() >= 6 ? byte(pdu, 5) : -1;
        const int needed = coils ? (value + 7) / 8 : value * 2;
        const int limit = coils ? MaxWriteBits : MaxWriteRegisters;
        if (value < 1 || value > limit || bytes != needed || pdu.size() != 6 + bytes) {
            out.exception = IllegalDataValue;
            return out;
        }
        if (coils)
            r.bits = getBits(pdu, 6, value);
        else
            for (int i = 0; i < value; ++i)
                r.registers.push_back(std::uint16_t(get16(pdu, 6 + 2 * i)));
        return out;
    }
    default:
        r.count = value;
        if (value < 1 || value > (isBitRead(r.function) ? MaxReadBits : MaxReadRegisters) ||
            pdu.size() != 5)
            out.exception = IllegalDataValue;
        return out;
    }
}

// ----- master side -----

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

// ----- slave side -----

void RequestDecoder::next() {
    m_buffer.remove(0, m_used);
    m_used = 0;
    m_status = FrameStatus::NeedMore;
    m_parsed = {};
    feed({});
}

FrameStatus RequestDecoder::take(qsizetype length) {
    const QByteArrayView frame = QByteArrayView(m_buffer).first(length);
    m_used = length;
    if (m_framing == Framing::Rtu) {
        if (length < 4 || crc16(frame.first(length - 2)) !=
                              (byte(frame, length - 2) | byte(frame, length - 1) << 8)) {
            ++m_dropped; // Serial line V1.02 2.5.1.1: a frame with a bad CRC gets no answer
            m_buffer.remove(0, length);
            m_used = 0;
            return m_status;
        }
        m_unit = byte(frame, 0);
        m_parsed = parseRequestPdu(frame.sliced(1, length - 3));
    } else {
        m_transaction = get16(frame, 0);
        m_unit = byte(frame, 6);
        m_parsed = parseRequestPdu(frame.sliced(7));
    }
    m_status = FrameStatus::Complete;
    return m_status;
}

void RequestDecoder::drop(QString why) {
    m_discarded = {Kind::Garbage, 0, std::move(why)};
    ++m_dropped;
    m_buffer.clear();
}

// While a request waits for next(), a master waits for its answer: more than one frame
// after it is a stream gone wrong, and the excess is dropped.
void RequestDecoder::keepPending() {
    if (m_status != FrameStatus::Complete || m_buffer.size() - m_used <= MaxTcpFrame)
        return;
    m_discarded = {Kind::Garbage, 0,
                   QCoreApplication::translate(
                       "rung::comms::Protocol",
                       "Modbus: %1 bytes arrived before the request was answered; the %2 "
                       "beyond the first %3 were dropped")
                       .arg(m_buffer.size() - m_used)
                       .arg(m_buffer.size() - m_used - MaxTcpFrame)
                       .arg(MaxTcpFrame)};
    m_buffer.truncate(m_used + MaxTcpFrame);
}

FrameStatus RequestDecoder::feed(QByteArrayView bytes) {
    if (m_skipToSilence)
        bytes = {}; // the rest of a frame already dropped: nothing in it can be trusted
    m_buffer += bytes;
    while (m_status == FrameStatus::NeedMore) {
        if (m_framing == Framing::Tcp) {
            if (m_buffer.size() < 7)
                break;
            const int protocol = get16(m_buffer, 2);
            const int length = get16(m_buffer, 4);
            if (protocol != 0 || length < 2 || length > 254) {
                // Not Modbus: nothing after it can be trusted either.
                drop(QCoreApplication::translate(
                         "rung::comms::Protocol",
                         "Modbus TCP: not a Modbus header (protocol %1, length %2): %3")
                         .arg(protocol)
                         .arg(length)
                         .arg(hexDump(m_buffer)));
                break;
            }
            if (m_buffer.size() < 6 + length)
                break;
            take(6 + length);
            break;
        }
        if (m_buffer.size() < 2)
            break;
        const int function = byte(m_buffer, 1);
        qsizetype length = 0;
        if (function == WriteMultipleCoils || function == WriteMultipleRegisters) {
            if (m_buffer.size() < 7)
                break;
            length = 7 + byte(m_buffer, 6) + 2;
        } else if (known(function)) {
            length = 8;
        } else if (m_buffer.size() <= MaxRtuFrame) {
            break; // unknown length: wait for silence()
        } else {
            length = m_buffer.size();
        }
        if (length > MaxRtuFrame) {
            // No RTU frame is this long: the line carries no gaps or no Modbus. Per serial
            // line V1.02 2.5.1.1 a frame ends at a silence, so everything up to it is dropped.
            drop(QCoreApplication::translate(
                     "rung::comms::Protocol",
                     "Modbus RTU: a frame of function %1h runs past %2 bytes, the longest an "
                     "RTU frame can be: dropped with what follows until the line is quiet")
                     .arg(hex2(function))
                     .arg(MaxRtuFrame));
            m_skipToSilence = true;
            break;
        }
        if (m_buffer.size() < length)
            break;
        const int before = m_dropped;
        take(length);
        if (m_dropped == before)
            break;
    }
    keepPending();
    return m_status;
}

FrameStatus RequestDecoder::silence() {
    m_skipToSilence = false;
    if (m_framing != Framing::Rtu || m_status != FrameStatus::NeedMore || m_buffer.isEmpty())
        return m_status;
    if (m_buffer.size() < 4) {
        m_buffer.clear();
        ++m_dropped;
        return m_status;
    }
    take(m_buffer.size());
    return m_status;
}

} // namespace rung::comms::modbus
