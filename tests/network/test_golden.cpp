// Golden runs of the manuals' example networks (resources/examples/networks): each
// tests/data/network/NAME.args holds the network file (from the source root) on its first
// line and the trace's options on the second; NAME.csv is the trace and NAME.traffic the
// traffic, byte for byte. A run is made twice: the same network and stimulus give the same
// trace and traffic (determinism).

#include "network_fixture.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kData = QStringLiteral(RUNG_TEST_DATA_DIR "/network/");

QString readText(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

} // namespace

TEST(NetworkGolden, EveryExampleRunsAsRecorded) {
    const QStringList cases = QDir(kData).entryList({QStringLiteral("*.args")}, QDir::Files);
    ASSERT_GE(cases.size(), 2);
    for (const QString &name : cases) {
        SCOPED_TRACE(name.toStdString());
        const QStringList lines = readText(kData + name).split(QLatin1Char('\n'));
        ASSERT_GE(lines.size(), 2);
        const QString file = QStringLiteral(RUNG_SOURCE_DIR "/") + lines[0].trimmed();
        const QStringList args = QProcess::splitCommand(lines[1]);
        const NetRun first = runNetwork({}, {}, args, file);
        ASSERT_TRUE(first.net) << first.error.toStdString();
        ASSERT_TRUE(first.error.isEmpty()) << first.error.toStdString();
        const QString stem = kData + QFileInfo(name).completeBaseName();
        EXPECT_EQ(first.trace.toStdString(), readText(stem + QStringLiteral(".csv")).toStdString());
        EXPECT_EQ(first.traffic.toStdString(),
                  readText(stem + QStringLiteral(".traffic")).toStdString());
        const NetRun second = runNetwork({}, {}, args, file);
        EXPECT_EQ(first.trace, second.trace);
        EXPECT_EQ(first.traffic, second.traffic);
    }
}
