// The traffic decoder (network/traffic_decode.h): the Computer Link vectors of the spec's
// protocols page verbatim, MODBUS frames made by the product's own codec, every example
// network's traffic decoded without a problem, and frames a fault or the line spoiled read
// with what is wrong, never a crash.

#include "network_fixture.h"

#include "network/traffic_decode.h"

#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_slave.h"

#include <QDirIterator>

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

// A PC (a line device) on the Computer Link port of a VB, station 0, as the manual's
// vectors address it.
const QByteArray kPcAndPlc = R"({
    "stations": [{"name": "plc", "program": "p.il", "model": "VB",
                  "ports": {"CP2": {"application": "computer-link", "station": 0}}}],
    "devices": [{"name": "pc", "kind": "line", "baud": 19200, "frame": "7E1"}],
    "wires": [["pc", "plc/CP2"]]
})";
const std::map<QString, QString> kIdle = {
    {QStringLiteral("p.il"), QStringLiteral("LD X0\nOUT Y0\nEND\n")}};

TrafficRecord transmission(const char *sender, const QByteArray &bytes, const char *wire = "w1") {
    static qint64 us = 0;
    us += 10'000;
    return {us, us + 5'000, QString::fromLatin1(wire), QString::fromLatin1(sender), bytes, {}};
}

struct VigorVector {
    const char *request;
    const char *reply;
    int command;
    const char *address;
    int count;
    const char *requestData;
    const char *replyData;
};

std::vector<QString> exampleNetworks() {
    std::vector<QString> out;
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks"),
                    {QStringLiteral("*.rungnet")}, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext())
        out.push_back(it.next());
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

// Vigor M/VB/VH communication manual, B-5: its six example frames, request then reply.
TEST(TrafficDecode, ComputerLinkVectorsOfTheManual) {
    const NetRun run = runNetwork(kPcAndPlc, kIdle);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    const VigorVector vectors[] = {
        {"02 30 30 35 31 30 30 38 31 30 32 03 46 34", "06 30 30 35 31 30 30 41 37 39 33 03 30 44",
         0x51, "M8 (0081h)", 2, "", "A7 93"},
        {"02 30 30 35 31 31 43 30 32 30 34 03 30 33",
         "06 30 30 35 31 30 30 33 34 31 32 43 44 41 42 03 46 44", 0x51, "D1 (1C02h)", 4, "",
         "34 12 CD AB"},
        {"02 30 30 36 31 30 30 34 33 30 32 43 36 33 45 03 45 34", "06 30 30 36 31 30 30 03 32 41",
         0x61, "Y30 (0043h)", 2, "C6 3E", ""},
        {"02 30 30 36 31 31 43 30 32 30 32 32 35 41 33 03 44 44", "06 30 30 36 31 30 30 03 32 41",
         0x61, "D1 (1C02h)", 2, "25 A3", ""},
        {"02 30 30 37 30 30 34 30 41 03 39 46", "06 30 30 37 30 30 30 03 32 41", 0x70,
         "M10 (040Ah)", -1, "", ""},
        {"02 30 30 37 31 30 34 36 34 03 39 39", "06 30 30 37 31 30 30 03 32 42", 0x71,
         "M100 (0464h)", -1, "", ""},
    };
    for (const VigorVector &v : vectors) {
        SCOPED_TRACE(v.request);
        const DecodedFrame request = decoder.decode(transmission("pc", hex(v.request)));
        EXPECT_EQ(request.kind, DecodedFrame::Kind::Request);
        EXPECT_EQ(request.protocol.toStdString(), "Computer Link");
        EXPECT_EQ(request.receiver.toStdString(), "plc/CP2");
        EXPECT_EQ(request.station, 0);
        EXPECT_EQ(request.command, v.command);
        EXPECT_EQ(request.address.toStdString(), v.address);
        EXPECT_EQ(request.count, v.count);
        EXPECT_EQ(request.data.toStdString(), v.requestData);
        EXPECT_EQ(request.problem.toStdString(), "");
        const DecodedFrame reply = decoder.decode(transmission("plc/CP2", hex(v.reply)));
        EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
        EXPECT_EQ(reply.receiver.toStdString(), "pc");
        EXPECT_EQ(reply.station, 0);
        EXPECT_EQ(reply.command, v.command);
        EXPECT_EQ(reply.address.toStdString(), v.address);
        EXPECT_EQ(reply.data.toStdString(), v.replyData);
        EXPECT_EQ(reply.errorCode, -1);
        EXPECT_EQ(reply.problem.toStdString(), "");
    }
    // The commands' names come with the code.
    EXPECT_EQ(decoder.decode(transmission("pc", hex("02 30 30 35 31 30 30 38 31 30 32 03 46 34")))
                  .commandText.toStdString(),
              "51h read");
}

TEST(TrafficDecode, ComputerLinkErrorsAndSpoiledFrames) {
    const NetRun run = runNetwork(kPcAndPlc, kIdle);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    // Vector 1 with its sum spoiled: the slave answers 11h; the decoder says both sums.
    const DecodedFrame badSum =
        decoder.decode(transmission("pc", hex("02 30 30 35 31 30 30 38 31 30 32 03 46 35")));
    EXPECT_TRUE(badSum.failed());
    EXPECT_EQ(badSum.problem.toStdString(),
              "wrong sum (received F5, computed F4): the slave answers error 11h");
    // The slave's refusal: error 28h (address out of range) is the PLC's code, not a problem.
    decoder.decode(transmission("pc", hex("02 30 30 35 31 30 30 38 31 30 32 03 46 34")));
    const DecodedFrame refused = decoder.decode(transmission(
        "plc/CP2", comms::vigor::encodeReply({0, comms::vigor::Command::Read, 0x28, {}})));
    EXPECT_EQ(refused.problem.toStdString(), "");
    EXPECT_EQ(refused.errorCode, 0x28);
    EXPECT_NE(refused.errorText.indexOf(QStringLiteral("28h")), -1)
        << refused.errorText.toStdString();
    // A reply cut short, a reply of noise, an empty-looking request: a problem each.
    decoder.decode(transmission("pc", hex("02 30 30 35 31 30 30 38 31 30 32 03 46 34")));
    const DecodedFrame cut = decoder.decode(transmission("plc/CP2", hex("06 30 30 35 31 30")));
    EXPECT_NE(cut.problem.indexOf(QStringLiteral("stops after 6 byte")), -1)
        << cut.problem.toStdString();
    const DecodedFrame noise = decoder.decode(transmission("plc/CP2", hex("FF 00 13")));
    EXPECT_FALSE(noise.problem.isEmpty());
    const DecodedFrame lone = decoder.decode(transmission("plc/CP2", hex("06")));
    EXPECT_FALSE(lone.problem.isEmpty());
    // Bytes from the PC that are no request are its text.
    const DecodedFrame text = decoder.decode(transmission("pc", QByteArrayLiteral("HELLO\r")));
    EXPECT_EQ(text.kind, DecodedFrame::Kind::Raw);
    EXPECT_EQ(text.data.toStdString(), "HELLO\\r");
    EXPECT_EQ(text.receiver.toStdString(), "plc/CP2");
    EXPECT_FALSE(text.failed());
}

// MODBUS RTU frames as the product's own master and slave codecs make them, on the modbus
// example's wire: the address as the slave VB's device (Vigor M/VB/VH communication manual,
// B-3-6: D0..D8191 are registers 0..8191).
TEST(TrafficDecode, ModbusRequestsRepliesAndExceptions) {
    const NetRun run = runNetwork(
        {}, {}, {},
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/modbus/modbus.rungnet"));
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    namespace mb = comms::modbus;
    mb::Request read;
    read.function = mb::ReadHoldingRegisters;
    read.address = 100;
    read.count = 2;
    const DecodedFrame request =
        decoder.decode(transmission("master/CP2", mb::rtuFrame(2, mb::encodeRequestPdu(read))));
    EXPECT_EQ(request.kind, DecodedFrame::Kind::Request);
    EXPECT_EQ(request.protocol.toStdString(), "MODBUS RTU");
    EXPECT_EQ(request.receiver.toStdString(), "s2/CP2");
    EXPECT_EQ(request.station, 2);
    EXPECT_EQ(request.command, 3);
    EXPECT_EQ(request.commandText.toStdString(), "03h read holding registers");
    EXPECT_EQ(request.rawAddress, 100);
    EXPECT_EQ(request.address.toStdString(), "D100 (100)");
    EXPECT_EQ(request.count, 2);
    EXPECT_EQ(request.problem.toStdString(), "");
    mb::Response response;
    response.function = mb::ReadHoldingRegisters;
    response.registers = {1234, 65535};
    const DecodedFrame reply =
        decoder.decode(transmission("s2/CP2", mb::rtuFrame(2, mb::encodeResponsePdu(response))));
    EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(reply.receiver.toStdString(), "master/CP2");
    EXPECT_EQ(reply.address.toStdString(), "D100 (100)");
    EXPECT_EQ(reply.data.toStdString(), "1234 65535");
    EXPECT_FALSE(reply.failed());

    mb::Request write;
    write.function = mb::WriteSingleCoil;
    write.address = 512 + 10; // M10 (B-3-6: M0 is coil 512)
    write.bits = {true};
    const DecodedFrame coil =
        decoder.decode(transmission("master/CP2", mb::rtuFrame(1, mb::encodeRequestPdu(write))));
    EXPECT_EQ(coil.receiver.toStdString(), "s1/CP2");
    EXPECT_EQ(coil.address.toStdString(), "M10 (522)");
    EXPECT_EQ(coil.data.toStdString(), "1");
    mb::Response refused;
    refused.function = mb::WriteSingleCoil;
    refused.exception = mb::IllegalDataAddress;
    const DecodedFrame exception =
        decoder.decode(transmission("s1/CP2", mb::rtuFrame(1, mb::encodeResponsePdu(refused))));
    EXPECT_EQ(exception.errorCode, 2);
    EXPECT_NE(exception.errorText.indexOf(QStringLiteral("illegal data address")), -1);
    EXPECT_EQ(exception.problem.toStdString(), "");
    EXPECT_TRUE(exception.failed());

    // A broadcast is for every slave and waits for nobody.
    mb::Request all;
    all.function = mb::WriteSingleRegister;
    all.registers = {7};
    const DecodedFrame broadcast =
        decoder.decode(transmission("master/CP2", mb::rtuFrame(0, mb::encodeRequestPdu(all))));
    EXPECT_EQ(broadcast.receiver.toStdString(), "every slave (broadcast)");
    EXPECT_EQ(broadcast.data.toStdString(), "7");

    // Spoiled: a CRC, a frame cut short, noise, a lone byte: a problem each, no crash.
    QByteArray bad = mb::rtuFrame(2, mb::encodeRequestPdu(read));
    bad[bad.size() - 1] = char(bad[bad.size() - 1] ^ 0x01);
    const DecodedFrame crc = decoder.decode(transmission("master/CP2", bad));
    EXPECT_NE(crc.problem.indexOf(QStringLiteral("wrong CRC")), -1) << crc.problem.toStdString();
    for (const QByteArray &garbled : {hex("02 03"), hex("02"), hex("FF FF FF FF FF FF FF FF FF"),
                                      mb::rtuFrame(2, mb::encodeRequestPdu(read)).left(5)}) {
        SCOPED_TRACE(garbled.toHex(' ').toStdString());
        EXPECT_FALSE(decoder.decode(transmission("master/CP2", garbled)).problem.isEmpty());
        EXPECT_FALSE(decoder.decode(transmission("s2/CP2", garbled)).problem.isEmpty());
    }
}

// Each example of the manuals, run for three seconds of virtual time: every frame on every
// wire is read without a problem, the requests and replies each find their receiver, and each
// network with a protocol shows both.
TEST(TrafficDecode, EveryExampleNetworkDecodesWithoutAProblem) {
    const std::vector<QString> files = exampleNetworks();
    ASSERT_GE(files.size(), 10u);
    for (const QString &file : files) {
        SCOPED_TRACE(file.toStdString());
        NetRun run = runNetwork({}, {}, {}, file);
        ASSERT_TRUE(run.net) << run.error.toStdString();
        run.net->runUntil(3'000'000);
        // The CPM1's peripheral port answers a host on its bridge's real line (cpm1-host-link):
        // without one there is nothing on the wire.
        if (file.contains(QStringLiteral("cpm1-host-link"))) {
            EXPECT_TRUE(run.records.empty());
            EXPECT_FALSE(run.net->description().bridges.empty());
            continue;
        }
        ASSERT_FALSE(run.records.empty());
        TrafficDecoder decoder(*run.net);
        int requests = 0;
        int replies = 0;
        for (const TrafficRecord &r : run.records) {
            const DecodedFrame f = decoder.decode(r);
            SCOPED_TRACE(formatTraffic(r).toStdString());
            EXPECT_EQ(f.problem.toStdString(), "");
            EXPECT_EQ(f.errorCode, -1) << f.errorText.toStdString();
            EXPECT_FALSE(f.protocol.isEmpty());
            EXPECT_FALSE(f.previousUnanswered); // every request of the examples is answered
            if (f.kind == DecodedFrame::Kind::Request || f.kind == DecodedFrame::Kind::Reply) {
                EXPECT_FALSE(f.receiver.isEmpty());
                EXPECT_GE(f.station, 0);
                EXPECT_GE(f.command, 0);
                EXPECT_FALSE(f.address.isEmpty());
            }
            requests += f.kind == DecodedFrame::Kind::Request;
            replies += f.kind == DecodedFrame::Kind::Reply;
        }
        const bool framesOfAProtocol = !file.contains(QStringLiteral("cpu-link")) &&
                                       !file.contains(QStringLiteral("parallel-link")) &&
                                       !file.contains(QStringLiteral("free-port"));
        if (framesOfAProtocol) {
            EXPECT_GT(requests, 0);
            EXPECT_GT(replies, 0);
        }
    }
}

// The network's corrupt fault (network-format.md, "Faults") spoils a byte of a frame: the
// decoder says what the slave saw (a wrong CRC or sum), and the frames after it read again.
TEST(TrafficDecode, ACorruptedFrameIsDecodedWithItsProblem) {
    struct Case {
        const char *file;
        const char *wire;
        const char *problem;
    };
    for (const Case &c : {Case{"modbus/modbus.rungnet", "w1", "wrong CRC"},
                          Case{"easy-link/easy-link.rungnet", "w1", "wrong sum"}}) {
        SCOPED_TRACE(c.file);
        NetworkDescription d;
        QString error;
        ASSERT_TRUE(readNetworkFile(
            QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/") + QLatin1String(c.file),
            &d, &error))
            << error.toStdString();
        FaultDescription fault;
        fault.kind = FaultDescription::Kind::Corrupt;
        fault.wire = QLatin1String(c.wire);
        fault.frame = 0;
        fault.byte = 4;
        fault.mask = 0x01;
        d.faults.push_back(fault);
        auto net = Network::build(d, listingLoader(), &error);
        ASSERT_TRUE(net) << error.toStdString();
        std::vector<TrafficRecord> records;
        net->setTrafficSink([&](const TrafficRecord &r) { records.push_back(r); });
        net->runUntil(1'000'000);
        ASSERT_GE(records.size(), 3u);
        TrafficDecoder decoder(*net);
        const DecodedFrame spoiled = decoder.decode(records[0]);
        EXPECT_FALSE(records[0].note.isEmpty());
        EXPECT_NE(spoiled.problem.indexOf(QLatin1String(c.problem)), -1)
            << spoiled.problem.toStdString();
        EXPECT_TRUE(spoiled.failed());
        int fine = 0;
        for (std::size_t i = 1; i < records.size(); ++i)
            fine += decoder.decode(records[i]).problem.isEmpty();
        EXPECT_GT(fine, 0);
    }
}

// A silent slave (network-format.md, "Faults"): the master's request to it gets no reply, and
// the next request on the wire says so; a request that was answered is not marked.
TEST(TrafficDecode, TheRequestAfterAnUnansweredOneSaysSo) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/easy-link/easy-link.rungnet"),
        &d, &error))
        << error.toStdString();
    FaultDescription silent;
    silent.kind = FaultDescription::Kind::Silent;
    silent.station = QStringLiteral("s5");
    d.faults.push_back(silent);
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    std::vector<TrafficRecord> records;
    net->setTrafficSink([&](const TrafficRecord &r) { records.push_back(r); });
    net->runUntil(2'000'000);
    TrafficDecoder decoder(*net);
    std::vector<DecodedFrame> frames;
    for (const TrafficRecord &r : records)
        frames.push_back(decoder.decode(r));
    int unanswered = 0;
    for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
        if (frames[i].kind != DecodedFrame::Kind::Request)
            continue;
        // s5 is silent: what it "sends" is recorded with the fault's note and never arrives.
        const bool toS5 = frames[i].receiver == QStringLiteral("s5/CP2");
        std::size_t next = i + 1;
        while (next < frames.size() && records[next].sender == QStringLiteral("s5/CP2"))
            ++next;
        if (next >= frames.size() || frames[next].kind != DecodedFrame::Kind::Request)
            continue;
        EXPECT_EQ(frames[next].previousUnanswered, toS5) << i;
        unanswered += toS5;
    }
    EXPECT_GT(unanswered, 0);
    EXPECT_EQ(TrafficDecoder::noReplyText().toStdString(),
              "no reply came before the next request (a time-out)");
}
