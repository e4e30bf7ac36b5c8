#include "network/traffic.h"
#include "network/tr.h"

#include <QCoreApplication>

namespace rung::network {

QString trafficHeader(const QString &networkFile) {
    return TrafficTr::tr("# traffic of %1: virtual time (ms), wire, sender, bytes, |as text|, note")
        .arg(networkFile);
}

QString formatTraffic(const TrafficRecord &r) {
    QString line = QStringLiteral("%1.%2 %3 %4")
                       .arg(r.startUs / 1000, 8)
                       .arg(r.startUs % 1000, 3, 10, QLatin1Char('0'))
                       .arg(r.wire.isEmpty() ? QStringLiteral("-") : r.wire, r.sender);
    if (!r.bytes.isEmpty()) {
        line += QLatin1Char(' ') + QString::fromLatin1(r.bytes.toHex(' ').toUpper());
        QString text;
        for (char c : r.bytes)
            text += c >= 0x20 && c < 0x7F ? QLatin1Char(c) : QLatin1Char('.');
        line += QStringLiteral(" |%1|").arg(text);
    }
    if (!r.note.isEmpty())
        line += QStringLiteral("  ") + r.note;
    return line;
}

} // namespace rung::network
