#pragma once

// The languages Rung Studio speaks (translations/rungstudio_*.ts): one table for the IDE's
// Language menu and the command-line tool's --lang. A language added here needs its catalogue.

#include <QString>
#include <QStringList>

#include <array>

namespace rung::app {

struct Language {
    const char *code; // two letters, as the catalogue's file name and QLocale give it
    const char *name; // in the language itself (UTF-8), as a menu shows it to its readers
};

inline constexpr std::array<Language, 3> kLanguages{{
    {"en", "English"},
    {"hu", "Magyar"},
    {"it", "Italiano"},
}};

inline QStringList languageCodes() {
    QStringList codes;
    for (const Language &l : kLanguages)
        codes << QString::fromLatin1(l.code);
    return codes;
}

} // namespace rung::app
