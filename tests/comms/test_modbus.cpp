#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "tests/comms/hex.h"

#include <gtest/gtest.h>

namespace rung::comms::modbus {
namespace {

using test::bytes;
using Kind = ProtocolError::Kind;

Request read(std::uint8_t function, int address, int count) {
    Request r;
    r.function = function;
    r.address = address;
    r.count = count;
    return r;
}

TEST(Modbus, Crc16MatchesTheSerialLineSpecExample) {
    // Modbus Application Protocol 6.3's request "read holding registers 108..110 of slave 17"
    // as an RTU frame: 11 03 00 6B 00 03 + CRC 76 87 (low byte first).
    EXPECT_EQ(rtuFrame(0x11, encodeRequestPdu(read(ReadHoldingRegisters, 0x6B, 3))).toHex(' '),
              bytes("11 03 00 6B 00 03 76 87").toHex(' '));
    EXPECT_EQ(crc16(bytes("01 03 00 00 00 0A")), 0xCDC5);
}

TEST(Modbus, EncodesEveryFunctionsRequestPdu) {
    EXPECT_EQ(encodeRequestPdu(read(ReadCoils, 0x13, 0x13)), bytes("01 00 13 00 13"));
    EXPECT_EQ(encodeRequestPdu(read(ReadDiscreteInputs, 0xC4, 0x16)), bytes("02 00 C4 00 16"));
    EXPECT_EQ(encodeRequestPdu(read(ReadInputRegisters, 0x08, 1)), bytes("04 00 08 00 01"));
    Request coil{WriteSingleCoil, 0xAC, 1, {}, {true}};
    EXPECT_EQ(encodeRequestPdu(coil), bytes("05 00 AC FF 00"));
    Request reg{WriteSingleRegister, 1, 1, {3}, {}};
    EXPECT_EQ(encodeRequestPdu(reg), bytes("06 00 01 00 03"));
    Request coils{WriteMultipleCoils,
                  0x13,
                  10,
                  {},
                  {true, false, true, true, false, false, true, true, true, false}};
    EXPECT_EQ(encodeRequestPdu(coils), bytes("0F 00 13 00 0A 02 CD 01"));
    Request regs{WriteMultipleRegisters, 1, 2, {0x000A, 0x0102}, {}};
    EXPECT_EQ(encodeRequestPdu(regs), bytes("10 00 01 00 02 04 00 0A 01 02"));
}

QByteArray framed(Framing framing, int transaction, int unit, const QByteArray &pdu) {
    return framing == Framing::Rtu     ? rtuFrame(unit, pdu)
           : framing == Framing::Ascii ? asciiFrame(unit, pdu)
                                       : tcpFrame(transaction, unit, pdu);
}

// Each function through both sides over RTU, ASCII and TCP, the reply fed one byte at a time.
void roundTrip(Framing framing, const Request &request, const Response &answer) {
    const int unit = 17;
    const QByteArray pdu = encodeRequestPdu(request);
    const QByteArray sent = framed(framing, 9, unit, pdu);
    RequestDecoder slave(framing);
    ASSERT_EQ(slave.feed(sent), FrameStatus::Complete);
    EXPECT_EQ(slave.unit(), unit);
    EXPECT_EQ(slave.parsed().exception, 0);
    EXPECT_EQ(slave.parsed().request.function, request.function);
    EXPECT_EQ(slave.parsed().request.address, request.address);
    EXPECT_EQ(slave.parsed().request.registers, request.registers);
    EXPECT_EQ(slave.parsed().request.bits, request.bits);
    const QByteArray replyPdu = encodeResponsePdu(answer);
    const QByteArray reply = framed(framing, slave.transaction(), unit, replyPdu);
    ReplyDecoder master(framing, unit, request, 9);
    for (qsizetype i = 0; i < reply.size(); ++i)
        master.feed(reply.sliced(i, 1));
    ASSERT_EQ(master.status(), FrameStatus::Complete) << master.error().message.toStdString();
    EXPECT_EQ(master.response().registers, answer.registers);
    EXPECT_EQ(master.response().bits, answer.bits);
}

TEST(Modbus, EveryFunctionRoundTripsOverRtuAsciiAndTcp) {
    for (auto framing : {Framing::Rtu, Framing::Ascii, Framing::Tcp}) {
        SCOPED_TRACE(framing == Framing::Rtu ? "RTU" : framing == Framing::Ascii ? "ASCII" : "TCP");
        const std::vector<bool> ten{true, false, true, true, false, false, true, true, true, false};
        roundTrip(framing, read(ReadCoils, 0, 10), {ReadCoils, 0, 0, 0, {}, ten});
        roundTrip(framing, read(ReadDiscreteInputs, 5, 10), {ReadDiscreteInputs, 0, 0, 0, {}, ten});
        roundTrip(framing, read(ReadHoldingRegisters, 0, 3),
                  {ReadHoldingRegisters, 0, 0, 0, {1, 0xFFFF, 0x1234}, {}});
        roundTrip(framing, read(ReadInputRegisters, 100, 1),
                  {ReadInputRegisters, 0, 0, 0, {7}, {}});
        roundTrip(framing, {WriteSingleCoil, 3, 1, {}, {true}},
                  {WriteSingleCoil, 0, 3, 0xFF00, {}, {}});
        roundTrip(framing, {WriteSingleRegister, 2000, 1, {0xBEEF}, {}},
                  {WriteSingleRegister, 0, 2000, 0xBEEF, {}, {}});
        roundTrip(framing, {WriteMultipleCoils, 2400, 10, {}, ten},
                  {WriteMultipleCoils, 0, 2400, 10, {}, {}});
        roundTrip(framing, {WriteMultipleRegisters, 2000, 3, {1, 2, 3}, {}},
                  {WriteMultipleRegisters, 0, 2000, 3, {}, {}});
    }
}

TEST(Modbus, EveryExceptionCodeIsADeviceErrorWithItsOwnText) {
    QSet<QString> texts;
    for (int code : {1, 2, 3, 4, 5, 6, 8, 0x0A, 0x0B}) {
        const Request request = read(ReadHoldingRegisters, 0, 1);
        ReplyDecoder d(Framing::Rtu, 1, request);
        Response refusal;
        refusal.function = ReadHoldingRegisters;
        refusal.exception = code;
        const QByteArray frame = rtuFrame(1, encodeResponsePdu(refusal));
        EXPECT_EQ(frame.size(), 5);
        EXPECT_EQ(static_cast<quint8>(frame[1]), 0x83);
        ASSERT_EQ(d.feed(frame), FrameStatus::Failed);
        EXPECT_EQ(d.error().kind, Kind::DeviceError);
        EXPECT_EQ(d.error().code, code);
        texts.insert(exceptionText(code));
    }
    EXPECT_EQ(texts.size(), 9);
}

TEST(Modbus, ABadCrcNamesBothValues) {
    Response r{ReadHoldingRegisters, 0, 0, 0, {1}, {}};
    QByteArray reply = rtuFrame(0x11, encodeResponsePdu(r)); // CRC 47B8h, low byte first
    ASSERT_EQ(reply, bytes("11 03 02 00 01 B8 47"));
    reply[reply.size() - 1] = char(reply[reply.size() - 1] ^ 0x40); // 07B8h arrives
    ReplyDecoder d(Framing::Rtu, 0x11, read(ReadHoldingRegisters, 0x6B, 1));
    ASSERT_EQ(d.feed(reply), FrameStatus::Failed);
    EXPECT_EQ(d.error().kind, Kind::BadChecksum);
    EXPECT_TRUE(d.error().retryable());
    const QString message = d.error().message;
    EXPECT_TRUE(message.contains(QLatin1String("received 07B8"))) << message.toStdString();
    EXPECT_TRUE(message.contains(QLatin1String("computed 47B8"))) << message.toStdString();
}

// MODBUS Application Protocol Specification V1.1b3, the example of each function, request
// and response PDU verbatim: 6.1 (01 Read Coils, coils 20-38), 6.2 (02 Read Discrete Inputs,
// inputs 197-218), 6.3 (03 Read Holding Registers 108-110), 6.4 (04 Read Input Register 9),
// 6.5 (05 Write Single Coil 173 ON), 6.6 (06 Write Single Register 2 = 3), 6.11 (0F Write
// Multiple Coils 20-29), 6.12 (10 Write Multiple Registers 2-3). Each request is read by the
// slave and each response decoded by the master against it, over TCP.
TEST(Modbus, TheApplicationProtocolsOwnExamplesOfEveryFunctionBothWays) {
    const auto bits = [](std::initializer_list<int> values) {
        std::vector<bool> out;
        for (int v : values)
            out.push_back(v != 0);
        return out;
    };
    struct Example {
        const char *section;
        const char *request;
        const char *response;
        Request expected;
        std::vector<std::uint16_t> registers; // read back (03, 04)
        std::vector<bool> bits;               // read back (01, 02), as many as asked for
    };
    const std::vector<Example> examples = {
        {"6.1",
         "01 00 13 00 13",
         "01 03 CD 6B 05",
         read(ReadCoils, 0x13, 19),
         {},
         // CD: outputs 27..20, 6B: 35..28, 05: 38..36 (LSB first)
         bits({1, 0, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1, 0, 1, 1, 0, 1, 0, 1})},
        {"6.2",
         "02 00 C4 00 16",
         "02 03 AC DB 35",
         read(ReadDiscreteInputs, 0xC4, 22),
         {},
         bits({0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 0, 1, 1, 0, 1, 1, 1, 0, 1, 0, 1, 1})},
        {"6.3",
         "03 00 6B 00 03",
         "03 06 02 2B 00 00 00 64",
         read(ReadHoldingRegisters, 0x6B, 3),
         {555, 0, 100},
         {}},
        {"6.4", "04 00 08 00 01", "04 02 00 0A", read(ReadInputRegisters, 0x08, 1), {10}, {}},
        {"6.5", "05 00 AC FF 00", "05 00 AC FF 00", {WriteSingleCoil, 0xAC, 1, {}, {true}}, {}, {}},
        {"6.6", "06 00 01 00 03", "06 00 01 00 03", {WriteSingleRegister, 1, 1, {3}, {}}, {}, {}},
        {"6.11",
         "0F 00 13 00 0A 02 CD 01",
         "0F 00 13 00 0A",
         {WriteMultipleCoils, 0x13, 10, {}, bits({1, 0, 1, 1, 0, 0, 1, 1, 1, 0})},
         {},
         {}},
        {"6.12",
         "10 00 01 00 02 04 00 0A 01 02",
         "10 00 01 00 02",
         {WriteMultipleRegisters, 1, 2, {0x000A, 0x0102}, {}},
         {},
         {}},
    };
    for (const auto &e : examples) {
        SCOPED_TRACE(e.section);
        const ParsedRequest parsed = parseRequestPdu(bytes(e.request));
        EXPECT_EQ(parsed.exception, 0);
        EXPECT_EQ(parsed.request.function, e.expected.function);
        EXPECT_EQ(parsed.request.address, e.expected.address);
        EXPECT_EQ(parsed.request.count, e.expected.count);
        EXPECT_EQ(parsed.request.registers, e.expected.registers);
        EXPECT_EQ(parsed.request.bits, e.expected.bits);
        EXPECT_EQ(encodeRequestPdu(e.expected), bytes(e.request));

        ReplyDecoder master(Framing::Tcp, 1, e.expected, 7);
        ASSERT_EQ(master.feed(tcpFrame(7, 1, bytes(e.response))), FrameStatus::Complete)
            << master.error().message.toStdString();
        const Response &got = master.response();
        EXPECT_EQ(got.registers, e.registers);
        EXPECT_EQ(got.bits, e.bits);
        // The slave answers with the same bytes.
        Response answer{e.expected.function, 0, got.address, got.count, got.registers, got.bits};
        EXPECT_EQ(encodeResponsePdu(answer), bytes(e.response));
    }
}

TEST(Modbus, WrongUnitWrongFunctionGarbageAndMismatchedEchoes) {
    const Request request = read(ReadHoldingRegisters, 0, 1);
    ReplyDecoder other(Framing::Rtu, 1, request);
    ASSERT_EQ(other.feed(rtuFrame(2, encodeResponsePdu({ReadHoldingRegisters, 0, 0, 0, {5}, {}}))),
              FrameStatus::Failed);
    EXPECT_EQ(other.error().kind, Kind::WrongStation);

    ReplyDecoder garbage(Framing::Rtu, 1, request);
    EXPECT_EQ(garbage.feed(bytes("01 07 00")), FrameStatus::Failed);
    EXPECT_EQ(garbage.error().kind, Kind::Garbage);

    ReplyDecoder count(Framing::Rtu, 1, read(ReadHoldingRegisters, 0, 2));
    ASSERT_EQ(count.feed(rtuFrame(1, encodeResponsePdu({ReadHoldingRegisters, 0, 0, 0, {5}, {}}))),
              FrameStatus::Failed);
    EXPECT_EQ(count.error().kind, Kind::WrongReply);

    // A write echoed with another value was not done as asked.
    const Request write{WriteSingleRegister, 10, 1, {99}, {}};
    ReplyDecoder echo(Framing::Tcp, 1, write, 4);
    ASSERT_EQ(
        echo.feed(tcpFrame(4, 1, encodeResponsePdu({WriteSingleRegister, 0, 10, 98, {}, {}}))),
        FrameStatus::Failed);
    EXPECT_EQ(echo.error().kind, Kind::WrongReply);

    ReplyDecoder transaction(Framing::Tcp, 1, write, 4);
    ASSERT_EQ(transaction.feed(
                  tcpFrame(5, 1, encodeResponsePdu({WriteSingleRegister, 0, 10, 99, {}, {}}))),
              FrameStatus::Failed);
    EXPECT_EQ(transaction.error().kind, Kind::WrongReply);

    ReplyDecoder notModbus(Framing::Tcp, 1, write, 4);
    EXPECT_EQ(notModbus.feed("HTTP/1.1 200"), FrameStatus::Failed);
    EXPECT_EQ(notModbus.error().kind, Kind::Garbage);
}

TEST(Modbus, TruncatedAndSilentRepliesSayWhatArrived) {
    ReplyDecoder d(Framing::Rtu, 1, read(ReadHoldingRegisters, 0, 2));
    EXPECT_TRUE(d.deadlinePassed(100).message.contains(QLatin1String("unit 1")));
    EXPECT_EQ(d.feed(bytes("01 03 04 00")), FrameStatus::NeedMore);
    EXPECT_TRUE(d.deadlinePassed(100).message.contains(QLatin1String("4 bytes")));
}

// Serial line V1.02, 2.5.2 and 6.2.1: the same request as ASCII, ':' then the address and PDU
// as hex digits, the LRC (the two's complement of their sum: 11h+03h+6Bh+03h = 82h -> 7Eh),
// CR LF.
TEST(Modbus, AsciiFrameAndLrcOfTheSerialLineSpecExample) {
    EXPECT_EQ(lrc(bytes("11 03 00 6B 00 03")), 0x7E);
    EXPECT_EQ(asciiFrame(0x11, encodeRequestPdu(read(ReadHoldingRegisters, 0x6B, 3))),
              QByteArray(":1103006B00037E\r\n"));
}

// A slave drops an ASCII frame with a wrong LRC (no answer, as with a wrong CRC) and noise
// before a colon, and reads the next frame.
TEST(Modbus, AsciiSlaveDropsABadLrcAndNoiseAndReadsTheNextFrame) {
    RequestDecoder s(Framing::Ascii);
    EXPECT_EQ(s.feed(QByteArray("\x7Fzz:1103006B00037F\r\n:1103006B00037E\r\n")),
              FrameStatus::Complete);
    EXPECT_EQ(s.droppedFrames(), 1);
    EXPECT_EQ(s.discarded().kind, Kind::BadChecksum);
    EXPECT_EQ(s.unit(), 0x11);
    EXPECT_EQ(s.parsed().request.address, 0x6B);
    EXPECT_EQ(s.parsed().request.count, 3);
}

// The master's side: a wrong LRC names both values; characters after CR LF are garbage; a
// colon and no CR LF within the longest frame is too.
TEST(Modbus, AsciiMasterSaysWhatIsWrongWithAReply) {
    const Request q = read(ReadHoldingRegisters, 0x6B, 1);
    ReplyDecoder bad(Framing::Ascii, 0x11, q);
    EXPECT_EQ(bad.feed(QByteArray(":1103020001E8\r\n")), FrameStatus::Failed);
    EXPECT_EQ(bad.error().kind, Kind::BadChecksum);
    EXPECT_TRUE(bad.error().message.contains(QStringLiteral("E8")))
        << bad.error().message.toStdString();
    ReplyDecoder good(Framing::Ascii, 0x11, q);
    EXPECT_EQ(good.feed(QByteArray(":1103020001E9\r\n")), FrameStatus::Complete)
        << good.error().message.toStdString();
    EXPECT_EQ(good.response().registers, (std::vector<std::uint16_t>{1}));
    ReplyDecoder extra(Framing::Ascii, 0x11, q);
    EXPECT_EQ(extra.feed(QByteArray(":1103020001E9\r\nX")), FrameStatus::Failed);
    EXPECT_EQ(extra.error().kind, Kind::Garbage);
    ReplyDecoder endless(Framing::Ascii, 0x11, q);
    endless.feed(QByteArray(":") + QByteArray(ReplyDecoder::MaxAsciiBuffered, '0'));
    EXPECT_EQ(endless.status(), FrameStatus::Failed);
    EXPECT_LE(endless.buffered(), ReplyDecoder::MaxAsciiBuffered);
}

TEST(Modbus, SlaveDropsBadCrcFramesAndReadsTheNextOne) {
    RequestDecoder s(Framing::Rtu);
    QByteArray bad = bytes("11 03 00 6B 00 03 76 88");
    EXPECT_EQ(s.feed(bad + bytes("11 03 00 6B 00 03 76 87")), FrameStatus::Complete);
    EXPECT_EQ(s.droppedFrames(), 1);
    EXPECT_EQ(s.parsed().request.address, 0x6B);
}

TEST(Modbus, SlaveEndsAnUnknownFunctionAtTheSilenceGapAndAnswersIllegalFunction) {
    RequestDecoder s(Framing::Rtu);
    const QByteArray frame = rtuFrame(1, bytes("2B 0E 01 00")); // read device identification
    EXPECT_EQ(s.feed(frame), FrameStatus::NeedMore);
    EXPECT_EQ(s.silence(), FrameStatus::Complete);
    EXPECT_EQ(s.parsed().exception, IllegalFunction);
}

TEST(Modbus, SlaveRefusesCountsBeyondTheProtocolsLimits) {
    auto exceptionOf = [](const QByteArray &pdu) {
        RequestDecoder s(Framing::Tcp);
        EXPECT_EQ(s.feed(tcpFrame(1, 1, pdu)), FrameStatus::Complete);
        return s.parsed().exception;
    };
    EXPECT_EQ(exceptionOf(encodeRequestPdu(read(ReadHoldingRegisters, 0, 126))), IllegalDataValue);
    EXPECT_EQ(exceptionOf(encodeRequestPdu(read(ReadCoils, 0, 2001))), IllegalDataValue);
    EXPECT_EQ(exceptionOf(encodeRequestPdu(read(ReadCoils, 0, 0))), IllegalDataValue);
    EXPECT_EQ(exceptionOf(bytes("05 00 01 12 34")), IllegalDataValue);
    EXPECT_EQ(exceptionOf(bytes("10 00 01 00 02 03 00 0A 01")), IllegalDataValue);
    EXPECT_EQ(exceptionOf(bytes("41 00")), IllegalFunction);
}

TEST(Modbus, SlaveTakesTcpRequestsSplitAndJoined) {
    RequestDecoder s(Framing::Tcp);
    const QByteArray a = tcpFrame(1, 1, encodeRequestPdu(read(ReadCoils, 0, 8)));
    const QByteArray b = tcpFrame(2, 1, encodeRequestPdu(read(ReadInputRegisters, 3, 2)));
    const QByteArray both = a + b;
    for (qsizetype i = 0; i < a.size() - 1; ++i)
        EXPECT_EQ(s.feed(both.sliced(i, 1)), FrameStatus::NeedMore);
    EXPECT_EQ(s.feed(both.sliced(a.size() - 1)), FrameStatus::Complete);
    EXPECT_EQ(s.transaction(), 1);
    s.next();
    ASSERT_EQ(s.status(), FrameStatus::Complete);
    EXPECT_EQ(s.transaction(), 2);
    EXPECT_EQ(s.parsed().request.function, ReadInputRegisters);
}

} // namespace
} // namespace rung::comms::modbus
