// Vigor MBUS (Vigor M/VB/VH communication manual, B-3-6): the programming example's table of
// three sets against simulated MODBUS slaves, frame by frame, and the application example of
// three VB PLCs (resources/examples/networks); each under a fault, shown in the working area
// S2 as the manual lists the codes.

#include "network_fixture.h"

#include "network/devices.h"

#include "comms/protocol/modbus.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kTable = QStringLiteral(
    RUNG_SOURCE_DIR "/resources/examples/networks/modbus-table/modbus-table.rungnet");
const QString kApplication =
    QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/modbus/modbus.rungnet");

std::unique_ptr<Network> build(const QString &file, const std::vector<FaultDescription> &faults,
                               std::vector<TrafficRecord> *records) {
    NetworkDescription d;
    QString error;
    EXPECT_TRUE(readNetworkFile(file, &d, &error)) << error.toStdString();
    d.faults = faults;
    auto net = Network::build(d, listingLoader(), &error);
    EXPECT_TRUE(net) << error.toStdString();
    if (net && records)
        net->setTrafficSink([records](const TrafficRecord &t) { records->push_back(t); });
    return net;
}

void write(Network &net, const char *station, const char *device, int v) {
    Station *s = net.station(QString::fromLatin1(station));
    s->engine().writeWord(
        std::get<model::Address>(model::parseAddress(s->target(), QString::fromLatin1(device))), v);
}

QByteArray rtu(const char *hexPdu, int unit) {
    return comms::modbus::rtuFrame(unit, hex(hexPdu));
}

} // namespace

// Set 1 reads 40000..40009 of station 5 into D2000..D2009 (function 03), set 2 writes
// D2010..D2014 to 41000..41004 of station 2 (10h), set 3 writes D2015 to 42000 of station 3
// (06h, the length ignored); M9199 ON for a scan after each complete table.
TEST(Mbus, TheProgrammingExamplesTableRunsItsThreeSets) {
    std::vector<TrafficRecord> records;
    auto net = build(kTable, {}, &records);
    ASSERT_TRUE(net);
    for (int k = 0; k < 5; ++k)
        write(*net, "master", QStringLiteral("D%1").arg(2010 + k).toLatin1().constData(), 11 + k);
    write(*net, "master", "D2015", 0x1234);
    bool pulse = false;
    for (qint64 t = 0; t <= 300'000; t += 10'000) {
        net->runUntil(t);
        pulse = pulse || bit(*net, QStringLiteral("master"), QStringLiteral("M9199"));
    }
    EXPECT_TRUE(pulse);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D%1").arg(2000 + k)),
                  100 + k);
    auto *s2 = dynamic_cast<ModbusSlaveDevice *>(net->endpoint(QStringLiteral("s2")));
    auto *s3 = dynamic_cast<ModbusSlaveDevice *>(net->endpoint(QStringLiteral("s3")));
    ASSERT_TRUE(s2 && s3);
    for (int k = 0; k < 5; ++k)
        EXPECT_EQ(s2->holding.at(1000 + k), 11 + k);
    EXPECT_EQ(s3->holding.at(2000), 0x1234);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0);
    // The frames: the master's requests in the order of the table, each answered.
    std::vector<QByteArray> sent;
    for (const TrafficRecord &t : records)
        if (t.sender == QLatin1String("master/CP2"))
            sent.push_back(t.bytes);
    ASSERT_GE(sent.size(), 6u);
    EXPECT_EQ(sent[0], rtu("03 0000 000A", 5));
    EXPECT_EQ(sent[1], rtu("10 03E8 0005 0A 000B 000C 000D 000E 000F", 2));
    EXPECT_EQ(sent[2], rtu("06 07D0 1234", 3));
    EXPECT_EQ(sent[3], sent[0]); // and again from the first set
}

