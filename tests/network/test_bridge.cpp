// Bridges (docs/network.md): a station's port on a real pseudo-terminal, the network in real
// time. A master on the other end (here the test, as an HMI would) polls the simulated PLC
// with the product's own Modbus RTU codec over the real pty, and the PLC answers from its
// program's memory; a port whose frames are unpublished is never bridged.

#include "network_fixture.h"

#include "network/bridge.h"

#include "comms/protocol/host_link_master.h"
#include "comms/protocol/modbus_master.h"
#include "comms/transport/pty_transport.h"
#include "comms/transport/tcp_listen_transport.h"

#include <QDeadlineTimer>

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const char *kSlave = "; target: vigor\nLD M9000\nMOV K321 D0\nEND\n";

// A request through the pty, the network turned until its reply is whole (at most 3 s).
comms::FrameStatus poll(RealTime &rt, comms::Transport &hmi, comms::modbus::ReplyDecoder &reply,
                        const QByteArray &request) {
    QString error;
    EXPECT_TRUE(hmi.write(request, QDeadlineTimer(1000), &error)) << error.toStdString();
    const QDeadlineTimer deadline(3000);
    while (reply.status() == comms::FrameStatus::NeedMore && !deadline.hasExpired()) {
        QString failure;
        EXPECT_TRUE(rt.turn(2, &failure)) << failure.toStdString();
        const comms::ReadResult r = hmi.read(QDeadlineTimer(1));
        if (r.status == comms::ReadResult::Status::Data)
            reply.feed(r.bytes);
    }
    return reply.status();
}

// A Host Link command through the pty, the network turned until its reply is whole (at most
// 3 s), the parts of a long one asked for with a CR as the master does.
comms::FrameStatus command(RealTime &rt, comms::Transport &host,
                           comms::hostlink::ReplyDecoder &reply,
                           const comms::hostlink::Frame &frame) {
    QString error;
    for (const QByteArray &part : comms::hostlink::encode(frame))
        EXPECT_TRUE(host.write(part, QDeadlineTimer(1000), &error)) << error.toStdString();
    const QDeadlineTimer deadline(3000);
    comms::FrameStatus status = comms::FrameStatus::NeedMore;
    while (status == comms::FrameStatus::NeedMore && !deadline.hasExpired()) {
        QString failure;
        EXPECT_TRUE(rt.turn(2, &failure)) << failure.toStdString();
        const comms::ReadResult r = host.read(QDeadlineTimer(1));
        if (r.status == comms::ReadResult::Status::Data)
            status = reply.feed(r.bytes);
        if (reply.takeDelimiterRequest())
            EXPECT_TRUE(host.write("\r", QDeadlineTimer(1000), &error));
    }
    return status;
}

} // namespace

TEST(Bridge, ARealMasterPollsASimulatedSlaveThroughAPty) {
    NetRun r = runNetwork(R"({"stations": [{"name": "plc", "program": "s.il", "model": "VB",
                              "ports": {"CP2": {"application": "modbus", "station": 1}}}]})",
                          {{QStringLiteral("s.il"), QString::fromLatin1(kSlave)}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    QString error;
    auto pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    comms::PtyTransport hmi(pty->peerPath());
    ASSERT_TRUE(hmi.open(&error)) << error.toStdString();
    RealTime rt(*r.net);
    ASSERT_TRUE(rt.addBridge(QStringLiteral("plc/CP2"), std::move(pty), &error))
        << error.toStdString();
    comms::modbus::Request read;
    read.function = comms::modbus::ReadHoldingRegisters;
    read.address = 0; // D0
    read.count = 1;
    comms::modbus::ReplyDecoder reply(comms::modbus::Framing::Rtu, 1, read);
    ASSERT_EQ(
        poll(rt, hmi, reply, comms::modbus::rtuFrame(1, comms::modbus::encodeRequestPdu(read))),
        comms::FrameStatus::Complete)
        << reply.error().message.toStdString();
    EXPECT_EQ(reply.response().registers, (std::vector<std::uint16_t>{321}));
    // The traffic shows the real line's bytes on the wire, as a station's would be.
    bool fromBridge = false;
    for (const TrafficRecord &t : r.records)
        fromBridge = fromBridge || t.sender == QLatin1String("bridge:plc/CP2");
    EXPECT_TRUE(fromBridge);
}

