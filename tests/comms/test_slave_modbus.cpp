// The Modbus slave over the Vigor CP2 map (Vigor M/VB/VH communication manual, B-3-6) and the
// PL110 map (PL110 manual, chapter 3): what each function reads and writes, the exceptions,
// broadcast and units.

#include "comms/slave/modbus_responder.h"
#include "tests/comms/slave_fixture.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

namespace rung::comms::slave {
// Named, so that the using-directive stays in this file when the test files are compiled
// together (tests/CMakeLists.txt).
namespace modbus_slave {
namespace {

using namespace modbus;
using test::Image;

using rung::testing::target;

struct ModbusSlave {
    const model::Target &t;
    Image plc;
    ModbusResponder slave;
    Framing framing;
    int transaction = 0;

    explicit ModbusSlave(model::Family family, Framing framing = Framing::Rtu, int station = 1)
        : t(target(family))
        , plc(t)
        , slave(t, *model::findProtocolMap(t, model::ProtocolId::Modbus), station, plc.image,
                framing)
        , framing(framing) {}

    QByteArray frame(int unit, const Request &r) {
        return framing == Framing::Rtu ? rtuFrame(unit, encodeRequestPdu(r))
                                       : tcpFrame(++transaction, unit, encodeRequestPdu(r));
    }
    // The decoded reply of unit `unit` to r; status NeedMore when nothing came back.
    ReplyDecoder ask(const Request &r, int unit = 1) {
        ReplyDecoder d(framing, unit, r, transaction + 1);
        const QByteArrayList out = slave.feed(frame(unit, r));
        EXPECT_LE(out.size(), 1);
        if (!out.isEmpty())
            d.feed(out.front());
        return d;
    }
    std::vector<std::uint16_t> registers(int address, int count, int unit = 1) {
        ReplyDecoder d = ask({ReadHoldingRegisters, address, count, {}, {}}, unit);
        EXPECT_EQ(d.status(), FrameStatus::Complete) << d.error().message.toStdString();
        return d.response().registers;
    }
    std::vector<bool> coils(int address, int count, std::uint8_t function = ReadCoils) {
        ReplyDecoder d = ask({function, address, count, {}, {}});
        EXPECT_EQ(d.status(), FrameStatus::Complete) << d.error().message.toStdString();
        return d.response().bits;
    }
    int exceptionOf(const Request &r, int unit = 1) {
        ReplyDecoder d = ask(r, unit);
        return d.error().kind == ProtocolError::Kind::DeviceError ? d.error().code : -1;
    }
};

TEST(ModbusSlave, VigorCp2MapHoldingRegistersAreDAndCoilsAreY) {
    ModbusSlave f(model::Family::Vigor);
    f.plc.set("D0", 1234);
    f.plc.set("D1", -2);
    f.plc.set("D8191", 7);
    f.plc.set("T0", 55);
    f.plc.set("C200", 0x00012345); // two registers, low word first
    f.plc.set("D9000", 9);
    f.plc.set("Y0", 1);
    f.plc.set("Y10", 1); // octal: coil 8
    f.plc.set("M0", 1);  // coil 512
    f.plc.set("X7", 1);  // input 7
    EXPECT_EQ(f.registers(0, 2), (std::vector<std::uint16_t>{1234, 0xFFFE}));
    EXPECT_EQ(f.registers(8191, 1), (std::vector<std::uint16_t>{7}));
    EXPECT_EQ(f.registers(8192, 1), (std::vector<std::uint16_t>{55}));
    EXPECT_EQ(f.registers(8648, 2), (std::vector<std::uint16_t>{0x2345, 0x0001}));
    EXPECT_EQ(f.registers(8760, 1), (std::vector<std::uint16_t>{9}));
    const auto y = f.coils(0, 9);
    EXPECT_TRUE(y[0]);
    EXPECT_FALSE(y[1]);
    EXPECT_TRUE(y[8]);
    EXPECT_TRUE(f.coils(512, 1)[0]);
    EXPECT_TRUE(f.coils(7, 1, ReadDiscreteInputs)[0]);
    EXPECT_FALSE(f.coils(6, 1, ReadDiscreteInputs)[0]);
}

TEST(ModbusSlave, WritesOfEveryFunctionReachTheImage) {
    ModbusSlave f(model::Family::Vigor);
    EXPECT_EQ(f.ask({WriteSingleRegister, 100, 1, {0xBEEF}, {}}).status(), FrameStatus::Complete);
    EXPECT_EQ(f.plc.value("D100") & 0xFFFF, 0xBEEF);
    EXPECT_EQ(f.ask({WriteMultipleRegisters, 8648, 2, {0x5678, 0x0002}, {}}).status(),
              FrameStatus::Complete);
    EXPECT_EQ(f.plc.value("C200"), 0x00025678);
    EXPECT_EQ(f.ask({WriteSingleCoil, 512 + 10, 1, {}, {true}}).status(), FrameStatus::Complete);
    EXPECT_TRUE(f.plc.bit("M10"));
    EXPECT_EQ(f.ask({WriteMultipleCoils, 0, 3, {}, {true, false, true}}).status(),
              FrameStatus::Complete);
    EXPECT_TRUE(f.plc.bit("Y0"));
    EXPECT_FALSE(f.plc.bit("Y1"));
    EXPECT_TRUE(f.plc.bit("Y2"));
    EXPECT_EQ(f.slave.statistics().writes, 4u);
}

TEST(ModbusSlave, ExceptionsOfTheVigorMap) {
    ModbusSlave f(model::Family::Vigor);
    // Past D9255 (register 9015) there is nothing: 02, also for a read that runs into it.
    EXPECT_EQ(f.exceptionOf({ReadHoldingRegisters, 9016, 1, {}, {}}), IllegalDataAddress);
    EXPECT_EQ(f.exceptionOf({ReadHoldingRegisters, 9010, 10, {}, {}}), IllegalDataAddress);
    EXPECT_EQ(f.exceptionOf({WriteSingleRegister, 60000, 1, {1}, {}}), IllegalDataAddress);
    // The CP2 map has no input registers.
    EXPECT_EQ(f.exceptionOf({ReadInputRegisters, 0, 1, {}, {}}), IllegalDataAddress);
    // More than the protocol allows: 126 registers.
    EXPECT_EQ(f.exceptionOf({ReadHoldingRegisters, 0, 126, {}, {}}), IllegalDataValue);
}

TEST(ModbusSlave, AnUnknownFunctionEndsAtTheSilenceAndGetsException01) {
    ModbusSlave f(model::Family::Vigor);
    EXPECT_TRUE(f.slave.feed(rtuFrame(1, QByteArray("\x2B\x0E\x01\x00", 4))).isEmpty());
    const QByteArrayList out = f.slave.silence();
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), rtuFrame(1, QByteArray("\xAB\x01", 2)));
}

TEST(ModbusSlave, Pl110ThirtyWordsAndItsOwnIllegalValueCode) {
    ModbusSlave f(model::Family::Pl110);
    EXPECT_EQ(f.registers(2000, 30).size(), 30u);
    // PL110 manual 3.1: at most 30 words, and ILLEGAL DATA VALUE is 04 there.
    EXPECT_EQ(f.exceptionOf({ReadHoldingRegisters, 2000, 31, {}, {}}), 0x04);
    EXPECT_EQ(
        f.exceptionOf({WriteMultipleRegisters, 2000, 31, std::vector<std::uint16_t>(31, 1), {}}),
        0x04);
    // Bits are not limited to 30.
    EXPECT_EQ(f.coils(2400, 256).size(), 256u);
}

TEST(ModbusSlave, Pl110WordsPackBitsAndReadOnlyRangesRefuseWrites) {
    ModbusSlave f(model::Family::Pl110);
    f.plc.set("I1", 1);
    f.plc.set("I16", 1);
    f.plc.set("Q3", 1);
    EXPECT_EQ(f.registers(100, 1), (std::vector<std::uint16_t>{0x8001}));
    // Register 150 = Q1..Q16: writable, bit by bit.
    EXPECT_EQ(f.registers(150, 1), (std::vector<std::uint16_t>{0x0004}));
    EXPECT_EQ(f.ask({WriteSingleRegister, 150, 1, {0x0011}, {}}).status(), FrameStatus::Complete);
    EXPECT_TRUE(f.plc.bit("Q1"));
    EXPECT_FALSE(f.plc.bit("Q3"));
    EXPECT_TRUE(f.plc.bit("Q5"));
    // Inputs as words, timer bits, analog inputs: R only (02); inputs as bits: R/W.
    EXPECT_EQ(f.exceptionOf({WriteSingleRegister, 100, 1, {1}, {}}), IllegalDataAddress);
    EXPECT_EQ(f.exceptionOf({WriteSingleCoil, 4800, 1, {}, {true}}), IllegalDataAddress);
    EXPECT_EQ(f.exceptionOf({WriteSingleRegister, 19000, 1, {1}, {}}), IllegalDataAddress);
    EXPECT_EQ(f.ask({WriteSingleCoil, 1601, 1, {}, {true}}).status(), FrameStatus::Complete);
    EXPECT_TRUE(f.plc.bit("I2"));
    // 02 reads the coils' table, 04 the registers' (inputsShareSpaces).
    EXPECT_TRUE(f.coils(1600, 1, ReadDiscreteInputs)[0]);
    ReplyDecoder d = f.ask({ReadInputRegisters, 150, 1, {}, {}});
    ASSERT_EQ(d.status(), FrameStatus::Complete);
    EXPECT_EQ(d.response().registers, (std::vector<std::uint16_t>{0x0011}));
}

TEST(ModbusSlave, Pl110IdentityRegistersAndRunBit) {
    ModbusSlave f(model::Family::Pl110, Framing::Rtu, 7);
    EXPECT_EQ(f.registers(5, 1, 7), (std::vector<std::uint16_t>{7})); // protocol address
    EXPECT_EQ(f.registers(0, 2, 7).size(), 2u);
    EXPECT_EQ(f.exceptionOf({WriteSingleRegister, 0, 1, {1}, {}}, 7), IllegalDataAddress);
    // SM0 bit 0 is RUN: it reads the mode, and writing it stops and starts the PLC.
    EXPECT_TRUE(f.registers(1000, 1, 7)[0] & 1);
    EXPECT_EQ(f.ask({WriteSingleCoil, 16000, 1, {}, {false}}, 7).status(), FrameStatus::Complete);
    EXPECT_EQ(f.plc.image->mode(), OperatingMode::Program);
    EXPECT_FALSE(f.registers(1000, 1, 7)[0] & 1);
    EXPECT_EQ(f.ask({WriteSingleRegister, 1000, 1, {0x0001}, {}}, 7).status(),
              FrameStatus::Complete);
    EXPECT_EQ(f.plc.image->mode(), OperatingMode::Run);
}

TEST(ModbusSlave, BroadcastWritesAreDoneAndNeverAnswered) {
    ModbusSlave f(model::Family::Pl110);
    Request w{WriteSingleRegister, 2000, 1, {42}, {}};
    EXPECT_TRUE(f.slave.feed(f.frame(0, w)).isEmpty());
    EXPECT_EQ(f.plc.value("V0"), 42);
    // A broadcast read, or a broadcast that would fail, gets no answer either.
    EXPECT_TRUE(f.slave.feed(f.frame(0, {ReadHoldingRegisters, 2000, 1, {}, {}})).isEmpty());
    EXPECT_TRUE(f.slave.feed(f.frame(0, {WriteSingleRegister, 100, 1, {1}, {}})).isEmpty());
}

TEST(ModbusSlave, OtherUnitsAreIgnoredAndFFhIsAnsweredByThePl110) {
    ModbusSlave f(model::Family::Pl110, Framing::Rtu, 3);
    EXPECT_TRUE(f.slave.feed(f.frame(4, {ReadHoldingRegisters, 2000, 1, {}, {}})).isEmpty());
    EXPECT_EQ(f.slave.statistics().ignored, 1u);
    EXPECT_EQ(f.ask({ReadHoldingRegisters, 2000, 1, {}, {}}, 0xFF).status(), FrameStatus::Complete);
    ModbusSlave v(model::Family::Vigor, Framing::Rtu, 3); // the CP2 has no such address
    EXPECT_TRUE(v.slave.feed(v.frame(0xFF, {ReadHoldingRegisters, 0, 1, {}, {}})).isEmpty());
}

TEST(ModbusSlave, ABadCrcIsDroppedUnansweredAndTheNextFrameIsServed) {
    ModbusSlave f(model::Family::Vigor);
    QByteArray bad = f.frame(1, {ReadHoldingRegisters, 0, 1, {}, {}});
    bad[bad.size() - 1] = char(bad.back() ^ 0x01);
    EXPECT_TRUE(f.slave.feed(bad).isEmpty());
    EXPECT_EQ(f.slave.statistics().dropped, 1u);
    EXPECT_EQ(f.registers(0, 1).size(), 1u);
}

TEST(ModbusSlave, TcpEchoesTheTransactionAndTakesUnits0AndFF) {
    ModbusSlave f(model::Family::Vigor, Framing::Tcp, 1);
    f.plc.set("D3", 33);
    for (int unit : {1, 0, 0xFF}) {
        ReplyDecoder d = f.ask({ReadHoldingRegisters, 3, 1, {}, {}}, unit);
        ASSERT_EQ(d.status(), FrameStatus::Complete) << unit;
        EXPECT_EQ(d.response().registers, (std::vector<std::uint16_t>{33}));
    }
    EXPECT_TRUE(f.slave.feed(f.frame(2, {ReadHoldingRegisters, 3, 1, {}, {}})).isEmpty());
}

} // namespace
} // namespace modbus_slave
} // namespace rung::comms::slave
