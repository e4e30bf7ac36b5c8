// Real Modbus masters from Debian against the virtual PLC: mbpoll (over a pseudo-terminal and
// Modbus TCP), libmodbus linked into this test (RTU over a pty, and TCP), and python3-pymodbus
// as a second independent master; and `rungstudio-cli serve` itself, run as a user runs it.
// Each test skips, saying which package is missing, only when its peer is not installed
// (scripts/install-deps.sh installs them). Every child process has a deadline and is killed
// when it passes.

#include "tests/cli/virtual_plc_fixture.h"
#include "tests/test_files.h"

#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>

#include <gtest/gtest.h>

#ifdef RUNG_HAVE_LIBMODBUS
#include <modbus.h>
#endif

#include <cerrno>
#include <csignal>
#include <map>
#include <tuple>

namespace rung::test {
namespace {

using comms::modbus::Framing;
using model::ProtocolId;

// V1 follows V0, Q1 follows I1.
constexpr const char *kPeerPl110 = "; target: pl110\nLD I1\nOUT Q1\nLD SM0.0\nMOV V0 V1\nEND\n";
// Y0 follows M0; D1 = D0 + 1.
constexpr const char *kPeerVigor = "; target: vigor\nLD M0\nOUT Y0\nLD M9000\nADD D0 K1 D1\nEND\n";

struct Finished {
    bool inTime = false;
    int code = -1;
    QString out, err;
};

// Runs a program to its end, or kills it at the deadline.
Finished run(const QString &program, const QStringList &args, int ms = 5000) {
    QProcess p;
    p.start(program, args);
    Finished f;
    if (!p.waitForStarted(5000))
        return f;
    f.inTime = p.waitForFinished(ms);
    if (!f.inTime) {
        p.kill();
        p.waitForFinished(1000);
    }
    f.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    f.out = QString::fromUtf8(p.readAllStandardOutput());
    f.err = QString::fromUtf8(p.readAllStandardError());
    return f;
}

// ----- mbpoll -----

QString mbpoll() {
    return QStandardPaths::findExecutable(QStringLiteral("mbpoll"));
}

#define REQUIRE_MBPOLL()                                                                           \
    if (mbpoll().isEmpty())                                                                        \
    GTEST_SKIP() << "mbpoll is not installed (Debian package mbpoll; scripts/install-deps.sh)"

// mbpoll's options for one poll of the virtual PLC: 0-based references, one poll, 1 s time-out.
// count 0: a write (mbpoll takes no count then).
QStringList mbpollArgs(const VirtualPlcUnderTest &v, const QString &type, int reference,
                       int count) {
    QStringList a{
        QStringLiteral("-a"), QStringLiteral("1"),       QStringLiteral("-0"), QStringLiteral("-1"),
        QStringLiteral("-o"), QStringLiteral("1"),       QStringLiteral("-t"), type,
        QStringLiteral("-r"), QString::number(reference)};
    if (count > 0)
        a << QStringLiteral("-c") << QString::number(count);
    if (v.port)
        a << QStringLiteral("-m") << QStringLiteral("tcp") << QStringLiteral("-p")
          << QString::number(v.port) << QStringLiteral("127.0.0.1");
    else
        a << QStringLiteral("-m") << QStringLiteral("rtu") << QStringLiteral("-b")
          << QStringLiteral("19200") << QStringLiteral("-P") << QStringLiteral("none") << v.path;
    return a;
}

// The values mbpoll printed, "[2001]: 	42" per reference.
std::map<int, int> mbpollValues(const QString &out) {
    std::map<int, int> values;
    static const QRegularExpression line(QStringLiteral(R"(\[(\d+)\]:\s+(-?\d+))"));
    for (auto it = line.globalMatch(out); it.hasNext();) {
        const auto m = it.next();
        values[m.captured(1).toInt()] = m.captured(2).toInt();
    }
    return values;
}

int mbpollRead(const VirtualPlcUnderTest &v, const char *type, int reference) {
    const Finished f = run(mbpoll(), mbpollArgs(v, QLatin1String(type), reference, 1));
    EXPECT_TRUE(f.inTime);
    const auto values = mbpollValues(f.out);
    const auto it = values.find(reference);
    return f.code == 0 && it != values.end() ? it->second : -100000;
}

bool mbpollWrite(const VirtualPlcUnderTest &v, const char *type, int reference, int value) {
    const Finished f =
        run(mbpoll(), mbpollArgs(v, QLatin1String(type), reference, 0) << QString::number(value));
    EXPECT_TRUE(f.inTime);
    EXPECT_EQ(f.code, 0) << f.out.toStdString() << f.err.toStdString();
    return f.code == 0;
}

TEST(PeerMbpoll, ReadsAndWritesThePl110OverAPseudoTerminal) {
    REQUIRE_MBPOLL();
    VirtualPlcUnderTest v(kPeerPl110, {ProtocolId::Modbus, Framing::Rtu, 1}, false);
    ASSERT_TRUE(v.ready());
    ASSERT_TRUE(mbpollWrite(v, "4", 2000, 555));                              // V0
    ASSERT_TRUE(mbpollWrite(v, "0", 1600, 1));                                // I1
    EXPECT_TRUE(eventually([&] { return mbpollRead(v, "4", 2001) == 555; })); // V1
    EXPECT_TRUE(eventually([&] { return mbpollRead(v, "0", 2400) == 1; }));   // Q1
    // 31 words are one too many for the PL110: mbpoll reports the slave's refusal.
    const Finished f = run(mbpoll(), mbpollArgs(v, QStringLiteral("4"), 2000, 31));
    EXPECT_TRUE(f.inTime);
    EXPECT_NE(f.code, 0);
}

TEST(PeerMbpoll, ReadsAndWritesTheVigorCp2MapOverModbusTcp) {
    REQUIRE_MBPOLL();
    VirtualPlcUnderTest v(kPeerVigor, {ProtocolId::Modbus, Framing::Tcp, 1}, true);
    ASSERT_TRUE(v.ready());
    ASSERT_TRUE(mbpollWrite(v, "4", 0, 99));                               // D0
    ASSERT_TRUE(mbpollWrite(v, "0", 512, 1));                              // M0
    EXPECT_TRUE(eventually([&] { return mbpollRead(v, "4", 1) == 100; })); // D1 = D0 + 1
    EXPECT_TRUE(eventually([&] { return mbpollRead(v, "0", 0) == 1; }));   // Y0
    EXPECT_EQ(mbpollRead(v, "1", 0), 0);                                   // X0
}

// ----- libmodbus, linked in -----

#ifdef RUNG_HAVE_LIBMODBUS
struct Libmodbus {
    modbus_t *ctx = nullptr;
    explicit Libmodbus(const VirtualPlcUnderTest &v) {
        ctx = v.port ? modbus_new_tcp("127.0.0.1", v.port)
                     : modbus_new_rtu(qPrintable(v.path), 19200, 'N', 8, 1);
        if (!ctx)
            return;
        modbus_set_slave(ctx, 1);
        modbus_set_response_timeout(ctx, 1, 0);
        if (modbus_connect(ctx) != 0) {
            ADD_FAILURE() << "modbus_connect: " << modbus_strerror(errno);
            modbus_free(ctx);
            ctx = nullptr;
        }
    }
    ~Libmodbus() {
        if (ctx) {
            modbus_close(ctx);
            modbus_free(ctx);
        }
    }
    int reg(int address) {
        uint16_t value = 0;
        return modbus_read_registers(ctx, address, 1, &value) == 1 ? value : -1;
    }
    int coil(int address) {
        uint8_t value = 0;
        return modbus_read_bits(ctx, address, 1, &value) == 1 ? value : -1;
    }
};
#define REQUIRE_LIBMODBUS()
#else
#define REQUIRE_LIBMODBUS()                                                                        \
    GTEST_SKIP() << "libmodbus is not installed (Debian package libmodbus-dev; "                   \
                    "scripts/install-deps.sh): this test was built without it"
#endif

void libmodbusMaster(bool tcp) {
#ifdef RUNG_HAVE_LIBMODBUS
    VirtualPlcUnderTest v(kPeerPl110, {ProtocolId::Modbus, tcp ? Framing::Tcp : Framing::Rtu, 1},
                          tcp);
    ASSERT_TRUE(v.ready());
    Libmodbus m(v);
    ASSERT_TRUE(m.ctx);
    const uint16_t values[3] = {11, 22, 33};
    ASSERT_EQ(modbus_write_registers(m.ctx, 2000, 3, values), 3) << modbus_strerror(errno);
    uint16_t back[3] = {};
    ASSERT_EQ(modbus_read_registers(m.ctx, 2000, 3, back), 3);
    EXPECT_EQ(back[2], 33);
    EXPECT_TRUE(eventually([&] { return m.reg(2001) == 11; })); // V1 follows V0
    ASSERT_EQ(modbus_write_bit(m.ctx, 1600, 1), 1);             // I1
    EXPECT_TRUE(eventually([&] { return m.coil(2400) == 1; })); // Q1
    // The PL110's refusals, as libmodbus names them: 31 words (its ILLEGAL DATA VALUE is 04,
    // EMBXSFAIL to libmodbus), a read-only input word, an address with nothing behind it.
    uint16_t many[31];
    EXPECT_EQ(modbus_read_registers(m.ctx, 2000, 31, many), -1);
    EXPECT_EQ(errno, EMBXSFAIL);
    EXPECT_EQ(modbus_write_register(m.ctx, 100, 1), -1);
    EXPECT_EQ(errno, EMBXILADD);
    EXPECT_EQ(modbus_read_registers(m.ctx, 2350, 1, many), -1);
    EXPECT_EQ(errno, EMBXILADD);
    // And it goes on answering.
    EXPECT_EQ(m.reg(2002), 33);
#else
    (void)tcp;
#endif
}

TEST(PeerLibmodbus, MasterOverRtuOnAPseudoTerminal) {
    REQUIRE_LIBMODBUS();
    libmodbusMaster(false);
}

TEST(PeerLibmodbus, MasterOverModbusTcp) {
    REQUIRE_LIBMODBUS();
    libmodbusMaster(true);
}

TEST(PeerLibmodbus, BroadcastWritesAreDoneWithoutAnAnswer) {
    REQUIRE_LIBMODBUS();
#ifdef RUNG_HAVE_LIBMODBUS
    VirtualPlcUnderTest v(kPeerPl110, {ProtocolId::Modbus, Framing::Rtu, 1}, false);
    ASSERT_TRUE(v.ready());
    Libmodbus m(v);
    ASSERT_TRUE(m.ctx);
    modbus_set_slave(m.ctx, MODBUS_BROADCAST_ADDRESS);
    modbus_set_response_timeout(m.ctx, 0, 200'000);
    // Debian 12's libmodbus (3.1.6) waits for an answer to a broadcast too, and must meet
    // silence (ETIMEDOUT); a later one does not wait and returns 1.
    const int rc = modbus_write_register(m.ctx, 2000, 4242);
    if (rc == -1)
        EXPECT_EQ(errno, ETIMEDOUT) << modbus_strerror(errno);
    else
        EXPECT_EQ(rc, 1);
    modbus_set_response_timeout(m.ctx, 1, 0);
    modbus_set_slave(m.ctx, 1);
    EXPECT_TRUE(eventually([&] { return m.reg(2001) == 4242; }));
#endif
}

// ----- python3-pymodbus -----

// One Python run for both links (the interpreter and pymodbus take about a second to start):
// for each "tcp HOST:PORT" / "rtu PATH" pair, the values read back and whether 31 words were
// refused, one line each.
const char *kPymodbusScript = R"(
import sys, time
from pymodbus.client import ModbusTcpClient, ModbusSerialClient
args = sys.argv[1:]
for mode, where in zip(args[0::2], args[1::2]):
    if mode == 'tcp':
        host, port = where.rsplit(':', 1)
        c = ModbusTcpClient(host, port=int(port), timeout=1, retries=0)
    else:
        c = ModbusSerialClient(where, baudrate=19200, timeout=1, retries=0)
    if not c.connect():
        sys.exit('%s: cannot connect' % mode)
    w = c.write_register(2000, 2468, slave=1)
    if w.isError():
        sys.exit('%s: write_register: %s' % (mode, w))
    w = c.write_coil(1600, True, slave=1)
    if w.isError():
        sys.exit('%s: write_coil: %s' % (mode, w))
    v1, q1 = None, None
    end = time.time() + 3
    while time.time() < end and (v1 != 2468 or q1 is not True):
        r = c.read_holding_registers(2001, 1, slave=1)
        v1 = None if r.isError() else r.registers[0]
        r = c.read_coils(2400, 1, slave=1)
        q1 = None if r.isError() else r.bits[0]
        time.sleep(0.02)
    r = c.read_holding_registers(2000, 31, slave=1)
    print('%s V1=%s Q1=%s refused31=%s' % (mode, v1, q1, r.isError()))
    c.close()
)";

TEST(PeerPymodbus, MasterOverModbusTcpAndRtuOnAPseudoTerminal) {
    VirtualPlcUnderTest tcp(kPeerPl110, {ProtocolId::Modbus, Framing::Tcp, 1}, true);
    VirtualPlcUnderTest rtu(kPeerPl110, {ProtocolId::Modbus, Framing::Rtu, 1}, false);
    ASSERT_TRUE(tcp.ready() && rtu.ready());
    const Finished f =
        run(QStringLiteral("/usr/bin/python3"),
            {QStringLiteral("-c"), QLatin1String(kPymodbusScript), QStringLiteral("tcp"),
             QStringLiteral("127.0.0.1:%1").arg(tcp.port), QStringLiteral("rtu"), rtu.path},
            20000);
    ASSERT_TRUE(f.inTime) << f.err.toStdString();
    // Debian 12's python3-pymodbus imports serial_asyncio without depending on it.
    if (f.code != 0 && (f.err.contains(QLatin1String("ModuleNotFoundError")) ||
                        f.err.contains(QLatin1String("ImportError"))))
        GTEST_SKIP() << "python3-pymodbus with python3-serial-asyncio is not installed "
                        "(scripts/install-deps.sh): "
                     << f.err.toStdString();
    EXPECT_EQ(f.code, 0) << f.err.toStdString();
    EXPECT_EQ(f.out.trimmed(), QStringLiteral("tcp V1=2468 Q1=True refused31=True\n"
                                              "rtu V1=2468 Q1=True refused31=True"))
        << f.err.toStdString();
}

// ----- rungstudio-cli serve, as a user runs it -----

TEST(CliServe, ServesAPtyUntilSigtermAndExitsCleanly) {
    REQUIRE_MBPOLL();
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, QStringLiteral("plc.il"), kPeerPl110);
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH),
                {QStringLiteral("serve"), file, QStringLiteral("--protocol"),
                 QStringLiteral("modbus"), QStringLiteral("--pty"), QStringLiteral("--station"),
                 QStringLiteral("3")});
    ASSERT_TRUE(serve.waitForStarted(5000));
    // The first line is the path, flushed before anything else.
    const QDeadlineTimer deadline(15000);
    while (!serve.canReadLine() && !deadline.hasExpired() && serve.state() == QProcess::Running)
        serve.waitForReadyRead(100);
    const QString path = QString::fromUtf8(serve.readLine()).trimmed();
    ASSERT_TRUE(path.startsWith(QLatin1String("/dev/pts/")))
        << path.toStdString() << serve.readAllStandardError().toStdString();
    const QStringList common{QStringLiteral("-m"),    QStringLiteral("rtu"), QStringLiteral("-b"),
                             QStringLiteral("19200"), QStringLiteral("-P"),  QStringLiteral("none"),
                             QStringLiteral("-a"),    QStringLiteral("3"),   QStringLiteral("-0"),
                             QStringLiteral("-1"),    QStringLiteral("-o"),  QStringLiteral("1"),
                             QStringLiteral("-t"),    QStringLiteral("4"),   QStringLiteral("-r")};
    Finished w = run(mbpoll(), QStringList(common)
                                   << QStringLiteral("2000") << path << QStringLiteral("321"));
    EXPECT_EQ(w.code, 0) << w.out.toStdString();
    EXPECT_TRUE(eventually([&] {
        const Finished r = run(mbpoll(), QStringList(common) << QStringLiteral("2001") << path);
        return mbpollValues(r.out)[2001] == 321;
    }));
    serve.terminate(); // SIGTERM
    ASSERT_TRUE(serve.waitForFinished(5000));
    EXPECT_EQ(serve.exitStatus(), QProcess::NormalExit);
    EXPECT_EQ(serve.exitCode(), 0);
    const QString err = QString::fromUtf8(serve.readAllStandardError());
    EXPECT_TRUE(err.contains(QStringLiteral("writes"))) << err.toStdString();
}

