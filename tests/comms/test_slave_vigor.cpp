// The Vigor Computer Link slave (Vigor M/VB/VH communication manual, B-5): the manual's
// examples (B-5-3) from the PLC's side, byte for byte, and the error codes it answers with.

#include "comms/protocol/vigor_link_master.h"
#include "comms/slave/memory_image.h"
#include "comms/slave/vigor_responder.h"
#include "tests/comms/hex.h"
#include "tests/comms/slave_fixture.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

namespace rung::comms::slave {
namespace {

using test::bytes;
using test::Image;

using rung::testing::vigor;

struct VigorSlave {
    Image plc{vigor()};
    VigorResponder slave{vigor(), *model::findProtocolMap(vigor(), model::ProtocolId::VigorLink), 0,
                         plc.image};

    QByteArray ask(const QByteArray &request) {
        const QByteArrayList out = slave.feed(request);
        EXPECT_LE(out.size(), 1);
        return out.value(0);
    }
};

TEST(VigorSlave, Vector1ReadM8ToM23) {
    VigorSlave f;
    // M8..M15 = A7h, M16..M23 = 93h (bit 0 = the lowest device number).
    for (int i = 0; i < 8; ++i) {
        f.plc.set(qPrintable(QStringLiteral("M%1").arg(8 + i)), (0xA7 >> i) & 1);
        f.plc.set(qPrintable(QStringLiteral("M%1").arg(16 + i)), (0x93 >> i) & 1);
    }
    EXPECT_EQ(f.ask(bytes("02 30 30 35 31 30 30 38 31 30 32 03 46 34")),
              bytes("06 30 30 35 31 30 30 41 37 39 33 03 30 44"));
}

TEST(VigorSlave, Vector2ReadD1D2LowByteFirst) {
    VigorSlave f;
    f.plc.set("D1", 0x1234);
    f.plc.set("D2", 0xABCD);
    EXPECT_EQ(f.ask(bytes("02 30 30 35 31 31 43 30 32 30 34 03 30 33")),
              bytes("06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44"));
}

TEST(VigorSlave, Vector3WriteY30ToY47) {
    VigorSlave f;
    EXPECT_EQ(f.ask(bytes("02 30 30 36 31 30 30 34 33 30 32 43 36 33 45 03 45 34")),
              bytes("06 30 30 36 31 30 30 03 32 41"));
    // C6h on Y30..Y37 (octal), 3Eh on Y40..Y47.
    const char *on[] = {"Y31", "Y32", "Y36", "Y37", "Y41", "Y42", "Y43", "Y44", "Y45"};
    const char *off[] = {"Y30", "Y33", "Y34", "Y35", "Y40", "Y46", "Y47"};
    for (const char *d : on)
        EXPECT_TRUE(f.plc.bit(d)) << d;
    for (const char *d : off)
        EXPECT_FALSE(f.plc.bit(d)) << d;
}

TEST(VigorSlave, Vector4WriteD1) {
    VigorSlave f;
    EXPECT_EQ(f.ask(bytes("02 30 30 36 31 31 43 30 32 30 32 32 35 41 33 03 44 44")),
              bytes("06 30 30 36 31 30 30 03 32 41"));
    EXPECT_EQ(f.plc.value("D1") & 0xFFFF, 0xA325);
}

TEST(VigorSlave, Vectors5And6BitOnAndOff) {
    VigorSlave f;
    f.plc.set("M100", 1);
    EXPECT_EQ(f.ask(bytes("02 30 30 37 30 30 34 30 41 03 39 46")),
              bytes("06 30 30 37 30 30 30 03 32 41"));
    EXPECT_TRUE(f.plc.bit("M10"));
    EXPECT_EQ(f.ask(bytes("02 30 30 37 31 30 34 36 34 03 39 39")),
              bytes("06 30 30 37 31 30 30 03 32 42"));
    EXPECT_FALSE(f.plc.bit("M100"));
    EXPECT_EQ(f.slave.statistics().writes, 2u);
}

TEST(VigorSlave, ARequestInPiecesAndNoiseBeforeItIsAnsweredOnce) {
    VigorSlave f;
    f.plc.set("D1", 0x1234);
    f.plc.set("D2", 0xABCD);
    const QByteArray request = bytes("02 30 30 35 31 31 43 30 32 30 34 03 30 33");
    QByteArrayList out = f.slave.feed(QByteArray("\xFF\x00zz", 4));
    for (qsizetype i = 0; i < request.size(); ++i)
        out += f.slave.feed(request.sliced(i, 1));
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front(), bytes("06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44"));
}

TEST(VigorSlave, AnotherStationsRequestIsNotAnswered) {
    VigorSlave f;
    vigor::Request r{5, vigor::Command::Read, 0x1C02, 4, {}};
    EXPECT_TRUE(f.slave.feed(vigor::encodeRequest(r)).isEmpty());
    EXPECT_EQ(f.slave.statistics().ignored, 1u);
    // Nor a broken one for another station: its sum error is not ours to report.
    QByteArray broken = vigor::encodeRequest(r);
    broken[broken.size() - 1] = broken.back() == '0' ? '1' : '0';
    EXPECT_TRUE(f.slave.feed(broken).isEmpty());
}

// The reply's error code for a request to this station.
int errorOf(VigorSlave &f, const QByteArray &request) {
    const QByteArray reply = f.ask(request);
    if (reply.size() < 7)
        return -1;
    return reply.mid(5, 2).toInt(nullptr, 16);
}

TEST(VigorSlave, ErrorCodesOfB5) {
    VigorSlave f;
    // 11h: the sum does not match.
    QByteArray badSum = bytes("02 30 30 35 31 31 43 30 32 30 34 03 30 33");
    badSum[badSum.size() - 1] = '4';
    EXPECT_EQ(errorOf(f, badSum), 0x11);
    // 10h: a character that is not hexadecimal, with a correct sum.
    QByteArray body("00511C0G04\x03");
    EXPECT_EQ(errorOf(f, "\x02" + body + vigor::sum(body)), 0x10);
    // 12h: no such command.
    body = QByteArray("00521C0204\x03");
    EXPECT_EQ(errorOf(f, "\x02" + body + vigor::sum(body)), 0x12);
    // 28h: more than 128 bytes, an address past the map, a read that runs off its end.
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Read, 0x1C00, 129, {}})), 0x28);
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Read, 0x6000, 2, {}})), 0x28);
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Read, 0x5BFE, 4, {}})), 0x28);
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Write, 0x0400, 1, "\x01"})),
              0x28);
    EXPECT_EQ(f.slave.statistics().refused, 7u);
    EXPECT_EQ(f.slave.statistics().answered, 0u);
}

