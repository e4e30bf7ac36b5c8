// `rungstudio-cli read` and `write` against a PLC on a real pseudo-terminal (a fake PLC
// answering on the pty's other side).

#include "tests/cli/cli_run.h"
#include "tests/comms/fake_plc.h"
#include "tests/comms/pty_peer.h"

#include <QElapsedTimer>

#include <gtest/gtest.h>

namespace {

using rung::test::cli;
using namespace rung::comms::test;

QStringList online(const char *command, const char *target, const char *protocol,
                   const QString &pty, QStringList more) {
    return QStringList{QLatin1String(command),
                       QStringLiteral("--target"),
                       QLatin1String(target),
                       QStringLiteral("--protocol"),
                       QLatin1String(protocol),
                       QStringLiteral("--pty"),
                       pty,
                       QStringLiteral("--timeout"),
                       QStringLiteral("200")} +
           more;
}

TEST(CliOnline, ReadPrintsDeviceEqualsValueLinesInTheOrderGiven) {
    FakeModbusPlc plc;
    plc.setRegister(2010, 0xFFFE); // V10 = -2
    plc.setCoil(2400, true);       // Q1
    plc.setCoil(16000, true);      // SM0.0
    plc.setRegister(12000, 35);    // T1's current value
    PtyPeer peer(plc.responder());
    ASSERT_TRUE(peer.ok()) << peer.error().toStdString();
    const auto r = cli(online("read", "pl110", "modbus", peer.path(),
                              {QStringLiteral("--station"), QStringLiteral("1"),
                               QStringLiteral("V10"), QStringLiteral("Q1"), QStringLiteral("Q2"),
                               QStringLiteral("SM0.0"), QStringLiteral("T1")}));
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("V10=-2\nQ1=1\nQ2=0\nSM0.0=1\nT1=35\n"));
    EXPECT_TRUE(r.err.isEmpty()) << r.err.toStdString();
}

TEST(CliOnline, WriteSetsEachDeviceAndSaysNothingWhenAllWereAcknowledged) {
    FakeModbusPlc plc;
    PtyPeer peer(plc.responder());
    ASSERT_TRUE(peer.ok()) << peer.error().toStdString();
    const auto r = cli(online("write", "pl110", "modbus", peer.path(),
                              {QStringLiteral("V10=-3"), QStringLiteral("Q2=1"),
                               QStringLiteral("V11=0x1F"), QStringLiteral("M1=ON")}));
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_EQ(plc.reg(2010), 0xFFFD);
    EXPECT_TRUE(plc.coil(2401));
    EXPECT_EQ(plc.reg(2011), 0x1F);
    EXPECT_TRUE(plc.coil(4000));
}

TEST(CliOnline, ARefusedWriteStopsNamesItAndWhatWasNotWritten) {
    FakeModbusPlc plc;
    plc.refuseWritesAt(2011);
    PtyPeer peer(plc.responder());
    ASSERT_TRUE(peer.ok()) << peer.error().toStdString();
    const auto r =
        cli(online("write", "pl110", "modbus", peer.path(),
                   {QStringLiteral("V10=1"), QStringLiteral("V11=2"), QStringLiteral("V12=3")}));
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(plc.reg(2010), 1);
    EXPECT_EQ(plc.reg(2012), 0);
    EXPECT_TRUE(r.err.contains(QLatin1String("writing V11 = 2 to PL110 unit 1 on")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QLatin1String("illegal data address"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QLatin1String("not written: V12=3"))) << r.err.toStdString();
}

TEST(CliOnline, ASilentPlcIsAnErrorWithinTheTimeoutAndRetries) {
    FakeModbusPlc plc;
    plc.setSilent(true);
    PtyPeer peer(plc.responder());
    ASSERT_TRUE(peer.ok()) << peer.error().toStdString();
    QElapsedTimer clock;
    clock.start();
    const auto r =
        cli(online("read", "pl110", "modbus", peer.path(),
                   {QStringLiteral("--timeout"), QStringLiteral("50"), QStringLiteral("--retries"),
                    QStringLiteral("1"), QStringLiteral("V1")}));
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QLatin1String("no reply from unit 1 within 50 ms (2 attempts)")))
        << r.err.toStdString();
    EXPECT_LT(clock.elapsed(), 3000);
}

