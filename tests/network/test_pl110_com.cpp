// The PL110's COM / EXP master (PL110 manual 4.2.21) over MODBUS RTU: the queries' frames
// byte for byte, what they read and write, the status bits and counters of 2.1.2 (SM70, SM73,
// SM74, SM75, SM76, SM77) under a silent slave, a corrupted byte and a cut wire, read-write,
// slaves of every kind (the generic device, a Vigor, a PL110), and NAIS MATSUSHITA-MASTER,
// which puts no frame on a wire.

#include "network_fixture.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

// A PL110 whose COM1 is the MODBUS RTU master, a temperature controller as station 3.
QByteArray pl110ComNetwork(const QString &extra = {},
                           const QString &application = "modbus-master") {
    return QStringLiteral(R"({
        "stations": [{"name": "pl", "program": "p.il", "target": "pl110",
                      "ports": {"COM1": {"application": "%2"}}}],
        "devices": [{"name": "tc", "kind": "modbus-slave", "station": 3,
                     "registers": {"0": 250, "1": -10, "2": 7},
                     "coils": {"0": 1, "1": 0, "2": 1, "3": 1}}],
        "wires": [{"name": "bus", "ends": ["pl/COM1", "tc"]}]%1
    })")
        .arg(extra, application)
        .toUtf8();
}

NetRun pl110ComRun(const QString &program, const QString &extra = {},
                   const QString &application = QStringLiteral("modbus-master")) {
    return runNetwork(pl110ComNetwork(extra, application),
                      {{QStringLiteral("p.il"), QStringLiteral("; target: pl110\n") + program}});
}

std::vector<QByteArray> framesOf(const NetRun &r, const QString &sender) {
    std::vector<QByteArray> out;
    for (const TrafficRecord &t : r.records)
        if (t.sender == sender)
            out.push_back(t.bytes);
    return out;
}

int plWord(const NetRun &r, const char *device, const char *station = "pl") {
    return value(*r.net, QString::fromLatin1(station), QString::fromLatin1(device));
}

} // namespace

