// test_cli's own main: the virtual PLC's session thread runs a Qt event loop, which needs a
// QCoreApplication, as every Qt program (rungstudio-cli among them) has.

#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
