// `rungstudio-cli record`: the pass-through recorder as a user runs it, between a real master
// (`rungstudio-cli read`, as VPC Host Interface would sit there) and a virtual PLC on a
// pseudo-terminal; and what it refuses before it starts.

#include "tests/cli/cli_run.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <QDeadlineTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include <gtest/gtest.h>

#include <csignal>

namespace rung::test {
namespace {

constexpr const char *kVigor = "; target: vigor\nLD M9000\nOUT Y0\nEND\n";

CliRun record(QStringList args) {
    args.prepend(QStringLiteral("record"));
    return cli(args);
}

TEST(CliRecord, ARealMasterReadsAVirtualPlcThroughTheRecorderAndTheCaptureHoldsBothSides) {
    VirtualPlcUnderTest plc(kVigor, {model::ProtocolId::VigorLink, comms::modbus::Framing::Rtu, 0},
                            false);
    ASSERT_TRUE(plc.ready());
    ASSERT_TRUE(plc.scanned()); // Y0 is ON from the end of the first scan
    QTemporaryDir dir;
    const QString capture = dir.filePath(QStringLiteral("capture.txt"));
    QProcess recorder;
    recorder.start(QStringLiteral(RUNG_CLI_PATH),
                   {QStringLiteral("record"), QStringLiteral("--pc"), QStringLiteral("pty"),
                    QStringLiteral("--plc"), plc.path, QStringLiteral("-o"), capture});
    ASSERT_TRUE(recorder.waitForStarted(5000));
    // The first line says where the PC's software connects.
    const QDeadlineTimer deadline(15000);
    while (!recorder.canReadLine() && !deadline.hasExpired() &&
           recorder.state() == QProcess::Running)
        recorder.waitForReadyRead(100);
    const QString first = QString::fromUtf8(recorder.readLine()).trimmed();
    ASSERT_TRUE(first.startsWith(QLatin1String("pc /dev/pts/")))
        << first.toStdString() << recorder.readAllStandardError().toStdString();
    const QString pcPath = first.mid(3);

    QProcess read;
    read.start(QStringLiteral(RUNG_CLI_PATH),
               {QStringLiteral("read"), QStringLiteral("--target"), QStringLiteral("vigor"),
                QStringLiteral("--protocol"), QStringLiteral("vigor"), QStringLiteral("--pty"),
                pcPath, QStringLiteral("Y0")});
    ASSERT_TRUE(read.waitForFinished(15000));
    EXPECT_EQ(read.exitCode(), 0) << read.readAllStandardError().toStdString();
    EXPECT_EQ(QString::fromUtf8(read.readAllStandardOutput()).trimmed(), QStringLiteral("Y0=1"));

    ::kill(pid_t(recorder.processId()), SIGINT);
    ASSERT_TRUE(recorder.waitForFinished(5000));
    EXPECT_EQ(recorder.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(recorder.exitCode(), 0) << recorder.readAllStandardError().toStdString();

    QFile file(capture);
    ASSERT_TRUE(file.open(QIODevice::ReadOnly | QIODevice::Text));
    const QStringList lines = QString::fromUtf8(file.readAll()).split(u'\n', Qt::SkipEmptyParts);
    ASSERT_GE(lines.size(), 3) << lines.join(u'\n').toStdString();
    EXPECT_TRUE(lines[0].startsWith(QStringLiteral("# rungstudio-cli record: PC ") + pcPath))
        << lines[0].toStdString();
    EXPECT_TRUE(lines[0].contains(plc.path)) << lines[0].toStdString();
    // The master's 51h read of Y0's byte (0040h, Vigor M/VB/VH communication manual, B-5-3),
    // STX first, and the PLC's ACK.
    QString toPlc, toPc;
    for (const QString &line : lines.mid(1)) {
        ASSERT_TRUE(line.contains(QLatin1String(" PC>PLC ")) ||
                    line.contains(QLatin1String(" PLC>PC ")))
            << line.toStdString();
        const QString hex = line.section(u' ', 2).section(QLatin1String("  |"), 0, 0);
        (line.contains(QLatin1String(" PC>PLC ")) ? toPlc : toPc) += hex + u' ';
    }
    EXPECT_TRUE(toPlc.startsWith(QLatin1String("02 30 30 35 31 30 30 34 30")))
        << toPlc.toStdString();
    EXPECT_TRUE(toPc.startsWith(QLatin1String("06 30 30 35 31 30 30"))) << toPc.toStdString();
}

TEST(CliRecord, WhatItRefusesBeforeItStartsIsSaid) {
    CliRun r = record({QStringLiteral("--pc"), QStringLiteral("pty")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QLatin1String("--pc and --plc"))) << r.err.toStdString();
    r = record({QStringLiteral("--pc"), QStringLiteral("pty"), QStringLiteral("--plc"),
                QStringLiteral("pty"), QStringLiteral("--frame"), QStringLiteral("9Q1")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QLatin1String("9Q1"))) << r.err.toStdString();
    const QString missing = QStringLiteral("/dev/ttyRUNG-no-such-port");
    r = record({QStringLiteral("--pc"), QStringLiteral("pty"), QStringLiteral("--plc"), missing,
                QStringLiteral("--seconds"), QStringLiteral("0.2")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(missing)) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QLatin1String("the PLC's side"))) << r.err.toStdString();
}

TEST(CliRecord, TwoNewPseudoTerminalsAreJoinedForSecondsAndTheCountsAreSaid) {
    QTemporaryDir dir;
    const QString capture = dir.filePath(QStringLiteral("c.txt"));
    const CliRun r = record({QStringLiteral("--pc"), QStringLiteral("pty"), QStringLiteral("--plc"),
                             QStringLiteral("pty"), QStringLiteral("--seconds"),
                             QStringLiteral("0.2"), QStringLiteral("-o"), capture});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    const QStringList out = r.out.split(u'\n', Qt::SkipEmptyParts);
    ASSERT_EQ(out.size(), 2) << r.out.toStdString();
    EXPECT_TRUE(out[0].startsWith(QLatin1String("pc /dev/pts/")));
    EXPECT_TRUE(out[1].startsWith(QLatin1String("plc /dev/pts/")));
    EXPECT_TRUE(r.err.contains(QLatin1String("0 bytes from the PC, 0 bytes from the PLC")))
        << r.err.toStdString();
    EXPECT_TRUE(QFile::exists(capture));
}

} // namespace
} // namespace rung::test
