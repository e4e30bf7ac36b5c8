// The drivers against the manuals' example frames (Vigor M/VB/VH communication manual, B-5-3;
// Omron CPM1/SRM1 programming manual W353, Host Link; the Modbus application protocol
// specification): each device read or write puts the example's exact bytes on the wire and
// reads the example's reply into the right devices.

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/comms/driver_fixture.h"
#include "tests/comms/hex.h"

namespace rung::comms::test {
namespace {

using Kind = model::DeviceCommand::Kind;
using model::Family;

QByteArray hostLinkReply(const char *header, int endCode, const QByteArray &text = {},
                         int unit = 0) {
    return hostlink::encode({unit, header, endCode, text}).value(0);
}

QByteArray rtu(int unit, const char *pduHex) {
    return modbus::rtuFrame(unit, bytes(pduHex));
}

TEST(VigorLinkDriver, ReadsM8ToM23WithTheSpecFrameAndSplitsTheBitsOverTheDevices) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // Vector 1: 2 bytes from 0081h; M8..M15 = A7h, M16..M23 = 93h. The reply comes a byte
    // at a time.
    QList<QByteArray> chunks;
    for (char c : bytes("06 30 30 35 31 30 30 41 37 39 33 03 30 44"))
        chunks << QByteArray(1, c);
    f.port->reply(bytes("02 30 30 35 31 30 30 38 31 30 32 03 46 34"), chunks);
    DriverError e;
    const auto values = f.read({"M8", "M9", "M10", "M11", "M12", "M13", "M14", "M15", "M16", "M17",
                                "M18", "M19", "M20", "M21", "M22", "M23"},
                               &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{1, 1, 1, 0, 0, 1, 0, 1, 1, 1, 0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(f.port->writes(), 1);
}

TEST(VigorLinkDriver, ReadsD1AndD2LowByteFirst) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    f.port->reply(bytes("02 30 30 35 31 31 43 30 32 30 34 03 30 33"),
                  bytes("06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44"));
    DriverError e;
    const auto values = f.read({"D1", "D2"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{0x1234, std::int16_t(0xABCD)}));
}

TEST(VigorLinkDriver, WritesD1AndSetsAndResetsBitsWithTheSpecFrames) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    f.port->reply(bytes("02 30 30 36 31 31 43 30 32 30 32 32 35 41 33 03 44 44"),
                  bytes("06 30 30 36 31 30 30 03 32 41"));
    f.port->reply(bytes("02 30 30 37 30 30 34 30 41 03 39 46"),
                  bytes("06 30 30 37 30 30 30 03 32 41"));
    f.port->reply(bytes("02 30 30 37 31 30 34 36 34 03 39 39"),
                  bytes("06 30 30 37 31 30 30 03 32 42"));
    EXPECT_TRUE(f.execute(Kind::WriteWord, "D1", 0xA325).ok());
    EXPECT_TRUE(f.execute(Kind::WriteBit, "M10", 1).ok());
    EXPECT_TRUE(f.execute(Kind::WriteBit, "M100", 0).ok());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_TRUE(f.port->scriptDone());
}

TEST(VigorLinkDriver, ANegativeWordIsWrittenAsTwosComplement) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // D1 = -1: FFFFh, low byte first.
    vigor::Request r{0, vigor::Command::Write, 0x1C02, 2, QByteArray("\xFF\xFF", 2)};
    f.port->reply(vigor::encodeRequest(r), bytes("06 30 30 36 31 30 30 03 32 41"));
    EXPECT_TRUE(f.execute(Kind::WriteWord, "D1", -1).ok());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(VigorLinkDriver, A32BitCounterTakesFourBytesLowFirst) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // The contact, from 03A0h + 200 / 8 = 03B9h bit 0, then C200's value at 1A00h, 4 bytes:
    // 0x00012345 = 74565.
    vigor::Request contact{0, vigor::Command::Read, 0x03B9, 1, {}};
    f.port->reply(vigor::encodeRequest(contact),
                  vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray("\x01", 1)}));
    vigor::Request r{0, vigor::Command::Read, 0x1A00, 4, {}};
    f.port->reply(vigor::encodeRequest(r), vigor::encodeReply({0, vigor::Command::Read, 0,
                                                               QByteArray("\x45\x23\x01\x00", 4)}));
    DriverError e;
    const auto values = f.read({"C200"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, std::vector<qint64>{0x12345});
}

