#include "model/comm/serial_line.h"

namespace rung::model {

bool parseFrameFormat(QStringView text, SerialSettings *line) {
    if (text.size() != 3)
        return false;
    const int data = text[0].digitValue();
    const QChar parity = text[1].toUpper();
    const int stop = text[2].digitValue();
    if (data < 7 || data > 8 || (stop != 1 && stop != 2))
        return false;
    if (parity == u'N')
        line->parity = SerialSettings::Parity::None;
    else if (parity == u'E')
        line->parity = SerialSettings::Parity::Even;
    else if (parity == u'O')
        line->parity = SerialSettings::Parity::Odd;
    else
        return false;
    line->dataBits = data;
    line->stopBits = stop;
    return true;
}

QString frameFormatText(const SerialSettings &line) {
    const char parity = line.parity == SerialSettings::Parity::None   ? 'N'
                        : line.parity == SerialSettings::Parity::Even ? 'E'
                                                                      : 'O';
    return QStringLiteral("%1%2%3").arg(line.dataBits).arg(QLatin1Char(parity)).arg(line.stopBits);
}

} // namespace rung::model
