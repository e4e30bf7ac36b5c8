#pragma once

// rungstudio-cli --lang en|hu|it: the language of the messages, in place of the locale's
// (LANG), for a script or a user who wants another than the system's.

#include <QString>
#include <QStringList>

namespace rung::app {

// Takes `--lang CODE` or `--lang=CODE` out of the arguments (anywhere after the program's
// name). `language` is the code, empty when the option is not there. False with the reason
// when the option has no code or one we have no catalogue for.
bool takeLanguageOption(QStringList *arguments, QString *language, QString *error);

} // namespace rung::app