TEST(VigorLinkDriver, ForceAndRunStopAreRefusedWithTheReason) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    const DriverError e = f.execute(Kind::Force, "Y0", 1);
    EXPECT_EQ(e.kind, DriverError::Kind::Unsupported);
    EXPECT_TRUE(e.message.contains(QLatin1String("cannot force over Vigor Computer Link")))
        << e.message.toStdString();
    EXPECT_TRUE(e.message.contains(QLatin1String("Y0"))) << e.message.toStdString();
    EXPECT_FALSE(f.driver->canSetMode());
    const DriverError mode = f.driver->setMode(PlcMode::Stop);
    EXPECT_EQ(mode.kind, DriverError::Kind::Unsupported);
    EXPECT_EQ(f.port->writes(), 0); // nothing was sent
}

TEST(VigorLinkDriver, TheRunStateIsTheOnWhileRunningBit) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // M9000 sits at 03E0h bit 0.
    ASSERT_TRUE(f.driver->runStateDevice().valid());
    vigor::Request r{0, vigor::Command::Read, 0x03E0, 1, {}};
    f.port->reply(vigor::encodeRequest(r),
                  vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray("\x01", 1)}));
    f.port->reply(vigor::encodeRequest(r),
                  vigor::encodeReply({0, vigor::Command::Read, 0, QByteArray("\x00", 1)}));
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(f.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Run);
    ASSERT_TRUE(f.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Stop);
}

TEST(ModbusDriver, ReadsTheVigorCp2MapWithTheSpecExample) {
    // Modbus Application Protocol 6.3: registers 108..110 (006Bh, 3) of unit 11h hold 022Bh,
    // 0000h, 0064h; on the CP2 map they are D107..D109.
    FakeDriver f(Family::Vigor, ProtocolKind::ModbusRtu, 0x11);
    f.port->reply(bytes("11 03 00 6B 00 03 76 87"), rtu(0x11, "03 06 02 2B 00 00 00 64"));
    DriverError e;
    const auto values = f.read({"D107", "D108", "D109"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{555, 0, 100}));
}

