// The virtual PLC (app/virtual_plc): a simulated program served by a comms slave. A master's
// write reaches the program at a scan boundary and is answered after it took effect; reads
// show what the program made of it. Masters here are our own codecs over a real pty or TCP.

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/transport/tcp_transport.h"
#include "model/target/address.h"
#include "tests/cli/cli_run.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <gtest/gtest.h>

namespace rung::test {
namespace {

using namespace comms;
using model::ProtocolId;

// 010.00 follows HR 00.00 (IR 000 is an input: the program's own); DM 0001 = DM 0000.
constexpr const char *kServedCpm1 = "; target: cpm1\n"
                                    "LD HR 00.00\nOUT 010.00\nLD 253.13\nMOV(21) DM 0000 DM 0001\n"
                                    "END(01)\n";

template <typename Decoder>
FrameStatus exchange(Transport &t, const QByteArray &request, Decoder &d) {
    QString error;
    EXPECT_TRUE(t.write(request, QDeadlineTimer(1000), &error)) << error.toStdString();
    const QDeadlineTimer deadline(2000);
    while (d.status() == FrameStatus::NeedMore) {
        const ReadResult r = t.read(deadline);
        if (r.status != ReadResult::Status::Data)
            break;
        d.feed(r.bytes);
        if constexpr (std::is_same_v<Decoder, hostlink::ReplyDecoder>)
            if (d.takeDelimiterRequest())
                t.write("\r", QDeadlineTimer(1000), &error);
    }
    return d.status();
}

struct ModbusMaster {
    Transport &t;
    modbus::Framing framing;
    int transaction = 0;

