// The traffic decoder (network/traffic_decode.h): the Computer Link and Host Link vectors of
// the spec's protocols page verbatim, MODBUS frames made by the product's own codec, every example
// network's traffic decoded without a problem, and frames a fault or the line spoiled read
// with what is wrong, never a crash.

#include "network_fixture.h"

#include "network/bridge.h"
#include "network/traffic_decode.h"

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_slave.h"
#include "comms/transport/pty_transport.h"

#include <QDirIterator>

#include <random>

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

// A host (a line device at the port's Host Link defaults, 9600 bps 7E2) on a CPM1's peripheral
// port, unit 0, as the spec's Host Link vectors address it; DM 0000 holds 1234.
const QByteArray kHostAndCpm1 = R"({
    "stations": [{"name": "plc", "program": "c.il", "model": "CPM1-20CDR",
                  "ports": {"PERIPHERAL": {"application": "host-link", "station": 0}}}],
    "devices": [{"name": "host", "kind": "line", "baud": 9600, "frame": "7E2"}],
    "wires": [["plc/PERIPHERAL", "host"]]
})";
const std::map<QString, QString> kCpm1 = {
    {QStringLiteral("c.il"),
     QStringLiteral("; target: cpm1\nLD 253.13\nMOV(21) #1234 DM0000\nEND(01)\n")}};

