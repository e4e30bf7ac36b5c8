#include "comms/protocol/modbus_slave.h"

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

bool known(int function) {
    return isRead(function) || function == WriteSingleCoil || function == WriteSingleRegister ||
           function == WriteMultipleCoils || function == WriteMultipleRegisters;
}

} // namespace

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

void RequestDecoder::feedAscii() {
    while (m_status == FrameStatus::NeedMore) {
        // Characters before the colon are noise between frames (serial line 2.5.2.1).
        const qsizetype colon = m_buffer.indexOf(':');
        if (colon < 0) {
            m_buffer.clear();
            return;
        }
        m_buffer.remove(0, colon);
        const qsizetype end = m_buffer.indexOf("\r\n");
        if (end < 0) {
            if (m_buffer.size() > MaxAsciiFrame) {
                drop(QCoreApplication::translate(
                         "rung::comms::Protocol",
                         "Modbus ASCII: no CR LF within %1 characters of the colon: dropped")
                         .arg(MaxAsciiFrame));
            }
            return;
        }
        QString why;
        const auto body = detail::asciiBody(QByteArrayView(m_buffer).sliced(1, end - 1), &why);
        m_buffer.remove(0, end + 2);
        if (!body || body->size() < 2) {
            // A frame with a wrong LRC gets no answer, as one with a wrong CRC (2.5.2.1).
            m_discarded = {Kind::BadChecksum, 0, why};
            ++m_dropped;
            continue;
        }
        m_unit = byte(*body, 0);
        m_parsed = parseRequestPdu(QByteArrayView(*body).sliced(1));
        m_used = 0;
        m_status = FrameStatus::Complete;
    }
}

FrameStatus RequestDecoder::feed(QByteArrayView bytes) {
    if (m_skipToSilence)
        bytes = {}; // the rest of a frame already dropped: nothing in it can be trusted
    m_buffer += bytes;
    if (m_framing == Framing::Ascii) {
        feedAscii();
        if (m_status == FrameStatus::Complete && m_buffer.size() > MaxAsciiFrame)
            m_buffer.truncate(MaxAsciiFrame); // a request waits: one more frame is kept
        return m_status;
    }
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
