// Every fault a line or a PLC can produce, through the fake transport: a clear error that
// names the device, the PLC and the cause; bounded retries for noise and silence only; no
// hang; and no write reported done that the PLC did not acknowledge.

#include "comms/driver/connection.h"
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/comms/driver_fixture.h"
#include "tests/comms/hex.h"

#include <QElapsedTimer>

namespace rung::comms::test {
namespace {

using Kind = model::DeviceCommand::Kind;
using EK = DriverError::Kind;
using model::Family;

// One protocol's frames for "read D1 / DM 0001 / V1" and "write it = 5".
struct Proto {
    const char *name;
    Family family;
    ProtocolKind kind;
    const char *device;
    QByteArray readRequest, readReply, writeRequest, writeReply;
    QByteArray badChecksum;                           // the read reply with its check wrong
    QByteArray otherStation;                          // the read reply from another station
    std::vector<std::pair<int, QByteArray>> refusals; // code, a reply refusing the write
};

std::vector<Proto> protocols() {
    std::vector<Proto> out;
    {
        Proto p{
            "Vigor link", Family::Vigor, ProtocolKind::VigorLink, "D1", {}, {}, {}, {}, {}, {}, {}};
        const vigor::Request read{0, vigor::Command::Read, 0x1C02, 2, {}};
        const vigor::Request write{0, vigor::Command::Write, 0x1C02, 2, QByteArray("\x05\x00", 2)};
        p.readRequest = vigor::encodeRequest(read);
        p.readReply = vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray("\x34\x12", 2)});
        p.writeRequest = vigor::encodeRequest(write);
        p.writeReply = vigor::encodeReply({0, vigor::Command::Write, 0, {}});
        p.badChecksum = p.readReply;
        p.badChecksum[p.badChecksum.size() - 1] = p.badChecksum.back() == '0' ? '1' : '0';
        p.otherStation =
            vigor::encodeReply({3, vigor::Command::Read, 0, QByteArray("\x34\x12", 2)});
        for (int code : {0x10, 0x11, 0x12, 0x14, 0x28})
            p.refusals.emplace_back(code, vigor::encodeReply({0, vigor::Command::Write, code, {}}));
        out.push_back(p);
    }
    {
        Proto p{
            "Modbus RTU", Family::Pl110, ProtocolKind::ModbusRtu, "V1", {}, {}, {}, {}, {}, {}, {}};
        p.readRequest = modbus::rtuFrame(1, bytes("03 07 D1 00 01"));
        p.readReply = modbus::rtuFrame(1, bytes("03 02 12 34"));
        p.writeRequest = modbus::rtuFrame(1, bytes("06 07 D1 00 05"));
        p.writeReply = p.writeRequest;
        p.badChecksum = p.readReply;
        p.badChecksum[p.badChecksum.size() - 1] = char(p.badChecksum.back() ^ 0x55);
        p.otherStation = modbus::rtuFrame(2, bytes("03 02 12 34"));
        for (int code : {1, 2, 3, 4, 5, 6, 8, 10, 11})
            p.refusals.emplace_back(code, modbus::rtuFrame(1, QByteArray("\x86", 1) + char(code)));
        out.push_back(p);
    }
    {
        Proto p{
            "Host Link", Family::Cpm1, ProtocolKind::HostLink, "DM 0001", {}, {}, {}, {}, {}, {},
            {}};
        using hostlink::encode;
        p.readRequest =
            encode(hostlink::readCommand(0, model::ProtocolSpace::HostLinkDm, 1, 1)).value(0);
        p.readReply = encode({0, "RD", 0, "1234"}).value(0);
        p.writeRequest =
            encode(hostlink::writeCommand(0, model::ProtocolSpace::HostLinkDm, 1, {5})).value(0);
        p.writeReply = encode({0, "WD", 0, {}}).value(0);
        p.badChecksum = p.readReply;
        p.badChecksum[p.badChecksum.size() - 3] =
            p.badChecksum[p.badChecksum.size() - 3] == '0' ? '1' : '0';
        p.otherStation = encode({5, "RD", 0, "1234"}).value(0);
        for (int code : {0x01, 0x02, 0x03, 0x04, 0x0B, 0x13, 0x14, 0x15, 0x16, 0x18})
            p.refusals.emplace_back(code, encode({0, "WD", code, {}}).value(0));
        out.push_back(p);
    }
    return out;
}