TEST(CliOnline, HostLinkWriteInRunSaysItSwitchedToMonitor) {
    FakeHostLinkPlc plc;
    PtyPeer peer(plc.responder());
    ASSERT_TRUE(peer.ok()) << peer.error().toStdString();
    const auto r = cli(online("write", "cpm1", "hostlink", peer.path(),
                              {QStringLiteral("DM 0100=1234"), QStringLiteral("010.01=1")}));
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QLatin1String("note: CPM1 unit 0 on"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QLatin1String("MONITOR"))) << r.err.toStdString();
    EXPECT_EQ(plc.word(rung::model::ProtocolSpace::HostLinkDm, 100), 1234);
    EXPECT_EQ(plc.word(rung::model::ProtocolSpace::HostLinkIr, 10), 2);
    const auto read = cli(online("read", "cpm1", "hostlink", peer.path(),
                                 {QStringLiteral("DM 0100"), QStringLiteral("010.01")}));
    EXPECT_EQ(read.out, QStringLiteral("DM 0100=1234\n010.01=1\n")) << read.err.toStdString();
}

TEST(CliOnline, UsageErrorsExitTwoBeforeAnyPortIsOpened) {
    const QString nowhere = QStringLiteral("/dev/rung-no-such-port");
    struct Case {
        QStringList args;
        const char *says;
    } cases[] = {
        {{QStringLiteral("read"), QStringLiteral("V1")}, "--target and --protocol are needed"},
        {online("read", "pl110", "profibus", nowhere, {QStringLiteral("V1")}),
         "unknown protocol profibus"},
        {online("read", "pl110", "modbus", nowhere, {}), "no device given"},
        {online("read", "pl110", "modbus", nowhere, {QStringLiteral("Q999")}), "Q999"},
        {online("read", "pl110", "modbus", nowhere,
                {QStringLiteral("--tcp"), QStringLiteral("localhost:502"), QStringLiteral("V1")}),
         "exactly one of --port, --tcp and --pty"},
        {online("read", "pl110", "modbus", nowhere,
                {QStringLiteral("--frame"), QStringLiteral("9X1"), QStringLiteral("V1")}),
         "--frame"},
        {online("write", "pl110", "modbus", nowhere, {QStringLiteral("V1")}), "DEVICE=VALUE"},
        {online("read", "vpc", "modbus", nowhere, {QStringLiteral("r00")}), "does not speak"},
    };
    for (const Case &c : cases) {
        const auto r = cli(c.args);
        EXPECT_EQ(r.code, 2) << c.args.join(u' ').toStdString();
        EXPECT_TRUE(r.err.contains(QLatin1String(c.says))) << r.err.toStdString();
    }
    // A port that is not there: exit 2, named.
    const auto r = cli(online("read", "pl110", "modbus", nowhere, {QStringLiteral("V1")}));
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(nowhere)) << r.err.toStdString();
    // A bit takes 0 or 1.
    FakeModbusPlc plc;
    PtyPeer peer(plc.responder());
    const auto bit = cli(online("write", "pl110", "modbus", peer.path(), {QStringLiteral("Q1=2")}));
    EXPECT_EQ(bit.code, 2);
    EXPECT_TRUE(bit.err.contains(QLatin1String("a bit takes 0 or 1"))) << bit.err.toStdString();
    EXPECT_FALSE(plc.coil(2400));
}

} // namespace

// The real tool, as a user runs it, against Debian's libmodbus as the slave: over Modbus TCP,
// and over a pair of pseudo-terminals that socat links (as a null-modem cable would).
#ifdef RUNG_MODBUS_PEER
#include "tests/comms/peers/peer_values.h"

#include <QCoreApplication>
#include <QProcess>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTemporaryDir>

