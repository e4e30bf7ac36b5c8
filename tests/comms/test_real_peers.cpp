// Our master against real Modbus slaves from Debian: a program on libmodbus
// (peers/modbus_peer.cpp) and a script on python3-pymodbus (peers/pymodbus_peer.py), over a
// real pseudo-terminal (RTU) and TCP loopback (Modbus TCP). Both hold the values of
// peers/peer_values.h, so every read is checked against a number computed here.

#include "comms/driver/driver.h"
#include "comms/driver/online_session.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/tcp_transport.h"
#include "model/target/address.h"
#include "model/target/target.h"
#include "tests/comms/peers/peer_values.h"
#include "tests/eventually.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QTcpServer>
#include <QTemporaryFile>
#include <QThread>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rung::comms::test {
namespace {

namespace peer = rung::comms::test::peer;
using model::Family;
using waits::eventually;

enum class Peer { LibModbus, PyModbus };
enum class Wire { RtuPty, Tcp };

// A peer process that serves until the object goes. Started with posix_spawn, not QProcess:
// once a QProcess has started a child, ThreadSanitizer no longer sees the main thread's mutex
// locks (Qt 6.4 spawns through forkfd, which TSan does not know) and reports races that are
// not there; a probe of /bin/true through QProcess before an OnlineSession was enough.
// Its output goes to a file, so a talkative peer never blocks on a full pipe.
struct PeerProcess {
    pid_t pid = -1;
    QTemporaryFile output;
    QString failure;

    bool start(const QStringList &command, const QStringList &args) {
        if (!output.open()) {
            failure = QStringLiteral("no temporary file for the peer's output");
            return false;
        }
        pid = spawn(command + args, output.fileName());
        if (pid < 0) {
            failure = QStringLiteral("cannot start %1").arg(command.front());
            return false;
        }
        QElapsedTimer clock;
        clock.start();
        for (;;) {
            output.seek(0);
            const QByteArray out = output.readAll();
            if (out.contains("ready"))
                return true;
            int status = 0;
            const bool exited = ::waitpid(pid, &status, WNOHANG) == pid;
            if (exited)
                pid = -1; // reaped: nothing left for stop()
            if (exited || clock.elapsed() > 15000) {
                failure =
                    QStringLiteral("the peer did not start: %1").arg(QString::fromLocal8Bit(out));
                return false;
            }
            QThread::msleep(20);
        }
    }
    void stop() {
        if (pid > 0) {
            ::kill(pid, SIGKILL);
            int status = 0;
            ::waitpid(pid, &status, 0);
            pid = -1;
        }
    }
    ~PeerProcess() { stop(); }

    // argv[0] is a path; stdout and stderr go to outputPath. -1 when it cannot start.
    static pid_t spawn(const QStringList &argv, const QString &outputPath) {
        std::vector<QByteArray> bytes;
        for (const QString &a : argv)
            bytes.push_back(a.toLocal8Bit());
        std::vector<char *> raw;
        for (QByteArray &b : bytes)
            raw.push_back(b.data());
        raw.push_back(nullptr);
        const QByteArray out = outputPath.toLocal8Bit();
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 1, out.constData(), O_WRONLY | O_APPEND, 0);
        posix_spawn_file_actions_adddup2(&actions, 1, 2);
        pid_t child = -1;
        const int rc = ::posix_spawn(&child, raw.front(), &actions, nullptr, raw.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        return rc == 0 ? child : -1;
    }
};

// The peer's program and why it is missing, if it is.
QStringList program(Peer p, QString *missing) {
    if (p == Peer::LibModbus) {
#ifdef RUNG_MODBUS_PEER
        return {QStringLiteral(RUNG_MODBUS_PEER)};
#else
        *missing = QStringLiteral("libmodbus-dev is not installed (scripts/install-deps.sh)");
        return {};
#endif
    }
    static const bool have = [] {
        const pid_t check =
            PeerProcess::spawn({QStringLiteral("/usr/bin/python3"), QStringLiteral("-c"),
                                QStringLiteral("import pymodbus, serial_asyncio")},
                               QStringLiteral("/dev/null"));
        int status = 0;
        return check > 0 && ::waitpid(check, &status, 0) == check && WIFEXITED(status) &&
               WEXITSTATUS(status) == 0;
    }();
    if (!have) {
        *missing = QStringLiteral("python3-pymodbus or python3-serial-asyncio is not installed "
                                  "(scripts/install-deps.sh)");
        return {};
    }
    return {QStringLiteral("/usr/bin/python3"), QStringLiteral(RUNG_PYMODBUS_PEER)};
}

quint16 freePort() {
    QTcpServer probe;
    probe.listen(QHostAddress::LocalHost, 0);
    return probe.serverPort();
}

class RealPeers : public ::testing::TestWithParam<std::tuple<Peer, Wire>> {
protected:
    void SetUp() override {
        const auto [who, wire] = GetParam();
        QString missing;
        const QStringList command = program(who, &missing);
        if (command.isEmpty())
            GTEST_SKIP() << missing.toStdString();
        std::unique_ptr<Transport> transport;
        QStringList args;
        if (wire == Wire::RtuPty) {
            QString error;
            auto pair = PtyTransport::createPair(&error);
            ASSERT_TRUE(pair) << error.toStdString();
            args = {QStringLiteral("rtu"), pair->peerPath(), QStringLiteral("1")};
            transport = std::move(pair);
        } else {
            const quint16 port = freePort();
            args = {QStringLiteral("tcp"), QString::number(port), QStringLiteral("1")};
            transport = std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), port);
        }
        ASSERT_TRUE(m_peer.start(command, args)) << m_peer.failure.toStdString();
        m_transport = std::move(transport);
    }

    std::unique_ptr<Driver> driver(Family family) {
        QString error;
        auto d = Driver::create(model::Target::get(family),
                                std::get<1>(GetParam()) == Wire::Tcp ? ProtocolKind::ModbusTcp
                                                                     : ProtocolKind::ModbusRtu,
                                std::move(m_transport), 1, {1000, 2, 20}, &error);
        EXPECT_TRUE(d) << error.toStdString();
        if (d) {
            EXPECT_TRUE(d->link().open(&error)) << error.toStdString();
        }
        return d;
    }
    static model::Address device(const Driver &d, const QString &name) {
        return std::get<model::Address>(d.parseDevice(name));
    }

    PeerProcess m_peer;
    std::unique_ptr<Transport> m_transport;
};

