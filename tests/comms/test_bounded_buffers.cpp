// A garbled or hostile stream never grows a decoder's memory without bound (issue 12 review):
// each decoder is fed a long stream built to defeat its framing, buffered() is checked after
// every feed, the decoder says what it dropped and why, and a good frame from the manuals'
// examples is still read after the garbage.
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/comms/hex.h"

#include <gtest/gtest.h>

#include <random>

namespace rung::comms {
namespace {

using test::bytes;

constexpr int Rounds = 20000; // chunks per stream: hundreds of kilobytes in all

QByteArray noise(std::mt19937 &random, int size) {
    QByteArray out(size, '\0');
    for (char &c : out)
        c = char(random() & 0xFF);
    return out;
}

// ----- Host Link -----

TEST(BoundedBuffers, HostLinkSlaveDropsAnEndlessCommandOfPartsWithoutStar) {
    // A first part, then parts that never carry the "*" of the last one: the text would grow
    // for ever. The decoder answers 18 (frame length) once the text passes the longest legal
    // command and then waits for the next "@".
    hostlink::CommandDecoder s;
    QByteArray first = "@00WD0000";
    first += hostlink::fcs(first) + "\r";
    ASSERT_EQ(s.feed(first), FrameStatus::NeedMore);
    EXPECT_TRUE(s.takeDelimiterRequest());
    QByteArray later = QByteArray(120, '1');
    later += hostlink::fcs(later) + "\r";
    bool answered = false;
    for (int i = 0; i < Rounds && !answered; ++i) {
        s.feed(later);
        EXPECT_LE(s.buffered(), hostlink::CommandDecoder::MaxBuffered);
        answered = s.status() == FrameStatus::Complete;
    }
    ASSERT_TRUE(answered);
    EXPECT_EQ(s.endCode(), hostlink::FrameLengthError);
    EXPECT_EQ(s.discarded().code, hostlink::FrameLengthError);
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("WD")));
    EXPECT_TRUE(s.discarded().message.contains(QString::number(hostlink::MaxText)));
    // The rest of the runaway command is noise; the spec's status command is read after it.
    s.next();
    for (int i = 0; i < 100; ++i)
        s.feed(later);
    EXPECT_EQ(s.status(), FrameStatus::NeedMore);
    ASSERT_EQ(s.feed("@00MS5E*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.endCode(), 0);
    EXPECT_EQ(s.command().header, QByteArray("MS"));
}

TEST(BoundedBuffers, HostLinkSlaveDropsCharactersWithoutACr) {
    hostlink::CommandDecoder s;
    std::mt19937 random(12);
    for (int i = 0; i < Rounds; ++i) {
        QByteArray chunk = noise(random, 1 + int(random() % 64)).replace('\r', '@');
        s.feed(chunk);
        ASSERT_LE(s.buffered(), hostlink::CommandDecoder::MaxBuffered);
        if (s.status() == FrameStatus::Complete)
            s.next();
    }
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("without a CR")));
    s.feed("\r"); // ends whatever part of the noise was still open
    if (s.status() == FrameStatus::Complete)
        s.next();
    ASSERT_EQ(s.feed("@00RD0000000157*\r"), FrameStatus::Complete);
    EXPECT_EQ(s.command().header, QByteArray("RD"));
    EXPECT_EQ(s.endCode(), 0);
}

TEST(BoundedBuffers, HostLinkSlaveKeepsOneFrameWhileACommandWaitsForItsAnswer) {
    hostlink::CommandDecoder s;
    ASSERT_EQ(s.feed("@00MS5E*\r"), FrameStatus::Complete);
    for (int i = 0; i < Rounds; ++i) {
        s.feed("@00RD0000000157*\r");
        ASSERT_LE(s.buffered(), hostlink::CommandDecoder::MaxBuffered);
    }
    EXPECT_LE(s.buffered(), hostlink::MaxPartBuffer);
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("before the command was answered")));
    s.next(); // the first of the waiting commands comes out whole
    ASSERT_EQ(s.status(), FrameStatus::Complete);
    EXPECT_EQ(s.command().header, QByteArray("RD"));
}