TEST(VigorSlave, BitCommandsActOnBitDevicesOnly) {
    VigorSlave f;
    // S20: byte 0302h, bit 4 -> 1814h (Vigor M/VB/VH communication manual, B-5-3).
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::BitOn, 0x1814, 0, {}})), 0);
    EXPECT_TRUE(f.plc.bit("S20"));
    // T0's contact (0380h) is no X, Y, M or S: 28h, and nothing changes.
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::BitOn, 0x0380 << 3, 0, {}})),
              0x28);
    EXPECT_FALSE(f.plc.bit("T0"));
}

TEST(VigorSlave, AWordWrittenAsTwoBytesIsOneWriteOfTheWholeWord) {
    VigorSlave f;
    f.plc.set("D5", 0x1111);
    const int before = f.plc.image->changes();
    // D5 low byte only (1C0Ah): the high byte stays.
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Write, 0x1C0A, 1, "\x22"})), 0);
    EXPECT_EQ(f.plc.value("D5"), 0x1122);
    EXPECT_EQ(f.plc.image->changes(), before + 1);
}

TEST(VigorSlave, A32BitCounterValueReadsLowByteFirst) {
    VigorSlave f;
    f.plc.set("C200", 0x01020304);
    const QByteArray reply = f.ask(vigor::encodeRequest({0, vigor::Command::Read, 0x1A00, 4, {}}));
    vigor::ReplyDecoder d({0, vigor::Command::Read, 0x1A00, 4, {}});
    ASSERT_EQ(d.feed(reply), FrameStatus::Complete);
    EXPECT_EQ(d.reply().data, bytes("04 03 02 01"));
}

// The bytes a 51h read answers with; empty when it is refused.
QByteArray readBytes(VigorSlave &f, int address, int length) {
    const vigor::Request request{0, vigor::Command::Read, address, length, {}};
    vigor::ReplyDecoder d(request);
    if (d.feed(f.ask(vigor::encodeRequest(request))) != FrameStatus::Complete)
        return {};
    return d.reply().data;
}

