// One QCoreApplication for the simulator tests: the session tests need an event loop on the
// thread that owns a SimulatorSession (its signals arrive there).
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