class Faults : public ::testing::TestWithParam<int> {
protected:
    Proto proto() const { return protocols()[std::size_t(GetParam())]; }
    // Host Link checks the mode before the first write: MONITOR.
    void expectModeCheck(FakeDriver &f) const {
        if (proto().kind == ProtocolKind::HostLink)
            f.port->reply("@00MS5E*\r", hostlink::encode({0, "MS", 0, "0300"}).value(0));
    }
    static void expectNames(const DriverError &e, const char *device) {
        EXPECT_TRUE(e.message.contains(QLatin1String(device))) << e.message.toStdString();
        EXPECT_TRUE(e.message.contains(QLatin1String("/dev/ttyFAKE0"))) << e.message.toStdString();
    }
};

TEST_P(Faults, ABadCheckIsRetriedAndThenTheGoodReplyCounts) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    f.port->reply(p.readRequest, p.badChecksum);
    f.port->reply(p.readRequest, p.readReply);
    DriverError e;
    const auto values = f.read({p.device}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, std::vector<qint64>{0x1234});
    EXPECT_EQ(f.driver->link().statistics().retries, 1u);
    EXPECT_EQ(f.driver->link().statistics().replies, 1u);
}

TEST_P(Faults, NoiseOnEveryAttemptEndsAfterTheRetriesWithTheCause) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    for (int i = 0; i < 3; ++i)
        f.port->reply(p.readRequest, p.badChecksum);
    f.port->reply(p.readRequest, p.readReply); // never asked for: 3 attempts only
    DriverError e;
    f.read({p.device}, &e);
    EXPECT_EQ(e.kind, EK::Garbled);
    expectNames(e, p.device);
    EXPECT_TRUE(e.message.contains(QLatin1String("3 attempts"))) << e.message.toStdString();
    EXPECT_EQ(f.port->writes(), 3);
    EXPECT_EQ(f.driver->link().statistics().errors, 1u);
}

TEST_P(Faults, GarbageIsRetried) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    f.port->reply(p.readRequest, QByteArray("\xFF\xFE garbage", 10));
    f.port->reply(p.readRequest, p.readReply);
    DriverError e;
    EXPECT_EQ(f.read({p.device}, &e), std::vector<qint64>{0x1234});
    EXPECT_TRUE(e.ok()) << e.message.toStdString();
}

TEST_P(Faults, SilenceIsRetriedAFixedNumberOfTimesWithinItsDeadlines) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0, {30, 2, 5});
    QElapsedTimer clock;
    clock.start();
    DriverError e;
    f.read({p.device}, &e); // nothing scripted: the PLC is silent
    EXPECT_EQ(e.kind, EK::NoReply);
    EXPECT_TRUE(e.linkLost());
    expectNames(e, p.device);
    EXPECT_TRUE(e.message.contains(QLatin1String("no reply"))) << e.message.toStdString();
    EXPECT_EQ(f.port->writes(), 3);
    EXPECT_EQ(f.driver->link().statistics().timeouts, 3u);
    EXPECT_LT(clock.elapsed(), 2000);
}

TEST_P(Faults, ATruncatedReplyIsRetried) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0, {30, 1, 5});
    f.port->reply(p.readRequest, p.readReply.left(p.readReply.size() - 2));
    f.port->reply(p.readRequest, p.readReply);
    DriverError e;
    EXPECT_EQ(f.read({p.device}, &e), std::vector<qint64>{0x1234});
    EXPECT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(f.driver->link().statistics().timeouts, 1u);
}

TEST_P(Faults, AReplySplitIntoSingleBytesIsOneReply) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    QList<QByteArray> chunks;
    for (char c : p.readReply)
        chunks << QByteArray(1, c);
    f.port->reply(p.readRequest, chunks);
    DriverError e;
    EXPECT_EQ(f.read({p.device}, &e), std::vector<qint64>{0x1234});
    EXPECT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(f.port->writes(), 1);
}

TEST_P(Faults, AnAnswerFromAnotherStationIsReportedNotRetried) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    f.port->reply(p.readRequest, p.otherStation);
    DriverError e;
    f.read({p.device}, &e);
    EXPECT_EQ(e.kind, EK::WrongPeer);
    expectNames(e, p.device);
    EXPECT_EQ(f.port->writes(), 1);
}

TEST_P(Faults, EveryRefusalOfAWriteIsReportedWithItsCodeAndNeverRetried) {
    const Proto p = proto();
    for (const auto &[code, reply] : p.refusals) {
        FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
        expectModeCheck(f);
        f.port->reply(p.writeRequest, reply);
        f.port->reply(p.writeRequest, p.writeReply); // a retry would find this: none may come
        const DriverError e = f.execute(Kind::WriteWord, p.device, 5);
        EXPECT_EQ(e.kind, EK::Refused) << code;
        EXPECT_EQ(e.code, code);
        expectNames(e, p.device);
        EXPECT_TRUE(e.message.contains(QString::number(code, 16).toUpper().rightJustified(2, u'0')))
            << e.message.toStdString();
        EXPECT_FALSE(f.port->scriptDone()) << "a refused write was sent again, code " << code;
        EXPECT_EQ(f.driver->link().statistics().refusals, 1u);
    }
}