// `rungstudio-cli serve FILE ARGS...` started as a user starts it; its first line (where the
// PLC is reached) read, or empty when it ended or said nothing within 15 s.
struct Served {
    QProcess process;
    QString where;

    Served(const QString &file, const QStringList &args) {
        process.start(QStringLiteral(RUNG_CLI_PATH),
                      QStringList{QStringLiteral("serve"), file} + args);
        if (!process.waitForStarted(5000))
            return;
        const QDeadlineTimer deadline(15000);
        while (!process.canReadLine() && !deadline.hasExpired() &&
               process.state() == QProcess::Running)
            process.waitForReadyRead(100);
        where = QString::fromUtf8(process.readLine()).trimmed();
    }
    // SIGTERM, as a service manager stops it; its exit code (-1: it had to be killed).
    int stop() {
        process.terminate();
        if (process.waitForFinished(5000))
            return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
        process.kill();
        process.waitForFinished(1000);
        return -1;
    }
    ~Served() {
        if (process.state() != QProcess::NotRunning)
            stop();
    }
};

QStringList mbpollRtu(int station, const char *type, int reference, const QString &path) {
    return {QStringLiteral("-m"),
            QStringLiteral("rtu"),
            QStringLiteral("-b"),
            QStringLiteral("19200"),
            QStringLiteral("-P"),
            QStringLiteral("none"),
            QStringLiteral("-a"),
            QString::number(station),
            QStringLiteral("-0"),
            QStringLiteral("-1"),
            QStringLiteral("-o"),
            QStringLiteral("1"),
            QStringLiteral("-t"),
            QLatin1String(type),
            QStringLiteral("-r"),
            QString::number(reference),
            path};
}