TEST_P(RealPeers, ReadsScatteredPl110DevicesWithinThe30WordLimitAndWritesThem) {
    auto d = driver(Family::Pl110);
    ASSERT_TRUE(d);
    // 60 scattered V words, 40 Q bits, presets, the RUN bit: every value is the peer's formula.
    std::vector<model::Address> devices;
    std::vector<qint64> expected;
    for (int v = 0; v < 350; v += 6) {
        devices.push_back(device(*d, QStringLiteral("V%1").arg(v)));
        expected.push_back(std::int16_t(peer::reg(2000 + v)));
    }
    for (int q = 1; q <= 200; q += 5) {
        devices.push_back(device(*d, QStringLiteral("Q%1").arg(q)));
        expected.push_back(peer::coil(2400 + q - 1));
    }
    devices.push_back(device(*d, QStringLiteral("PT3")));
    expected.push_back(std::int16_t(peer::reg(13002)));
    devices.push_back(device(*d, QStringLiteral("SM0.0")));
    expected.push_back(peer::coil(16000));
    const auto plan = d->plan(devices);
    for (const PlannedRead &r : plan.reads) {
        if (r.span.space == model::ProtocolSpace::HoldingRegisters) {
            EXPECT_LE(r.span.count, 30);
        }
    }
    std::vector<qint64> values;
    DriverError e = d->read(devices, &values);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, expected);

    // Writes, each acknowledged, then read back.
    using Kind = model::DeviceCommand::Kind;
    e = d->execute({Kind::WriteWord, device(*d, QStringLiteral("V10")), -7});
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    e = d->execute({Kind::WriteBit, device(*d, QStringLiteral("Q2")), 1});
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    e = d->execute({Kind::WriteBit, device(*d, QStringLiteral("V3.5")), 1});
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    e = d->execute({Kind::WriteSetValue, device(*d, QStringLiteral("T1")), 250});
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    ASSERT_TRUE(d->setMode(PlcMode::Stop).ok());
    e = d->read({device(*d, QStringLiteral("V10")), device(*d, QStringLiteral("Q2")),
                 device(*d, QStringLiteral("V3.5")), device(*d, QStringLiteral("PT1"))},
                &values);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{-7, 1, 1, 250}));
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(d->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Stop);
    // The model and firmware words.
    PlcIdentity id;
    ASSERT_TRUE(d->identify(&id).ok());
    EXPECT_EQ(id.model, QStringLiteral("device type %1").arg(peer::reg(0)));
}