TEST(ModbusDriver, OutputsAreCoilsAndInputsAreDiscreteInputsOnTheCp2Map) {
    FakeDriver f(Family::Vigor, ProtocolKind::ModbusRtu, 1);
    // Y0 = coil 0, Y7 = coil 7 (one read of 8 coils); X1 = input 1.
    f.port->reply(rtu(1, "01 00 00 00 08"), rtu(1, "01 01 81"));
    f.port->reply(rtu(1, "02 00 01 00 01"), rtu(1, "02 01 01"));
    DriverError e;
    const auto values = f.read({"Y0", "Y7", "X1"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{1, 1, 1}));
    // Y0 ON with function 05, D0 = 7 with 06; X is an input: Modbus cannot write it.
    f.port->reply(rtu(1, "05 00 00 FF 00"), rtu(1, "05 00 00 FF 00"));
    f.port->reply(rtu(1, "06 00 00 00 07"), rtu(1, "06 00 00 00 07"));
    EXPECT_TRUE(f.execute(Kind::WriteBit, "Y0", 1).ok());
    EXPECT_TRUE(f.execute(Kind::WriteWord, "D0", 7).ok());
    const DriverError x = f.execute(Kind::WriteBit, "X1", 1);
    EXPECT_EQ(x.kind, DriverError::Kind::BadDevice);
    EXPECT_TRUE(x.message.contains(QLatin1String("discrete inputs"))) << x.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(ModbusDriver, ModbusTcpCarriesTheSameRequestInAnMbapHeader) {
    FakeDriver f(Family::Vigor, ProtocolKind::ModbusTcp, 1);
    f.port->reply(modbus::tcpFrame(1, 1, bytes("03 00 0A 00 01")),
                  modbus::tcpFrame(1, 1, bytes("03 02 FF FE")));
    DriverError e;
    const auto values = f.read({"D10"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, std::vector<qint64>{-2});
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(ModbusDriver, StationZeroIsRefusedBecauseNoPlcAnswersABroadcast) {
    QString error;
    auto d = Driver::create(model::Target::get(Family::Pl110), ProtocolKind::ModbusRtu,
                            std::make_unique<FakeTransport>(), 0, {}, &error);
    EXPECT_FALSE(d);
    EXPECT_TRUE(error.contains(QLatin1String("broadcast"))) << error.toStdString();
}

TEST(ModbusDriver, Pl110RunStopIsSm0Bit0AndTheModelIsWordsZeroAndOne) {
    FakeDriver f(Family::Pl110, ProtocolKind::ModbusRtu, 1);
    ASSERT_TRUE(f.driver->canSetMode());
    // SM0.0 = coil 16000 (3E80h).
    f.port->reply(rtu(1, "01 3E 80 00 01"), rtu(1, "01 01 01"));
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(f.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Run);
    f.port->reply(rtu(1, "05 3E 80 00 00"), rtu(1, "05 3E 80 00 00"));
    EXPECT_TRUE(f.driver->setMode(PlcMode::Stop).ok());
    f.port->reply(rtu(1, "03 00 00 00 02"), rtu(1, "03 04 00 6E 00 0C"));
    PlcIdentity id;
    ASSERT_TRUE(f.driver->identify(&id).ok());
    EXPECT_EQ(id.model, QStringLiteral("device type 110"));
    EXPECT_EQ(id.version, QStringLiteral("12")); // the panel says "version 12"
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(ModbusDriver, Pl110BitsOfVAreCoilsAndPresetsAreWritable) {
    FakeDriver f(Family::Pl110, ProtocolKind::ModbusRtu, 1);
    // V3.5 = coil 32000 + 3 * 16 + 5 = 32053 (7D35h); PT1 = register 13000 (32C8h).
    f.port->reply(rtu(1, "05 7D 35 FF 00"), rtu(1, "05 7D 35 FF 00"));
    f.port->reply(rtu(1, "06 32 C8 00 64"), rtu(1, "06 32 C8 00 64"));
    EXPECT_TRUE(f.execute(Kind::WriteBit, "V3.5", 1).ok());
    EXPECT_TRUE(f.execute(Kind::WriteSetValue, "T1", 100).ok());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    const DriverError force = f.execute(Kind::Force, "Q1", 1);
    EXPECT_EQ(force.kind, DriverError::Kind::Unsupported);
    EXPECT_TRUE(force.message.contains(QLatin1String("cannot force")))
        << force.message.toStdString();
}

TEST(HostLinkDriver, ReadsDmIrAndTimersWithTheSpecFrames) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    // IR first, then DM: a refresh goes through the spaces in the map's order.
    f.port->reply("@00RR0000000242*\r", hostLinkReply("RR", 0, "00FF8001"));
    f.port->reply("@00RD0000000157*\r", hostLinkReply("RD", 0, "1234"));
    DriverError e;
    auto values = f.read({"DM 0000", "000", "001.15", "001.00", "001.01"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{0x1234, 0xFF, 1, 1, 0}));
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    // Timer present values are BCD: 0150 is 150.
    f.port->reply(bytes("40 30 30 52 43 30 30 30 30 30 30 30 32 35 33 2A 0D"),
                  hostLinkReply("RC", 0, "01500009"));
    f.port->reply(
        hostlink::encode(hostlink::readCommand(0, model::ProtocolSpace::HostLinkCompletion, 0, 2))
            .value(0),
        hostLinkReply("RG", 0, "10"));
    values = f.read({"TIM 000", "TIM 001"}, &e);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{150, 9}));
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(HostLinkDriver, TheImageHoldsPresentValuesAsThePlcKeepsThemInBcd) {
    // The online image is the PLC's memory, as the simulator's is: TIM 000 = 150 is the word
    // 0150h there (W353), which the ladder and the watch table read as BCD. A refresh that
    // turned it into 150 (0096h) would show "96" beside the simulation's "150".
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    f.port->reply("@00RC0000000253*\r", hostLinkReply("RC", 0, "01500009"));
    const Driver::Plan plan = f.driver->plan(f.devices({"TIM 000", "TIM 001"}));
    // Only the values: the plan reads the completion flags (RG) too.
    f.port->reply(
        hostlink::encode(hostlink::readCommand(0, model::ProtocolSpace::HostLinkCompletion, 0, 2))
            .value(0),
        hostLinkReply("RG", 0, "00"));
    std::vector<std::int32_t> words(std::size_t(f.driver->layout()->wordCount()), 0);
    ASSERT_TRUE(f.driver->refresh(plan, words, nullptr).ok());
    model::Snapshot image;
    image.layout = f.driver->layout();
    image.words = words;
    EXPECT_EQ(image.value(f.device("TIM 000")), 0x0150);
    EXPECT_EQ(image.value(f.device("TIM 001")), 0x0009);
    EXPECT_EQ(f.driver->number(image, f.device("TIM 000")), 150);
    // A command carries the word too (the watch table's BCD 150 is 0150h): WC sends it as it
    // is, @00WC0000 0150 (W353), not 0336, the digits of 0150h read as a number.
    f.port->reply("@00MS5E*\r", hostLinkReply("MS", 0, "0300")); // MONITOR
    f.port->reply(hostlink::encode(
                      hostlink::writeCommand(0, model::ProtocolSpace::HostLinkTimerPv, 0, {0x0150}))
                      .value(0),
                  hostLinkReply("WC", 0));
    const DriverError written = f.execute(Kind::WriteWord, "TIM 000", 0x0150);
    EXPECT_TRUE(written.ok()) << written.message.toStdString();
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    // The way a user types it: 150 is the word 0150h; past four digits it does not fit.
    QString why;
    EXPECT_EQ(f.driver->wordOf(f.device("TIM 000"), 150, &why), 0x0150);
    EXPECT_EQ(f.driver->wordOf(f.device("TIM 000"), 10000, &why), std::nullopt);
    EXPECT_TRUE(why.contains(QLatin1String("0..9999"))) << why.toStdString();
    EXPECT_EQ(f.driver->wordOf(f.device("DM 0000"), 150, &why), 150); // a plain word
}

TEST(HostLinkDriver, AWriteInRunSwitchesToMonitorFirstAndSaysSo) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    f.port->reply("@00MS5E*\r", hostLinkReply("MS", 0, "0200")); // bits 9-8 = 10: RUN
    f.port->reply("@00SC0252*\r", hostLinkReply("SC", 0));
    f.port->reply("@00WD0100123456*\r", hostLinkReply("WD", 0));
    QString notice;
    const DriverError e = f.execute(Kind::WriteWord, "DM 0100", 0x1234, &notice);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_TRUE(notice.contains(QLatin1String("switched to MONITOR"))) << notice.toStdString();
    EXPECT_TRUE(notice.contains(QLatin1String("CPM1 unit 0"))) << notice.toStdString();
    // The next write finds the PLC in MONITOR: no second switch.
    f.port->reply("@00WR001000FF44*\r", hostLinkReply("WR", 0));
    notice.clear();
    EXPECT_TRUE(f.execute(Kind::WriteWord, "010", 0xFF, &notice).ok());
    EXPECT_TRUE(notice.isEmpty());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
    EXPECT_TRUE(f.port->scriptDone());
}

TEST(HostLinkDriver, ForcesAChannelBitAndReleasesAll) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    f.port->reply("@00MS5E*\r", hostLinkReply("MS", 0, "0300")); // MONITOR
    f.port->reply("@00KSCIO 0010003C*\r", hostLinkReply("KS", 0));
    ASSERT_TRUE(f.execute(Kind::Force, "010.00", 1).ok());
    EXPECT_EQ(f.driver->forced().size(), 1u);
    const DriverError one = f.execute(Kind::Release, "010.00", 0);
    EXPECT_EQ(one.kind, DriverError::Kind::Unsupported);
    EXPECT_TRUE(one.message.contains(QLatin1String("KC"))) << one.message.toStdString();
    f.port->reply(hostlink::encode(hostlink::cancelForceCommand(0)).value(0),
                  hostLinkReply("KC", 0));
    ASSERT_TRUE(f.execute(Kind::ReleaseAll, "010.00", 0).ok());
    EXPECT_TRUE(f.driver->forced().empty());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(HostLinkDriver, ModeAndModelComeFromMsSmAndMm) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    f.port->reply("@00MS5E*\r", hostLinkReply("MS", 0, "0000"));
    PlcMode mode = PlcMode::Unknown;
    ASSERT_TRUE(f.driver->readMode(&mode).ok());
    EXPECT_EQ(mode, PlcMode::Program);
    f.port->reply("@00SC0353*\r", hostLinkReply("SC", 0));
    EXPECT_TRUE(f.driver->setMode(PlcMode::Run).ok());
    f.port->reply("@00SC0050*\r", hostLinkReply("SC", 0));
    EXPECT_TRUE(f.driver->setMode(PlcMode::Stop).ok()); // STOP is PROGRAM on a CPM1
    f.port->reply("@00MM40*\r", hostLinkReply("MM", 0, "12"));
    PlcIdentity id;
    ASSERT_TRUE(f.driver->identify(&id).ok());
    EXPECT_EQ(id.model, QStringLiteral("model code 12h"));
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(HostLinkDriver, AChannelBitIsWrittenByReadingAndWritingItsWord) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    f.port->reply("@00MS5E*\r", hostLinkReply("MS", 0, "0300"));
    f.port->reply(
        hostlink::encode(hostlink::readCommand(0, model::ProtocolSpace::HostLinkIr, 10, 1))
            .value(0),
        hostLinkReply("RR", 0, "00F0"));
    f.port->reply(
        hostlink::encode(hostlink::writeCommand(0, model::ProtocolSpace::HostLinkIr, 10, {0x00F1}))
            .value(0),
        hostLinkReply("WR", 0));
    EXPECT_TRUE(f.execute(Kind::WriteBit, "010.00", 1).ok());
    EXPECT_TRUE(f.port->mismatch().isEmpty()) << f.port->mismatch().toStdString();
}

