// Writing a network file: what is read is written back, key for key (networkToJson,
// writeNetworkFile).

#include "network/network_file.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace rung::network {
namespace {

QStringList writtenExampleNetworks() {
    QStringList out;
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks"),
                    {QStringLiteral("*.rungnet")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        out << it.next();
    out.sort();
    return out;
}

QByteArray writtenFileBytes(const QString &path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

TEST(NetworkWrite, EveryExampleIsWrittenBackKeyForKey) {
    const QStringList files = writtenExampleNetworks();
    ASSERT_GE(files.size(), 10);
    for (const QString &file : files) {
        SCOPED_TRACE(file.toStdString());
        NetworkDescription read;
        QString error;
        ASSERT_TRUE(readNetworkFile(file, &read, &error)) << error.toStdString();
        const QByteArray written = networkToJson(read, file);
        // The same JSON the user wrote: every key, no key added.
        EXPECT_EQ(QJsonDocument::fromJson(written), QJsonDocument::fromJson(writtenFileBytes(file)))
            << written.toStdString();
        NetworkDescription back;
        ASSERT_TRUE(parseNetwork(written, file, &back, &error)) << error.toStdString();
        EXPECT_TRUE(back == read);
        EXPECT_TRUE(networkDifferences(read, back).isEmpty());
        // Stable: written again, the same bytes.
        EXPECT_EQ(networkToJson(back, file), written);
        // Readable: no line past 100 columns but a long text.
        for (const QByteArray &line : written.split('\n'))
            if (!line.contains("\"comment\"")) {
                EXPECT_LE(line.size(), 100) << line.toStdString();
            }
    }
}

TEST(NetworkWrite, EveryKeyOfTheFormatIsWrittenBack) {
    // Defaults written out (period 10, from 0, xor 1), a wire named as its place would name it,
    // comments and the format key, bridges of every kind, both kinds of device.
    const QByteArray json = R"({
        "comment": "all of it", "format": "rungnet", "period": 10,
        "stations": [
            {"name": "a", "program": "a.il", "target": "vigor", "model": "VB", "period": 20,
             "ports": {"CP2": {"application": "modbus", "station": 0, "mode": "rtu",
                               "baud": 19200, "frame": "8N1"},
                       "CP3": {}},
             "comment": {"note": "any JSON"}},
            {"name": "b", "program": "sub/b.rung"}
        ],
        "devices": [
            {"name": "tc", "kind": "modbus-slave", "station": 3, "delay": 2,
             "registers": {"10": 1, "9": 2, "100": 3}, "coils": {"0": 1}},
            {"name": "scale", "kind": "line", "answers": [{"expectText": "W\r", "replyText": "1"}]}
        ],
        "wires": [{"name": "w1", "ends": ["a/CP2", "tc"]}, ["b/CP2", "scale"],
                  {"name": "bus", "ends": ["a/CP3", "b/CP3"]}],
        "bridges": [{"port": "a/CP2", "pty": true}, {"port": "b/CP2", "serial": "/dev/ttyUSB0"},
                    {"port": "a/CP3", "tcp": "192.168.1.50:4001"},
                    {"port": "b/CP3", "listen": "0.0.0.0:5020"}],
        "faults": [{"kind": "cut", "wire": "w1", "from": 0, "to": 3000},
                   {"kind": "silent", "station": "tc", "from": 100},
                   {"kind": "corrupt", "wire": "bus", "frame": 0, "byte": 2, "xor": 1},
                   {"kind": "corrupt", "wire": "w2"}]
    })";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("all.rungnet"));
    NetworkDescription read;
    QString error;
    ASSERT_TRUE(parseNetwork(json, file, &read, &error)) << error.toStdString();
    QStringList notKept;
    ASSERT_TRUE(writeNetworkFile(read, file, &notKept, &error)) << error.toStdString();
    EXPECT_TRUE(notKept.isEmpty()) << notKept.join(QLatin1Char('\n')).toStdString();
    const QByteArray written = writtenFileBytes(file);
    EXPECT_EQ(QJsonDocument::fromJson(written), QJsonDocument::fromJson(json))
        << written.toStdString();
    NetworkDescription back;
    ASSERT_TRUE(readNetworkFile(file, &back, &error)) << error.toStdString();
    EXPECT_TRUE(back == read);
    // The registers in the order of their numbers, the keys in the order of the format's tables.
    EXPECT_TRUE(written.contains(R"("registers": {"9": 2, "10": 1, "100": 3})"))
        << written.toStdString();
    EXPECT_TRUE(written.contains(R"({"name": "b", "program": "sub/b.rung"})"))
        << written.toStdString();
    EXPECT_LT(written.indexOf("\"comment\": \"all of it\""), written.indexOf("\"period\""));
}

TEST(NetworkWrite, SaveAsElsewhereKeepsTheProgramsWhereTheyAre) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString first = dir.filePath(QStringLiteral("plant/net.rungnet"));
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(parseNetwork(R"({"stations": [{"name": "a", "program": "progs/a.il"},
                                              {"name": "b", "program": "/abs/b.il"}]})",
                             first, &d, &error))
        << error.toStdString();
    ASSERT_TRUE(QDir().mkpath(dir.filePath(QStringLiteral("other/deeper"))));
    const QString second = dir.filePath(QStringLiteral("other/deeper/net.rungnet"));
    QStringList notKept;
    ASSERT_TRUE(writeNetworkFile(d, second, &notKept, &error)) << error.toStdString();
    EXPECT_TRUE(notKept.isEmpty()) << notKept.join(QLatin1Char('\n')).toStdString();
    NetworkDescription back;
    ASSERT_TRUE(readNetworkFile(second, &back, &error)) << error.toStdString();
    ASSERT_EQ(back.stations.size(), 2u);
    EXPECT_EQ(back.stations[0].program, QStringLiteral("../../plant/progs/a.il"));
    EXPECT_EQ(QFileInfo(back.stations[0].path).absoluteFilePath(),
              QFileInfo(d.stations[0].path).absoluteFilePath());
    EXPECT_EQ(back.stations[1].program, QStringLiteral("/abs/b.il"));
}

