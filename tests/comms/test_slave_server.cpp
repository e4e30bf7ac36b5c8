// SlaveServer over real pseudo-terminals and TCP loopback, with our own master-side codecs:
// each protocol answers across the wire, several TCP clients at once, the fault modes look to a
// master as they should, and a hostile line neither hangs the slave nor grows its memory.

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/slave/slave_server.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/tcp_transport.h"
#include "tests/comms/hex.h"
#include "tests/comms/slave_fixture.h"
#include "tests/eventually.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

#include <functional>
#include <thread>

namespace rung::comms::slave {
namespace {

using waits::eventually;

using model::Family;
using model::ProtocolId;
using test::bytes;
using test::Image;

using rung::testing::target;

// A slave on a new pseudo-terminal and a master's end of it.
struct PtyLink {
    std::unique_ptr<SlaveServer> server;
    std::unique_ptr<PtyTransport> master;

    PtyLink(const model::Target &t, SlaveOptions options, std::shared_ptr<DeviceImage> image) {
        QString error;
        auto pty = PtyTransport::createPair(&error);
        EXPECT_TRUE(pty) << error.toStdString();
        if (!pty)
            return;
        const QString path = pty->peerPath();
        server = std::make_unique<SlaveServer>(t, std::move(options), std::move(image));
        EXPECT_TRUE(server->start(std::move(pty), &error)) << error.toStdString();
        master = std::make_unique<PtyTransport>(path);
        EXPECT_TRUE(master->open(&error)) << error.toStdString();
    }
};

using test::exchange;

TEST(SlaveServer, VigorLinkVectorAcrossAPseudoTerminal) {
    Image plc(target(Family::Vigor));
    plc.set("D1", 0x1234);
    plc.set("D2", 0xABCD);
    PtyLink link(target(Family::Vigor), {ProtocolId::VigorLink, {}, 0}, plc.image);
    ASSERT_TRUE(link.master);
    QString error;
    ASSERT_TRUE(link.master->write(bytes("02 30 30 35 31 31 43 30 32 30 34 03 30 33"),
                                   QDeadlineTimer(1000), &error));
    const QByteArray expected = bytes("06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44");
    QByteArray got;
    const QDeadlineTimer deadline(2000);
    while (got.size() < expected.size()) {
        const ReadResult r = link.master->read(deadline);
        if (r.status != ReadResult::Status::Data)
            break;
        got += r.bytes;
    }
    EXPECT_EQ(got, expected);
}

TEST(SlaveServer, ModbusRtuAcrossAPseudoTerminalReadsWhatItWrote) {
    Image plc(target(Family::Pl110));
    PtyLink link(target(Family::Pl110), {ProtocolId::Modbus, modbus::Framing::Rtu, 1}, plc.image);
    ASSERT_TRUE(link.master);
    const modbus::Request write{modbus::WriteMultipleRegisters, 2010, 3, {1, 2, 3}, {}};
    modbus::ReplyDecoder w(modbus::Framing::Rtu, 1, write);
    EXPECT_EQ(exchange(*link.master, modbus::rtuFrame(1, modbus::encodeRequestPdu(write)), w),
              FrameStatus::Complete)
        << w.error().message.toStdString();
    const modbus::Request read{modbus::ReadHoldingRegisters, 2010, 3, {}, {}};
    modbus::ReplyDecoder r(modbus::Framing::Rtu, 1, read);
    EXPECT_EQ(exchange(*link.master, modbus::rtuFrame(1, modbus::encodeRequestPdu(read)), r),
              FrameStatus::Complete);
    EXPECT_EQ(r.response().registers, (std::vector<std::uint16_t>{1, 2, 3}));
    EXPECT_EQ(plc.value("V12"), 3);
}

TEST(SlaveServer, HostLinkAcrossAPseudoTerminalWithAnAnswerInParts) {
    Image plc(target(Family::Cpm1), OperatingMode::Monitor);
    plc.set("DM 0150", 0x4321);
    PtyLink link(target(Family::Cpm1), {ProtocolId::HostLink, {}, 0}, plc.image);
    ASSERT_TRUE(link.master);
    const hostlink::Frame command =
        hostlink::readCommand(0, model::ProtocolSpace::HostLinkDm, 100, 60);
    hostlink::ReplyDecoder d(command);
    QString error;
    ASSERT_TRUE(
        link.master->write(hostlink::encode(command).front(), QDeadlineTimer(1000), &error));
    const QDeadlineTimer deadline(2000);
    while (d.status() == FrameStatus::NeedMore) {
        const ReadResult r = link.master->read(deadline);
        ASSERT_EQ(r.status, ReadResult::Status::Data);
        d.feed(r.bytes);
        if (d.takeDelimiterRequest()) {
            ASSERT_TRUE(link.master->write("\r", QDeadlineTimer(1000), &error));
        }
    }
    ASSERT_EQ(d.status(), FrameStatus::Complete) << d.error().message.toStdString();
    ASSERT_EQ(d.reply().words.size(), 60u);
    EXPECT_EQ(d.reply().words[50], 0x4321);
}

TEST(SlaveServer, ModbusTcpServesSeveralClientsAtOnce) {
    Image plc(target(Family::Vigor));
    SlaveServer server(target(Family::Vigor), {ProtocolId::Modbus, modbus::Framing::Tcp, 1},
                       plc.image);
    QString error;
    ASSERT_TRUE(server.listen(QHostAddress::LocalHost, 0, &error)) << error.toStdString();
    ASSERT_NE(server.port(), 0);
    constexpr int kClients = 4;
    std::vector<int> ok(kClients, 0);
    std::vector<std::thread> threads;
    for (int c = 0; c < kClients; ++c)
        threads.emplace_back([&, c] {
            TcpTransport client(QStringLiteral("127.0.0.1"), server.port());
            QString e;
            if (!client.open(&e))
                return;
            for (int i = 0; i < 20; ++i) {
                const int transaction = c * 100 + i;
                const modbus::Request w{
                    modbus::WriteSingleRegister, 100 + c, 1, {std::uint16_t(i)}, {}};
                modbus::ReplyDecoder wd(modbus::Framing::Tcp, 1, w, transaction);
                if (exchange(client, modbus::tcpFrame(transaction, 1, modbus::encodeRequestPdu(w)),
                             wd) != FrameStatus::Complete)
                    return;
                const modbus::Request r{modbus::ReadHoldingRegisters, 100 + c, 1, {}, {}};
                modbus::ReplyDecoder rd(modbus::Framing::Tcp, 1, r, transaction + 50);
                if (exchange(client,
                             modbus::tcpFrame(transaction + 50, 1, modbus::encodeRequestPdu(r)),
                             rd) != FrameStatus::Complete ||
                    rd.response().registers != std::vector<std::uint16_t>{std::uint16_t(i)})
                    return;
            }
            ok[std::size_t(c)] = 1;
        });
    for (auto &t : threads)
        t.join();
    for (int c = 0; c < kClients; ++c) {
        EXPECT_EQ(ok[std::size_t(c)], 1) << "client " << c;
        EXPECT_EQ(plc.value(qPrintable(QStringLiteral("D%1").arg(100 + c))), 19);
    }
    EXPECT_EQ(server.statistics().writes, quint64(kClients * 20));
}

TEST(SlaveServer, StopEndsEveryWaitPromptly) {
    Image plc(target(Family::Vigor));
    SlaveServer server(target(Family::Vigor), {ProtocolId::Modbus, modbus::Framing::Tcp, 1},
                       plc.image);
    QString error;
    ASSERT_TRUE(server.listen(QHostAddress::LocalHost, 0, &error));
    TcpTransport client(QStringLiteral("127.0.0.1"), server.port());
    ASSERT_TRUE(client.open(&error));
    const QDeadlineTimer wait(2000);
    while (server.clients() == 0 && !wait.hasExpired())
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_EQ(server.clients(), 1);
    QElapsedTimer clock;
    clock.start();
    server.stop();
    EXPECT_LT(clock.elapsed(), 1000);
    // The client sees the connection end.
    EXPECT_EQ(client.read(QDeadlineTimer(2000)).status, ReadResult::Status::Failed);
}

TEST(SlaveServer, ADisconnectedClientIsLetGoAndOneOverTheLimitRefused) {
    Image plc(target(Family::Vigor));
    SlaveOptions options{ProtocolId::Modbus, modbus::Framing::Tcp, 1};
    options.maxClients = 1;
    SlaveServer server(target(Family::Vigor), options, plc.image);
    QString error;
    ASSERT_TRUE(server.listen(QHostAddress::LocalHost, 0, &error));
    const modbus::Request r{modbus::ReadHoldingRegisters, 0, 1, {}, {}};
    for (int round = 0; round < 3; ++round) {
        TcpTransport client(QStringLiteral("127.0.0.1"), server.port());
        ASSERT_TRUE(client.open(&error));
        modbus::ReplyDecoder d(modbus::Framing::Tcp, 1, r, round);
        EXPECT_EQ(exchange(client, modbus::tcpFrame(round, 1, modbus::encodeRequestPdu(r)), d),
                  FrameStatus::Complete)
            << "round " << round;
        // A second client while the first is served: over the limit, its connection ends.
        TcpTransport second(QStringLiteral("127.0.0.1"), server.port());
        ASSERT_TRUE(second.open(&error));
        EXPECT_EQ(second.read(QDeadlineTimer(2000)).status, ReadResult::Status::Failed);
        EXPECT_TRUE(server.lastProblem().contains(QLatin1String("refused")));
        client.close();
        EXPECT_TRUE(eventually([&] { return server.clients() == 0; })) << "round " << round;
    }
}

TEST(SlaveServer, AMissingMapOrABusyPortIsSaidAtOnce) {
    Image plc(target(Family::Vpc));
    SlaveServer vpc(target(Family::Vpc), {ProtocolId::Modbus, modbus::Framing::Tcp, 1}, plc.image);
    QString error;
    EXPECT_FALSE(vpc.listen(QHostAddress::LocalHost, 0, &error));
    EXPECT_TRUE(error.contains(QLatin1String("VPC"))) << error.toStdString();
    Image vigor(target(Family::Vigor));
    SlaveServer a(target(Family::Vigor), {ProtocolId::Modbus, modbus::Framing::Tcp, 1},
                  vigor.image);
    ASSERT_TRUE(a.listen(QHostAddress::LocalHost, 0, &error));
    SlaveServer b(target(Family::Vigor), {ProtocolId::Modbus, modbus::Framing::Tcp, 1},
                  vigor.image);
    EXPECT_FALSE(b.listen(QHostAddress::LocalHost, a.port(), &error));
    EXPECT_TRUE(error.contains(QString::number(a.port()))) << error.toStdString();
}

// ----- faults: what a master meets -----

// A fault whose answer never completes is given 300 ms; the others as long as a slow machine
// needs (split sends a byte every 3 ms).
ProtocolError::Kind vigorReadWith(Fault fault) {
    const int ms = fault == Fault::Silent || fault == Fault::Truncated ? 300 : 3000;
    Image plc(target(Family::Vigor));
    SlaveOptions options{ProtocolId::VigorLink, {}, 0};
    options.fault = fault;
    PtyLink link(target(Family::Vigor), options, plc.image);
    if (!link.master)
        return ProtocolError::Kind::None;
    const vigor::Request request{0, vigor::Command::Read, 0x1C02, 4, {}};
    vigor::ReplyDecoder d(request);
    if (exchange(*link.master, vigor::encodeRequest(request), d, ms) == FrameStatus::NeedMore)
        return d.deadlinePassed(ms).kind;
    return d.status() == FrameStatus::Complete ? ProtocolError::Kind::None : d.error().kind;
}

TEST(SlaveServer, FaultModesLookToAMasterAsTheirNamesSay) {
    using K = ProtocolError::Kind;
    EXPECT_EQ(vigorReadWith(Fault::None), K::None);
    EXPECT_EQ(vigorReadWith(Fault::BadChecksum), K::BadChecksum);
    EXPECT_EQ(vigorReadWith(Fault::Silent), K::Truncated);
    EXPECT_EQ(vigorReadWith(Fault::WrongStation), K::WrongStation);
    EXPECT_EQ(vigorReadWith(Fault::Garbage), K::Garbage);
    EXPECT_EQ(vigorReadWith(Fault::Truncated), K::Truncated);
    EXPECT_EQ(vigorReadWith(Fault::Split), K::None);
}

TEST(SlaveServer, ModbusFaultModes) {
    using K = ProtocolError::Kind;
    for (const auto &[fault, kind] :
         {std::pair{Fault::BadChecksum, K::BadChecksum},
          std::pair{Fault::WrongStation, K::WrongStation}, std::pair{Fault::Garbage, K::Garbage}}) {
        Image plc(target(Family::Pl110));
        SlaveOptions options{ProtocolId::Modbus, modbus::Framing::Rtu, 1};
        options.fault = fault;
        PtyLink link(target(Family::Pl110), options, plc.image);
        ASSERT_TRUE(link.master);
        const modbus::Request r{modbus::ReadHoldingRegisters, 2000, 2, {}, {}};
        modbus::ReplyDecoder d(modbus::Framing::Rtu, 1, r);
        exchange(*link.master, modbus::rtuFrame(1, modbus::encodeRequestPdu(r)), d, 3000);
        EXPECT_EQ(d.error().kind, kind) << faultNames().at(int(fault)).toStdString();
    }
}

TEST(SlaveServer, FaultNamesRoundTrip) {
    for (const QString &name : faultNames())
        EXPECT_TRUE(faultFromName(name).has_value()) << name.toStdString();
    EXPECT_FALSE(faultFromName(u"sometimes").has_value());
}

// ----- a hostile line -----

// The master's side of resynchronising: a request the slave may miss while it drops what came
// before is sent again (a few times, each with a short deadline), as a driver retries.
template <typename Decoder, typename Make>
FrameStatus askUntilAnswered(Transport &t, const QByteArray &request, Make make) {
    for (int attempt = 0; attempt < 5; ++attempt) {
        Decoder d = make();
        t.discardInput();
        if (exchange(t, request, d, 400) == FrameStatus::Complete)
            return FrameStatus::Complete;
    }
    return FrameStatus::Failed;
}

TEST(SlaveServer, GarbageTruncationAndOtherStationsNeverHangTheSlave) {
    Image plc(target(Family::Pl110));
    plc.set("V0", 77);
    PtyLink link(target(Family::Pl110), {ProtocolId::Modbus, modbus::Framing::Rtu, 1}, plc.image);
    ASSERT_TRUE(link.master);
    QString error;
    const modbus::Request r{modbus::ReadHoldingRegisters, 2000, 1, {}, {}};
    const QByteArray good = modbus::rtuFrame(1, modbus::encodeRequestPdu(r));
    const auto decoder = [&r] { return modbus::ReplyDecoder(modbus::Framing::Rtu, 1, r); };
    // A megabyte of noise: none of it is answered, and the slave takes requests again.
    QByteArray noise;
    for (int i = 0; i < 1 << 20; ++i)
        noise += char((i * 131 + 7) & 0xFF);
    ASSERT_TRUE(link.master->write(noise, QDeadlineTimer(5000), &error)) << error.toStdString();
    ASSERT_EQ(askUntilAnswered<modbus::ReplyDecoder>(*link.master, good, decoder),
              FrameStatus::Complete);
    EXPECT_GE(link.server->statistics().dropped, 1u);
    // A truncated request (dropped at the gap) and one for unit 9 (not ours): no answer...
    const SlaveStatistics before = link.server->statistics();
    ASSERT_TRUE(link.master->write(good.first(5), QDeadlineTimer(1000), &error));
    EXPECT_TRUE(eventually([&] { return link.server->statistics().dropped > before.dropped; }));
    ASSERT_TRUE(link.master->write(modbus::rtuFrame(9, modbus::encodeRequestPdu(r)),
                                   QDeadlineTimer(1000), &error));
    EXPECT_TRUE(eventually([&] { return link.server->statistics().ignored > before.ignored; }));
    EXPECT_EQ(link.master->read(QDeadlineTimer(100)).status, ReadResult::Status::Timeout);
    EXPECT_EQ(link.server->statistics().answered, before.answered);
    // ... and the next good request is answered.
    modbus::ReplyDecoder d = decoder();
    ASSERT_EQ(exchange(*link.master, good, d), FrameStatus::Complete)
        << d.error().message.toStdString();
    EXPECT_EQ(d.response().registers, (std::vector<std::uint16_t>{77}));
}

TEST(SlaveServer, HostLinkAndVigorResynchroniseAfterGarbage) {
    Image cpm(target(Family::Cpm1), OperatingMode::Monitor);
    PtyLink h(target(Family::Cpm1), {ProtocolId::HostLink, {}, 0}, cpm.image);
    ASSERT_TRUE(h.master);
    QString error;
    ASSERT_TRUE(h.master->write(QByteArray(5000, 'x') + "@00RD00" + QByteArray(3000, '9'),
                                QDeadlineTimer(2000), &error));
    const hostlink::Frame ms = hostlink::statusCommand(0);
    hostlink::ReplyDecoder hd(ms);
    EXPECT_EQ(exchange(*h.master, "\r" + hostlink::encode(ms).front(), hd), FrameStatus::Complete)
        << hd.error().message.toStdString();

    Image vig(target(Family::Vigor));
    PtyLink v(target(Family::Vigor), {ProtocolId::VigorLink, {}, 0}, vig.image);
    ASSERT_TRUE(v.master);
    ASSERT_TRUE(v.master->write("\x02" + QByteArray(4000, '0'), QDeadlineTimer(2000), &error));
    const vigor::Request request{0, vigor::Command::Read, 0x0000, 1, {}};
    vigor::ReplyDecoder vd(request);
    EXPECT_EQ(exchange(*v.master, vigor::encodeRequest(request), vd), FrameStatus::Complete)
        << vd.error().message.toStdString();
}

} // namespace
} // namespace rung::comms::slave