// A "listen" bridge: the port waits on TCP for a master (an HMI or SCADA carrying RTU frames
// over raw TCP, as to a serial device server in server mode). A master that leaves does not
// end the line: the next one that connects is answered.
TEST(Bridge, MastersConnectingOverTcpOneAfterTheOtherPollASimulatedSlave) {
    NetRun r = runNetwork(R"({"stations": [{"name": "plc", "program": "s.il", "model": "VB",
                              "ports": {"CP2": {"application": "modbus", "station": 1}}}]})",
                          {{QStringLiteral("s.il"), QString::fromLatin1(kSlave)}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    RealTime rt(*r.net);
    BridgeDescription listen;
    listen.end = QStringLiteral("plc/CP2");
    listen.kind = BridgeDescription::Kind::Listen;
    listen.where = QStringLiteral("127.0.0.1:0");
    listen.path = QStringLiteral("bridges[0]");
    QString where, error;
    ASSERT_TRUE(rt.addBridge(listen, &where, &error)) << error.toStdString();
    ASSERT_TRUE(where.startsWith(QStringLiteral("127.0.0.1:"))) << where.toStdString();
    const quint16 port = quint16(where.section(QLatin1Char(':'), 1).toUInt());
    ASSERT_NE(port, 0);
    comms::modbus::Request read;
    read.function = comms::modbus::ReadHoldingRegisters;
    read.address = 0; // D0
    read.count = 1;
    for (int client = 0; client < 2; ++client) {
        comms::TcpTransport hmi(QStringLiteral("127.0.0.1"), port);
        ASSERT_TRUE(hmi.open(&error)) << error.toStdString();
        comms::modbus::ReplyDecoder reply(comms::modbus::Framing::Rtu, 1, read);
        ASSERT_EQ(
            poll(rt, hmi, reply, comms::modbus::rtuFrame(1, comms::modbus::encodeRequestPdu(read))),
            comms::FrameStatus::Complete)
            << "client " << client << ": " << reply.error().message.toStdString();
        EXPECT_EQ(reply.response().registers, (std::vector<std::uint16_t>{321})) << client;
    } // each client closes its connection here
}

// HOST:PORT, read in one place for the file, the bridge dialog and the lines: split at the
// last colon (an IPv6 address keeps its own), a port of 0..65535, a host before it.
TEST(Bridge, HostAndPortAreSplitAtTheLastColon) {
    const auto a = splitHostPort(QStringLiteral("192.168.1.50:4001"));
    ASSERT_TRUE(a);
    EXPECT_EQ(a->host, QStringLiteral("192.168.1.50"));
    EXPECT_EQ(a->port, 4001);
    const auto b = splitHostPort(QStringLiteral("::1:502"));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->host, QStringLiteral("::1"));
    EXPECT_EQ(b->port, 502);
    EXPECT_EQ(splitHostPort(QStringLiteral("0.0.0.0:0"))->port, 0);
    for (const char *bad : {"plc", "plc:", ":502", "plc:70000", "plc:50x", "plc:-1"})
        EXPECT_FALSE(splitHostPort(QString::fromLatin1(bad))) << bad;
}

TEST(Bridge, AListenAddressThatIsNotOneIsRefusedWithWhatAndWhere) {
    NetRun r = runNetwork(R"({"stations": [{"name": "plc", "program": "s.il", "model": "VB",
                              "ports": {"CP2": {"application": "modbus", "station": 1}}}]})",
                          {{QStringLiteral("s.il"), QString::fromLatin1(kSlave)}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    RealTime rt(*r.net);
    BridgeDescription listen;
    listen.end = QStringLiteral("plc/CP2");
    listen.kind = BridgeDescription::Kind::Listen;
    listen.where = QStringLiteral("plc.example:5020");
    listen.path = QStringLiteral("bridges[0]");
    QString where, error;
    EXPECT_FALSE(rt.addBridge(listen, &where, &error));
    EXPECT_TRUE(error.startsWith(QStringLiteral("bridges[0].listen: \"plc.example:5020\"")))
        << error.toStdString();
}