// A slave that does not answer: its set ends after D9129's time-out (0: 100 ms) with status A
// and its station in S2's low byte, and the other sets run; a clean table clears S2.
TEST(Mbus, ASilentSlaveShowsNoResponseA) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Silent;
    f.station = QStringLiteral("s5");
    f.fromMs = 0;
    f.toMs = 500;
    auto net = build(kTable, {f}, nullptr);
    ASSERT_TRUE(net);
    write(*net, "master", "D2015", 77);
    net->runUntil(300'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0x0A05);
    auto *s3 = dynamic_cast<ModbusSlaveDevice *>(net->endpoint(QStringLiteral("s3")));
    EXPECT_EQ(s3->holding.at(2000), 77);
    net->runUntil(1'000'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D2009")), 109);
}

// D9129 sets the time-out in 10 ms: 3 -> 30 ms, so a silent slave costs 30 ms, not 100.
TEST(Mbus, D9129SetsTheTimeOut) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Silent;
    f.station = QStringLiteral("s5");
    std::vector<TrafficRecord> records;
    auto net = build(kTable, {f}, &records);
    ASSERT_TRUE(net);
    write(*net, "master", "D9129", 3);
    net->runUntil(200'000);
    std::vector<qint64> starts;
    for (const TrafficRecord &t : records)
        if (t.sender == QLatin1String("master/CP2") && t.bytes.at(0) == 5)
            starts.push_back(t.startUs);
    ASSERT_GE(starts.size(), 2u);
    // The request leaves, 30 ms pass after its last byte, the next END goes on: the second
    // request to station 5 comes one table later, well before 100 ms.
    EXPECT_LT(starts[1] - starts[0], 100'000);
}

// A slave that refuses (exception 02, an address its map lacks): abnormal communication, B.
TEST(Mbus, AnExceptionReplyShowsAbnormalB) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(kTable, &d, &error)) << error.toStdString();
    for (DeviceDescription &dev : d.devices)
        if (dev.name == QLatin1String("s2"))
            dev.json.insert(QStringLiteral("registers"), QJsonObject{{QStringLiteral("1000"), 0}});
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    net->runUntil(60'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0x0B02);
}

// A corrupted byte in station 5's reply: the CRC is wrong, the master takes it as abnormal.
TEST(Mbus, ACorruptedReplyShowsAbnormalB) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Corrupt;
    f.wire = QStringLiteral("w1");
    f.frame = 1; // the reply to the first request
    f.byte = 4;
    auto net = build(kTable, {f}, nullptr);
    ASSERT_TRUE(net);
    net->runUntil(45'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0x0B05);
}

// A wrong table: a slave data type MBUS does not know (2) is status 4 (a wrong device type),
// found before anything is sent; it stays while the table holds it.
TEST(Mbus, AWrongSlaveTypeShowsStatus4) {
    auto net = build(kTable, {}, nullptr);
    ASSERT_TRUE(net);
    net->runUntil(10'000); // the first scan writes the table
    write(*net, "master", "D1006", 2);
    net->runUntil(300'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0x0405);
}

// B-3-6's application example: slave 1 shows the master's VR1 (its D100), slave 2 the
// master's VR2; the master shows each slave's VR1 scaled to 0..99 ("D10x99/255 -> D0", MUL
// and DDIV) in D10 (right) and D11 (left).
TEST(Mbus, TheApplicationExampleShowsEachOthersVolumes) {
    auto net = build(kApplication, {}, nullptr);
    ASSERT_TRUE(net);
    write(*net, "master", "VR1", 200);
    write(*net, "master", "VR2", 30);
    write(*net, "s1", "VR1", 255);
    write(*net, "s2", "VR1", 120);
    net->runUntil(500'000);
    EXPECT_EQ(value(*net, QStringLiteral("s1"), QStringLiteral("D100")), 200);
    EXPECT_EQ(value(*net, QStringLiteral("s2"), QStringLiteral("D100")), 30);
    EXPECT_EQ(value(*net, QStringLiteral("s1"), QStringLiteral("D0")), 99); // 255 x 99 / 255
    EXPECT_EQ(value(*net, QStringLiteral("s2"), QStringLiteral("D0")), 46); // 11880 / 255
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D10")), 99);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D11")), 46);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D9080")), 4);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0);
}

// The same with slave 2 at another baud rate: it reads garbage and never answers; the master
// shows A with station 2, slave 1's exchange goes on.
TEST(Mbus, TheApplicationExampleWithAMismatchedSlave) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(kApplication, &d, &error)) << error.toStdString();
    for (StationDescription &s : d.stations)
        if (s.name == QLatin1String("s2")) {
            QJsonObject cp2 = s.ports.value(QStringLiteral("CP2")).toObject();
            cp2.insert(QStringLiteral("baud"), 9600);
            s.ports.insert(QStringLiteral("CP2"), cp2);
        }
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    write(*net, "master", "VR1", 200);
    write(*net, "s1", "VR1", 255);
    net->runUntil(500'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0x0A02);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D10")), 99);
    EXPECT_EQ(value(*net, QStringLiteral("s1"), QStringLiteral("D100")), 200);
}

// The application example in MODBUS ASCII (CP2 "Modbus", mode ASCII, B-3-6), 7E1 on every
// station: the same exchange, the frames ':' .. LRC CR LF.
TEST(Mbus, TheApplicationExampleInAscii) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(kApplication, &d, &error)) << error.toStdString();
    for (StationDescription &s : d.stations) {
        QJsonObject cp2 = s.ports.value(QStringLiteral("CP2")).toObject();
        cp2.insert(QStringLiteral("mode"), QStringLiteral("ascii"));
        cp2.insert(QStringLiteral("frame"), QStringLiteral("7E1"));
        s.ports.insert(QStringLiteral("CP2"), cp2);
    }
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    std::vector<TrafficRecord> records;
    net->setTrafficSink([&records](const TrafficRecord &t) { records.push_back(t); });
    write(*net, "master", "VR1", 200);
    write(*net, "s1", "VR1", 255);
    net->runUntil(500'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D10")), 99);
    EXPECT_EQ(value(*net, QStringLiteral("s1"), QStringLiteral("D100")), 200);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D100")), 0);
    ASSERT_GE(records.size(), 2u);
    // Read station 1, holding register 0, one register: 01 03 0000 0001, LRC FBh.
    EXPECT_EQ(records[0].bytes, QByteArray(":010300000001FB\r\n"));
    EXPECT_EQ(records[1].bytes, QByteArray(":0103020063"
                                           "97\r\n"));
}

// A PL110 on the wire as the MODBUS RTU slave of its COM1 (PL110 manual, chapter 3): a Vigor
// MBUS reads its V0 (holding register 2000 of the PL110's map) into D10.
TEST(Mbus, AVigorMasterReadsAPl110) {
    NetRun r = runNetwork(
        R"({"stations": [
        {"name": "vb", "program": "m.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 0}}},
        {"name": "pl", "program": "p.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus", "station": 1}}}],
        "wires": [["vb/CP2", "pl/COM1"]]})",
        {{QStringLiteral("m.il"),
          QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K1 D1001\n"
                         "MOV K1 D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K10 "
                         "D1005\nMOV K4 D1006\nMOV K2000 D1007\nLD M9000\nMBUS "
                         "D1000 D100\nEND\n")},
         {QStringLiteral("p.il"), QStringLiteral("; target: pl110\nLD SM0.0\nMOV 321 V0\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(200'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 321);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D100")), 0);
}