TEST(BoundedBuffers, HostLinkMasterFailsAReplyLongerThanItsCommandAsks) {
    // RD of 2 words: 8 characters of data. A peer that sends part after part never ends.
    hostlink::ReplyDecoder d(hostlink::readCommand(0, hostlink::ProtocolSpace::HostLinkDm, 0, 2));
    QByteArray first = "@00RD00";
    first += hostlink::fcs(first) + "\r";
    d.feed(first);
    EXPECT_TRUE(d.takeDelimiterRequest());
    QByteArray later = "1234";
    later += hostlink::fcs(later) + "\r";
    int parts = 0;
    while (d.status() == FrameStatus::NeedMore && parts < Rounds) {
        d.feed(later);
        ASSERT_LE(d.buffered(), hostlink::ReplyDecoder::MaxBuffered);
        ++parts;
    }
    ASSERT_EQ(d.status(), FrameStatus::Failed);
    EXPECT_EQ(parts, 3); // 4 + 4 characters fit, the third part does not
    EXPECT_EQ(d.error().kind, ProtocolError::Kind::Malformed);
    EXPECT_TRUE(d.error().message.contains(QLatin1String("RD")));
    EXPECT_TRUE(d.error().message.contains(QLatin1String("8 characters")));

    // A read of the most words the count allows is bounded the same way.
    hostlink::ReplyDecoder big(
        hostlink::readCommand(0, hostlink::ProtocolSpace::HostLinkDm, 0, 9999));
    big.feed(first);
    QByteArray word = QByteArray(120, 'A');
    word += hostlink::fcs(word) + "\r";
    for (int i = 0; i < Rounds && big.status() == FrameStatus::NeedMore; ++i) {
        big.feed(word);
        ASSERT_LE(big.buffered(), hostlink::ReplyDecoder::MaxBuffered);
    }
    EXPECT_EQ(big.status(), FrameStatus::Failed);
}

// ----- Modbus -----

TEST(BoundedBuffers, ModbusRtuSlaveDropsAnUnknownFunctionThatNeverPauses) {
    // Function 2Bh (not served) on a line that never goes quiet: without a bound the buffer
    // would wait for silence() for ever.
    modbus::RequestDecoder s(modbus::Framing::Rtu);
    std::mt19937 random(5);
    s.feed(bytes("01 2B"));
    for (int i = 0; i < Rounds; ++i) {
        s.feed(noise(random, 1 + int(random() % 32)));
        ASSERT_LE(s.buffered(), modbus::RequestDecoder::MaxBuffered);
        ASSERT_LE(s.buffered(), modbus::MaxRtuFrame);
    }
    EXPECT_EQ(s.status(), FrameStatus::NeedMore);
    EXPECT_GE(s.droppedFrames(), 1);
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("2Bh")));
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("256")));
    // After the gap the Serial Line spec's own example request is read.
    s.silence();
    ASSERT_EQ(s.feed(bytes("11 03 00 6B 00 03 76 87")), FrameStatus::Complete);
    EXPECT_EQ(s.parsed().request.address, 0x6B);
}

TEST(BoundedBuffers, ModbusRtuSlaveDropsAByteCountNoFrameCanHold) {
    // 10h with byte count FFh announces 264 bytes, more than an RTU frame holds.
    modbus::RequestDecoder s(modbus::Framing::Rtu);
    s.feed(bytes("01 10 00 00 00 7F FF"));
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("10h")));
    EXPECT_EQ(s.buffered(), 0);
    s.feed(QByteArray(300, '\x11')); // the rest of it, before the gap
    EXPECT_EQ(s.buffered(), 0);
    s.silence();
    EXPECT_EQ(s.feed(bytes("11 03 00 6B 00 03 76 87")), FrameStatus::Complete);
}

TEST(BoundedBuffers, ModbusSlavesKeepOneFrameWhileARequestWaitsForItsAnswer) {
    for (const auto framing : {modbus::Framing::Rtu, modbus::Framing::Tcp}) {
        modbus::RequestDecoder s(framing);
        const QByteArray pdu = bytes("03 00 6B 00 03");
        const QByteArray frame = framing == modbus::Framing::Rtu ? modbus::rtuFrame(0x11, pdu)
                                                                 : modbus::tcpFrame(1, 0x11, pdu);
        ASSERT_EQ(s.feed(frame), FrameStatus::Complete);
        for (int i = 0; i < Rounds; ++i) {
            s.feed(frame);
            ASSERT_LE(s.buffered(), modbus::RequestDecoder::MaxBuffered);
        }
        EXPECT_TRUE(
            s.discarded().message.contains(QLatin1String("before the request was answered")));
        s.next();
        ASSERT_EQ(s.status(), FrameStatus::Complete);
        EXPECT_EQ(s.parsed().request.address, 0x6B);
    }
}

