// A hostile line on the slave's side: long garbage never grows a responder past its
// decoder's bound, frames too long get the protocol's answer, and a stream that fails ends its
// worker and says why. Also the protocols' frames over raw TCP, as a serial device server
// carries them.

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "comms/slave/host_link_responder.h"
#include "comms/slave/modbus_responder.h"
#include "comms/slave/slave_server.h"
#include "comms/slave/vigor_responder.h"
#include "comms/transport/tcp_transport.h"
#include "tests/comms/slave_fixture.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <mutex>

namespace rung::comms::slave {
namespace {

using model::Family;
using model::ProtocolId;
using test::Image;

using rung::testing::target;

const model::ProtocolMap &mapOf(Family f, ProtocolId p) {
    return *model::findProtocolMap(target(f), p);
}

// A stream of every kind of noise: random bytes, the protocols' start bytes without ends,
// frames' ends without starts.
QByteArray noise(int size) {
    QByteArray out;
    quint32 x = 12345;
    while (out.size() < size) {
        x = x * 1103515245u + 12345u;
        switch ((x >> 16) % 5) {
        case 0:
            out += char(0x02);
            break;
        case 1:
            out += '@';
            break;
        case 2:
            out += QByteArray(40, '0');
            break;
        default:
            out += char((x >> 8) & 0xFF);
        }
    }
    return out;
}

void feedNoise(Responder &r, qsizetype bound) {
    const QByteArray bytes = noise(1 << 18);
    for (qsizetype at = 0; at < bytes.size(); at += 997) {
        r.feed(QByteArrayView(bytes).sliced(at, std::min<qsizetype>(997, bytes.size() - at)));
        r.silence();
        ASSERT_LE(r.buffered(), bound) << "after " << at << " bytes";
    }
}

TEST(SlaveFaults, QuarterOfAMegabyteOfNoiseNeverGrowsAResponderPastItsBound) {
    Image vigor(target(Family::Vigor));
    VigorResponder v(target(Family::Vigor), mapOf(Family::Vigor, ProtocolId::VigorLink), 0,
                     vigor.image);
    feedNoise(v, vigor::RequestDecoder::MaxBuffered);
    Image pl110(target(Family::Pl110));
    ModbusResponder m(target(Family::Pl110), mapOf(Family::Pl110, ProtocolId::Modbus), 1,
                      pl110.image, modbus::Framing::Rtu);
    feedNoise(m, modbus::RequestDecoder::MaxBuffered);
    Image cpm1(target(Family::Cpm1), OperatingMode::Monitor);
    HostLinkResponder h(target(Family::Cpm1), mapOf(Family::Cpm1, ProtocolId::HostLink), 0,
                        cpm1.image);
    feedNoise(h, hostlink::CommandDecoder::MaxBuffered + 4 * hostlink::MaxWords);
    // And answers the next good request (after what the noise left, which a CR may end).
    const QByteArrayList out = h.feed("\r@00MS5E*\r");
    ASSERT_FALSE(out.isEmpty());
    EXPECT_TRUE(out.back().startsWith("@00MS00")) << out.back().toStdString();
}

TEST(SlaveFaults, HostLinkAPartOver131CharactersIsAFrameLengthError) {
    Image cpm1(target(Family::Cpm1), OperatingMode::Monitor);
    HostLinkResponder h(target(Family::Cpm1), mapOf(Family::Cpm1, ProtocolId::HostLink), 0,
                        cpm1.image);
    QByteArray text = "@00WD0000" + QByteArray(4 * 40, '1'); // 40 words in one part
    const QByteArrayList out = h.feed(text + hostlink::fcs(text) + "*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00WD18") + hostlink::fcs("@00WD18") + "*\r");
    EXPECT_EQ(cpm1.value("DM 0000"), 0); // nothing written
}

TEST(SlaveFaults, ModbusATruncatedRequestIsDroppedAtTheGapAndTheNextServed) {
    Image pl110(target(Family::Pl110));
    pl110.set("V3", 3);
    ModbusResponder m(target(Family::Pl110), mapOf(Family::Pl110, ProtocolId::Modbus), 1,
                      pl110.image, modbus::Framing::Rtu);
    const modbus::Request r{modbus::ReadHoldingRegisters, 2003, 1, {}, {}};
    const QByteArray frame = modbus::rtuFrame(1, modbus::encodeRequestPdu(r));
    EXPECT_TRUE(m.feed(frame.first(5)).isEmpty());
    EXPECT_TRUE(m.silence().isEmpty()); // 5 bytes of an 8-byte frame: dropped, unanswered
    EXPECT_GE(m.statistics().dropped, 1u);
    const QByteArrayList out = m.feed(frame);
    ASSERT_EQ(out.size(), 1);
    modbus::ReplyDecoder d(modbus::Framing::Rtu, 1, r);
    ASSERT_EQ(d.feed(out.front()), FrameStatus::Complete);
    EXPECT_EQ(d.response().registers, (std::vector<std::uint16_t>{3}));
}

TEST(SlaveFaults, VigorATruncatedRequestIsLeftForTheNextStx) {
    Image vigor(target(Family::Vigor));
    VigorResponder v(target(Family::Vigor), mapOf(Family::Vigor, ProtocolId::VigorLink), 0,
                     vigor.image);
    const vigor::Request r{0, vigor::Command::Read, 0x1C00, 2, {}};
    const QByteArray frame = vigor::encodeRequest(r);
    EXPECT_TRUE(v.feed(frame.first(6)).isEmpty());
    const QByteArrayList out = v.feed(frame);
    ASSERT_EQ(out.size(), 1);
    vigor::ReplyDecoder d(r);
    EXPECT_EQ(d.feed(out.front()), FrameStatus::Complete);
}

// ----- over raw TCP -----

using test::exchange;

TEST(SlaveFaults, HostLinkAndModbusRtuFramesOverRawTcp) {
    Image cpm1(target(Family::Cpm1), OperatingMode::Monitor);
    cpm1.set("DM 0007", 0x0707);
    SlaveServer h(target(Family::Cpm1), {ProtocolId::HostLink, {}, 0}, cpm1.image);
    QString error;
    ASSERT_TRUE(h.listen(QHostAddress::LocalHost, 0, &error)) << error.toStdString();
    TcpTransport hc(QStringLiteral("127.0.0.1"), h.port());
    ASSERT_TRUE(hc.open(&error));
    const hostlink::Frame read = hostlink::readCommand(0, model::ProtocolSpace::HostLinkDm, 7, 1);
    hostlink::ReplyDecoder hd(read);
    ASSERT_EQ(exchange(hc, hostlink::encode(read).front(), hd), FrameStatus::Complete);
    EXPECT_EQ(hd.reply().words, (std::vector<std::uint16_t>{0x0707}));

    Image pl110(target(Family::Pl110));
    SlaveServer m(target(Family::Pl110), {ProtocolId::Modbus, modbus::Framing::Rtu, 1},
                  pl110.image);
    ASSERT_TRUE(m.listen(QHostAddress::LocalHost, 0, &error));
    TcpTransport mc(QStringLiteral("127.0.0.1"), m.port());
    ASSERT_TRUE(mc.open(&error));
    const modbus::Request w{modbus::WriteSingleRegister, 2009, 1, {99}, {}};
    modbus::ReplyDecoder md(modbus::Framing::Rtu, 1, w);
    ASSERT_EQ(exchange(mc, modbus::rtuFrame(1, modbus::encodeRequestPdu(w)), md),
              FrameStatus::Complete);
    EXPECT_EQ(pl110.value("V9"), 99);
}

TEST(SlaveFaults, AStreamThatFailsEndsItsWorkerAndSaysWhy) {
    TcpServer peer; // the other end of the stream, which goes away
    QString error;
    ASSERT_TRUE(peer.listen(QHostAddress::LocalHost, 0, &error));
    Image plc(target(Family::Vigor));
    std::mutex mutex;
    std::condition_variable told;
    QString failure;
    SlaveOptions options{ProtocolId::VigorLink, {}, 0};
    options.onFailure = [&](const QString &why) {
        std::lock_guard lock(mutex);
        failure = why;
        told.notify_all();
    };
    SlaveServer server(target(Family::Vigor), options, plc.image);
    ASSERT_TRUE(server.start(
        std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), peer.port()), &error))
        << error.toStdString();
    auto accepted = peer.accept(QDeadlineTimer(2000));
    ASSERT_TRUE(accepted);
    accepted->close();
    std::unique_lock lock(mutex);
    ASSERT_TRUE(told.wait_for(lock, std::chrono::seconds(3), [&] { return !failure.isEmpty(); }));
    EXPECT_TRUE(failure.contains(QLatin1String("127.0.0.1"))) << failure.toStdString();
    EXPECT_EQ(server.lastProblem(), failure);
}

TEST(SlaveFaults, AStreamThatCannotOpenIsRefusedAtOnce) {
    quint16 port = 0;
    {
        TcpServer s;
        QString error;
        ASSERT_TRUE(s.listen(QHostAddress::LocalHost, 0, &error));
        port = s.port();
    }
    Image plc(target(Family::Vigor));
    SlaveServer server(target(Family::Vigor), {ProtocolId::VigorLink, {}, 0}, plc.image);
    QString error;
    EXPECT_FALSE(
        server.start(std::make_unique<TcpTransport>(QStringLiteral("127.0.0.1"), port), &error));
    EXPECT_TRUE(error.contains(QString::number(port))) << error.toStdString();
}

} // namespace
} // namespace rung::comms::slave