// The frames a run of kHostAndCpm1 carries when the host sends `command` at 100 ms: the
// command, then the PLC's answer (if any) within 100 ms, each decoded.
std::vector<DecodedFrame> hostLinkExchange(const QByteArray &command,
                                           std::vector<TrafficRecord> *records = nullptr) {
    NetRun r = runNetwork(kHostAndCpm1, kCpm1);
    EXPECT_TRUE(r.net) << r.error.toStdString();
    if (!r.net)
        return {};
    EXPECT_TRUE(r.net->runUntil(100'000));
    r.net->inject(r.net->endpoint(QStringLiteral("host")), command);
    EXPECT_TRUE(r.net->runUntil(200'000));
    TrafficDecoder decoder(*r.net);
    std::vector<DecodedFrame> out;
    for (const TrafficRecord &t : r.records)
        out.push_back(decoder.decode(t));
    if (records)
        *records = r.records;
    return out;
}

struct HostLinkVector {
    const char *command;
    const char *commandText;
    const char *address;
    int count;
    const char *data;
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

// The Host Link command examples of the Omron CPM1/SRM1 programming manual W353 (Host Link, unit
// 00) verbatim, as test_host_link.cpp has them, each read as the command it is, for the CPM1 on the
// wire, with the address as the CPM1's device beside the four digits on the wire.
TEST(TrafficDecode, HostLinkVectorsOfTheSpec) {
    const NetRun run = runNetwork(kHostAndCpm1, kCpm1);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    const HostLinkVector vectors[] = {
        {"@00RD0000000157*\r", "RD read DM words", "DM 0000 (0000)", 1, ""},
        {"@00WD0100123456*\r", "WD write DM words", "DM 0100 (0100)", 1, "1234"},
        {"@00RR0000000242*\r", "RR read IR/SR words", "000 (0000)", 2, ""},
        {"@00WR001000FF44*\r", "WR write IR/SR words", "010 (0010)", 1, "00FF"},
        {"@00RC0000000253*\r", "RC read timer/counter PVs", "TIM 000 (0000)", 2, ""},
        {"@00MS5E*\r", "MS read status", "", -1, ""},
        {"@00SC0050*\r", "SC change mode", "", -1, "00 PROGRAM"},
        {"@00SC0252*\r", "SC change mode", "", -1, "02 MONITOR"},
        {"@00SC0353*\r", "SC change mode", "", -1, "03 RUN"},
        {"@00MM40*\r", "MM read model", "", -1, ""},
        {"@00KSCIO 0010003C*\r", "KS force set", "010.00 (CIO 001000)", -1, ""},
    };
    for (const HostLinkVector &v : vectors) {
        SCOPED_TRACE(v.command);
        const DecodedFrame f = decoder.decode(transmission("host", v.command));
        EXPECT_EQ(f.kind, DecodedFrame::Kind::Request);
        EXPECT_EQ(f.protocol.toStdString(), "Host Link");
        EXPECT_EQ(f.receiver.toStdString(), "plc/PERIPHERAL");
        EXPECT_EQ(f.station, 0);
        EXPECT_EQ(f.command, QByteArray(v.command).at(3) << 8 | QByteArray(v.command).at(4));
        EXPECT_EQ(f.commandText.toStdString(), v.commandText);
        EXPECT_EQ(f.address.toStdString(), v.address);
        EXPECT_EQ(f.count, v.count);
        EXPECT_EQ(f.data.toStdString(), v.data);
        EXPECT_EQ(f.problem.toStdString(), "");
        EXPECT_EQ(f.errorCode, -1);
        EXPECT_FALSE(f.previousUnanswered);
        decoder.reset(); // no reply here: the next vector is not a request after a silent one
    }
    // Unit 01 is not on the wire: the command reads, but nobody is there to answer it.
    const DecodedFrame elsewhere = decoder.decode(transmission("host", "@01RD0000000156*\r"));
    EXPECT_EQ(elsewhere.protocol.toStdString(), "Host Link");
    EXPECT_EQ(elsewhere.station, 1);
    EXPECT_EQ(elsewhere.receiver.toStdString(), "");
    EXPECT_EQ(elsewhere.problem.toStdString(), "");
}

// The spec's read of DM 0000 on a running CPM1 (MOV #1234 DM0000): the PLC's reply read
// against it, with the request's address and the word it carries.
TEST(TrafficDecode, AHostLinkReadOfDmAndItsReplyOnARun) {
    std::vector<TrafficRecord> records;
    const std::vector<DecodedFrame> f = hostLinkExchange("@00RD0000000157*\r", &records);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(records[1].bytes, QByteArray("@00RD00123452*\r"));
    const DecodedFrame &reply = f[1];
    EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(reply.protocol.toStdString(), "Host Link");
    EXPECT_EQ(reply.receiver.toStdString(), "host");
    EXPECT_EQ(reply.station, 0);
    EXPECT_EQ(reply.commandText.toStdString(), "RD read DM words");
    EXPECT_EQ(reply.address.toStdString(), "DM 0000 (0000)");
    EXPECT_EQ(reply.count, 1);
    EXPECT_EQ(reply.data.toStdString(), "1234");
    EXPECT_EQ(reply.errorCode, -1);
    EXPECT_EQ(reply.problem.toStdString(), "");
}

// W353, TEST: the PLC returns the characters without an end code; the reply reads as an
// answer with the characters as its data, with its command seen and alone.
TEST(TrafficDecode, AHostLinkTestReturnsItsCharactersWithoutAnEndCode) {
    const QByteArray command = comms::hostlink::encode({0, "TS", -1, "HELLO 123"}).front();
    std::vector<TrafficRecord> records;
    const std::vector<DecodedFrame> f = hostLinkExchange(command, &records);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(records[1].bytes, command) << "the echo is the command itself";
    EXPECT_EQ(f[0].commandText.toStdString(), "TS test");
    EXPECT_EQ(f[0].data.toStdString(), "HELLO 123");
    const NetRun other = runNetwork(kHostAndCpm1, kCpm1);
    ASSERT_TRUE(other.net);
    const DecodedFrame alone = TrafficDecoder(*other.net).decode(records[1]);
    for (const DecodedFrame &reply : {f[1], alone}) {
        EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
        EXPECT_EQ(reply.commandText.toStdString(), "TS test");
        EXPECT_EQ(reply.data.toStdString(), "HELLO 123");
        EXPECT_EQ(reply.errorCode, -1);
        EXPECT_EQ(reply.problem.toStdString(), "");
        EXPECT_FALSE(reply.failed());
    }
}

// W353: a write in RUN is refused with end code 01; the reply says the PLC's code and its
// text (the PLC's answer, not a fault of the frame).
TEST(TrafficDecode, AHostLinkWriteRefusedInRunSaysEndCode01) {
    std::vector<TrafficRecord> records;
    const std::vector<DecodedFrame> f = hostLinkExchange("@00WD0100123456*\r", &records);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(records[1].bytes, QByteArray("@00WD0152*\r"));
    EXPECT_EQ(f[0].problem.toStdString(), "");
    EXPECT_EQ(f[0].data.toStdString(), "1234");
    const DecodedFrame &reply = f[1];
    EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(reply.commandText.toStdString(), "WD write DM words");
    EXPECT_EQ(reply.address.toStdString(), "DM 0100 (0100)");
    EXPECT_EQ(reply.errorCode, 0x01);
    EXPECT_EQ(reply.errorText, comms::hostlink::endCodeText(0x01));
    EXPECT_NE(reply.errorText.indexOf(QStringLiteral("end code 01")), -1)
        << reply.errorText.toStdString();
    EXPECT_EQ(reply.problem.toStdString(), "");
    EXPECT_TRUE(reply.failed());
}

// The spec's read of DM 0000 with its FCS spoiled (58 for 57): the command says both FCSs,
// and the PLC's answer, end code 13, is read against it.
TEST(TrafficDecode, AHostLinkCommandWithAWrongFcsAndThePlcsEndCode13) {
    std::vector<TrafficRecord> records;
    const std::vector<DecodedFrame> f = hostLinkExchange("@00RD0000000158*\r", &records);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(f[0].problem.toStdString(),
              "wrong FCS (received 58, computed 57): the PLC answers end code 13");
    EXPECT_EQ(f[0].receiver.toStdString(), "plc/PERIPHERAL");
    EXPECT_EQ(f[0].commandText.toStdString(), "RD read DM words");
    EXPECT_EQ(records[1].bytes.left(7), QByteArray("@00RD13"));
    EXPECT_EQ(f[1].errorCode, 0x13);
    EXPECT_EQ(f[1].errorText, comms::hostlink::endCodeText(0x13));
    EXPECT_EQ(f[1].problem.toStdString(), "");
}

// The cpm1-host-link example: the peripheral port is on no wire of the file, and its bridge's
// real line joins it when the bridge opens, after the decoder learnt the wiring (the IDE's
// Traffic view learns it when the session is built). The decoder knows the line and its wire
// from the file's bridges: the host's read through the line is a Host Link command, the
// PLC's answer its reply.
TEST(TrafficDecode, TheCpm1ExamplesBridgedPortIsDecodedThoughTheLineOpensLater) {
    NetRun run =
        runNetwork({}, {}, {},
                   QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/cpm1-host-link/"
                                                  "cpm1-host-link.rungnet"));
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    QString error;
    std::shared_ptr<comms::Transport> pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    BridgeEndpoint *line =
        attachBridgeLine(*run.net, QStringLiteral("cpm1/PERIPHERAL"), pty, &error);
    ASSERT_NE(line, nullptr) << error.toStdString();
    ASSERT_TRUE(run.net->runUntil(100'000));
    run.net->inject(line, "@00RD0000000157*\r");
    ASSERT_TRUE(run.net->runUntil(200'000));
    ASSERT_EQ(run.records.size(), 2u);
    const DecodedFrame request = decoder.decode(run.records[0]);
    EXPECT_EQ(run.records[0].sender.toStdString(), "bridge:cpm1/PERIPHERAL");
    EXPECT_EQ(request.kind, DecodedFrame::Kind::Request);
    EXPECT_EQ(request.protocol.toStdString(), "Host Link");
    EXPECT_EQ(request.receiver.toStdString(), "cpm1/PERIPHERAL");
    EXPECT_EQ(request.commandText.toStdString(), "RD read DM words");
    EXPECT_EQ(request.address.toStdString(), "DM 0000 (0000)");
    const DecodedFrame reply = decoder.decode(run.records[1]);
    EXPECT_EQ(reply.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(reply.receiver.toStdString(), "bridge:cpm1/PERIPHERAL");
    EXPECT_EQ(reply.data.toStdString(), "0000"); // the batch count after a start
    EXPECT_EQ(reply.problem.toStdString(), "");
    EXPECT_EQ(decoder.ownerOf(QStringLiteral("bridge:cpm1/PERIPHERAL")).toStdString(),
              "bridge:cpm1/PERIPHERAL");
}

// Frames cut short (no "*" CR) and bytes that are no frame: what is wrong, never a crash; the
// host's text that is no command stays text.
TEST(TrafficDecode, AHostLinkFrameCutShortOrNoFrameSaysWhatIsWrong) {
    const NetRun run = runNetwork(kHostAndCpm1, kCpm1);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    const DecodedFrame cut = decoder.decode(transmission("host", "@00RD00000001"));
    EXPECT_EQ(cut.protocol.toStdString(), "Host Link");
    EXPECT_NE(cut.problem.indexOf(QStringLiteral("stops after 13 byte")), -1)
        << cut.problem.toStdString();
    EXPECT_EQ(cut.station, 0);
    EXPECT_EQ(cut.receiver.toStdString(), "plc/PERIPHERAL");
    const DecodedFrame noEnd = decoder.decode(transmission("host", "@00RD0000000157"));
    EXPECT_NE(noEnd.problem.indexOf(QStringLiteral("stops after 15 byte")), -1)
        << noEnd.problem.toStdString();
    // The PLC's reply cut short, and bytes from it that are no frame.
    decoder.decode(transmission("host", "@00RD0000000157*\r"));
    const DecodedFrame cutReply = decoder.decode(transmission("plc/PERIPHERAL", "@00RD0012"));
    EXPECT_EQ(cutReply.kind, DecodedFrame::Kind::Reply);
    EXPECT_NE(cutReply.problem.indexOf(QStringLiteral("stops after 9 byte")), -1)
        << cutReply.problem.toStdString();
    decoder.decode(transmission("host", "@00RD0000000157*\r"));
    const DecodedFrame noise = decoder.decode(transmission("plc/PERIPHERAL", "\x13\xFF\r"));
    EXPECT_NE(noise.problem.indexOf(QStringLiteral("not a Host Link answer")), -1)
        << noise.problem.toStdString();
    // A reply whose FCS is wrong.
    decoder.decode(transmission("host", "@00RD0000000157*\r"));
    const DecodedFrame badFcs = decoder.decode(transmission("plc/PERIPHERAL", "@00RD00123453*\r"));
    EXPECT_NE(badFcs.problem.indexOf(QStringLiteral("received 53, computed 52")), -1)
        << badFcs.problem.toStdString();
    // Text from the host that is no command is the host's text.
    const DecodedFrame text = decoder.decode(transmission("host", "HELLO\r"));
    EXPECT_EQ(text.kind, DecodedFrame::Kind::Raw);
    EXPECT_EQ(text.data.toStdString(), "HELLO\\r");
}

// A command the PLC does not have ("XX") gets IC: no end code, the reply says so.
TEST(TrafficDecode, AHostLinkCommandThePlcDoesNotKnowIsAnsweredIc) {
    QByteArray command = "@00XX";
    command += comms::hostlink::fcs(command) + "*\r";
    std::vector<TrafficRecord> records;
    const std::vector<DecodedFrame> f = hostLinkExchange(command, &records);
    ASSERT_EQ(f.size(), 2u);
    EXPECT_EQ(f[0].commandText.toStdString(), "XX unknown command");
    EXPECT_EQ(records[1].bytes.left(5), QByteArray("@00IC"));
    EXPECT_EQ(f[1].commandText.toStdString(), "IC command not recognised");
    EXPECT_EQ(f[1].errorCode, -1);
    EXPECT_NE(f[1].problem.indexOf(QStringLiteral("(IC)")), -1) << f[1].problem.toStdString();
}

// W353: a frame over 131 characters goes in parts; the other side answers a lone CR after
// each part but the last. A read of 40 DM words (a reply of 30 then 10 words) and a write of
// 40 (a command in two parts), as the product's codec writes them: every part is read, the
// last with the whole frame's data.
TEST(TrafficDecode, HostLinkFramesInPartsAndTheirDelimiters) {
    namespace hl = comms::hostlink;
    const NetRun run = runNetwork(kHostAndCpm1, kCpm1);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    std::vector<std::uint16_t> words;
    QByteArray text;
    QStringList expected;
    for (int i = 0; i < 40; ++i) {
        words.push_back(std::uint16_t(0x1000 + i));
        text += QByteArray::number(0x1000 + i, 16).toUpper();
        expected << QString::number(0x1000 + i, 16).toUpper();
    }
    const hl::Frame read = hl::readCommand(0, model::ProtocolSpace::HostLinkDm, 0, 40);
    ASSERT_EQ(hl::encode(read).size(), 1);
    const QList<QByteArray> replyParts = hl::encode({0, "RD", 0, text});
    ASSERT_EQ(replyParts.size(), 2);
    EXPECT_EQ(decoder.decode(transmission("host", hl::encode(read).front())).count, 40);
    const DecodedFrame first = decoder.decode(transmission("plc/PERIPHERAL", replyParts[0]));
    EXPECT_EQ(first.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(first.problem.toStdString(), "");
    EXPECT_NE(first.data.indexOf(QStringLiteral("part 1")), -1) << first.data.toStdString();
    const DecodedFrame more = decoder.decode(transmission("host", "\r"));
    EXPECT_EQ(more.protocol.toStdString(), "Host Link");
    EXPECT_EQ(more.commandText.toStdString(), "RD read DM words");
    EXPECT_EQ(more.data.toStdString(), "CR: the next part, please");
    EXPECT_EQ(more.problem.toStdString(), "");
    EXPECT_FALSE(more.previousUnanswered);
    const DecodedFrame last = decoder.decode(transmission("plc/PERIPHERAL", replyParts[1]));
    EXPECT_EQ(last.problem.toStdString(), "");
    EXPECT_EQ(last.address.toStdString(), "DM 0000 (0000)");
    EXPECT_EQ(last.data, expected.join(u' '));

    const QList<QByteArray> commandParts =
        hl::encode(hl::writeCommand(0, model::ProtocolSpace::HostLinkDm, 100, words));
    ASSERT_EQ(commandParts.size(), 2);
    const DecodedFrame part1 = decoder.decode(transmission("host", commandParts[0]));
    EXPECT_EQ(part1.commandText.toStdString(), "WD write DM words");
    EXPECT_EQ(part1.problem.toStdString(), "");
    EXPECT_FALSE(part1.previousUnanswered) << "the read was answered";
    EXPECT_NE(part1.data.indexOf(QStringLiteral("part 1")), -1) << part1.data.toStdString();
    const DecodedFrame delimiter = decoder.decode(transmission("plc/PERIPHERAL", "\r"));
    EXPECT_EQ(delimiter.kind, DecodedFrame::Kind::Reply);
    EXPECT_EQ(delimiter.data.toStdString(), "CR: the next part, please");
    EXPECT_EQ(delimiter.receiver.toStdString(), "host");
    const DecodedFrame part2 = decoder.decode(transmission("host", commandParts[1]));
    EXPECT_EQ(part2.problem.toStdString(), "");
    EXPECT_EQ(part2.address.toStdString(), "DM 0100 (0100)");
    EXPECT_EQ(part2.count, 40);
    EXPECT_EQ(part2.data, expected.join(u' '));
    const DecodedFrame refused = decoder.decode(transmission("plc/PERIPHERAL", "@00WD0152*\r"));
    EXPECT_EQ(refused.errorCode, 0x01);
    EXPECT_EQ(refused.count, 40);
}

// Whatever comes on a Host Link wire, from the host or the PLC, in whatever order: every
// prefix of the spec's vectors and of their replies, and bytes made of the characters Host
// Link frames are built of, are read as something, never a crash; a cut vector says so.
TEST(TrafficDecode, AnyBytesOnAHostLinkWireAreReadWithoutACrash) {
    const NetRun run = runNetwork(kHostAndCpm1, kCpm1);
    ASSERT_TRUE(run.net) << run.error.toStdString();
    TrafficDecoder decoder(*run.net);
    const QByteArray frames[] = {"@00RD0000000157*\r", "@00RD00123452*\r",     "@00WD0100123456*\r",
                                 "@00WD0152*\r",       "@00KSCIO 0010003C*\r", "@00MS5E*\r"};
    for (const QByteArray &frame : frames)
        for (qsizetype n = 1; n <= frame.size(); ++n)
            for (const char *sender : {"host", "plc/PERIPHERAL"}) {
                const DecodedFrame f = decoder.decode(transmission(sender, frame.first(n)));
                EXPECT_FALSE(f.protocol.isEmpty()) << sender << ' ' << frame.first(n).data();
                if (n < frame.size() - 1 && frame.front() == '@' && sender[0] == 'h')
                    EXPECT_TRUE(f.failed()) << frame.first(n).data();
            }
    std::mt19937 random(30);
    const QByteArray alphabet = "@*\r0123456789ABCDEFRDWMSCKI ";
    for (int i = 0; i < 3000; ++i) {
        QByteArray bytes;
        const int size = 1 + int(random() % 300);
        for (int c = 0; c < size; ++c)
            bytes += alphabet[qsizetype(random() % std::uint32_t(alphabet.size()))];
        const DecodedFrame f =
            decoder.decode(transmission(random() % 2 ? "host" : "plc/PERIPHERAL", bytes));
        EXPECT_FALSE(f.protocol.isEmpty()) << bytes.data();
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