TEST(CliServe, APl110AnswersEveryWordItsManualListsAsMbpollFirstAsksThem) {
    REQUIRE_MBPOLL();
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, QStringLiteral("plc.il"), kPeerPl110);
    Served serve(file, {QStringLiteral("--protocol"), QStringLiteral("modbus"),
                        QStringLiteral("--pty"), QStringLiteral("--station"), QStringLiteral("7")});
    ASSERT_TRUE(serve.where.startsWith(QLatin1String("/dev/pts/"))) << serve.where.toStdString();
    const auto poll = [&](const char *type, int reference, int count) {
        return run(mbpoll(), mbpollRtu(7, type, reference, serve.where)
                                 << QStringLiteral("-c") << QString::number(count));
    };
    // Words 0..5 in one request (PL110 manual 3.2: device type, firmware, the protocols of
    // COM1 / EXP1 / COM2, the protocol address): the station the PLC answers as is word 5.
    Finished f = poll("4", 0, 6);
    EXPECT_EQ(f.code, 0) << f.out.toStdString() << f.err.toStdString();
    EXPECT_EQ(mbpollValues(f.out),
              (std::map<int, int>{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 7}}))
        << f.out.toStdString();
    // Function 04 reads the same words (3.1).
    f = poll("3", 0, 6);
    EXPECT_EQ(f.code, 0) << f.out.toStdString() << f.err.toStdString();
    EXPECT_EQ(mbpollValues(f.out)[5], 7);
    // The other listed words with no device of the simulated PLC read 0: the positioners
    // (90, 95), the analog blocks past AI4 / AQ2, the PID percentages; bits 1440.., 1520..
    for (const auto &[type, reference, count] :
         {std::tuple{"4", 90, 1}, std::tuple{"4", 95, 1}, std::tuple{"4", 19000, 30},
          std::tuple{"4", 19030, 30}, std::tuple{"4", 19060, 6}, std::tuple{"4", 19400, 30},
          std::tuple{"4", 19430, 30}, std::tuple{"4", 19460, 4}, std::tuple{"4", 19800, 16},
          std::tuple{"0", 1440, 2}, std::tuple{"0", 1520, 2}}) {
        f = poll(type, reference, count);
        EXPECT_EQ(f.code, 0) << reference << ": " << f.out.toStdString() << f.err.toStdString();
        EXPECT_EQ(int(mbpollValues(f.out).size()), count) << reference;
    }
    // What the manual does not list is refused: word 6, 19066, 19816; bit 1442.
    for (const auto &[type, reference] :
         {std::pair{"4", 6}, std::pair{"4", 19066}, std::pair{"4", 19816}, std::pair{"0", 1442}}) {
        f = poll(type, reference, 1);
        EXPECT_NE(f.code, 0) << reference << ": " << f.out.toStdString();
        EXPECT_TRUE(f.out.contains(QLatin1String("Illegal data address")) ||
                    f.err.contains(QLatin1String("Illegal data address")))
            << reference << ": " << f.out.toStdString() << f.err.toStdString();
    }
    // Read only: word 2 is not written (exception 02).
    f = run(mbpoll(), mbpollRtu(7, "4", 2, serve.where) << QStringLiteral("5"));
    EXPECT_NE(f.code, 0) << f.out.toStdString();
    EXPECT_EQ(serve.stop(), 0);
}