TEST(HostLinkDriver, ALongReadComesInPartsAndTheDriverSendsTheDelimiters) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    // DM 0000..0039: 40 words, over 131 characters: two parts, a CR from us between them.
    QByteArray text;
    for (int i = 0; i < 40; ++i)
        text += QByteArray::number(i, 16).toUpper().rightJustified(4, '0');
    const QList<QByteArray> parts = hostlink::encode({0, "RD", 0, text});
    ASSERT_EQ(parts.size(), 2);
    f.port->reply("@00RD0000004052*\r", parts);
    std::vector<model::Address> devices;
    for (int i = 0; i < 40; i += 5)
        devices.push_back(f.device(
            QStringLiteral("DM %1").arg(i, 4, 10, QLatin1Char('0')).toLatin1().constData()));
    devices.push_back(f.device("DM 0039"));
    std::vector<qint64> values;
    const DriverError e = f.driver->read(devices, &values);
    ASSERT_TRUE(e.ok()) << e.message.toStdString();
    EXPECT_EQ(values, (std::vector<qint64>{0, 5, 10, 15, 20, 25, 30, 35, 39}));
    const auto written = f.port->written();
    ASSERT_EQ(written.size(), 2);
    EXPECT_EQ(written[1], QByteArray("\r"));
}

} // namespace
} // namespace rung::comms::test
