// The Host Link C-mode slave (Omron CPM1/SRM1 programming manual W353, Host Link): the
// manual's command examples from the PLC's side, modes, forcing, end codes and answers in
// parts.

#include "comms/slave/host_link_responder.h"
#include "tests/comms/slave_fixture.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

namespace rung::comms::slave {
// Named, so that the using-directive stays in this file when the test files are compiled
// together (tests/CMakeLists.txt).
namespace host_link_slave {
namespace {

using namespace hostlink;
using test::Image;

using rung::testing::cpm1;

struct HostLinkSlave {
    Image plc;
    HostLinkResponder slave;

    explicit HostLinkSlave(OperatingMode mode = OperatingMode::Run, int unit = 0)
        : plc(cpm1(), mode)
        , slave(cpm1(), *model::findProtocolMap(cpm1(), model::ProtocolId::HostLink), unit,
                plc.image) {}

    // Sends the command's parts (answering nothing but the delimiters) and decodes the reply,
    // asking for each later part with a CR as a master does.
    ReplyDecoder ask(const Frame &command) {
        ReplyDecoder d(command);
        QByteArrayList out;
        for (const QByteArray &part : encode(command)) {
            out = slave.feed(part);
            if (!out.isEmpty() && out.front() == QByteArray(1, Cr))
                out.removeFirst();
        }
        while (!out.isEmpty()) {
            d.feed(out.takeFirst());
            if (d.takeDelimiterRequest())
                out += slave.feed(QByteArray(1, Cr));
        }
        return d;
    }
    int endCodeOf(const Frame &command) {
        const ReplyDecoder d = ask(command);
        if (d.status() == FrameStatus::Complete)
            return 0;
        return d.error().kind == ProtocolError::Kind::DeviceError ? d.error().code : -1;
    }
};

TEST(HostLinkSlave, TheCommandVectorsOfProtocolsMdAreAnswered) {
    HostLinkSlave f(OperatingMode::Monitor);
    f.plc.set("DM 0000", 0x1234);
    f.plc.set("000", 0x00F0);
    f.plc.set("001", 0x0102);
    // @00RD0000000157*: read DM0000, 1 word.
    QByteArrayList out = f.slave.feed("@00RD0000000157*\r");
    ASSERT_EQ(out.size(), 1);
    const QByteArray text = "@00RD001234";
    EXPECT_EQ(out.front(), text + fcs(text) + "*\r");
    // @00WD0100123456*: DM0100 = 1234 (in MONITOR).
    out = f.slave.feed("@00WD0100123456*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00WD00") + fcs("@00WD00") + "*\r");
    EXPECT_EQ(f.plc.value("DM 0100"), 0x1234);
    // @00RR0000000242*: IR 000, 2 words.
    out = f.slave.feed("@00RR0000000242*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00RR0000F00102") + fcs("@00RR0000F00102") + "*\r");
    // @00WR001000FF44*: channel 010 = 00FF.
    out = f.slave.feed("@00WR001000FF44*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(f.plc.value("010"), 0x00FF);
    // @00KSCIO 0010003C*: force set 010.00.
    out = f.slave.feed("@00KSCIO 0010003C*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00KS00") + fcs("@00KS00") + "*\r");
    EXPECT_TRUE(f.plc.image->snapshot()->forced(test::device(cpm1(), "010.00")));
    // @00MM40*: model code 11h, CPM1 (W353 6-3-28).
    out = f.slave.feed("@00MM40*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00MM0011") + fcs("@00MM0011") + "*\r");
}

TEST(HostLinkSlave, ModeChangesAndTheStatusTheyShow) {
    HostLinkSlave f(OperatingMode::Run);
    auto status = [&f] {
        const ReplyDecoder d = f.ask(statusCommand(0));
        EXPECT_EQ(d.status(), FrameStatus::Complete);
        return modeOfStatus(d.reply().status);
    };
    EXPECT_EQ(status(), Mode::Run);
    // @00SC0050* PROGRAM, @00SC0252* MONITOR, @00SC0353* RUN: the vectors, byte for byte.
    for (const auto &[vector, mode] :
         {std::pair{"@00SC0050*\r", Mode::Program}, std::pair{"@00SC0252*\r", Mode::Monitor},
          std::pair{"@00SC0353*\r", Mode::Run}}) {
        const QByteArrayList out = f.slave.feed(vector);
        ASSERT_EQ(out.size(), 1);
        EXPECT_EQ(out.front(), QByteArray("@00SC00") + fcs("@00SC00") + "*\r");
        EXPECT_EQ(status(), mode);
    }
    EXPECT_EQ(f.slave.feed("@00MS5E*\r").size(), 1); // the MS vector
}

