#pragma once

// The files the program ships beside itself: the example projects and the user guide. They are
// found relative to the program (bin/rungstudio -> share/rungstudio/examples), so an install
// moved to another prefix (`cmake --install build --prefix DIR`, a .deb under /usr) finds them
// as well; the build folder lays them out at the same relative place (app/ -> share/).

#include <QString>

namespace rung::app {

// The folder of the example projects, one folder per target (vigor/traffic-light.rung);
// empty when it is not there (a program copied away from its install).
QString examplesFolder();
// A file of the documentation folder (share/doc/rungstudio: the guides, `copyright` with the
// licences); empty when it is not there.
QString installedDocument(const QString &name);
// The user guide shipped with the program (HTML where it was rendered, else the Markdown
// source); empty when it is not there.
QString userGuidePath();

} // namespace rung::app
