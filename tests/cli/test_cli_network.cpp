// `rungstudio-cli simulate NET.rungnet` and `check NET.rungnet` (docs/network.md): a network's
// trace with every device named STATION/DEVICE, its traffic file, and the wiring checks.

#include "tests/cli/cli_run.h"

#include "app/cli/cli_network.h"
#include "comms/protocol/modbus_master.h"
#include "comms/transport/pty_transport.h"
#include "network/bridge.h"
#include "network/station.h"
#include "tests/comms/peers/peer_values.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTemporaryDir>
#include <QThread>

#include <gtest/gtest.h>

#include <functional>

using rung::test::cli;

namespace {

const QString kExamples = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/");

// Writes the files into the directory; the network is "net.rungnet".
QString network(const QTemporaryDir &dir, const std::map<QString, QString> &files) {
    for (const auto &[name, text] : files) {
        QFile f(dir.filePath(name));
        if (!f.open(QIODevice::WriteOnly))
            return {};
        f.write(text.toUtf8());
    }
    return dir.filePath(QStringLiteral("net.rungnet"));
}

QString readAll(const QString &path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// Station `name`'s D registers, by number.
std::function<int(int)> dRegister(const rung::network::Network &net, const QString &name) {
    rung::network::Station *s = net.station(name);
    return [s](int d) {
        return s->engine().value(std::get<rung::model::Address>(
            rung::model::parseAddress(s->target(), QStringLiteral("D%1").arg(d))));
    };
}

// Runs a bridged network in real time until its MBUS (working area D100) has completed its
// table twice without an error, having read the libmodbus peer's registers 0..9 into
// D2000..D2009 (at most 15 s); false on a failed line or at the deadline.
bool turnUntilTwoTablesRead(rung::network::RealTime &rt, const std::function<int(int)> &value,
                            QString *failure) {
    using rung::comms::test::peer::reg;
    const QDeadlineTimer deadline(15000);
    while (!deadline.hasExpired()) {
        if (!rt.turn(5, failure))
            return false;
        if (value(2009) == reg(9) && value(100) == 0 && value(102) >= 2)
            return true;
    }
    *failure = QStringLiteral("the MBUS did not read its table twice in 15 s");
    return false;
}

} // namespace

// The B-3-9 example through the command line: the trace names each column STATION/DEVICE,
// the traffic file holds every frame with its virtual time, wire, sender and bytes; run
// twice, both are the same byte for byte.
TEST(CliNetwork, SimulateWritesTheTraceAndTheTraffic) {
    QTemporaryDir dir;
    const QStringList args = {
        QStringLiteral("simulate"), kExamples + QStringLiteral("non-protocol/non-protocol.rungnet"),
        QStringLiteral("--scans"),  QStringLiteral("30"),
        QStringLiteral("--set"),    QStringLiteral("left/VR1=120@0"),
        QStringLiteral("--set"),    QStringLiteral("right/VR1=77@0"),
        QStringLiteral("--trace"),  QStringLiteral("left/D110,right/D1"),
        QStringLiteral("--traffic")};
    const auto first = cli(args + QStringList{dir.filePath(QStringLiteral("a.traffic"))});
    ASSERT_EQ(first.code, 0) << first.err.toStdString();
    EXPECT_TRUE(first.err.isEmpty()) << first.err.toStdString();
    const QStringList lines = first.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(lines.size(), 31);
    EXPECT_TRUE(lines[0].endsWith(QStringLiteral("left/D110,right/D1"))) << lines[0].toStdString();
    EXPECT_TRUE(lines.back().endsWith(QStringLiteral(",77,120"))) << lines.back().toStdString();
    const QString traffic = readAll(dir.filePath(QStringLiteral("a.traffic")));
    // The read of D0 as the manual prints it, from the left PLC on wire w1.
    EXPECT_TRUE(
        traffic.contains(QStringLiteral("w1 left/CP2 02 30 31 35 31 31 43 30 30 30 32 03 30 30")))
        << traffic.toStdString();
    const auto second = cli(args + QStringList{dir.filePath(QStringLiteral("b.traffic"))});
    EXPECT_EQ(second.out, first.out);
    EXPECT_EQ(readAll(dir.filePath(QStringLiteral("b.traffic"))), traffic);
}

TEST(CliNetwork, ADeviceOfAStationThatIsNotThereIsAnError) {
    const auto r =
        cli({QStringLiteral("simulate"), kExamples + QStringLiteral("easy-link/easy-link.rungnet"),
             QStringLiteral("--scans"), QStringLiteral("3"), QStringLiteral("--trace"),
             QStringLiteral("s9/D0")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("s9"))) << r.err.toStdString();
}

TEST(CliNetwork, EveryExampleChecksClean) {
    for (const QString &name : QDir(kExamples).entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        const QString file =
            kExamples + name + QLatin1Char('/') + name + QStringLiteral(".rungnet");
        const auto r = cli({QStringLiteral("check"), file});
        EXPECT_EQ(r.code, 0) << name.toStdString() << "\n"
                             << r.out.toStdString() << r.err.toStdString();
        EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
    }
}

// The wiring checks the issue names: two masters on one wire, one station number twice, a
// LINK table naming a station that is not there, an application the model does not have.
TEST(CliNetwork, CheckFindsWiringMistakes) {
    QTemporaryDir dir;
    const QString link = QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K7 D1001\n"
                                        "MOV K1 D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K0 "
                                        "D1005\nMOV K13 D1006\nMOV K0 D1007\nLD M9000\nLINK "
                                        "D1000 D100\nEND\n");
    const QString file =
        network(dir, {{QStringLiteral("m.il"), link},
                      {QStringLiteral("s.il"), QStringLiteral("; target: vigor\nEND\n")},
                      {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [
                {"name": "m1", "program": "m.il", "model": "VB",
                 "ports": {"CP2": {"application": "easy-link", "station": 0}}},
                {"name": "m2", "program": "m.il", "model": "VB",
                 "ports": {"CP2": {"application": "easy-link", "station": 1}}},
                {"name": "a", "program": "s.il", "ports": {"CP2": {"station": 5}}},
                {"name": "b", "program": "s.il", "ports": {"CP2": {"station": 5}}}],
                "wires": [["m1/CP2", "m2/CP2", "a/CP2", "b/CP2"]]})")}});
    const auto r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("wire w1: error: 2 masters on one wire: m1/CP2 (LINK), m2/CP2 (LINK)")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("wire w1: error: a/CP2 and b/CP2 both answer Computer Link station 5")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral(
        "m1: line 12: error: LINK set 1 names station 7, which no port or device on w1 answers "
        "with Computer Link")))
        << r.out.toStdString();

    QTemporaryDir other;
    const QString vh =
        network(other, {{QStringLiteral("s.il"), QStringLiteral("; target: vigor\nEND\n")},
                        {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [
                {"name": "a", "program": "s.il", "model": "VH",
                 "ports": {"CP2": {"application": "cpu-link"}}}]})")}});
    const auto h = cli({QStringLiteral("check"), vh});
    EXPECT_EQ(h.code, 1);
    EXPECT_TRUE(h.out.contains(
        QStringLiteral("stations[0].ports.CP2.application: the Vigor VH has no CPU Link on CP2")))
        << h.out.toStdString();
}