TEST(VigorSlave, EveryAreaOfTheB53TableIsServedFromItsFirstByteToItsLast) {
    // The Vigor M/VB/VH communication manual, B-5-3: each area's first and last device at its
    // first and last byte, and every byte between them readable (in reads of 128 bytes).
    VigorSlave f;
    const model::Target &t = vigor();
    auto on = [&](const char *device) {
        const auto done =
            f.plc.image->apply({{model::DeviceCommand::Kind::WriteBit, test::device(t, device), 1}},
                               QDeadlineTimer(1000));
        ASSERT_TRUE(done.done()) << device;
    };
    struct Bits {
        const char *first, *last;
        int from, to;
    };
    for (const Bits &row : {Bits{"X0", "X777", 0x0000, 0x003F}, Bits{"Y0", "Y777", 0x0040, 0x007F},
                            Bits{"M0", "M5119", 0x0080, 0x02FF}, Bits{"S0", "S999", 0x0300, 0x037C},
                            Bits{"T0", "T255", 0x0380, 0x039F}, Bits{"C0", "C255", 0x03A0, 0x03BF},
                            Bits{"M9000", "M9255", 0x03E0, 0x03FF}}) {
        on(row.first);
        on(row.last);
        EXPECT_EQ(readBytes(f, row.from, 1), QByteArray(1, '\x01')) << row.first;
        EXPECT_EQ(readBytes(f, row.to, 1), QByteArray(1, '\x80')) << row.last;
    }
    // The coils: 0780h..079Fh T0..T255, 07A0h..07BFh C0..C255 (an image without a program
    // holds them OFF; the virtual PLC's program drives them, tests/cli).
    EXPECT_EQ(readBytes(f, 0x0780, 0x40), QByteArray(0x40, '\0'));
    struct Words {
        const char *first, *last;
        int from, to, bytes;
    };
    for (const Words &row :
         {Words{"T0", "T255", 0x1400, 0x15FE, 2}, Words{"D9000", "D9255", 0x1600, 0x17FE, 2},
          Words{"C0", "C199", 0x1800, 0x198E, 2}, Words{"C200", "C255", 0x1A00, 0x1ADC, 4},
          Words{"D0", "D8191", 0x1C00, 0x5BFE, 2}}) {
        f.plc.set(row.first, 0x1234);
        f.plc.set(row.last, row.bytes == 4 ? 0x01020304 : 0xABCD);
        EXPECT_EQ(readBytes(f, row.from, row.bytes),
                  row.bytes == 4 ? bytes("34 12 00 00") : bytes("34 12"))
            << row.first;
        EXPECT_EQ(readBytes(f, row.to, row.bytes),
                  row.bytes == 4 ? bytes("04 03 02 01") : bytes("CD AB"))
            << row.last;
    }
    // No hole inside an area: every byte of it in reads of at most 128 bytes.
    for (const auto &[from, to] :
         {std::pair{0x0000, 0x037C}, std::pair{0x0380, 0x03BF}, std::pair{0x03E0, 0x03FF},
          std::pair{0x0780, 0x07BF}, std::pair{0x1400, 0x198F}, std::pair{0x1A00, 0x1ADF},
          std::pair{0x1C00, 0x5BFF}}) {
        for (int at = from; at <= to; at += 128) {
            const int length = std::min(128, to - at + 1);
            EXPECT_EQ(readBytes(f, at, length).size(), length) << std::hex << at;
        }
    }
    // Between the areas the table lists nothing: 037Dh, 03C0h, 0400h, 07C0h, 1990h, 1AE0h.
    for (const int gap : {0x037D, 0x03C0, 0x0400, 0x07C0, 0x1990, 0x1AE0, 0x5C00})
        EXPECT_TRUE(readBytes(f, gap, 1).isEmpty()) << std::hex << gap;
}

TEST(VigorSlave, ACoilIsReadButNotWrittenAndAnImageWithoutCoilsSaysSo) {
    VigorSlave f;
    // 61h to T0..T7's coils: the program drives a coil, so the write is refused (28h).
    EXPECT_EQ(errorOf(f, vigor::encodeRequest({0, vigor::Command::Write, 0x0780, 1, "\x01"})),
              0x28);
    EXPECT_EQ(f.plc.image->changes(), 0);
    // An online image does not know the coils: 28h rather than a made-up 00.
    auto online = std::make_shared<MemoryImage>(vigor());
    struct NoCoils final : DeviceImage {
        std::shared_ptr<MemoryImage> inner;
        std::shared_ptr<const model::Snapshot> snapshot() const override {
            auto s = std::make_shared<model::Snapshot>(*inner->snapshot());
            s->coils.clear();
            return s;
        }
        ImageChange apply(const std::vector<model::DeviceCommand> &c, QDeadlineTimer d) override {
            return inner->apply(c, d);
        }
        OperatingMode mode() const override { return inner->mode(); }
        ImageChange setMode(OperatingMode m, QDeadlineTimer d) override {
            return inner->setMode(m, d);
        }
    };
    auto image = std::make_shared<NoCoils>();
    image->inner = online;
    VigorResponder slave(vigor(), *model::findProtocolMap(vigor(), model::ProtocolId::VigorLink), 0,
                         image);
    const QByteArrayList out =
        slave.feed(vigor::encodeRequest({0, vigor::Command::Read, 0x0780, 1, {}}));
    ASSERT_EQ(out.size(), 1);
    EXPECT_EQ(out.front().mid(5, 2), "28");
    // The contacts beside them are served.
    const QByteArrayList contacts =
        slave.feed(vigor::encodeRequest({0, vigor::Command::Read, 0x0380, 1, {}}));
    ASSERT_EQ(contacts.size(), 1);
    EXPECT_EQ(contacts.front().mid(5, 2), "00");
}

} // namespace
} // namespace rung::comms::slave
