// The pass-through recorder (comms::Relay): two real pseudo-terminals joined, bytes passed on
// untouched both ways and recorded in order with their direction; a side that cannot be
// opened or that fails is named. The PLC's side is a fake only where a port must vanish.

#include "comms/driver/relay.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/serial_transport.h"
#include "tests/comms/fake_transport.h"
#include "tests/comms/hex.h"
#include "tests/comms/pty_pair.h"
#include "tests/eventually.h"

#include <gtest/gtest.h>

#include <QDeadlineTimer>
#include <QThread>

namespace rung::comms {
namespace {

using waits::eventually;

using R = ReadResult::Status;
using Direction = TrafficRecord::Direction;

using test::readAll;

// Each pseudo-terminal's master side is the relay's, its peer the test's.
// Every record of the tap, joined per direction in the order they came.
QByteArray recorded(const Relay &relay, Direction direction) {
    QByteArray out;
    for (const TrafficRecord &r : relay.tap().records(0))
        if (r.direction == direction)
            out += r.bytes;
    return out;
}

// The Vigor M/VB/VH communication manual's 70H example (B-5-3): M10 ON and the PLC's ACK.
const QByteArray kRequest = test::bytes("02 30 30 37 30 30 34 30 41 03 39 46");
const QByteArray kAck = test::bytes("06 30 30 37 30 30 30 03 32 41");

TEST(Relay, ARequestAndItsAnswerPassUntouchedAndAreRecordedWithTheirDirection) {
    test::PtyPair pc = test::makePtyPair();
    test::PtyPair plc = test::makePtyPair();
    ASSERT_TRUE(pc.peer && plc.peer);
    Relay relay(std::move(pc.master), std::move(plc.master));
    QString error;
    ASSERT_TRUE(relay.start(&error)) << error.toStdString();

    ASSERT_TRUE(pc.peer->write(kRequest, QDeadlineTimer(2000), &error));
    EXPECT_EQ(readAll(*plc.peer, kRequest.size(), 3000), kRequest);
    ASSERT_TRUE(plc.peer->write(kAck, QDeadlineTimer(2000), &error));
    EXPECT_EQ(readAll(*pc.peer, kAck.size(), 3000), kAck);

    ASSERT_TRUE(eventually([&] { return recorded(relay, Direction::Received) == kAck; }));
    EXPECT_EQ(recorded(relay, Direction::Sent), kRequest);
    // In the order they were said, with times that do not go back.
    const std::vector<TrafficRecord> records = relay.tap().records(0);
    ASSERT_GE(records.size(), 2u);
    EXPECT_EQ(records.front().direction, Direction::Sent);
    EXPECT_EQ(records.back().direction, Direction::Received);
    for (std::size_t i = 1; i < records.size(); ++i)
        EXPECT_GE(records[i].timeUs, records[i - 1].timeUs);
    EXPECT_TRUE(relay.running());
    EXPECT_TRUE(relay.failure().isEmpty());
    relay.stop();
    EXPECT_FALSE(relay.running());
}

TEST(Relay, EveryByteValuePassesBothWaysAtOnce) {
    test::PtyPair pc = test::makePtyPair();
    test::PtyPair plc = test::makePtyPair();
    ASSERT_TRUE(pc.peer && plc.peer);
    Relay relay(std::move(pc.master), std::move(plc.master));
    QString error;
    ASSERT_TRUE(relay.start(&error)) << error.toStdString();
    QByteArray all, reversed;
    for (int i = 0; i < 256; ++i) {
        all += char(i);
        reversed += char(255 - i);
    }
    // Both directions at the same time: neither waits for the other.
    ASSERT_TRUE(pc.peer->write(all, QDeadlineTimer(2000), &error));
    ASSERT_TRUE(plc.peer->write(reversed, QDeadlineTimer(2000), &error));
    EXPECT_EQ(readAll(*plc.peer, all.size()), all);
    EXPECT_EQ(readAll(*pc.peer, reversed.size()), reversed);
    ASSERT_TRUE(eventually([&] { return recorded(relay, Direction::Received).size() == 256; }));
    EXPECT_EQ(recorded(relay, Direction::Sent), all);
    EXPECT_EQ(recorded(relay, Direction::Received), reversed);
}

TEST(Relay, APortThatCannotBeOpenedIsNamedWithItsSide) {
    test::PtyPair pc = test::makePtyPair();
    ASSERT_TRUE(pc.peer);
    const QString missing = QStringLiteral("/dev/ttyRUNG-no-such-port");
    Relay relay(std::move(pc.master), std::make_unique<SerialTransport>(missing, SerialSettings{}));
    QString error;
    EXPECT_FALSE(relay.start(&error));
    EXPECT_TRUE(error.contains(QLatin1String("the PLC's side"))) << error.toStdString();
    EXPECT_TRUE(error.contains(missing)) << error.toStdString();
    EXPECT_FALSE(relay.running());
}

TEST(Relay, APlcSideThatVanishesStopsTheRelayAndSaysWhich) {
    test::PtyPair pc = test::makePtyPair();
    ASSERT_TRUE(pc.peer);
    auto fake = std::make_unique<test::FakeTransport>(QStringLiteral("ttyUSB7"));
    test::FakeTransport *plc = fake.get();
    plc->setResponder([](const QByteArray &) { return QList<QByteArray>{kAck}; });
    Relay relay(std::move(pc.master), std::move(fake));
    QString error;
    ASSERT_TRUE(relay.start(&error)) << error.toStdString();
    ASSERT_TRUE(pc.peer->write(kRequest, QDeadlineTimer(2000), &error));
    EXPECT_EQ(readAll(*pc.peer, kAck.size(), 3000), kAck);

    plc->unplug();
    ASSERT_TRUE(eventually([&] { return !relay.running(); }));
    EXPECT_TRUE(relay.failure().contains(QLatin1String("the PLC's side (ttyUSB7)")))
        << relay.failure().toStdString();
    // What was said before it went is kept.
    EXPECT_EQ(recorded(relay, Direction::Sent), kRequest);
    EXPECT_EQ(recorded(relay, Direction::Received), kAck);
}

TEST(Relay, ARecordReadsAsTimeDirectionHexAndText) {
    const QDateTime start(QDate(2026, 11, 26), QTime(12, 30, 1, 123));
    TrafficRecord r;
    r.timeUs = 2'000'456; // 2.000456 s after the start
    r.direction = Direction::Sent;
    r.bytes = test::bytes("05 30 31 46 0D");
    EXPECT_EQ(formatTrafficRecord(r, start, QStringLiteral("PC>PLC"), QStringLiteral("PLC>PC")),
              QStringLiteral("12:30:03.123456 PC>PLC 05 30 31 46 0D  |.01F.|"));
    r.direction = Direction::Received;
    r.bytes = kAck;
    EXPECT_EQ(formatTrafficRecord(r, start, QStringLiteral("TX"), QStringLiteral("RX")),
              QStringLiteral("12:30:03.123456 RX 06 30 30 37 30 30 30 03 32 41  |.007000.2A|"));
}

} // namespace
} // namespace rung::comms
