// One QCoreApplication for the network tests: a NetworkSession's stations tell their readers
// on the thread that owns them, through its event loop.
#include <QCoreApplication>

#include <gtest/gtest.h>

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