// COM_1 reads two words of station 3 from its register 0 into V0, V1 while its coil is ON:
// "03 03 00 00 00 02" and its CRC, again and again (continuously, 4.2.21).
TEST(Pl110Com, AReadQueryPollsTheSlaveAndStoresItsWords) {
    NetRun r = pl110ComRun(QStringLiteral("LD I1\nCOM 1 READ 3 WORD 0 V0 2\nEND\n"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station *s = r.net->station(QStringLiteral("pl"));
    s->engine().setBit(
        std::get<model::Address>(model::parseAddress(s->target(), QStringLiteral("I1"))), true);
    r.net->runUntil(200'000);
    EXPECT_EQ(plWord(r, "V0"), 250);
    EXPECT_EQ(plWord(r, "V1"), -10);
    const std::vector<QByteArray> requests = framesOf(r, QStringLiteral("pl/COM1"));
    ASSERT_GE(requests.size(), 3u); // polled, not once
    for (const QByteArray &q : requests)
        EXPECT_EQ(q, hex("03 03 00 00 00 02 C5 E9"));
    // The power-on values of 2.1.2: SM73 20 ms, SM74 5 ms, SM75 10; no error.
    EXPECT_EQ(plWord(r, "SM73"), 20);
    EXPECT_EQ(plWord(r, "SM74"), 5);
    EXPECT_EQ(plWord(r, "SM75"), 10);
    EXPECT_EQ(plWord(r, "SM70"), 0);
    EXPECT_EQ(plWord(r, "SM76"), 0);
    EXPECT_EQ(plWord(r, "SM77"), 0);
}

// The coil OFF: no query goes out.
TEST(Pl110Com, ACoilOffSendsNothing) {
    NetRun r = pl110ComRun(QStringLiteral("LD I1\nCOM 1 READ 3 WORD 0 V0 2\nEND\n"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(200'000);
    EXPECT_TRUE(framesOf(r, QStringLiteral("pl/COM1")).empty());
    EXPECT_EQ(plWord(r, "V0"), 0);
}

// Writes (function 10h with the area's words), bits read (01h) into M1.., bits written (0Fh)
// from V10's bits, several queries served one after the other by index.
TEST(Pl110Com, WritesAndBitsGoOneQueryAfterTheOther) {
    NetRun r = pl110ComRun(QStringLiteral("LD SM0.1\nMOV 123 V10\nMOV 5 V11\nLD SM0.0\n"
                                          "COM 2 WRITE 3 WORD 1 V10 1\n"
                                          "COM 1 READ 3 BIT 0 M1 4\n"
                                          "COM 3 WRITE 3 BIT 4 V11 3\nEND\n"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(300'000);
    const std::vector<QByteArray> requests = framesOf(r, QStringLiteral("pl/COM1"));
    ASSERT_GE(requests.size(), 6u);
    // By index: COM_1, COM_2, COM_3, COM_1, ...
    EXPECT_EQ(requests[0], hex("03 01 00 00 00 04 3C 2B"));
    EXPECT_EQ(requests[1], hex("03 10 00 01 00 01 02 00 7B FE C2"));
    EXPECT_EQ(requests[2].left(7), hex("03 0F 00 04 00 03 01"));
    EXPECT_EQ(static_cast<quint8>(requests[2][7]), 0x05); // V11.0..V11.2 = 1, 0, 1
    EXPECT_EQ(requests[3], requests[0]);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("pl"), QStringLiteral("M1")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("pl"), QStringLiteral("M2")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("pl"), QStringLiteral("M3")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("pl"), QStringLiteral("M4")));
    EXPECT_EQ(plWord(r, "SM70"), 0);
}

// A silent slave: every query times out (SM76 counts them); after SM75 of them in a row its
// status bit SM70.(index-1) comes ON; the PLC keeps scanning; when the slave answers again the
// bit goes OFF and the data comes.
TEST(Pl110Com, ASilentSlaveSetsTheStatusBitAfterSm75TimeOuts) {
    NetRun r = pl110ComRun(
        QStringLiteral("LD SM0.1\nMOV 3 SM75\nMOV 50 SM73\nLD SM0.0\nCOM 4 READ 3 WORD 2 V0 1\n"
                       "END\n"),
        QStringLiteral(
            R"(, "faults": [{"kind": "silent", "station": "tc", "from": 0, "to": 500}])"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(100'000); // one time-out (50 ms) so far
    EXPECT_GE(plWord(r, "SM76"), 1);
    EXPECT_EQ(plWord(r, "SM70"), 0); // fewer than SM75 in a row
    r.net->runUntil(400'000);
    EXPECT_GE(plWord(r, "SM76"), 3);
    EXPECT_EQ(plWord(r, "SM70"), 1 << 3); // COM_4: bit 3
    EXPECT_EQ(plWord(r, "V0"), 0);
    EXPECT_EQ(plWord(r, "SM77"), 0);
    r.net->runUntil(650'000);
    const int timeouts = plWord(r, "SM76");
    r.net->runUntil(800'000);
    EXPECT_EQ(plWord(r, "V0"), 7);
    EXPECT_EQ(plWord(r, "SM70"), 0);
    EXPECT_EQ(plWord(r, "SM76"), timeouts); // counted, not cleared; no more since
}

// A corrupted byte in the slave's reply: a CRC error, counted in SM77; the next poll reads.
TEST(Pl110Com, ACorruptedReplyIsCountedAsAnError) {
    NetRun r = pl110ComRun(
        QStringLiteral("LD SM0.0\nCOM 1 READ 3 WORD 0 V0 1\nEND\n"),
        QStringLiteral(
            R"(, "faults": [{"kind": "corrupt", "wire": "bus", "frame": 1, "byte": 4}])"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(60'000);
    EXPECT_EQ(plWord(r, "SM77"), 1);
    EXPECT_EQ(plWord(r, "SM70"), 0); // one error, SM75 is 10
    r.net->runUntil(200'000);
    EXPECT_EQ(plWord(r, "V0"), 250);
    EXPECT_EQ(plWord(r, "SM77"), 1);
    EXPECT_EQ(plWord(r, "SM76"), 0);
}

// A cut wire: time-outs until it is joined again.
TEST(Pl110Com, ACutWireTimesOutAndTheQueryRecovers) {
    NetRun r = pl110ComRun(
        QStringLiteral("LD SM0.1\nMOV 1 SM75\nLD SM0.0\nCOM 16 READ 3 WORD 0 V0 1\nEND\n"),
        QStringLiteral(R"(, "faults": [{"kind": "cut", "wire": "bus", "from": 0, "to": 300}])"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(200'000);
    EXPECT_EQ(static_cast<quint16>(plWord(r, "SM70")), 0x8000); // COM_16: bit 15
    EXPECT_GE(plWord(r, "SM76"), 3);
    r.net->runUntil(500'000);
    EXPECT_EQ(plWord(r, "SM70"), 0);
    EXPECT_EQ(plWord(r, "V0"), 250);
}

// Read-write (4.2.21): read continuously; a datum the program changes goes to the slave with
// a write of that one datum (06h), then the reads go on.
TEST(Pl110Com, ReadWriteWritesWhatTheProgramChangedOneDatumAtATime) {
    NetRun r = pl110ComRun(QStringLiteral("LD SM0.0\nCOM 1 READWRITE 3 WORD 0 V0 3\nEND\n"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(100'000);
    EXPECT_EQ(plWord(r, "V2"), 7);
    Station *s = r.net->station(QStringLiteral("pl"));
    s->engine().writeWord(
        std::get<model::Address>(model::parseAddress(s->target(), QStringLiteral("V1"))), 42);
    r.records.clear();
    r.net->runUntil(300'000);
    const std::vector<QByteArray> requests = framesOf(r, QStringLiteral("pl/COM1"));
    ASSERT_GE(requests.size(), 2u);
    int writes = 0;
    for (const QByteArray &q : requests)
        if (q.size() > 1 && q[1] == 0x06) {
            ++writes;
            EXPECT_EQ(q.left(6), hex("03 06 00 01 00 2A"));
        } else {
            EXPECT_EQ(q, hex("03 03 00 00 00 03 04 29"));
        }
    EXPECT_EQ(writes, 1);
    EXPECT_EQ(plWord(r, "V1"), 42); // read back from the slave
}

// NAIS MATSUSHITA-MASTER (4.2.21): the manual publishes no frames, so none goes on the wire;
// every query times out.
TEST(Pl110Com, NaisMatsushitaMasterPutsNoFrameOnTheWire) {
    NetRun r = pl110ComRun(QStringLiteral("LD SM0.0\nCOM 1 READ 1 WORD 10000 V0 10\nEND\n"), {},
                           QStringLiteral("nais-master"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(500'000);
    EXPECT_TRUE(r.records.empty());
    EXPECT_GE(plWord(r, "SM76"), 10);
    EXPECT_EQ(plWord(r, "SM70"), 1);
}

// A PL110 COM master reads a Vigor's D0, D1 (its MODBUS holding registers 0, 1) and writes its
// D10; the Vigor answers with the product's MODBUS slave, as its CP2 does (B-3-6).
TEST(Pl110Com, APl110MasterReadsAndWritesAVigor) {
    NetRun r = runNetwork(
        R"({"stations": [
        {"name": "pl", "program": "p.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus-master"}}},
        {"name": "vb", "program": "v.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 1, "frame": "8N1"}}}],
        "wires": [["pl/COM1", "vb/CP2"]]})",
        {{QStringLiteral("p.il"),
          QStringLiteral("; target: pl110\nLD SM0.1\nMOV 100 SM73\nMOV 77 V20\nLD SM0.0\n"
                         "COM 1 READ 1 WORD 0 V0 2\nCOM 2 WRITE 1 WORD 10 V20 1\nEND\n")},
         {QStringLiteral("v.il"),
          QStringLiteral("; target: vigor\nLD M9000\nMOV K1234 D0\nMOV K-5 D1\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(300'000);
    EXPECT_EQ(plWord(r, "V0"), 1234);
    EXPECT_EQ(plWord(r, "V1"), -5);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 77);
    EXPECT_EQ(plWord(r, "SM70"), 0);
    EXPECT_EQ(plWord(r, "SM76"), 0);
}

// A PL110 master reads a PL110 slave (chapter 3's map: V5 is holding register 2005).
TEST(Pl110Com, APl110MasterReadsAPl110Slave) {
    NetRun r = runNetwork(
        R"({"stations": [
        {"name": "m", "program": "m.il", "target": "pl110",
         "ports": {"EXP1": {"application": "modbus-master"}}},
        {"name": "s", "program": "s.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus", "station": 2}}}],
        "wires": [["m/EXP1", "s/COM1"]]})",
        {{QStringLiteral("m.il"), QStringLiteral("; target: pl110\nLD SM0.1\nMOV 100 SM83\n"
                                                 "LD SM0.0\nEXP 1 READ 2 WORD 2005 V0 1\nEND\n")},
         {QStringLiteral("s.il"),
          QStringLiteral("; target: pl110\nLD SM0.0\nMOV 4321 V5\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(300'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("m"), QStringLiteral("V0")), 4321);
    EXPECT_EQ(value(*r.net, QStringLiteral("m"), QStringLiteral("SM80")), 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("m"), QStringLiteral("SM86")), 0);
}
