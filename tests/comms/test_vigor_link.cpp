#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/comms/hex.h"

#include <gtest/gtest.h>

namespace rung::comms::vigor {
namespace {

using test::bytes;
using Kind = ProtocolError::Kind;

// Feeds a reply one byte at a time, as a slow line delivers it.
ReplyDecoder decodeBytewise(const Request &request, const QByteArray &reply) {
    ReplyDecoder d(request);
    for (qsizetype i = 0; i < reply.size(); ++i) {
        const auto s = d.feed(reply.sliced(i, 1));
        EXPECT_TRUE(i + 1 == reply.size() || s == FrameStatus::NeedMore) << "at byte " << i;
    }
    return d;
}

struct Vector {
    const char *name;
    Request request;
    const char *requestBytes;
    const char *replyBytes;
    QByteArray replyData;
};

// Vigor M/VB/VH communication manual, B-5-3: the six examples of commands 51h, 61h, 70h and
// 71h, byte for byte.
std::vector<Vector> vectors() {
    return {
        {"read M8..M23",
         {0, Command::Read, 0x0081, 2, {}},
         "02 30 30 35 31 30 30 38 31 30 32 03 46 34",
         "06 30 30 35 31 30 30 41 37 39 33 03 30 44",
         bytes("A7 93")},
        {"read D1 D2",
         {0, Command::Read, 0x1C02, 4, {}},
         "02 30 30 35 31 31 43 30 32 30 34 03 30 33",
         "06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44",
         bytes("34 12 CD AB")},
        {"write Y30..Y47",
         {0, Command::Write, 0x0043, 2, bytes("C6 3E")},
         "02 30 30 36 31 30 30 34 33 30 32 43 36 33 45 03 45 34",
         "06 30 30 36 31 30 30 03 32 41",
         {}},
        {"write D1",
         {0, Command::Write, 0x1C02, 2, bytes("25 A3")},
         "02 30 30 36 31 31 43 30 32 30 32 32 35 41 33 03 44 44",
         "06 30 30 36 31 30 30 03 32 41",
         {}},
        {"M10 ON",
         {0, Command::BitOn, 0x040A, 0, {}},
         "02 30 30 37 30 30 34 30 41 03 39 46",
         "06 30 30 37 30 30 30 03 32 41",
         {}},
        {"M100 OFF",
         {0, Command::BitOff, 0x0464, 0, {}},
         "02 30 30 37 31 30 34 36 34 03 39 39",
         "06 30 30 37 31 30 30 03 32 42",
         {}},
    };
}

TEST(VigorLink, EncodesEveryRequestOfTheSpecByteForByte) {
    for (const auto &v : vectors())
        EXPECT_EQ(encodeRequest(v.request).toHex(' '), bytes(v.requestBytes).toHex(' ')) << v.name;
}

TEST(VigorLink, DecodesEveryReplyOfTheSpecSplitIntoSingleBytes) {
    for (const auto &v : vectors()) {
        const auto d = decodeBytewise(v.request, bytes(v.replyBytes));
        ASSERT_EQ(d.status(), FrameStatus::Complete)
            << v.name << ": " << d.error().message.toStdString();
        EXPECT_EQ(d.reply().data, v.replyData) << v.name;
        EXPECT_EQ(d.reply().command, v.request.command);
    }
}

TEST(VigorLink, SlaveParsesEveryRequestAndEncodesEveryReplyOfTheSpec) {
    for (const auto &v : vectors()) {
        RequestDecoder slave;
        ASSERT_EQ(slave.feed(bytes(v.requestBytes)), FrameStatus::Complete) << v.name;
        EXPECT_EQ(slave.errorCode(), 0) << v.name;
        EXPECT_EQ(slave.request().command, v.request.command);
        EXPECT_EQ(slave.request().address, v.request.address);
        EXPECT_EQ(slave.request().data, v.request.data);
        const Reply reply{0, v.request.command, 0, v.replyData};
        EXPECT_EQ(encodeReply(reply).toHex(' '), bytes(v.replyBytes).toHex(' ')) << v.name;
    }
}

TEST(VigorLink, BitAddressIsByteShiftedThreeOrBit) {
    // Vigor M/VB/VH communication manual, B-5-3: S20 -> byte 0302h bit 4 -> 1814h; M10 ->
    // 0081h bit 2 -> 040Ah.
    EXPECT_EQ(bitAddress(0x0302, 4), 0x1814);
    EXPECT_EQ(bitAddress(0x0081, 2), 0x040A);
}

TEST(VigorLink, RoundTripsAFullReadOf128BytesOnAnotherStation) {
    QByteArray data;
    for (int i = 0; i < MaxBytes; ++i)
        data += char(i * 7);
    const Request request{37, Command::Read, 0x1C00, MaxBytes, {}};
    RequestDecoder slave;
    ASSERT_EQ(slave.feed(encodeRequest(request)), FrameStatus::Complete);
    EXPECT_EQ(slave.request().station, 37);
    EXPECT_EQ(slave.request().length, MaxBytes);
    ReplyDecoder master(request);
    ASSERT_EQ(master.feed(encodeReply({37, Command::Read, 0, data})), FrameStatus::Complete);
    EXPECT_EQ(master.reply().data, data);
}

TEST(VigorLink, EveryErrorCodeIsADeviceErrorWithItsOwnText) {
    const Request request{0, Command::Write, 0x1C02, 2, bytes("25 A3")};
    QSet<QString> texts;
    for (int code : {0x10, 0x11, 0x12, 0x14, 0x28}) {
        ReplyDecoder d(request);
        ASSERT_EQ(d.feed(encodeReply({0, Command::Write, code, {}})), FrameStatus::Failed);
        EXPECT_EQ(d.error().kind, Kind::DeviceError);
        EXPECT_EQ(d.error().code, code);
        EXPECT_FALSE(d.error().retryable());
        texts.insert(errorText(code));
    }
    EXPECT_EQ(texts.size(), 5);
    EXPECT_TRUE(errorText(0x28).contains(QStringLiteral("28h")));
    EXPECT_TRUE(errorText(0x14).contains(QStringLiteral("STOP")));
}

TEST(VigorLink, ABadSumIsReportedWithBothSums) {
    QByteArray reply = bytes("06 30 30 37 30 30 30 03 32 41");
    reply[reply.size() - 1] = 'B';
    ReplyDecoder d({0, Command::BitOn, 0x040A, 0, {}});
    ASSERT_EQ(d.feed(reply), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::BadChecksum);
    EXPECT_TRUE(d.error().retryable());
    EXPECT_TRUE(d.error().message.contains(QStringLiteral("2B")));
    EXPECT_TRUE(d.error().message.contains(QStringLiteral("2A")));
}

TEST(VigorLink, GarbageBeforeTheAckFailsAtOnce) {
    ReplyDecoder d({0, Command::BitOn, 0x040A, 0, {}});
    EXPECT_EQ(d.feed("\xFF\x06"), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::Garbage);
    EXPECT_TRUE(d.error().message.contains(QStringLiteral("FF")));
}

TEST(VigorLink, LowerCaseOrNonHexPayloadIsGarbage) {
    // A frame whose sum is right but whose data is not upper-case hex.
    QByteArray body = "0051"
                      "00"
                      "a7"
                      "93";
    body += Etx;
    QByteArray reply(1, Ack);
    reply += body + sum(body);
    ReplyDecoder d({0, Command::Read, 0x0081, 2, {}});
    ASSERT_EQ(d.feed(reply), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::Garbage);
}

TEST(VigorLink, AnAnswerFromAnotherStationIsWrongStation) {
    ReplyDecoder d({5, Command::BitOn, 0x040A, 0, {}});
    ASSERT_EQ(d.feed(encodeReply({6, Command::BitOn, 0, {}})), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::WrongStation);
    // Both stations, each in its place: the one that answered, the one that was asked.
    EXPECT_EQ(d.error().message,
              QStringLiteral("Vigor link: station 6 answered, station 5 was asked"));
}

TEST(VigorLink, AReplyToAnotherCommandOrWithTheWrongLengthIsRefused) {
    ReplyDecoder other({0, Command::BitOn, 0x040A, 0, {}});
    ASSERT_EQ(other.feed(encodeReply({0, Command::BitOff, 0, {}})), FrameStatus::Failed);
    EXPECT_EQ(other.error().kind, Kind::WrongReply);
    ReplyDecoder shortRead({0, Command::Read, 0x0081, 2, {}});
    ASSERT_EQ(shortRead.feed(encodeReply({0, Command::Read, 0, bytes("A7")})), FrameStatus::Failed);
    EXPECT_EQ(shortRead.error().kind, Kind::Malformed);
}

TEST(VigorLink, ATruncatedReplyAndSilenceNameWhatArrived) {
    const Request request{3, Command::Read, 0x0081, 2, {}};
    ReplyDecoder silent(request);
    EXPECT_TRUE(silent.deadlinePassed(250).message.contains(QLatin1String("250 ms")));
    EXPECT_TRUE(silent.deadlinePassed(250).message.contains(QLatin1String("station 3")));
    ReplyDecoder cut(request);
    const QByteArray whole = encodeReply({3, Command::Read, 0, bytes("A7 93")});
    EXPECT_EQ(cut.feed(whole.first(6)), FrameStatus::NeedMore);
    const auto e = cut.deadlinePassed(250);
    EXPECT_EQ(e.kind, Kind::Truncated);
    EXPECT_TRUE(e.message.contains(QLatin1String("6 bytes")));
}

TEST(VigorLink, AReplyThatNeverEndsIsGarbageNotAnEndlessBuffer) {
    ReplyDecoder d({0, Command::Read, 0x0081, 2, {}});
    QByteArray endless(1, Ack);
    endless += QByteArray(400, '0');
    EXPECT_EQ(d.feed(endless), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::Garbage);
}

TEST(VigorLink, SlaveAnswersCodesForBadSumBadHexUnknownCommandAndOverlongReads) {
    auto codeOf = [](const QByteArray &frame) {
        RequestDecoder s;
        EXPECT_EQ(s.feed(frame), FrameStatus::Complete);
        return s.errorCode();
    };
    QByteArray badSum = bytes("02 30 30 37 30 30 34 30 41 03 39 46");
    badSum[badSum.size() - 1] = 'E';
    EXPECT_EQ(codeOf(badSum), 0x11);
    auto frame = [](QByteArray body) {
        body += Etx;
        return QByteArray(1, Stx) + body + sum(body);
    };
    EXPECT_EQ(codeOf(frame("0070040g")), 0x10);
    EXPECT_EQ(codeOf(frame("00520081")), 0x12);
    EXPECT_EQ(codeOf(frame("0051008181")), 0x28); // 129 bytes: more than 128
    EXPECT_EQ(codeOf(frame("0051008100")), 0x28);
    EXPECT_EQ(codeOf(frame("00610081020A")), 0x10); // says 2 bytes, carries 1
}

TEST(VigorLink, SlaveSkipsNoiseAndTakesTwoRequestsFromOneRead) {
    RequestDecoder s;
    const QByteArray a = bytes("02 30 30 37 30 30 34 30 41 03 39 46");
    const QByteArray b = bytes("02 30 30 37 31 30 34 36 34 03 39 39");
    ASSERT_EQ(s.feed(QByteArray("\x00\xFFzz", 4) + a + b.first(4)), FrameStatus::Complete);
    EXPECT_EQ(s.request().command, Command::BitOn);
    s.next();
    EXPECT_EQ(s.status(), FrameStatus::NeedMore);
    ASSERT_EQ(s.feed(b.sliced(4)), FrameStatus::Complete);
    EXPECT_EQ(s.request().command, Command::BitOff);
    EXPECT_EQ(s.request().address, 0x0464);
}

} // namespace
} // namespace rung::comms::vigor