// The PL110's wiring checks (PL110 manual 4.2.19, 4.2.21): a COM master and a Vigor MBUS on one
// wire, a COM query naming a slave nothing answers, SEND on a port the first scan left out of
// free-port, a port in NAIS MATSUSHITA-MASTER (no published frames).
TEST(CliNetwork, CheckFindsPl110WiringMistakes) {
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("pl.il"),
               QStringLiteral("; target: pl110\nLD SM0.0\nCOM 1 READ 1 WORD 0 V0 1\n"
                              "COM 2 READ 9 WORD 0 V1 1\nSEND COM2 1\nEND\n")},
              {QStringLiteral("nais.il"),
               QStringLiteral("; target: pl110\nLD SM0.0\nEXP 1 READ 1 WORD 10000 V0 10\nEND\n")},
              {QStringLiteral("vb.il"),
               QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K1 D1001\nMOV K1 "
                              "D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K0 D1005\nMOV K4 "
                              "D1006\nMOV K0 D1007\nLD M9000\nMBUS D1000 D100\nEND\n")},
              {QStringLiteral("s.il"), QStringLiteral("; target: pl110\nEND\n")},
              {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [
                {"name": "pl", "program": "pl.il", "target": "pl110",
                 "ports": {"COM1": {"application": "modbus-master"}}},
                {"name": "vb", "program": "vb.il", "model": "VB",
                 "ports": {"CP2": {"application": "modbus", "station": 0, "frame": "8N1"}}},
                {"name": "s", "program": "s.il", "target": "pl110",
                 "ports": {"COM1": {"application": "modbus", "station": 1}}},
                {"name": "n", "program": "nais.il", "target": "pl110",
                 "ports": {"EXP1": {"application": "nais-master"}}}],
                "wires": [["pl/COM1", "vb/CP2", "s/COM1"], ["pl/COM2", "n/EXP1"]]})")}});
    const auto r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral(
        "wire w1: error: 2 masters on one wire: pl/COM1 (MODBUS RTU master (COM / EXP)), "
        "vb/CP2 (MBUS)")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("pl: line 4: error: COM_2 queries slave 9, which no port or device on w1 "
                       "answers with MODBUS")))
        << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("COM_1 queries"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral(
        "pl: line 5: warning: SEND on COM2, which is not in free-port after the first scan "
        "(SM98 bit 8 is OFF)")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral(
        "n/EXP1: warning: n/EXP1 runs NAIS MATSUSHITA-MASTER (COM / EXP, no frames): the PL110 "
        "manual publishes no frames of it")))
        << r.out.toStdString();
}

