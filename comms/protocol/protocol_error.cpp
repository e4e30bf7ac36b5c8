#include "comms/protocol/protocol_error.h"

namespace rung::comms {

QString hexDump(QByteArrayView bytes) {
    constexpr qsizetype shown = 32;
    QString out;
    for (qsizetype i = 0; i < bytes.size() && i < shown; ++i) {
        if (i)
            out += QLatin1Char(' ');
        out += QStringLiteral("%1")
                   .arg(static_cast<quint8>(bytes[i]), 2, 16, QLatin1Char('0'))
                   .toUpper();
    }
    if (bytes.size() > shown)
        out += QStringLiteral(" ...");
    return out;
}

} // namespace rung::comms
