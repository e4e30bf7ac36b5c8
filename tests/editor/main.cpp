// One QApplication for every GUI test, on the offscreen platform (tests/CMakeLists.txt).
#include "app/gui/recovery.h"

#include <QApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    // Test discovery runs the binary at build time, without the environment ctest sets.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true); // settings and recovery files out of the user's way
    // ctest runs the tests in parallel processes: each keeps its settings to itself, so a test
    // that changes the layout or the language cannot disturb another.
    QTemporaryDir settingsDir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QApplication app(argc, argv);
    // Recovery files in a folder of this process: the tests of another process must not
    // see them as work orphaned by a crash.
    QTemporaryDir recoveryDir;
    rung::app::RecoveryFile::setDirectory(recoveryDir.path());
    QApplication::setOrganizationName(QStringLiteral("RungStudioTests"));
    QApplication::setApplicationName(QStringLiteral("Rung Studio Tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