// A station's program with an error: named by its file and line, as `check FILE` names it.
TEST(CliNetwork, CheckNamesAStationsProgramErrors) {
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("p.il"), QStringLiteral("; target: vigor\nLD X0\nOUT\nEND\n")},
              {QStringLiteral("net.rungnet"),
               QStringLiteral(R"({"stations": [{"name": "a", "program": "p.il"}]})")}});
    const auto r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(dir.filePath(QStringLiteral("p.il")) + QStringLiteral(":3:")))
        << r.out.toStdString();
}

// An instruction on a port that runs another application: the network does not start.
TEST(CliNetwork, LinkOnAModbusPortDoesNotStart) {
    QTemporaryDir dir;
    const QString file =
        network(dir, {{QStringLiteral("p.il"),
                       QStringLiteral("; target: vigor\nLD M9000\nLINK D1000 D100\nEND\n")},
                      {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [{"name": "a",
                "program": "p.il", "model": "VB", "ports": {"CP2": {"application": "modbus"}}}]})")}});
    const auto r = cli({QStringLiteral("simulate"), file, QStringLiteral("--scans"),
                        QStringLiteral("1"), QStringLiteral("--trace"), QStringLiteral("a/D100")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral(
        "a: line 3: LINK drives a/CP2, which runs modbus; LINK needs easy-link / computer-link")))
        << r.err.toStdString();
}

// A station's program may be a project: it brings its target, model and port settings
// ("ports"), which the network's settings override key by key.
TEST(CliNetwork, AProjectBringsItsPortSettings) {
    QTemporaryDir dir;
    const QString slave = dir.filePath(QStringLiteral("s5.il"));
    {
        QFile f(slave);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("; target: vigor\nLD M9000\nMOV K321 D10\nEND\n");
    }
    const QString project = dir.filePath(QStringLiteral("s5.rung"));
    const auto converted = cli({QStringLiteral("convert"), slave, QStringLiteral("--to"),
                                QStringLiteral("project"), QStringLiteral("-o"), project});
    ASSERT_EQ(converted.code, 0) << converted.err.toStdString();
    QFile pf(project);
    ASSERT_TRUE(pf.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(pf.readAll()).object();
    pf.close();
    root.insert(QStringLiteral("model"), QStringLiteral("VB"));
    // Station 5 at 9600 bps in the project; the network sets 19200, its master's rate.
    root.insert(QStringLiteral("ports"),
                QJsonObject{{QStringLiteral("CP2"), QJsonObject{{QStringLiteral("application"),
                                                                 QStringLiteral("computer-link")},
                                                                {QStringLiteral("station"), 5},
                                                                {QStringLiteral("baud"), 9600}}}});
    ASSERT_TRUE(pf.open(QIODevice::WriteOnly | QIODevice::Truncate));
    pf.write(QJsonDocument(root).toJson());
    pf.close();
    const QString master = QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K5 D1001\n"
                                          "MOV K1 D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K0 "
                                          "D1005\nMOV K13 D1006\nMOV K10 D1007\nLD M9000\nLINK "
                                          "D1000 D100\nEND\n");
    const QString file =
        network(dir, {{QStringLiteral("m.il"), master},
                      {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [
                {"name": "m", "program": "m.il", "model": "VB",
                 "ports": {"CP2": {"application": "easy-link", "station": 0}}},
                {"name": "s5", "program": "s5.rung", "ports": {"CP2": {"baud": 19200}}}],
                "wires": [["m/CP2", "s5/CP2"]]})")}});
    const auto r =
        cli({QStringLiteral("simulate"), file, QStringLiteral("--scans"), QStringLiteral("10"),
             QStringLiteral("--trace"), QStringLiteral("m/D0,hex:m/D100")});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.trimmed().endsWith(QStringLiteral(",321,#0000"))) << r.out.toStdString();
    // Without the override the slave listens at 9600 bps and never answers: status A, 05.
    QFile nf(file);
    ASSERT_TRUE(nf.open(QIODevice::ReadOnly));
    QByteArray text = nf.readAll();
    nf.close();
    text.replace(R"(, "ports": {"CP2": {"baud": 19200}})", "");
    ASSERT_TRUE(nf.open(QIODevice::WriteOnly | QIODevice::Truncate));
    nf.write(text);
    nf.close();
    const auto slow =
        cli({QStringLiteral("simulate"), file, QStringLiteral("--scans"), QStringLiteral("20"),
             QStringLiteral("--trace"), QStringLiteral("m/D0,hex:m/D100")});
    ASSERT_EQ(slow.code, 0) << slow.err.toStdString();
    EXPECT_TRUE(slow.out.trimmed().endsWith(QStringLiteral(",0,#0A05"))) << slow.out.toStdString();
}

// `serve NET.rungnet` as a user runs it: the first line names where each bridged port is
// reached; a master polls the simulated PLC through the pseudo-terminal; SIGTERM ends it, 0.
TEST(CliNetwork, ServeBridgesAPortToAPseudoTerminal) {
    QTemporaryDir dir;
    const QString file = network(
        dir,
        {{QStringLiteral("s.il"), QStringLiteral("; target: vigor\nLD M9000\nMOV K321 D0\nEND\n")},
         {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [{"name": "plc",
                "program": "s.il", "model": "VB",
                "ports": {"CP2": {"application": "modbus", "station": 1}}}],
                "bridges": [{"port": "plc/CP2", "pty": true}]})")}});
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH), {QStringLiteral("serve"), file});
    ASSERT_TRUE(serve.waitForStarted(10000));
    QString first;
    const QDeadlineTimer started(20000);
    while (!serve.canReadLine() && !started.hasExpired())
        serve.waitForReadyRead(100);
    first = QString::fromUtf8(serve.readLine()).trimmed();
    ASSERT_TRUE(first.startsWith(QStringLiteral("plc/CP2 /dev/pts/")))
        << first.toStdString() << serve.readAllStandardError().toStdString();
    rung::comms::PtyTransport hmi(first.section(QLatin1Char(' '), 1));
    QString error;
    ASSERT_TRUE(hmi.open(&error)) << error.toStdString();
    rung::comms::modbus::Request read;
    read.function = rung::comms::modbus::ReadHoldingRegisters;
    read.count = 1;
    ASSERT_TRUE(
        hmi.write(rung::comms::modbus::rtuFrame(1, rung::comms::modbus::encodeRequestPdu(read)),
                  QDeadlineTimer(1000), &error));
    rung::comms::modbus::ReplyDecoder reply(rung::comms::modbus::Framing::Rtu, 1, read);
    const QDeadlineTimer deadline(10000);
    while (reply.status() == rung::comms::FrameStatus::NeedMore && !deadline.hasExpired()) {
        const auto r = hmi.read(QDeadlineTimer(100));
        if (r.status == rung::comms::ReadResult::Status::Data)
            reply.feed(r.bytes);
    }
    ASSERT_EQ(reply.status(), rung::comms::FrameStatus::Complete)
        << reply.error().message.toStdString();
    EXPECT_EQ(reply.response().registers, (std::vector<std::uint16_t>{321}));
    serve.terminate(); // SIGTERM
    ASSERT_TRUE(serve.waitForFinished(10000));
    EXPECT_EQ(serve.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(serve.exitCode(), 0) << serve.readAllStandardError().toStdString();
}

// A CPM1 station's peripheral port (Omron CPM1 guide 2.1, item 9, for "Monitorozás (PLC-PC
// on-line kapcsolat)") bridged by `serve` to a pseudo-terminal, monitored by the product's own
// Host Link master as the IDE's Connection dock drives it (`read` / `write`, Host Link at its
// defaults 9600 7E2 unit 0): the program's DM 0000 and 010.00 are read; a write switches the
// station to MONITOR (W353: writes are refused in RUN), and the program runs on.
TEST(CliNetwork, TheHostLinkMasterMonitorsACpm1ThroughItsBridgedPeripheralPort) {
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("c.il"),
               QStringLiteral("; target: cpm1\nLD 253.13\nMOV(21) #1234 DM0000\nLD 000.00\n"
                              "OUT NOT 010.00\nEND(01)\n")},
              {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [{"name": "plc",
                "program": "c.il", "model": "CPM1-20CDR", "ports": {"PERIPHERAL": {}}}],
                "bridges": [{"port": "plc/PERIPHERAL", "pty": true}]})")}});
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH), {QStringLiteral("serve"), file});
    ASSERT_TRUE(serve.waitForStarted(10000));
    const QDeadlineTimer started(20000);
    while (!serve.canReadLine() && !started.hasExpired())
        serve.waitForReadyRead(100);
    const QString first = QString::fromUtf8(serve.readLine()).trimmed();
    ASSERT_TRUE(first.startsWith(QStringLiteral("plc/PERIPHERAL /dev/pts/")))
        << first.toStdString() << serve.readAllStandardError().toStdString();
    const QString pty = first.section(QLatin1Char(' '), 1);
    const auto online = [&](const char *command, QStringList devices) {
        return cli(QStringList{QLatin1String(command), QStringLiteral("--target"),
                               QStringLiteral("cpm1"), QStringLiteral("--protocol"),
                               QStringLiteral("hostlink"), QStringLiteral("--pty"), pty} +
                   devices);
    };
    const auto read = online("read", {QStringLiteral("DM 0000"), QStringLiteral("010.00")});
    EXPECT_EQ(read.code, 0) << read.err.toStdString();
    EXPECT_EQ(read.out, QStringLiteral("DM 0000=4660\n010.00=1\n")) << read.err.toStdString();
    const auto write = online("write", {QStringLiteral("DM 0100=1234")});
    EXPECT_EQ(write.code, 0) << write.err.toStdString();
    EXPECT_TRUE(write.err.contains(QLatin1String("MONITOR"))) << write.err.toStdString();
    const auto back = online("read", {QStringLiteral("DM 0100"), QStringLiteral("DM 0000")});
    EXPECT_EQ(back.out, QStringLiteral("DM 0100=1234\nDM 0000=4660\n")) << back.err.toStdString();
    serve.terminate(); // SIGTERM
    ASSERT_TRUE(serve.waitForFinished(10000));
    EXPECT_EQ(serve.exitCode(), 0) << serve.readAllStandardError().toStdString();
}

