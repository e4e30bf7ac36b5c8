#pragma once

#include <QString>

namespace rung::model {
class Target;
}

namespace rung::app {

// The title File > Examples shows for an example project, in the user's language: the
// examples' own names where they have one ("traffic-light" -> "Traffic light"), the target's
// mnemonics as its manuals write them ("difu-difd" -> "DIFU / DIFD"), else the file name made
// readable.
QString exampleTitle(const model::Target *target, const QString &baseName);

// The base names with a translatable title, for the tests.
QStringList examplesWithTitles();

} // namespace rung::app