namespace {

namespace peer = rung::comms::test::peer;

struct Process {
    QProcess p;
    ~Process() {
        if (p.state() != QProcess::NotRunning) {
            p.kill();
            p.waitForFinished(5000);
        }
    }
    // Starts and waits for `ready` on stdout (the peer), or for the path to exist (socat).
    bool start(const QString &program, const QStringList &args, const QString &waitFor = {}) {
        p.start(program, args);
        QElapsedTimer clock;
        clock.start();
        QByteArray out;
        while (clock.elapsed() < 15000 && p.state() != QProcess::NotRunning) {
            if (waitFor.isEmpty() ? out.contains("ready") : QFile::exists(waitFor))
                return true;
            p.waitForReadyRead(50);
            out += p.readAllStandardOutput();
        }
        return false;
    }
};

struct CliResult {
    int code = -1;
    QString out, err;
};

CliResult runTool(const QStringList &args) {
    QProcess p;
    p.start(QStringLiteral(RUNG_CLI_PATH), args);
    CliResult r;
    if (!p.waitForFinished(30000))
        return r;
    r.code = p.exitCode();
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

void readWriteRead(const QStringList &where) {
    const QStringList common = QStringList{QStringLiteral("--target"), QStringLiteral("pl110")} +
                               where +
                               QStringList{QStringLiteral("--station"), QStringLiteral("1")};
    auto r =
        runTool(QStringList{QStringLiteral("read")} + common +
                QStringList{QStringLiteral("V10"), QStringLiteral("Q1"), QStringLiteral("Q2")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("V10=%1\nQ1=%2\nQ2=%3\n")
                         .arg(std::int16_t(peer::reg(2010)))
                         .arg(int(peer::coil(2400)))
                         .arg(int(peer::coil(2401))));
    r = runTool(QStringList{QStringLiteral("write")} + common +
                QStringList{QStringLiteral("V10=-321"), QStringLiteral("Q2=ON")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    r = runTool(QStringList{QStringLiteral("read")} + common +
                QStringList{QStringLiteral("V10"), QStringLiteral("Q2")});
    EXPECT_EQ(r.out, QStringLiteral("V10=-321\nQ2=1\n")) << r.err.toStdString();
}

TEST(CliBinaryOnline, ReadsAndWritesALibmodbusSlaveOverModbusTcp) {
    quint16 port = 0;
    {
        QTcpServer probe;
        probe.listen(QHostAddress::LocalHost, 0);
        port = probe.serverPort();
    }
    Process slave;
    ASSERT_TRUE(slave.start(QStringLiteral(RUNG_MODBUS_PEER),
                            {QStringLiteral("tcp"), QString::number(port), QStringLiteral("1")}))
        << slave.p.readAllStandardError().toStdString();
    readWriteRead({QStringLiteral("--protocol"), QStringLiteral("modbus-tcp"),
                   QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:%1").arg(port)});
}

TEST(CliBinaryOnline, ReadsAndWritesALibmodbusSlaveOverPtysLinkedBySocat) {
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        GTEST_SKIP() << "socat is not installed (scripts/install-deps.sh)";
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("plc-side")),
                  b = dir.filePath(QStringLiteral("pc-side"));
    Process link;
    ASSERT_TRUE(link.start(socat,
                           {QStringLiteral("pty,raw,echo=0,link=%1").arg(a),
                            QStringLiteral("pty,raw,echo=0,link=%1").arg(b)},
                           b));
    QElapsedTimer clock;
    clock.start();
    while (!QFile::exists(a) && clock.elapsed() < 5000)
        link.p.waitForFinished(20);
    ASSERT_TRUE(QFile::exists(a));
    Process slave;
    ASSERT_TRUE(slave.start(QStringLiteral(RUNG_MODBUS_PEER),
                            {QStringLiteral("rtu"), a, QStringLiteral("1")}))
        << slave.p.readAllStandardError().toStdString();
    readWriteRead(
        {QStringLiteral("--protocol"), QStringLiteral("modbus"), QStringLiteral("--pty"), b});
}

} // namespace
#endif