TEST(CliServe, ALinkLeadsToThePlcAcrossRestartsAndGoesWhenServeEnds) {
    REQUIRE_MBPOLL();
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, QStringLiteral("plc.il"), kPeerPl110);
    const QString link = dir.filePath(QStringLiteral("plc"));
    // A link left by a serve that was killed (SIGKILL: no cleanup) is taken over.
    ASSERT_TRUE(QFile::link(QStringLiteral("/dev/pts/4000"), link));
    const QStringList args{QStringLiteral("--protocol"), QStringLiteral("modbus"),
                           QStringLiteral("--pty"), QStringLiteral("--link"), link};
    const QStringList v0 = mbpollRtu(1, "4", 2000, link);
    const QStringList v1 = mbpollRtu(1, "4", 2001, link);
    for (const int value : {321, 654}) { // a first run, then a restart
        Served serve(file, args);
        ASSERT_EQ(serve.where, link) << serve.process.readAllStandardError().toStdString();
        const QString pty = QFileInfo(link).symLinkTarget();
        EXPECT_TRUE(pty.startsWith(QLatin1String("/dev/pts/"))) << pty.toStdString();
        EXPECT_NE(pty, QStringLiteral("/dev/pts/4000"));
        // A master given the link's path, as the user gives it in the Connection panel.
        const Finished w = run(mbpoll(), QStringList(v0) << QString::number(value));
        EXPECT_EQ(w.code, 0) << w.out.toStdString() << w.err.toStdString();
        EXPECT_TRUE(eventually([&] { return mbpollValues(run(mbpoll(), v1).out)[2001] == value; }));
        EXPECT_EQ(serve.stop(), 0);
        const QString err = QString::fromUtf8(serve.process.readAllStandardError());
        EXPECT_TRUE(err.contains(QStringLiteral("a link to ") + pty)) << err.toStdString();
        // Gone with the serve that made it: no link to a pseudo-terminal that no longer is.
        EXPECT_FALSE(QFileInfo(link).isSymLink());
        EXPECT_FALSE(QFileInfo::exists(link));
    }
}

