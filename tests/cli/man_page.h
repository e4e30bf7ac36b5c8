#pragma once

// Reading a man page (roff) for the tests that keep it in step with a program's --help.

#include <QFile>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace rung::test {

inline QString readText(const QString &path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return QString();
    return QString::fromUtf8(file.readAll());
}

// The page's text without its comments (.\" lines) and with roff's escaped hyphens ("\-")
// as plain ones, so that an option reads as the program prints it.
inline QString manText(const QString &roff) {
    QStringList lines;
    for (const QString &line : roff.split(QLatin1Char('\n')))
        if (!line.startsWith(QLatin1String(".\\\"")))
            lines << line;
    return lines.join(QLatin1Char('\n')).replace(QLatin1String("\\-"), QLatin1String("-"));
}

// The options a text names (--target, -o, --help-all), sorted, each once. A hyphen inside a
// word ("read-only", "modbus-tcp") or before a digit ("-1") is no option.
inline QStringList optionsIn(const QString &text) {
    static const QRegularExpression option(
        QStringLiteral("(?<![\\w-])(--?[a-z][a-z-]*[a-z]|-[a-z])(?![\\w])"));
    QStringList found;
    for (auto it = option.globalMatch(text); it.hasNext();)
        found << it.next().captured(1);
    found.removeDuplicates();
    found.sort();
    return found;
}

} // namespace rung::test
