#pragma once

// The user interface's language: Rung Studio's catalogue and Qt's own (qtbase: the standard
// buttons, the file dialogs), switched while the program runs. Installing them makes Qt send
// every widget a LanguageChange event; each retranslates its texts there.

#include <QString>
#include <QStringList>

namespace rung::app {

// The languages the catalogues cover, as two-letter codes: en, hu, it.
QStringList availableLanguages();
// The language of this start: as chosen in the Language menu (QSettings "ui/language"), else
// the system's when we have it, else English.
QString startLanguage();
// Installs the catalogues of `code` in place of the ones before and remembers the choice when
// `remember`. False when `code` is no language we have (nothing changes then).
bool setLanguage(const QString &code, bool remember = true);
QString currentLanguage();

} // namespace rung::app