TEST(HostLinkSlave, WritesAndForcingAreRefusedInRunUntilMonitor) {
    HostLinkSlave f(OperatingMode::Run);
    EXPECT_EQ(f.endCodeOf(writeCommand(0, model::ProtocolSpace::HostLinkDm, 5, {7})), NotInRun);
    EXPECT_EQ(f.endCodeOf(forceCommand(0, true, 10, 0)), NotInRun);
    EXPECT_EQ(f.endCodeOf(cancelForceCommand(0)), NotInRun);
    EXPECT_EQ(f.plc.value("DM 0005"), 0);
    EXPECT_EQ(f.endCodeOf(modeCommand(0, Mode::Monitor)), 0);
    EXPECT_EQ(f.endCodeOf(writeCommand(0, model::ProtocolSpace::HostLinkDm, 5, {7})), 0);
    EXPECT_EQ(f.plc.value("DM 0005"), 7);
    EXPECT_EQ(f.endCodeOf(forceCommand(0, false, 10, 1)), 0);
    EXPECT_TRUE(f.plc.image->snapshot()->forced(test::device(cpm1(), "010.01")));
    EXPECT_EQ(f.endCodeOf(cancelForceCommand(0)), 0);
    EXPECT_FALSE(f.plc.image->snapshot()->forced(test::device(cpm1(), "010.01")));
}

TEST(HostLinkSlave, PresentValuesTravelAsBcdAndCompletionFlagsAsDigits) {
    HostLinkSlave f(OperatingMode::Monitor);
    // The PLC keeps a present value as BCD digits (W353; the simulator too): TIM 002 = 1234
    // is the word 1234h, which RC carries as it is.
    f.plc.set("TIM 002", 0x1234);
    f.plc.set("TIM 003", 1);
    ReplyDecoder d = f.ask(readCommand(0, model::ProtocolSpace::HostLinkTimerPv, 2, 1));
    ASSERT_EQ(d.status(), FrameStatus::Complete);
    EXPECT_EQ(d.reply().words, (std::vector<std::uint16_t>{0x1234}));
    EXPECT_EQ(f.endCodeOf(writeCommand(0, model::ProtocolSpace::HostLinkTimerPv, 2, {0x0150})), 0);
    EXPECT_EQ(f.plc.value("TIM 002"), 0x0150);
    // Not BCD: 15.
    EXPECT_EQ(f.endCodeOf(writeCommand(0, model::ProtocolSpace::HostLinkTimerPv, 2, {0x00A0})),
              EntryNumberError);
    d = f.ask(readCommand(0, model::ProtocolSpace::HostLinkCompletion, 2, 2));
    ASSERT_EQ(d.status(), FrameStatus::Complete);
    EXPECT_EQ(d.reply().flags, (std::vector<bool>{false, false}));
}

TEST(HostLinkSlave, EndCodesForBrokenAndOutOfReachCommands) {
    HostLinkSlave f(OperatingMode::Monitor);
    // 13: a wrong FCS, answered since the unit is ours.
    QByteArrayList out = f.slave.feed("@00RD0000000158*\r");
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front().mid(5, 2), "13");
    // 14: a read whose count is not four digits.
    Frame broken = readCommand(0, model::ProtocolSpace::HostLinkDm, 0, 1);
    broken.text.chop(1);
    EXPECT_EQ(f.endCodeOf(broken), FormatError);
    // 04: DM 1024 is past the CPM1's DM (0000..1023, 6144..6655; W353, Host Link RD).
    EXPECT_EQ(f.endCodeOf(readCommand(0, model::ProtocolSpace::HostLinkDm, 1020, 5)), AddressOver);
    EXPECT_EQ(f.endCodeOf(readCommand(0, model::ProtocolSpace::HostLinkIr, 20, 1)), AddressOver);
    // 16: a Host Link command the virtual PLC does not serve; IC: not Host Link at all.
    EXPECT_EQ(f.endCodeOf({0, "RL", -1, "00000001"}), NotSupported);
    out = f.slave.feed(encode({0, "ZZ", -1, {}}).front());
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00IC") + fcs("@00IC") + "*\r");
    // 15: an unknown mode.
    EXPECT_EQ(f.endCodeOf({0, "SC", -1, "01"}), EntryNumberError);
}

