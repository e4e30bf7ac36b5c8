#include "comms/protocol/modbus.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/modbus_detail.h"

namespace rung::comms::modbus {

using comms::detail::hex2;
using detail::put16;

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

std::uint8_t lrc(QByteArrayView bytes) {
    std::uint8_t sum = 0;
    for (char c : bytes)
        sum = std::uint8_t(sum + static_cast<quint8>(c));
    return std::uint8_t(-sum);
}

QByteArray asciiFrame(int unit, QByteArrayView pdu) {
    QByteArray body(1, char(unit & 0xFF));
    body += pdu;
    QByteArray frame(1, ':');
    frame += body.toHex().toUpper();
    frame += hex2(lrc(body)).toLatin1();
    frame += "\r\n";
    return frame;
}

std::optional<QByteArray> detail::asciiBody(QByteArrayView text, QString *why) {
    if (text.size() < 6 || text.size() % 2 != 0) {
        *why = QCoreApplication::translate("rung::comms::Protocol",
                                           "Modbus ASCII: a frame of %1 characters: %2")
                   .arg(text.size())
                   .arg(hexDump(text));
        return std::nullopt;
    }
    QByteArray body;
    for (qsizetype i = 0; i < text.size(); i += 2) {
        const auto v = comms::detail::hexValue(text, i, 2);
        if (!v) {
            *why = QCoreApplication::translate("rung::comms::Protocol",
                                               "Modbus ASCII: \"%1\" is no hex digit pair")
                       .arg(QString::fromLatin1(text.sliced(i, 2)));
            return std::nullopt;
        }
        body += char(*v);
    }
    const QByteArrayView data = QByteArrayView(body).first(body.size() - 1);
    if (lrc(data) != static_cast<quint8>(body.back())) {
        *why = QCoreApplication::translate(
                   "rung::comms::Protocol",
                   "Modbus ASCII: wrong LRC (received %1, computed %2): noise on the line or a "
                   "wrong baud rate or parity")
                   .arg(hex2(static_cast<quint8>(body.back())), hex2(lrc(data)));
        return std::nullopt;
    }
    body.chop(1);
    return body;
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

} // namespace rung::comms::modbus