TEST(Bridge, ACpuLinkPortIsNeverPutOnARealLine) {
    NetRun r = runNetwork(
        {}, {}, {},
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/cpu-link/cpu-link.rungnet"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    QString error;
    auto pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    RealTime rt(*r.net);
    EXPECT_FALSE(rt.addBridge(QStringLiteral("master/CP2"), std::move(pty), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("does not publish"))) << error.toStdString();
}

// The CPM1's peripheral port (Omron CPM1 guide 2.1, item 9 "Perifériacsatlakozó", for
// "Monitorozás (PLC-PC on-line kapcsolat)") bridged to a pseudo-terminal, at its Host Link
// defaults (9600 7E2, unit 0): a host reads DM 0000 with the product's own Host Link codec,
// "@00RD0000000157*" (C-mode, Omron's public Host Link documentation), switches the PLC to
// MONITOR and writes DM 0100 ("@00WD0100123456*"). (The COMM lamp's timing is tested on
// virtual time alone: Cpm1PeripheralPort.*.)
TEST(Bridge, AHostLinkMasterReadsACpm1ThroughItsPeripheralPortOnAPty) {
    namespace hl = comms::hostlink;
    NetRun r = runNetwork(
        R"({"stations": [{"name": "plc", "program": "c.il",
                              "model": "CPM1-20CDR", "ports": {"PERIPHERAL": {}}}]})",
        {{QStringLiteral("c.il"), QStringLiteral("; target: cpm1\nLD 253.13\nMOV(21) #1234 DM0000\n"
                                                 "END(01)\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station *plc = r.net->station(QStringLiteral("plc"));
    ASSERT_NE(plc, nullptr);
    QString error;
    auto pty = comms::PtyTransport::createPair(&error);
    ASSERT_TRUE(pty) << error.toStdString();
    comms::PtyTransport host(pty->peerPath());
    ASSERT_TRUE(host.open(&error)) << error.toStdString();
    RealTime rt(*r.net);
    ASSERT_TRUE(rt.addBridge(QStringLiteral("plc/PERIPHERAL"), std::move(pty), &error))
        << error.toStdString();
    EXPECT_EQ(plc->snapshot().communicatedUs, -1) << "nothing on the port yet";

    const hl::Frame read = hl::readCommand(0, model::ProtocolSpace::HostLinkDm, 0, 1);
    EXPECT_EQ(hl::encode(read), QList<QByteArray>{"@00RD0000000157*\r"});
    hl::ReplyDecoder reply(read);
    ASSERT_EQ(command(rt, host, reply, read), comms::FrameStatus::Complete)
        << reply.error().message.toStdString();
    EXPECT_EQ(reply.reply().frame.endCode, 0);
    EXPECT_EQ(reply.reply().words, (std::vector<std::uint16_t>{0x1234}));
    EXPECT_GE(plc->snapshot().communicatedUs, 0);

    // Writes are refused in RUN (end code 01): MONITOR first, as the IDE's master does.
    const hl::Frame monitor = hl::modeCommand(0, hl::Mode::Monitor);
    hl::ReplyDecoder switched(monitor);
    ASSERT_EQ(command(rt, host, switched, monitor), comms::FrameStatus::Complete);
    EXPECT_EQ(switched.reply().frame.endCode, 0);
    const hl::Frame write = hl::writeCommand(0, model::ProtocolSpace::HostLinkDm, 100, {0x1234});
    EXPECT_EQ(hl::encode(write), QList<QByteArray>{"@00WD0100123456*\r"});
    hl::ReplyDecoder written(write);
    ASSERT_EQ(command(rt, host, written, write), comms::FrameStatus::Complete);
    EXPECT_EQ(written.reply().frame.endCode, 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("DM0100")), 0x1234);
    const hl::Frame status = hl::statusCommand(0);
    hl::ReplyDecoder monitoring(status);
    ASSERT_EQ(command(rt, host, monitoring, status), comms::FrameStatus::Complete);
    EXPECT_EQ(hl::modeOfStatus(monitoring.reply().status), hl::Mode::Monitor)
        << "the program runs on in MONITOR";

    // The frames are on the wire as the text they are, from the real line and from the port.
    QByteArray fromHost, fromPlc;
    for (const TrafficRecord &t : r.records) {
        if (t.sender == QLatin1String("bridge:plc/PERIPHERAL"))
            fromHost += t.bytes;
        if (t.sender == QLatin1String("plc/PERIPHERAL"))
            fromPlc += t.bytes;
    }
    EXPECT_TRUE(fromHost.startsWith("@00RD0000000157*\r")) << fromHost.toStdString();
    EXPECT_TRUE(fromPlc.startsWith("@00RD001234")) << fromPlc.toStdString();
}