TEST_P(Faults, AWriteWithoutAcknowledgementIsNotDone) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0, {30, 1, 5});
    expectModeCheck(f);
    f.port->silence(p.writeRequest);
    f.port->silence(p.writeRequest);
    const DriverError e = f.execute(Kind::WriteWord, p.device, 5);
    EXPECT_EQ(e.kind, EK::NoReply);
    EXPECT_FALSE(e.ok());
    expectNames(e, p.device);
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST_P(Faults, ThePortVanishingMidRequestIsALostLinkNamingThePort) {
    const Proto p = proto();
    FakeDriver f(p.family, p.kind, p.kind == ProtocolKind::ModbusRtu ? 1 : 0);
    f.port->vanish({p.readReply.left(3)});
    DriverError e;
    f.read({p.device}, &e);
    EXPECT_EQ(e.kind, EK::LinkDown);
    EXPECT_TRUE(e.linkLost());
    expectNames(e, p.device);
    EXPECT_TRUE(e.message.contains(QLatin1String("unplugged"))) << e.message.toStdString();
    EXPECT_EQ(f.port->writes(), 1);
    // And a write on the vanished port is not done either.
    EXPECT_EQ(f.execute(Kind::WriteWord, p.device, 5).kind, EK::LinkDown);
}

INSTANTIATE_TEST_SUITE_P(Protocols, Faults, ::testing::Range(0, 3),
                         [](const ::testing::TestParamInfo<int> &info) {
                             return std::string(info.param == 0   ? "VigorLink"
                                                : info.param == 1 ? "ModbusRtu"
                                                                  : "HostLink");
                         });

TEST(DriverFaults, ADeviceThePlcRefusesIsNamedAndTheOthersAreStillRead) {
    // D100 and D101 in one frame; the PLC refuses it (say D101 is past a small model's end):
    // each is read alone, D100 answers, D101 is refused and named.
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    f.port->reply(vigor::encodeRequest({0, vigor::Command::Read, 0x1C00 + 200, 4, {}}),
                  vigor::encodeReply({0, vigor::Command::Read, 0x28, {}}));
    f.port->reply(vigor::encodeRequest({0, vigor::Command::Read, 0x1C00 + 200, 2, {}}),
                  vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray("\x07\x00", 2)}));
    f.port->reply(vigor::encodeRequest({0, vigor::Command::Read, 0x1C00 + 202, 2, {}}),
                  vigor::encodeReply({0, vigor::Command::Read, 0x28, {}}));
    const auto plan = f.driver->plan(f.devices({"D100", "D101"}));
    ASSERT_EQ(plan.reads.size(), 1u);
    std::vector<std::int32_t> words(std::size_t(f.driver->layout()->wordCount()), 0);
    std::vector<std::pair<model::Address, QString>> refused;
    const DriverError e = f.driver->refresh(plan, words, &refused);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    ASSERT_EQ(refused.size(), 1u);
    EXPECT_EQ(refused[0].first, f.device("D101"));
    EXPECT_TRUE(refused[0].second.contains(QLatin1String("reading D101 from Vigor station 0")))
        << refused[0].second.toStdString();
    EXPECT_TRUE(refused[0].second.contains(QLatin1String("address out of range")))
        << refused[0].second.toStdString();
    EXPECT_EQ(words[std::size_t(f.driver->layout()->word(f.device("D100")))], 7);
}

TEST(DriverFaults, AValueThatDoesNotFitIsRefusedBeforeAnythingIsSent) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    // Timer present values are 4 BCD digits: the word 00A0h is none (the PLC: end code 15).
    const DriverError e = f.execute(Kind::WriteWord, "TIM 000", 0x00A0);
    EXPECT_EQ(e.kind, EK::BadDevice);
    EXPECT_TRUE(e.message.contains(QLatin1String("#0000..#9999"))) << e.message.toStdString();
    EXPECT_TRUE(e.message.contains(QLatin1String("00A0h"))) << e.message.toStdString();
    EXPECT_EQ(f.execute(Kind::WriteWord, "TIM 000", 0x10000).kind, EK::BadDevice);
    FakeDriver v(Family::Vigor, ProtocolKind::VigorLink, 0);
    EXPECT_EQ(v.execute(Kind::WriteWord, "D0", 70000).kind, EK::BadDevice);
    EXPECT_EQ(f.port->writes() + v.port->writes(), 0);
}

TEST(DriverFaults, ASetValueInTheProgramCannotBeWrittenAndSaysWhy) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    const DriverError e = f.execute(Kind::WriteSetValue, "T0", 10);
    EXPECT_EQ(e.kind, EK::Unsupported);
    EXPECT_TRUE(e.message.contains(QLatin1String("constant of the program")))
        << e.message.toStdString();
    EXPECT_EQ(f.port->writes(), 0);
}