TEST_P(RealPeers, AnAddressThePeerLacksIsRefusedByNameAndTheRestIsRead) {
    auto d = driver(Family::Pl110);
    ASSERT_TRUE(d);
    // MMC12999 is register 42999: past the peer's 40000 registers, exception 02.
    const auto plan =
        d->plan({device(*d, QStringLiteral("MMC12999")), device(*d, QStringLiteral("V1"))});
    std::vector<std::int32_t> words(std::size_t(d->layout()->wordCount()), 0);
    std::vector<std::pair<model::Address, QString>> refused;
    const DriverError e = d->refresh(plan, words, &refused);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_TRUE(refused[0].second.contains(QLatin1String("MMC12999")))
        << refused[0].second.toStdString();
    EXPECT_TRUE(refused[0].second.contains(QLatin1String("illegal data address")))
        << refused[0].second.toStdString();
    EXPECT_EQ(words[std::size_t(d->layout()->word(device(*d, QStringLiteral("V1"))))],
              std::int16_t(peer::reg(2001)));
}

TEST_P(RealPeers, TheVigorCp2MapReadsInputsOutputsAndRegisters) {
    auto d = driver(Family::Vigor);
    ASSERT_TRUE(d);
    std::vector<qint64> values;
    const DriverError e =
        d->read({device(*d, QStringLiteral("X0")), device(*d, QStringLiteral("X7")),
                 device(*d, QStringLiteral("X12")), device(*d, QStringLiteral("Y3")),
                 device(*d, QStringLiteral("M100")), device(*d, QStringLiteral("D0")),
                 device(*d, QStringLiteral("D107")), device(*d, QStringLiteral("C200"))},
                &values);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    const qint64 c200 = std::int32_t(peer::reg(8648) | std::uint32_t(peer::reg(8649)) << 16);
    EXPECT_EQ(values,
              (std::vector<qint64>{peer::input(0), peer::input(7), peer::input(10), peer::coil(3),
                                   peer::coil(612), std::int16_t(peer::reg(0)),
                                   std::int16_t(peer::reg(107)), c200}));
}

INSTANTIATE_TEST_SUITE_P(
    Debian, RealPeers,
    ::testing::Combine(::testing::Values(Peer::LibModbus, Peer::PyModbus),
                       ::testing::Values(Wire::RtuPty, Wire::Tcp)),
    [](const ::testing::TestParamInfo<std::tuple<Peer, Wire>> &info) {
        return std::string(std::get<0>(info.param) == Peer::LibModbus ? "LibModbus" : "PyModbus") +
               (std::get<1>(info.param) == Wire::RtuPty ? "RtuOverPty" : "Tcp");
    });

TEST(RealPeerSession, AnOnlineSessionLosesALibmodbusSlaveThatDiesAndFindsItsSuccessor) {
    QString missing;
    const QStringList command = program(Peer::LibModbus, &missing);
    if (command.isEmpty())
        GTEST_SKIP() << missing.toStdString();
    QString error;
    std::unique_ptr<PtyTransport> pair = PtyTransport::createPair(&error);
    ASSERT_TRUE(pair) << error.toStdString();
    const QString path = pair->peerPath();
    auto first = std::make_unique<PeerProcess>();
    ASSERT_TRUE(first->start(command, {QStringLiteral("rtu"), path, QStringLiteral("1")}))
        << first->failure.toStdString();
    const model::Target &target = model::Target::get(Family::Pl110);
    ConnectionSettings settings = defaultSettings(ProtocolKind::ModbusRtu);
    settings.via = ConnectionSettings::Via::Pty;
    settings.port = path;
    settings.link = {100, 1, 10};
    settings.reconnectMinMs = 20;
    settings.reconnectMaxMs = 100;
    OnlineSession session(target, settings, nullptr,
                          [&pair]() -> std::unique_ptr<Transport> { return std::move(pair); });
    QObject reader;
    const model::Address v5 = std::get<model::Address>(model::parseAddress(target, u"V5"));
    session.setWatched(&reader, {v5});
    session.connectToPlc();
    ASSERT_TRUE(eventually([&] {
        const auto s = session.snapshot();
        return s && s->value(v5) == std::int16_t(peer::reg(2005)) &&
               session.connectionState() == OnlineSession::ConnectionState::Online;
    })) << session.errorText().toStdString();
    first->stop(); // the PLC is switched off
    ASSERT_TRUE(eventually(
        [&] { return session.connectionState() == OnlineSession::ConnectionState::Lost; }));
    EXPECT_TRUE(session.snapshot()->stale);
    EXPECT_EQ(session.snapshot()->value(v5), std::int16_t(peer::reg(2005)));
    EXPECT_EQ(session.runState(), model::MonitorSource::RunState::Offline);
    PeerProcess second; // and on again
    ASSERT_TRUE(second.start(command, {QStringLiteral("rtu"), path, QStringLiteral("1")}))
        << second.failure.toStdString();
    EXPECT_TRUE(eventually([&] {
        return session.connectionState() == OnlineSession::ConnectionState::Online &&
               !session.snapshot()->stale;
    })) << session.errorText().toStdString();
}

} // namespace
} // namespace rung::comms::test