// mbpoll, a real Modbus master from Debian, as an HMI would poll the MODBUS application
// example's slave (Vigor M/VB/VH communication manual, B-3-6) bridged to a pseudo-terminal:
// it writes the slave's D100 (holding register 100, what the example's master writes) and
// reads it back.
TEST(CliNetwork, MbpollPollsABridgedStation) {
    const QString mbpoll = QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
    if (mbpoll.isEmpty())
        GTEST_SKIP() << "mbpoll is not installed (Debian package mbpoll; scripts/install-deps.sh)";
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("net.rungnet"),
               QStringLiteral(R"({"stations": [{"name": "s1", "program": "%1", "model": "VB",
                "ports": {"CP2": {"application": "modbus", "station": 1, "mode": "rtu"}}}],
                "bridges": [{"port": "s1/CP2", "pty": true}]})")
                   .arg(kExamples + QStringLiteral("modbus/slave.il"))}});
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH), {QStringLiteral("serve"), file});
    ASSERT_TRUE(serve.waitForStarted(10000));
    const QDeadlineTimer started(20000);
    while (!serve.canReadLine() && !started.hasExpired())
        serve.waitForReadyRead(100);
    const QString first = QString::fromUtf8(serve.readLine()).trimmed();
    ASSERT_TRUE(first.startsWith(QStringLiteral("s1/CP2 /dev/pts/"))) << first.toStdString();
    const QString pty = first.section(QLatin1Char(' '), 1);
    auto run = [&](QStringList args) {
        args = QStringList{QStringLiteral("-m"),    QStringLiteral("rtu"), QStringLiteral("-b"),
                           QStringLiteral("19200"), QStringLiteral("-P"),  QStringLiteral("none"),
                           QStringLiteral("-a"),    QStringLiteral("1"),   QStringLiteral("-0"),
                           QStringLiteral("-1"),    QStringLiteral("-o"),  QStringLiteral("1"),
                           QStringLiteral("-t"),    QStringLiteral("4")} +
               args;
        QProcess p;
        p.start(mbpoll, args);
        EXPECT_TRUE(p.waitForFinished(20000));
        return std::pair{p.exitCode(), QString::fromUtf8(p.readAllStandardOutput())};
    };
    const auto written =
        run({QStringLiteral("-r"), QStringLiteral("100"), pty, QStringLiteral("555")});
    EXPECT_EQ(written.first, 0) << written.second.toStdString();
    const auto read = run({QStringLiteral("-r"), QStringLiteral("100"), QStringLiteral("-c"),
                           QStringLiteral("1"), pty});
    EXPECT_EQ(read.first, 0) << read.second.toStdString();
    const auto m = QRegularExpression(QStringLiteral(R"(\[100\]:\s+(-?\d+))")).match(read.second);
    ASSERT_TRUE(m.hasMatch()) << read.second.toStdString();
    EXPECT_EQ(m.captured(1).toInt(), 555);
    serve.terminate();
    ASSERT_TRUE(serve.waitForFinished(10000));
    EXPECT_EQ(serve.exitCode(), 0) << serve.readAllStandardError().toStdString();
}