TEST(BoundedBuffers, ModbusTcpSlaveDropsWhatIsNotModbus) {
    modbus::RequestDecoder s(modbus::Framing::Tcp);
    for (int i = 0; i < Rounds; ++i) {
        s.feed("GET / HTTP/1.1\r\nHost: plc\r\n\r\n");
        ASSERT_LE(s.buffered(), modbus::RequestDecoder::MaxBuffered);
    }
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("not a Modbus header")));
    ASSERT_EQ(s.feed(modbus::tcpFrame(9, 1, bytes("03 00 6B 00 03"))), FrameStatus::Complete);
    EXPECT_EQ(s.transaction(), 9);
}

TEST(BoundedBuffers, ModbusMasterHoldsAtMostOneReplyAndAByte) {
    modbus::Request r;
    r.function = modbus::ReadHoldingRegisters;
    r.count = 3;
    modbus::ReplyDecoder d(modbus::Framing::Rtu, 0x11, r);
    ASSERT_EQ(d.feed(bytes("11 03 FF") + QByteArray(100000, '\0')), FrameStatus::Failed);
    EXPECT_LE(d.buffered(), modbus::ReplyDecoder::MaxBuffered);
    EXPECT_TRUE(d.error().message.contains(QLatin1String("bytes more than")));
}

// ----- Vigor -----

TEST(BoundedBuffers, VigorSlaveDropsAFrameThatNeverReachesEtx) {
    vigor::RequestDecoder s;
    std::mt19937 random(3);
    for (int i = 0; i < Rounds; ++i) {
        // STX now and then, ETX never: each candidate frame must be let go.
        QByteArray chunk = noise(random, 1 + int(random() % 64)).replace(vigor::Etx, '0');
        s.feed(chunk);
        ASSERT_LE(s.buffered(), vigor::RequestDecoder::MaxBuffered);
        ASSERT_LE(s.buffered(), vigor::MaxRequestFrame);
    }
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("without ETX")));
    // A new STX starts over (it cannot stand inside a frame). The first 51H example of the
    // Vigor M/VB/VH communication manual, B-5-3: read M8..M23.
    ASSERT_EQ(s.feed(bytes("02 30 30 35 31 30 30 38 31 30 32 03 46 34")), FrameStatus::Complete);
    EXPECT_EQ(s.errorCode(), 0);
    EXPECT_EQ(s.request().address, 0x81);
}

TEST(BoundedBuffers, VigorSlaveKeepsOneFrameWhileARequestWaitsForItsAnswer) {
    vigor::RequestDecoder s;
    const QByteArray request = bytes("02 30 30 37 30 30 34 30 41 03 39 46"); // M10 ON
    ASSERT_EQ(s.feed(request), FrameStatus::Complete);
    for (int i = 0; i < Rounds; ++i) {
        s.feed(request);
        ASSERT_LE(s.buffered(), vigor::RequestDecoder::MaxBuffered);
    }
    EXPECT_TRUE(s.discarded().message.contains(QLatin1String("before the request was answered")));
    s.next();
    ASSERT_EQ(s.status(), FrameStatus::Complete);
    EXPECT_EQ(s.request().command, vigor::Command::BitOn);
}

TEST(BoundedBuffers, VigorMasterFailsAtTheLongestReply) {
    vigor::Request r{0, vigor::Command::Read, 0x81, 2, {}};
    vigor::ReplyDecoder d(r);
    QByteArray endless(1, vigor::Ack);
    endless += QByteArray(100000, '0');
    ASSERT_EQ(d.feed(endless), FrameStatus::Failed);
    EXPECT_EQ(d.buffered(), vigor::MaxReplyFrame);
    EXPECT_TRUE(d.error().message.contains(QLatin1String("ETX")));
}

} // namespace
} // namespace rung::comms
