#pragma once

// The user interface's language: Rung Studio's catalogue and Qt's own (qtbase: the standard
// buttons, the file dialogs), switched while the program runs. Installing them makes Qt send
// every widget a LanguageChange event; each retranslates its texts there.

#include <QLocale>
#include <QString>
#include <QStringList>

namespace rung::app {

// The languages the catalogues cover, as two-letter codes: en, hu, it.
QStringList availableLanguages();
// The language of a start: the one remembered from the Language menu when we have it, else the
// locale's when we have it, else English (a German system starts in English).
QString languageFor(const QLocale &locale, const QString &remembered = QString());
// languageFor() this system's locale and the choice remembered (QSettings "ui/language").
QString startLanguage();
// Installs the catalogues of `code` in place of the ones before and remembers the choice when
// `remember`. False when `code` is no language we have (nothing changes then).
bool setLanguage(const QString &code, bool remember = true);
QString currentLanguage();

} // namespace rung::app