// A simulated master polls a real device: the MBUS of a VB station, its CP2 bridged to a
// pseudo-terminal on which Debian's libmodbus serves as slave 1 (tests/comms/peers), reads
// holding registers 0..9 into D2000..D2009, writes D2010 to register 20 and reads it back
// into D2020.
TEST(CliNetwork, AnMbusMasterPollsALibmodbusSlave) {
#ifndef RUNG_MODBUS_PEER
    GTEST_SKIP() << "libmodbus-dev is not installed (scripts/install-deps.sh)";
#else
    QTemporaryDir dir;
    const QString file = network(
        dir,
        {{QStringLiteral("m.il"),
          QStringLiteral(
              "; target: vigor\nLD M9002\nMOV K3 D1000\nMOV K1 D1001\nMOV K1 "
              "D1002\nMOV K10 D1003\nMOV K13 D1004\nMOV K2000 D1005\nMOV K4 "
              "D1006\nMOV K0 D1007\nMOV K1 D1008\nMOV K3 D1009\nMOV K1 D1010\n"
              "MOV K13 D1011\nMOV K2010 D1012\nMOV K4 D1013\nMOV K20 D1014\n"
              "MOV K1 D1015\nMOV K1 D1016\nMOV K1 D1017\nMOV K13 D1018\nMOV K2020 D1019\n"
              "MOV K4 D1020\nMOV K20 D1021\nMOV K4321 D2010\nLD M9000\nMBUS D1000 D100\nEND\n")},
         {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [{"name": "m",
                "program": "m.il", "model": "VB",
                "ports": {"CP2": {"application": "modbus", "station": 0, "mode": "rtu"}}}]})")}});
    rung::network::NetworkDescription d;
    QString error;
    ASSERT_TRUE(rung::network::readNetworkFile(file, &d, &error)) << error.toStdString();
    auto net = rung::network::Network::build(d, rung::app::cliProgramLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    auto pty = rung::comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    const QString path = pty->peerPath();
    rung::network::RealTime rt(*net);
    ASSERT_TRUE(rt.addBridge(QStringLiteral("m/CP2"), std::move(pty), &error))
        << error.toStdString();
    QProcess peer;
    peer.start(QStringLiteral(RUNG_MODBUS_PEER),
               {QStringLiteral("rtu"), path, QStringLiteral("1")});
    ASSERT_TRUE(peer.waitForReadyRead(10000)) << peer.readAllStandardError().toStdString();
    ASSERT_TRUE(peer.readLine().startsWith("ready"));
    const auto value = dRegister(*net, QStringLiteral("m"));
    using rung::comms::test::peer::reg;
    QString failure;
    EXPECT_TRUE(turnUntilTwoTablesRead(rt, value, &failure))
        << failure.toStdString() << " S2 " << std::hex << value(100);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(value(2000 + k), reg(k)) << k;
    EXPECT_EQ(value(2020), 4321); // written to the slave, read back from it
    peer.kill();
    peer.waitForFinished(5000);
#endif
}

// A simulated master polls a real device behind a serial device server: the same MBUS
// station as above, its CP2 bridged over TCP ("tcp": HOST:PORT) to socat, which stands for
// the device server and passes the bytes to a pseudo-terminal, where Debian's libmodbus
// serves as slave 1.
TEST(CliNetwork, AnMbusMasterPollsALibmodbusSlaveBehindADeviceServer) {
#ifndef RUNG_MODBUS_PEER
    GTEST_SKIP() << "libmodbus-dev is not installed (scripts/install-deps.sh)";
#else
    const QString socat = QStandardPaths::findExecutable(QStringLiteral("socat"));
    if (socat.isEmpty())
        GTEST_SKIP() << "socat is not installed (scripts/install-deps.sh)";
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("m.il"),
               QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K1 D1001\nMOV K1 "
                              "D1002\nMOV K10 D1003\nMOV K13 D1004\nMOV K2000 D1005\nMOV K4 "
                              "D1006\nMOV K0 D1007\nLD M9000\nMBUS D1000 D100\nEND\n")},
              {QStringLiteral("net.rungnet"), QStringLiteral(R"({"stations": [{"name": "m",
                "program": "m.il", "model": "VB",
                "ports": {"CP2": {"application": "modbus", "station": 0, "mode": "rtu"}}}]})")}});
    quint16 tcpPort = 0;
    {
        QTcpServer probe; // a free port for the device server
        ASSERT_TRUE(probe.listen(QHostAddress::LocalHost, 0));
        tcpPort = probe.serverPort();
    }
    const QString line = dir.filePath(QStringLiteral("line"));
    QProcess server;
    server.start(socat, {QStringLiteral("PTY,link=%1,raw,echo=0").arg(line),
                         QStringLiteral("TCP-LISTEN:%1,bind=127.0.0.1,reuseaddr").arg(tcpPort)});
    ASSERT_TRUE(server.waitForStarted(10000));
    const QDeadlineTimer made(10000);
    while (!QFile::exists(line) && !made.hasExpired())
        QThread::msleep(20);
    ASSERT_TRUE(QFile::exists(line)) << server.readAllStandardError().toStdString();
    QProcess peer;
    peer.start(QStringLiteral(RUNG_MODBUS_PEER),
               {QStringLiteral("rtu"), line, QStringLiteral("1")});
    ASSERT_TRUE(peer.waitForReadyRead(10000)) << peer.readAllStandardError().toStdString();
    ASSERT_TRUE(peer.readLine().startsWith("ready"));

    rung::network::NetworkDescription d;
    QString error;
    ASSERT_TRUE(rung::network::readNetworkFile(file, &d, &error)) << error.toStdString();
    auto net = rung::network::Network::build(d, rung::app::cliProgramLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    rung::network::RealTime rt(*net);
    rung::network::BridgeDescription tcp;
    tcp.end = QStringLiteral("m/CP2");
    tcp.kind = rung::network::BridgeDescription::Kind::Tcp;
    tcp.where = QStringLiteral("127.0.0.1:%1").arg(tcpPort);
    tcp.path = QStringLiteral("bridges[0]");
    QString where;
    ASSERT_TRUE(rt.addBridge(tcp, &where, &error)) << error.toStdString();
    EXPECT_EQ(where, tcp.where);
    const auto value = dRegister(*net, QStringLiteral("m"));
    using rung::comms::test::peer::reg;
    QString failure;
    EXPECT_TRUE(turnUntilTwoTablesRead(rt, value, &failure))
        << failure.toStdString() << " S2 " << std::hex << value(100);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(value(2000 + k), reg(k)) << k;
    peer.kill();
    peer.waitForFinished(5000);
    server.kill();
    server.waitForFinished(5000);
#endif
}