    modbus::ReplyDecoder ask(const modbus::Request &r) {
        ++transaction;
        modbus::ReplyDecoder d(framing, 1, r, transaction);
        const QByteArray pdu = modbus::encodeRequestPdu(r);
        exchange(t,
                 framing == modbus::Framing::Rtu ? modbus::rtuFrame(1, pdu)
                                                 : modbus::tcpFrame(transaction, 1, pdu),
                 d);
        return d;
    }
    bool write(const modbus::Request &r) { return ask(r).status() == FrameStatus::Complete; }
    int reg(int address) {
        const auto d = ask({modbus::ReadHoldingRegisters, address, 1, {}, {}});
        return d.status() == FrameStatus::Complete ? d.response().registers.front() : -1;
    }
    int coil(int address) {
        const auto d = ask({modbus::ReadCoils, address, 1, {}, {}});
        return d.status() == FrameStatus::Complete ? int(d.response().bits.front()) : -1;
    }
};

TEST(VirtualPlc, Pl110OverModbusRtuOnAPtyRunsWhatTheMasterWrites) {
    VirtualPlcUnderTest v(kFollowerPl110, {ProtocolId::Modbus, modbus::Framing::Rtu, 1}, false);
    ASSERT_TRUE(v.ready());
    PtyTransport pty(v.path);
    QString error;
    ASSERT_TRUE(pty.open(&error)) << error.toStdString();
    ModbusMaster m{pty, modbus::Framing::Rtu};
    // I1 (bit 1600) ON: Q1 (bit 2400) follows within scans.
    ASSERT_TRUE(m.write({modbus::WriteSingleCoil, 1600, 1, {}, {true}}));
    EXPECT_TRUE(eventually([&] { return m.coil(2400) == 1; }));
    // V0 (register 2000) = 4321: V1 follows.
    ASSERT_TRUE(m.write({modbus::WriteSingleRegister, 2000, 1, {4321}, {}}));
    EXPECT_EQ(m.reg(2000), 4321); // acknowledged after it took effect: read back at once
    EXPECT_TRUE(eventually([&] { return m.reg(2001) == 4321; }));
    // Q1 as a word bit (register 150, bit 0), I1 as a read-only word (100).
    EXPECT_EQ(m.reg(150) & 1, 1);
    EXPECT_EQ(m.reg(100) & 1, 1);
}

TEST(VirtualPlc, Pl110RunBitStopsAndStartsTheScan) {
    VirtualPlcUnderTest v(kFollowerPl110, {ProtocolId::Modbus, modbus::Framing::Tcp, 1}, true);
    ASSERT_TRUE(v.ready());
    TcpTransport tcp(QStringLiteral("127.0.0.1"), v.port);
    QString error;
    ASSERT_TRUE(tcp.open(&error)) << error.toStdString();
    ModbusMaster m{tcp, modbus::Framing::Tcp};
    EXPECT_EQ(m.coil(16000), 1); // SM0.0: RUN
    ASSERT_TRUE(m.write({modbus::WriteSingleCoil, 16000, 1, {}, {false}}));
    EXPECT_EQ(m.coil(16000), 0);
    EXPECT_EQ(v.plc->image()->mode(), slave::OperatingMode::Program);
    // Stopped: the write is taken, the program does not run on it.
    ASSERT_TRUE(m.write({modbus::WriteSingleRegister, 2000, 1, {77}, {}}));
    EXPECT_EQ(m.reg(2000), 77);
    // That something does not happen shows only over time: six scan periods, in which a
    // running program would have copied the word. The scan count must not move either.
    const quint64 scans = v.plc->image()->snapshot()->statistics.scans;
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    EXPECT_NE(m.reg(2001), 77);
    EXPECT_EQ(v.plc->image()->snapshot()->statistics.scans, scans);
    ASSERT_TRUE(m.write({modbus::WriteSingleCoil, 16000, 1, {}, {true}}));
    EXPECT_TRUE(eventually([&] { return m.reg(2001) == 77; }));
}

TEST(VirtualPlc, VigorCp2ModbusTcpAndTheLinkOnAPty) {
    {
        VirtualPlcUnderTest v(kFollowerVigor, {ProtocolId::Modbus, modbus::Framing::Tcp, 1}, true);
        ASSERT_TRUE(v.ready());
        TcpTransport tcp(QStringLiteral("127.0.0.1"), v.port);
        QString error;
        ASSERT_TRUE(tcp.open(&error));
        ModbusMaster m{tcp, modbus::Framing::Tcp};
        ASSERT_TRUE(m.write({modbus::WriteSingleCoil, 512, 1, {}, {true}})); // M0
        EXPECT_TRUE(eventually([&] { return m.coil(0) == 1; }));             // Y0
        ASSERT_TRUE(m.write({modbus::WriteSingleRegister, 0, 1, {41}, {}})); // D0
        EXPECT_TRUE(eventually([&] { return m.reg(1) == 42; }));             // D1
    }
    VirtualPlcUnderTest v(kFollowerVigor, {ProtocolId::VigorLink, {}, 0}, false);
    ASSERT_TRUE(v.ready());
    PtyTransport pty(v.path);
    QString error;
    ASSERT_TRUE(pty.open(&error));
    // M0 ON (70h, bit address 0080h << 3), then Y0 (0040h) reads 1; D0 = 9 (61h at 1C00h).
    const vigor::Request on{0, vigor::Command::BitOn, vigor::bitAddress(0x80, 0), 0, {}};
    vigor::ReplyDecoder onReply(on);
    ASSERT_EQ(exchange(pty, vigor::encodeRequest(on), onReply), FrameStatus::Complete);
    const vigor::Request write{0, vigor::Command::Write, 0x1C00, 2, QByteArray("\x09\x00", 2)};
    vigor::ReplyDecoder writeReply(write);
    ASSERT_EQ(exchange(pty, vigor::encodeRequest(write), writeReply), FrameStatus::Complete);
    EXPECT_TRUE(eventually([&] {
        const vigor::Request read{0, vigor::Command::Read, 0x0040, 1, {}};
        vigor::ReplyDecoder d(read);
        return exchange(pty, vigor::encodeRequest(read), d) == FrameStatus::Complete &&
               d.reply().data == QByteArray(1, '\x01');
    }));
    EXPECT_TRUE(eventually([&] {
        const vigor::Request read{0, vigor::Command::Read, 0x1C02, 2, {}};
        vigor::ReplyDecoder d(read);
        return exchange(pty, vigor::encodeRequest(read), d) == FrameStatus::Complete &&
               d.reply().data == QByteArray("\x0A\x00", 2);
    }));
}

TEST(VirtualPlc, VigorLinkReadsTheTimerAndCounterCoilsTheProgramDrives) {
    // The Vigor M/VB/VH communication manual, B-5-3: T0..T255's coils at 0780h..079Fh,
    // C0..C255's at 07A0h..07BFh. T5's coil follows M0, C3's follows M1.
    VirtualPlcUnderTest v("; target: vigor\nLD M0\nTMR T5 K1000\nLD M1\nCNT C3 K5\nEND\n",
                          {ProtocolId::VigorLink, {}, 0}, false);
    ASSERT_TRUE(v.ready());
    PtyTransport pty(v.path);
    QString error;
    ASSERT_TRUE(pty.open(&error));
    const auto bit = [&pty](int byte, int bit, bool on) {
        const vigor::Request r{0,
                               on ? vigor::Command::BitOn : vigor::Command::BitOff,
                               vigor::bitAddress(byte, bit),
                               0,
                               {}};
        vigor::ReplyDecoder d(r);
        return exchange(pty, vigor::encodeRequest(r), d) == FrameStatus::Complete;
    };
    const auto coils = [&pty] {
        const vigor::Request read{0, vigor::Command::Read, 0x0780, 0x40, {}};
        vigor::ReplyDecoder d(read);
        return exchange(pty, vigor::encodeRequest(read), d) == FrameStatus::Complete
                   ? d.reply().data
                   : QByteArray();
    };
    // The 64 bytes with T5's coil (0780h, bit 5) and C3's (07A0h, bit 3) as given.
    const auto with = [](bool t5, bool c3) {
        QByteArray b(0x40, '\0');
        b[0] = t5 ? '\x20' : '\0';
        b[0x20] = c3 ? '\x08' : '\0';
        return b;
    };
    ASSERT_TRUE(v.scanned());
    EXPECT_EQ(coils(), with(false, false));
    ASSERT_TRUE(bit(0x80, 0, true)); // M0
    EXPECT_TRUE(eventually([&] { return coils() == with(true, false); }));
    ASSERT_TRUE(bit(0x80, 1, true)); // M1
    EXPECT_TRUE(eventually([&] { return coils() == with(true, true); }));
    ASSERT_TRUE(bit(0x80, 0, false));
    EXPECT_TRUE(eventually([&] { return coils() == with(false, true); }));
}

TEST(VirtualPlc, HostLinkRefusesWritesInRunUntilMonitor) {
    VirtualPlcUnderTest v(kServedCpm1, {ProtocolId::HostLink, {}, 0}, false);
    ASSERT_TRUE(v.ready());
    PtyTransport pty(v.path);
    QString error;
    ASSERT_TRUE(pty.open(&error));
    auto ask = [&pty](const hostlink::Frame &command) {
        hostlink::ReplyDecoder d(command);
        exchange(pty, hostlink::encode(command).front(), d);
        return d;
    };
    const auto dm = model::ProtocolSpace::HostLinkDm;
    hostlink::ReplyDecoder refused = ask(hostlink::writeCommand(0, dm, 0, {0x1234}));
    ASSERT_EQ(refused.status(), FrameStatus::Failed);
    EXPECT_EQ(refused.error().code, hostlink::NotInRun);
    ASSERT_EQ(ask(hostlink::modeCommand(0, hostlink::Mode::Monitor)).status(),
              FrameStatus::Complete);
    EXPECT_EQ(hostlink::modeOfStatus(ask(hostlink::statusCommand(0)).reply().status),
              hostlink::Mode::Monitor);
    ASSERT_EQ(ask(hostlink::writeCommand(0, dm, 0, {0x1234})).status(), FrameStatus::Complete);
    EXPECT_TRUE(eventually([&] {
        const auto d = ask(hostlink::readCommand(0, dm, 1, 1));
        return d.status() == FrameStatus::Complete && d.reply().words.front() == 0x1234;
    }));
    // HR 00.00 ON by WH: 010.00 follows (IR 010 read by RR).
    ASSERT_EQ(ask(hostlink::writeCommand(0, model::ProtocolSpace::HostLinkHr, 0, {1})).status(),
              FrameStatus::Complete);
    EXPECT_TRUE(eventually([&] {
        const auto d = ask(hostlink::readCommand(0, model::ProtocolSpace::HostLinkIr, 10, 1));
        return d.status() == FrameStatus::Complete && (d.reply().words.front() & 1);
    }));
    // PROGRAM stops the scan: a forced output stays as forced... and KS is taken there too.
    ASSERT_EQ(ask(hostlink::modeCommand(0, hostlink::Mode::Program)).status(),
              FrameStatus::Complete);
    EXPECT_EQ(hostlink::modeOfStatus(ask(hostlink::statusCommand(0)).reply().status),
              hostlink::Mode::Program);
}

// CNT 000 and CNT 001 count down from #0150 and #0009; their inputs stay OFF, so the
// present values stay at the set values.
constexpr const char *kCountersCpm1 = "; target: cpm1\n"
                                      "LD 000.00\nLD 000.01\nCNT 000 #0150\n"
                                      "LD 000.02\nLD 000.03\nCNT 001 #0009\nEND(01)\n";

// Bytes as the PLC sends them, up to the end of one Host Link frame ("*" CR).
QByteArray askRaw(Transport &t, const QByteArray &command) {
    QString error;
    EXPECT_TRUE(t.write(command, QDeadlineTimer(1000), &error)) << error.toStdString();
    QByteArray reply;
    const QDeadlineTimer deadline(2000);
    while (!reply.endsWith("*\r")) {
        const ReadResult r = t.read(deadline);
        if (r.status != ReadResult::Status::Data)
            break;
        reply += r.bytes;
    }
    return reply;
}

TEST(VirtualPlc, HostLinkPresentValuesAreThePlcsBcdWordsBothWays) {
    // A CPM1 keeps a timer's or counter's present value as BCD digits (W353; the Omron CPM1
    // guide: set values are BCD), and so does the simulator: 150 is the word 0150h. RC / WC
    // carry that word as it is; converting it again would answer 0336 for 150.
    VirtualPlcUnderTest v(kCountersCpm1, {ProtocolId::HostLink, {}, 0}, false);
    ASSERT_TRUE(v.ready());
    ASSERT_TRUE(v.scanned());
    const model::Target &cpm1 = *model::Target::byId(QStringLiteral("cpm1"));
    const model::Address cnt0 = std::get<model::Address>(model::parseAddress(cpm1, u"CNT 000"));
    EXPECT_EQ(v.plc->image()->snapshot()->value(cnt0), 0x0150);
    PtyTransport pty(v.path);
    QString error;
    ASSERT_TRUE(pty.open(&error)) << error.toStdString();
    // Host Link's RC example (Omron CPM1/SRM1 manual W353): @00RC0000000253* reads TC 000 and 001.
    const QByteArray text = "@00RC0001500009";
    EXPECT_EQ(askRaw(pty, "@00RC0000000253*\r"), text + hostlink::fcs(text) + "*\r");
    // `read` prints the numbers, as the ladder shows them from the same words.
    pty.close();
    const auto read =
        cli({QStringLiteral("read"), QStringLiteral("--target"), QStringLiteral("cpm1"),
             QStringLiteral("--protocol"), QStringLiteral("hostlink"), QStringLiteral("--pty"),
             v.path, QStringLiteral("CNT 000"), QStringLiteral("TIM 001"), QStringLiteral("000"),
             QStringLiteral("253.13")});
    EXPECT_EQ(read.code, 0) << read.err.toStdString();
    EXPECT_EQ(read.out, QStringLiteral("CNT 000=150\nTIM 001=9\n000=0\n253.13=1\n"));
    // WC in PROGRAM (the scan stopped, so the program does not count over it): 0042 is the
    // word 0042h in the PLC and comes back by RC as 0042.
    ASSERT_TRUE(pty.open(&error)) << error.toStdString();
    EXPECT_EQ(askRaw(pty, "@00SC0050*\r"),
              QByteArray("@00SC00") + hostlink::fcs("@00SC00") + "*\r");
    const QByteArray wc = "@00WC00000042";
    EXPECT_EQ(askRaw(pty, wc + hostlink::fcs(wc) + "*\r"),
              QByteArray("@00WC00") + hostlink::fcs("@00WC00") + "*\r");
    EXPECT_EQ(v.plc->image()->snapshot()->value(cnt0), 0x0042);
    const QByteArray rc = "@00RC00000001";
    const QByteArray back = "@00RC000042";
    EXPECT_EQ(askRaw(pty, rc + hostlink::fcs(rc) + "*\r"), back + hostlink::fcs(back) + "*\r");
    pty.close();
    // `write` takes the number: CNT 001 = 12 is the word 0012h.
    const auto write =
        cli({QStringLiteral("write"), QStringLiteral("--target"), QStringLiteral("cpm1"),
             QStringLiteral("--protocol"), QStringLiteral("hostlink"), QStringLiteral("--pty"),
             v.path, QStringLiteral("CNT 001=12")});
    EXPECT_EQ(write.code, 0) << write.err.toStdString();
    const model::Address cnt1 = std::get<model::Address>(model::parseAddress(cpm1, u"CNT 001"));
    EXPECT_EQ(v.plc->image()->snapshot()->value(cnt1), 0x0012);
    // Past four digits: refused before the port is opened.
    const auto big =
        cli({QStringLiteral("write"), QStringLiteral("--target"), QStringLiteral("cpm1"),
             QStringLiteral("--protocol"), QStringLiteral("hostlink"), QStringLiteral("--pty"),
             v.path, QStringLiteral("CNT 001=10000")});
    EXPECT_EQ(big.code, 2);
    EXPECT_TRUE(big.err.contains(QLatin1String("10000 does not fit CNT 001 (0..9999)")))
        << big.err.toStdString();
    EXPECT_EQ(v.plc->image()->snapshot()->value(cnt1), 0x0012);
}

TEST(VirtualPlc, StopEndsAWaitingWriteAndTheWorkers) {
    VirtualPlcUnderTest v(kFollowerPl110, {ProtocolId::Modbus, modbus::Framing::Tcp, 1}, true);
    ASSERT_TRUE(v.ready());
    const auto started = std::chrono::steady_clock::now();
    v.plc->stop();
    v.plc.reset();
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(2));
}

} // namespace
} // namespace rung::test
