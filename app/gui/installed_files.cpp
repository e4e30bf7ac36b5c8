#include "installed_files.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace rung::app {

namespace {

// RUNG_DATA_FROM_BIN and RUNG_DOC_FROM_BIN are GNUInstallDirs' DATADIR/rungstudio and DOCDIR
// relative to BINDIR, as app/CMakeLists.txt computes them ("../share/rungstudio").
QString besideProgram(const char *relative) {
    return QDir::cleanPath(QCoreApplication::applicationDirPath() + QLatin1Char('/') +
                           QString::fromUtf8(relative));
}

} // namespace

QString examplesFolder() {
    const QString folder = besideProgram(RUNG_DATA_FROM_BIN "/examples");
    return QFileInfo(folder).isDir() ? folder : QString();
}

QString installedDocument(const QString &name) {
    const QString path = besideProgram(RUNG_DOC_FROM_BIN) + QLatin1Char('/') + name;
    return QFileInfo(path).isFile() ? path : QString();
}

QString userGuidePath() {
    const QString html = installedDocument(QStringLiteral("user-guide.html"));
    return html.isEmpty() ? installedDocument(QStringLiteral("user-guide.md")) : html;
}

} // namespace rung::app