TEST(DriverFaults, ModbusRtuLeavesTheLineQuietBeforeEachRequest) {
    // 3.5 characters at 1200 bps 8N1 (8.3 ms a character): 29 ms between the end of a reply
    // and the next request, so a slave sees where the frame starts.
    ConnectionSettings s = defaultSettings(ProtocolKind::ModbusRtu);
    s.serial.baud = 1200;
    const LinkSettings timing = lineTiming(s);
    EXPECT_EQ(timing.gapUs, s.serial.rtuGapMicroseconds());
    EXPECT_GT(timing.gapUs, 28000);
    FakeDriver f(Family::Pl110, ProtocolKind::ModbusRtu, 1, timing);
    f.port->reply(modbus::rtuFrame(1, bytes("03 07 D1 00 01")),
                  modbus::rtuFrame(1, bytes("03 02 00 01")));
    f.port->reply(modbus::rtuFrame(1, bytes("03 07 D1 00 01")),
                  modbus::rtuFrame(1, bytes("03 02 00 02")));
    DriverError e;
    EXPECT_EQ(f.read({"V1"}, &e), std::vector<qint64>{1});
    EXPECT_EQ(f.read({"V1"}, &e), std::vector<qint64>{2});
    const auto times = f.port->writeTimes();
    ASSERT_EQ(times.size(), 2);
    EXPECT_GE(times[1] - times[0], timing.gapUs / 1000.0);
}

TEST(DriverFaults, ALongReplyOnASlowLineIsNotCutOffByTheTimeout) {
    // On a serial line (characterUs set) each byte of a reply is awaited timeoutMs after the
    // one before: a reply that trickles in 6 pieces 25 ms apart (150 ms in all) is read whole
    // with a 40 ms timeout.
    LinkSettings slow{40, 0, 5};
    slow.characterUs = 33333; // 300 bps
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0, slow);
    f.port->setChunkDelayMs(25);
    const vigor::Request r{0, vigor::Command::Read, 0x1C00, 4, {}};
    const QByteArray reply = vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray(4, 7)});
    QList<QByteArray> chunks;
    for (qsizetype at = 0; at < reply.size(); at += 3)
        chunks << reply.mid(at, 3);
    ASSERT_EQ(chunks.size(), 6);
    f.port->reply(vigor::encodeRequest(r), chunks);
    DriverError e;
    EXPECT_EQ(f.read({"D0", "D1"}, &e), (std::vector<qint64>{0x0707, 0x0707}));
    EXPECT_TRUE(e.ok()) << e.message.toStdString();
    // Without a baud rate (a pty, TCP) the timeout is for the whole reply: it stops.
    FakeDriver g(Family::Vigor, ProtocolKind::VigorLink, 0, {40, 0, 5});
    g.port->setChunkDelayMs(25);
    g.port->reply(vigor::encodeRequest(r), chunks);
    g.read({"D0", "D1"}, &e);
    EXPECT_EQ(e.kind, EK::NoReply);
    EXPECT_TRUE(e.message.contains(QLatin1String("the reply stopped"))) << e.message.toStdString();
}

TEST(DriverFaults, TheTrafficTapSeesEveryByteBothWaysInOrder) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    f.port->reply(bytes("02 30 30 37 30 30 34 30 41 03 39 46"),
                  {bytes("06 30 30"), bytes("37 30 30 30 03 32 41")});
    ASSERT_TRUE(f.execute(Kind::WriteBit, "M10", 1).ok());
    quint64 next = 0;
    const auto records = f.driver->link().tap().records(0, &next);
    ASSERT_EQ(records.size(), 3u);
    EXPECT_EQ(records[0].direction, TrafficRecord::Direction::Sent);
    EXPECT_EQ(records[0].bytes, bytes("02 30 30 37 30 30 34 30 41 03 39 46"));
    EXPECT_EQ(records[1].direction, TrafficRecord::Direction::Received);
    EXPECT_EQ(records[1].bytes + records[2].bytes, bytes("06 30 30 37 30 30 30 03 32 41"));
    EXPECT_LE(records[0].timeUs, records[2].timeUs);
    EXPECT_EQ(next, 3u);
    EXPECT_TRUE(f.driver->link().tap().records(next).empty());
    const LinkStatistics s = f.driver->link().statistics();
    EXPECT_EQ(s.bytesSent, 12u);
    EXPECT_EQ(s.bytesReceived, 10u);
    EXPECT_GT(s.lastRoundTripMs, 0.0);
}

} // namespace
} // namespace rung::comms::test