TEST(NetworkWrite, ASaveThatCannotHoldEverythingSaysWhatAndWritesOnlyWhenTold) {
    // Settings that are not an object cannot be read back: the save says what would not be
    // kept and writes nothing, unless the caller (the user, asked) says to write anyway.
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath(QStringLiteral("n.rungnet"));
    NetworkDescription d;
    d.file = file;
    StationDescription s;
    s.name = QStringLiteral("a");
    s.program = QStringLiteral("a.il");
    s.path = dir.filePath(s.program);
    s.ports.insert(QStringLiteral("CP2"), 5);
    d.stations.push_back(s);
    QStringList notKept;
    QString error;
    EXPECT_FALSE(writeNetworkFile(d, file, &notKept, &error));
    EXPECT_FALSE(QFileInfo::exists(file));
    ASSERT_FALSE(notKept.isEmpty());
    EXPECT_TRUE(notKept.join(QLatin1Char(' ')).contains(QStringLiteral("stations[0].ports.CP2")))
        << notKept.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(error.contains(QStringLiteral("stations[0].ports.CP2"))) << error.toStdString();
    ASSERT_TRUE(writeNetworkFile(d, file, &notKept, &error, true)) << error.toStdString();
    EXPECT_TRUE(QFileInfo::exists(file));
    EXPECT_FALSE(notKept.isEmpty());

    // A network without stations is no network file: said too.
    d.stations.clear();
    EXPECT_FALSE(writeNetworkFile(d, file, &notKept, &error));
    EXPECT_FALSE(notKept.isEmpty());
}

TEST(NetworkWrite, ASaveThatCannotWriteSaysWhere) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(parseNetwork(R"({"stations": [{"name": "a", "program": "a.il"}]})",
                             dir.filePath(QStringLiteral("n.rungnet")), &d, &error));
    QStringList notKept;
    const QString inMissingFolder = dir.filePath(QStringLiteral("no/such/folder/n.rungnet"));
    EXPECT_FALSE(writeNetworkFile(d, inMissingFolder, &notKept, &error));
    EXPECT_TRUE(error.contains(inMissingFolder)) << error.toStdString();
}

TEST(NetworkWrite, AnEditedWireKeepsItsName) {
    // Removing the first of two unnamed wires must not rename the second (a fault names it).
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(parseNetwork(R"({"stations": [{"name": "a", "program": "a.il"},
                                              {"name": "b", "program": "b.il"}],
                                 "wires": [["a/CP2", "b/CP2"], ["a/CP3", "b/CP3"]],
                                 "faults": [{"kind": "cut", "wire": "w2"}]})",
                             QStringLiteral("/tmp/n.rungnet"), &d, &error))
        << error.toStdString();
    d.wires.erase(d.wires.begin());
    renumberNetwork(&d);
    const QByteArray written = networkToJson(d, QStringLiteral("/tmp/n.rungnet"));
    NetworkDescription back;
    ASSERT_TRUE(parseNetwork(written, QStringLiteral("/tmp/n.rungnet"), &back, &error))
        << error.toStdString();
    ASSERT_EQ(back.wires.size(), 1u);
    EXPECT_EQ(back.wires[0].name, QStringLiteral("w2"));
    EXPECT_TRUE(networkDifferences(d, back).isEmpty());
}

} // namespace
} // namespace rung::network
