// One QCoreApplication for the comms tests: the online session tests need an event loop on
// the thread that owns the session (its signals arrive there).
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