// pymodbus, a real Modbus master from Debian, as an HMI connecting over TCP with RTU framing
// to a "listen" bridge of a served network (what it would do with a serial device server in
// server mode): it writes the MODBUS example slave's D100 and reads it back.
TEST(CliNetwork, PymodbusPollsAStationListeningOnTcp) {
    QTemporaryDir dir;
    const QString file = network(
        dir, {{QStringLiteral("net.rungnet"),
               QStringLiteral(R"({"stations": [{"name": "s1", "program": "%1", "model": "VB",
                "ports": {"CP2": {"application": "modbus", "station": 1, "mode": "rtu"}}}],
                "bridges": [{"port": "s1/CP2", "listen": "127.0.0.1:0"}]})")
                   .arg(kExamples + QStringLiteral("modbus/slave.il"))}});
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH), {QStringLiteral("serve"), file});
    ASSERT_TRUE(serve.waitForStarted(10000));
    const QDeadlineTimer started(20000);
    while (!serve.canReadLine() && !started.hasExpired())
        serve.waitForReadyRead(100);
    const QString first = QString::fromUtf8(serve.readLine()).trimmed();
    ASSERT_TRUE(first.startsWith(QStringLiteral("s1/CP2 127.0.0.1:"))) << first.toStdString();
    const QString port = first.section(QLatin1Char(':'), 1);
    const char *script = R"(
