// One QApplication for every GUI test, on the offscreen platform (tests/CMakeLists.txt).
#include <QApplication>
#include <QStandardPaths>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    // Test discovery runs the binary at build time, without the environment ctest sets.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QStandardPaths::setTestModeEnabled(true); // settings and recovery files out of the user's way
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("RungStudioTests"));
    QApplication::setApplicationName(QStringLiteral("Rung Studio Tests"));
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
