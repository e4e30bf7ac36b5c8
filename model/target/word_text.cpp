#include "model/target/word_text.h"

namespace rung::model {

namespace {

bool showsDigits(const Target &target) {
    return target.constants.bcd && !target.constants.prefixed;
}

} // namespace

QString formatWord(const Target &target, qint64 value) {
    if (!showsDigits(target))
        return QString::number(value);
    return QStringLiteral("#%1")
        .arg(static_cast<quint64>(value) & 0xFFFFu, 4, 16, QLatin1Char('0'))
        .toUpper();
}

std::optional<qint64> parseWordValue(const Target &target, const QString &typed) {
    const QString t = typed.trimmed();
    bool ok = false;
    qint64 value = 0;
    if (t.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
        value = t.mid(2).toLongLong(&ok, 16);
    else if (showsDigits(target) && t.startsWith(QLatin1Char('#')))
        value = t.size() <= 5 ? t.mid(1).toLongLong(&ok, 16) : 0;
    else
        value = t.toLongLong(&ok, 10);
    if (!ok)
        return std::nullopt;
    return value;
}

} // namespace rung::model