import sys, time
from pymodbus.client import ModbusTcpClient
from pymodbus.transaction import ModbusRtuFramer
c = ModbusTcpClient('127.0.0.1', port=int(sys.argv[1]), framer=ModbusRtuFramer, timeout=2,
                    retries=3)
if not c.connect():
    sys.exit('cannot connect')
w = c.write_register(100, 777, slave=1)
if w.isError():
    sys.exit('write_register: %s' % w)
r = c.read_holding_registers(100, 1, slave=1)
if r.isError():
    sys.exit('read_holding_registers: %s' % r)
print('D100=%d' % r.registers[0])
c.close()
)";
    QProcess py;
    py.start(QStringLiteral("/usr/bin/python3"),
             {QStringLiteral("-c"), QLatin1String(script), port});
    ASSERT_TRUE(py.waitForFinished(30000));
    const QString err = QString::fromUtf8(py.readAllStandardError());
    if (py.exitCode() != 0 && (err.contains(QLatin1String("ModuleNotFoundError")) ||
                               err.contains(QLatin1String("ImportError"))))
        GTEST_SKIP() << "python3-pymodbus is not installed (scripts/install-deps.sh): "
                     << err.toStdString();
    EXPECT_EQ(py.exitCode(), 0) << err.toStdString();
    EXPECT_EQ(QString::fromUtf8(py.readAllStandardOutput()).trimmed(), QStringLiteral("D100=777"))
        << err.toStdString();
    serve.terminate();
    ASSERT_TRUE(serve.waitForFinished(10000));
    EXPECT_EQ(serve.exitCode(), 0) << serve.readAllStandardError().toStdString();
}
