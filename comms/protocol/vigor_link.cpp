#include "comms/protocol/vigor_link.h"

#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/vigor_link_detail.h"

namespace rung::comms::vigor {

using comms::detail::appendHex;
using comms::detail::hex2;

QByteArray detail::closeFrame(char start, QByteArray body) {
    body += Etx;
    QByteArray frame(1, start);
    frame += body;
    frame += sum(body);
    return frame;
}

QByteArray sum(QByteArrayView body) {
    unsigned total = 0;
    for (char c : body)
        total += static_cast<quint8>(c);
    QByteArray out;
    appendHex(out, int(total & 0xFF), 2);
    return out;
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
} // namespace rung::comms::vigor