// What `serve --protocol modbus-tcp --tcp 127.0.0.1:0` of a program says until SIGINT ends it.
struct TcpServe {
    QString where; // its first line: the address it listens on
    QString err;
    int exitCode = -1;
};

TcpServe serveOverTcpUntilSigint(const QByteArray &program) {
    TcpServe r;
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("plc.il"));
    QFile f(file);
    if (!f.open(QIODevice::WriteOnly))
        return r;
    f.write(program);
    f.close();
    QProcess serve;
    serve.start(QStringLiteral(RUNG_CLI_PATH),
                {QStringLiteral("serve"), file, QStringLiteral("--protocol"),
                 QStringLiteral("modbus-tcp"), QStringLiteral("--tcp"),
                 QStringLiteral("127.0.0.1:0")});
    if (!serve.waitForStarted(5000))
        return r;
    const QDeadlineTimer deadline(15000);
    while (!serve.canReadLine() && !deadline.hasExpired() && serve.state() == QProcess::Running)
        serve.waitForReadyRead(100);
    r.where = QString::fromUtf8(serve.readLine()).trimmed();
    ::kill(pid_t(serve.processId()), SIGINT);
    if (!serve.waitForFinished(5000)) {
        serve.kill();
        serve.waitForFinished(1000);
        return r;
    }
    r.err = QString::fromUtf8(serve.readAllStandardError());
    r.exitCode = serve.exitCode();
    return r;
}

TEST(CliServe, TcpPrintsTheAddressAndSigintStopsIt) {
    const TcpServe r = serveOverTcpUntilSigint(kPeerVigor);
    ASSERT_TRUE(r.where.startsWith(QLatin1String("127.0.0.1:"))) << r.where.toStdString();
    EXPECT_NE(r.where.section(u':', 1).toInt(), 0);
    EXPECT_EQ(r.exitCode, 0);
}

// A PL110 served over TCP calls its map a MODBUS slave, not an RTU one: the frames are TCP's.
TEST(CliServe, APl110OverTcpIsNotCalledAnRtuSlave) {
    const TcpServe r = serveOverTcpUntilSigint("; target: pl110\nLD I1\nOUT Q1\nEND\n");
    ASSERT_TRUE(r.where.startsWith(QLatin1String("127.0.0.1:"))) << r.where.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("PL110 MODBUS slave, modbus-tcp")))
        << r.err.toStdString();
    EXPECT_FALSE(r.err.contains(QStringLiteral("RTU"))) << r.err.toStdString();
}

} // namespace
} // namespace rung::test