TEST(HostLinkSlave, AnotherUnitIsNotAnswered) {
    HostLinkSlave f(OperatingMode::Run, 3);
    EXPECT_TRUE(f.slave.feed("@00RD0000000157*\r").isEmpty());
    EXPECT_EQ(f.slave.statistics().ignored, 1u);
    EXPECT_EQ(f.ask(readCommand(3, model::ProtocolSpace::HostLinkDm, 0, 1)).status(),
              FrameStatus::Complete);
}

TEST(HostLinkSlave, LongAnswersAndCommandsGoInPartsWithTheDelimiter) {
    HostLinkSlave f(OperatingMode::Monitor);
    std::vector<std::uint16_t> words;
    for (int i = 0; i < 100; ++i)
        words.push_back(std::uint16_t(0x1000 + i));
    // A write of 100 words is four parts; the slave answers a CR to each but the last.
    const Frame write = writeCommand(0, model::ProtocolSpace::HostLinkDm, 200, words);
    const QList<QByteArray> parts = encode(write);
    ASSERT_GT(parts.size(), 1);
    for (qsizetype i = 0; i < parts.size(); ++i) {
        const QByteArrayList out = f.slave.feed(parts[i]);
        ASSERT_EQ(out.size(), 1) << i;
        if (i + 1 < parts.size())
            EXPECT_EQ(out.front(), QByteArray(1, Cr));
        else
            EXPECT_TRUE(out.front().startsWith("@00WD00"));
    }
    EXPECT_EQ(f.plc.value("DM 0299") & 0xFFFF, 0x1000 + 99);
    // Read back: the answer comes in parts, each after the master's CR.
    const ReplyDecoder d = f.ask(readCommand(0, model::ProtocolSpace::HostLinkDm, 200, 100));
    ASSERT_EQ(d.status(), FrameStatus::Complete) << d.error().message.toStdString();
    EXPECT_EQ(d.reply().words, words);
}

TEST(HostLinkSlave, ANewCommandInsteadOfTheDelimiterDropsTheRestOfAnAnswer) {
    HostLinkSlave f(OperatingMode::Monitor);
    QByteArrayList out =
        f.slave.feed(encode(readCommand(0, model::ProtocolSpace::HostLinkDm, 0, 100)).front());
    ASSERT_EQ(out.size(), 1);
    EXPECT_FALSE(out.front().endsWith("*\r")); // the first of several parts
    out = f.slave.feed(encode(statusCommand(0)).front());
    ASSERT_EQ(out.size(), 1);
    EXPECT_TRUE(out.front().startsWith("@00MS00"));
    EXPECT_TRUE(f.slave.feed(QByteArray(1, Cr)).isEmpty());
}

TEST(HostLinkSlave, ACommandBegunAfreshInPlaceOfALaterPartIsServed) {
    HostLinkSlave f(OperatingMode::Monitor);
    std::vector<std::uint16_t> words(100, 0x1111);
    const QList<QByteArray> parts =
        encode(writeCommand(0, model::ProtocolSpace::HostLinkDm, 0, words));
    QByteArrayList out = f.slave.feed(parts.front());
    ASSERT_EQ(out, QByteArrayList{QByteArray(1, Cr)});
    // The master gave the write up and asks for the status: answered, nothing written.
    out = f.slave.feed(encode(statusCommand(0)).front());
    ASSERT_EQ(out.size(), 1);
    EXPECT_TRUE(out.front().startsWith("@00MS00")) << out.front().toStdString();
    EXPECT_EQ(f.plc.value("DM 0000"), 0);
}

TEST(HostLinkSlave, TestCommandEchoes) {
    HostLinkSlave f;
    const QByteArrayList out = f.slave.feed(encode({0, "TS", -1, "HELLO 123"}).front());
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), QByteArray("@00TSHELLO 123") + fcs("@00TSHELLO 123") + "*\r");
}

} // namespace
} // namespace host_link_slave
} // namespace rung::comms::slave
