#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "model/target/target.h"

#include <gtest/gtest.h>

namespace rung::comms::hostlink {
namespace {

using Kind = ProtocolError::Kind;

QByteArray wire(const Frame &f) {
    const auto parts = encode(f);
    EXPECT_EQ(parts.size(), 1);
    return parts.value(0);
}

// A reply frame as a PLC sends it, one part.
QByteArray reply(int unit, const char *header, int endCode, const QByteArray &text = {}) {
    return wire({unit, header, endCode, text});
}

TEST(HostLink, EncodesEveryCommandOfTheSpecByteForByte) {
    // Omron CPM1/SRM1 programming manual W353 (Host Link): the command examples (unit 00),
    // each ending in CR.
    EXPECT_EQ(wire(readCommand(0, ProtocolSpace::HostLinkDm, 0, 1)),
              QByteArray("@00RD0000000157*\r"));
    EXPECT_EQ(wire(writeCommand(0, ProtocolSpace::HostLinkDm, 100, {0x1234})),
              QByteArray("@00WD0100123456*\r"));
    EXPECT_EQ(wire(readCommand(0, ProtocolSpace::HostLinkIr, 0, 2)),
              QByteArray("@00RR0000000242*\r"));
    EXPECT_EQ(wire(writeCommand(0, ProtocolSpace::HostLinkIr, 10, {0x00FF})),
              QByteArray("@00WR001000FF44*\r"));
    EXPECT_EQ(wire(readCommand(0, ProtocolSpace::HostLinkTimerPv, 0, 2)),
              QByteArray("@00RC0000000253*\r"));
    EXPECT_EQ(wire(statusCommand(0)), QByteArray("@00MS5E*\r"));
    EXPECT_EQ(wire(modeCommand(0, Mode::Program)), QByteArray("@00SC0050*\r"));
    EXPECT_EQ(wire(modeCommand(0, Mode::Monitor)), QByteArray("@00SC0252*\r"));
    EXPECT_EQ(wire(modeCommand(0, Mode::Run)), QByteArray("@00SC0353*\r"));
    EXPECT_EQ(wire(modelCommand(0)), QByteArray("@00MM40*\r"));
    EXPECT_EQ(wire(forceCommand(0, true, 10, 0)), QByteArray("@00KSCIO 0010003C*\r"));
}

TEST(HostLink, SlaveReadsEveryCommandOfTheSpec) {
    CommandDecoder s;
    ASSERT_EQ(s.feed("@00KSCIO 0010003C*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), 0);
    EXPECT_EQ(s.command().header, QByteArray("KS"));
    const auto force = parseForce(s.command().text);
    ASSERT_TRUE(force.valid);
    EXPECT_EQ(force.begin, 10);
    EXPECT_EQ(force.bit, 0);
    s.next();
    ASSERT_EQ(s.feed("@00WD0100123456*\r"), FrameStatus::Complete);
    const auto write = parseWrite(s.command().text);
    ASSERT_TRUE(write.valid);
    EXPECT_EQ(write.begin, 100);
    EXPECT_EQ(write.words, std::vector<std::uint16_t>{0x1234});
    s.next();
    ASSERT_EQ(s.feed("@00RD0000000157*\r"), FrameStatus::Complete);
    const auto read = parseRead(s.command().text);
    ASSERT_TRUE(read.valid);
    EXPECT_EQ(read.count, 1);
}

TEST(HostLink, DecodesReadStatusModelAndWriteReplies) {
    ReplyDecoder rd(readCommand(0, ProtocolSpace::HostLinkDm, 0, 2));
    ASSERT_EQ(rd.feed(reply(0, "RD", 0, "1234ABCD")), FrameStatus::Complete);
    EXPECT_EQ(rd.reply().words, (std::vector<std::uint16_t>{0x1234, 0xABCD}));

    ReplyDecoder rg(readCommand(0, ProtocolSpace::HostLinkCompletion, 0, 3));
    ASSERT_EQ(rg.feed(reply(0, "RG", 0, "101")), FrameStatus::Complete);
    EXPECT_EQ(rg.reply().flags, (std::vector<bool>{true, false, true}));

    ReplyDecoder ms(statusCommand(0));
    ASSERT_EQ(ms.feed(reply(0, "MS", 0, "0300")), FrameStatus::Complete);
    EXPECT_EQ(modeOfStatus(ms.reply().status), Mode::Monitor);
    EXPECT_EQ(modeOfStatus(0x0200), Mode::Run);
    EXPECT_EQ(modeOfStatus(0x0000), Mode::Program);

    ReplyDecoder mm(modelCommand(0));
    ASSERT_EQ(mm.feed(reply(0, "MM", 0, "12")), FrameStatus::Complete);
    EXPECT_EQ(mm.reply().model, 0x12);

    ReplyDecoder sc(modeCommand(0, Mode::Monitor));
    EXPECT_EQ(sc.feed(reply(0, "SC", 0)), FrameStatus::Complete);
}

// W353, TEST: no end code in the reply; the characters come back as sent, and other
// characters are not this command's answer.
TEST(HostLink, TestIsAnsweredWithTheCharactersAndNoEndCode) {
    const Frame test{0, "TS", -1, "HELLO 123"};
    ReplyDecoder ok(test);
    ASSERT_EQ(ok.feed(encode(test).front()), FrameStatus::Complete)
        << ok.error().message.toStdString();
    EXPECT_EQ(ok.reply().frame.text, QByteArray("HELLO 123"));
    EXPECT_EQ(ok.reply().frame.endCode, -1);

    ReplyDecoder other(test);
    EXPECT_EQ(other.feed(encode({0, "TS", -1, "HELLO 124"}).front()), FrameStatus::Failed);
    EXPECT_EQ(other.error().kind, ProtocolError::Kind::WrongReply);
    EXPECT_NE(other.error().message.indexOf(QStringLiteral("HELLO 124")), -1)
        << other.error().message.toStdString();
}

TEST(HostLink, ALongReplyIsSplitThirtyThenThirtyOneWordsAndNeedsADelimiterPerPart) {
    std::vector<std::uint16_t> words;
    QByteArray text;
    for (int i = 0; i < 100; ++i) {
        words.push_back(std::uint16_t(i * 257));
        text += QByteArray::number(i * 257, 16).toUpper().rightJustified(4, '0');
    }
    const auto parts = encode({5, "RD", 0, text});
    ASSERT_EQ(parts.size(), 4); // 30 + 31 + 31 + 8 words
    EXPECT_EQ(parts[0].size(), 7 + 120 + 3);
    EXPECT_EQ(parts[1].size(), 124 + 3);
    for (const auto &p : parts)
        EXPECT_LE(p.size(), p == parts[0] ? MaxFirstFrame : MaxLaterFrame);
    EXPECT_TRUE(parts[3].endsWith("*\r"));
    EXPECT_FALSE(parts[0].endsWith("*\r"));

    ReplyDecoder d(readCommand(5, ProtocolSpace::HostLinkDm, 0, 100));
    int delimiters = 0;
    for (const auto &p : parts) {
        for (char c : p)
            d.feed(QByteArrayView(&c, 1));
        if (d.takeDelimiterRequest())
            ++delimiters;
    }
    EXPECT_EQ(delimiters, 3);
    ASSERT_EQ(d.status(), FrameStatus::Complete) << d.error().message.toStdString();
    EXPECT_EQ(d.reply().words, words);

    // The slave side joins a long write the same way.
    const auto command = encode(writeCommand(5, ProtocolSpace::HostLinkDm, 0, words));
    ASSERT_GT(command.size(), 1);
    CommandDecoder s;
    for (const auto &p : command)
        s.feed(p);
    ASSERT_EQ(s.status(), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), 0);
    EXPECT_EQ(parseWrite(s.command().text).words, words);
}

TEST(HostLink, EveryEndCodeIsADeviceErrorWithItsOwnText) {
    QSet<QString> texts;
    for (int code : {0x01, 0x02, 0x03, 0x04, 0x0B, 0x13, 0x14, 0x15, 0x16, 0x18}) {
        ReplyDecoder d(writeCommand(0, ProtocolSpace::HostLinkDm, 100, {0x1234}));
        ASSERT_EQ(d.feed(reply(0, "WD", code)), FrameStatus::Failed);
        EXPECT_EQ(d.error().kind, Kind::DeviceError);
        EXPECT_EQ(d.error().code, code);
        texts.insert(endCodeText(code));
    }
    EXPECT_EQ(texts.size(), 10);
    EXPECT_TRUE(endCodeText(NotInRun).contains(QLatin1String("MONITOR")));
}

TEST(HostLink, AnUnknownCommandAnswersIc) {
    ReplyDecoder d(modelCommand(0));
    ASSERT_EQ(d.feed(reply(0, "IC", -1)), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::DeviceError);
}

TEST(HostLink, FaultsAreNamed) {
    QByteArray bad = "@00MS000300";
    bad += "00*\r"; // wrong FCS
    ReplyDecoder fcs(statusCommand(0));
    ASSERT_EQ(fcs.feed(bad), FrameStatus::Failed);
    EXPECT_EQ(fcs.error().kind, Kind::BadChecksum);

    ReplyDecoder garbage(statusCommand(0));
    EXPECT_EQ(garbage.feed("\x15@00"), FrameStatus::Failed);
    EXPECT_EQ(garbage.error().kind, Kind::Garbage);

    ReplyDecoder station(statusCommand(3));
    EXPECT_EQ(station.feed(reply(4, "MS", 0, "0300")), FrameStatus::Failed);
    EXPECT_EQ(station.error().kind, Kind::WrongStation);

    ReplyDecoder header(statusCommand(0));
    EXPECT_EQ(header.feed(reply(0, "MM", 0, "12")), FrameStatus::Failed);
    EXPECT_EQ(header.error().kind, Kind::WrongReply);

    ReplyDecoder shortRead(readCommand(0, ProtocolSpace::HostLinkDm, 0, 2));
    EXPECT_EQ(shortRead.feed(reply(0, "RD", 0, "1234")), FrameStatus::Failed);
    EXPECT_EQ(shortRead.error().kind, Kind::Malformed);

    ReplyDecoder cut(readCommand(0, ProtocolSpace::HostLinkDm, 0, 2));
    EXPECT_EQ(cut.feed("@00RD0012"), FrameStatus::NeedMore);
    EXPECT_EQ(cut.deadlinePassed(500).kind, Kind::Truncated);
    EXPECT_TRUE(cut.deadlinePassed(500).message.contains(QLatin1String("500 ms")));

    ReplyDecoder endless(readCommand(0, ProtocolSpace::HostLinkDm, 0, 2));
    EXPECT_EQ(endless.feed("@" + QByteArray(200, '0')), FrameStatus::Failed);
}

TEST(HostLink, SlaveAnswersFcsAndFrameLengthErrorsAndSkipsNoise) {
    CommandDecoder s;
    ASSERT_EQ(s.feed("\r\r@00MS00*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), FcsError);
    EXPECT_EQ(s.command().header, QByteArray("MS"));
    s.next();
    QByteArray overlong = "@00WD0000" + QByteArray(4 * 40, '0');
    overlong += fcs(overlong) + "*\r";
    ASSERT_EQ(s.feed(overlong), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), FrameLengthError);
}

// The spec's "@00MS5E*" (read status) with its FCS spoiled: the slave says both FCSs (the
// traffic decoder shows them); a sound command after it has none, nor does a command begun
// afresh over an unfinished one.
TEST(HostLink, SlaveSaysTheWrongFcsAsReceivedAndComputed) {
    CommandDecoder s;
    ASSERT_EQ(s.feed("@00MS5F*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), FcsError);
    EXPECT_EQ(s.receivedFcs(), QByteArray("5F"));
    EXPECT_EQ(s.computedFcs(), QByteArray("5E"));
    s.next();
    ASSERT_EQ(s.feed("@00MS5E*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), Normal);
    EXPECT_TRUE(s.receivedFcs().isEmpty());
    EXPECT_TRUE(s.computedFcs().isEmpty());
    s.next();
    // A first part with a wrong FCS, then a new command where its second part was due.
    EXPECT_EQ(s.feed("@00WD0000" + QByteArray(4 * 29, '0') + "00\r"), FrameStatus::NeedMore);
    EXPECT_EQ(s.receivedFcs(), QByteArray("00"));
    ASSERT_EQ(s.feed("@00MS5E*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), Normal);
    EXPECT_TRUE(s.receivedFcs().isEmpty());
}

TEST(HostLink, CommandsReachTheSpacesOfTheCpm1ProtocolMap) {
    // The driver passes the space the CPM1 map gives; every one has its command and back.
    const auto &target = model::Target::get(model::Family::Cpm1);
    const model::ProtocolMap *map = model::findProtocolMap(target, model::ProtocolId::HostLink);
    ASSERT_NE(map, nullptr);
    for (const auto &range : map->ranges) {
        const Frame read = readCommand(0, range.space, 0, 1);
        ASSERT_EQ(read.header.size(), 2) << range.area;
        ProtocolSpace back = ProtocolSpace::Coils;
        bool write = true;
        ASSERT_TRUE(spaceOfHeader(read.header, back, write)) << range.area;
        EXPECT_EQ(back, range.space) << range.area;
        EXPECT_FALSE(write);
    }
    // Not a Host Link space: no header, so nothing the PLC would take for another command.
    EXPECT_TRUE(readCommand(0, ProtocolSpace::Coils, 0, 1).header.isEmpty());
    EXPECT_TRUE(writeCommand(0, ProtocolSpace::HostLinkCompletion, 0, {1}).header.isEmpty());
}

} // namespace
} // namespace rung::comms::hostlink
