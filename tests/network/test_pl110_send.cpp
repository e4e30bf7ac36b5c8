// PL110 free-port and SEND (PL110 manual 4.2.19 with the special markers of 2.1.2 and the byte
// areas of 2.1.14, 2.1.15): SM78 switches COM1 to free-port at its codes' line, SEND sends the
// characters of COM1_TX with SM0.6 ON meanwhile, what comes lands in COM1_RX with its count in
// SM79, a write of SM79 empties the buffer; a SEND during a transmission or with free-port off
// is ignored; the port's MODBUS slave is silent in free-port and answers again after it.

#include "network_fixture.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

// SM78 = 0x118: free-port on (bit 8), format code 1 (8,O,1), baud code 8 (19200). A line
// device at 19200 8O1 answers "OK" + CR to "AB". I1 rising sends V0 characters of COM1_TX.
QByteArray freePortNetwork(const QString &frame = QStringLiteral("8O1")) {
    return QStringLiteral(R"({
        "stations": [{"name": "pl", "program": "p.il", "target": "pl110",
                      "ports": {"COM1": {"application": "modbus", "station": 1}}}],
        "devices": [{"name": "dev", "kind": "line", "baud": 19200, "frame": "%1",
                     "answers": [{"expect": "41 42", "reply": "4F 4B 0D"}]}],
        "wires": [{"name": "line", "ends": ["pl/COM1", "dev"]}]
    })")
        .arg(frame)
        .toUtf8();
}

const char *kFreePort = "; target: pl110\n"
                        "LD SM0.1\nMOV 65 COM1_TX0\nMOV 66 COM1_TX1\n"
                        "LD I2\nMOV 280 SM78\n" // 0x118
                        "LD I1\nSEND COM1 V0\n"
                        "LD SM0.6\nOUT M1\n"
                        "END\n";

// A network of one PL110 in free-port mode and its station.
struct FreePortRun {
    explicit FreePortRun(const QString &frame)
        : run(runNetwork(freePortNetwork(frame),
                         {{QStringLiteral("p.il"), QString::fromLatin1(kFreePort)}})) {
        if (run.net)
            station = run.net->station(QStringLiteral("pl"));
    }
    NetRun run;
    Station *station = nullptr;
    model::Address at(const char *device) const {
        return std::get<model::Address>(
            model::parseAddress(station->target(), QString::fromLatin1(device)));
    }
    int word(const char *device) const { return station->engine().value(at(device)); }
    void set(const char *device, bool on) { station->engine().setBit(at(device), on); }
    void write(const char *device, int value) { station->engine().writeWord(at(device), value); }
};

FreePortRun freePortRun(const QString &frame = QStringLiteral("8O1")) {
    return FreePortRun(frame);
}

} // namespace

TEST(Pl110FreePort, SendTransmitsTheBufferAndTheReplyLandsInTheReceiveBuffer) {
    FreePortRun r = freePortRun();
    ASSERT_TRUE(r.run.net) << r.run.error.toStdString();
    r.write("V0", 2);
    r.set("I2", true);
    r.run.net->runUntil(20'000);
    EXPECT_EQ(r.word("SM78"), 0x118);
    r.set("I1", true);
    // Scan 3 sends at its END (30 ms); 2 characters of 11 bits at 19200 bps take 1.146 ms,
    // so SM0.6 is ON for that one scan.
    r.run.net->runUntil(30'000);
    EXPECT_TRUE(r.station->engine().bit(r.at("SM0.6")));
    EXPECT_TRUE(r.station->engine().bit(r.at("M1")));
    r.run.net->runUntil(60'000);
    EXPECT_FALSE(r.station->engine().bit(r.at("SM0.6")));
    ASSERT_GE(r.run.records.size(), 2u);
    EXPECT_EQ(r.run.records[0].sender, QStringLiteral("pl/COM1"));
    EXPECT_EQ(r.run.records[0].bytes, hex("41 42"));
    EXPECT_EQ(r.run.records[1].bytes, hex("4F 4B 0D"));
    // The reply: 3 characters in SM79, the bytes in COM1_RX0..2, one a word.
    EXPECT_EQ(r.word("SM79"), 3);
    EXPECT_EQ(r.word("COM1_RX0"), 'O');
    EXPECT_EQ(r.word("COM1_RX1"), 'K');
    EXPECT_EQ(r.word("COM1_RX2"), '\r');
    // Any write of SM79 empties the buffer: the next reply starts at COM1_RX0 again.
    r.write("SM79", 0);
    r.set("I1", false);
    r.run.net->runUntil(80'000);
    EXPECT_EQ(r.word("SM79"), 0);
    r.write("COM1_TX0", 'A');
    r.set("I1", true);
    r.run.net->runUntil(120'000);
    EXPECT_EQ(r.word("SM79"), 3);
    EXPECT_EQ(r.word("COM1_RX0"), 'O');
}

// "Chiamate alla funzione SEND ... con modalita free-port disabilitata verranno ignorate": with
// SM78 bit 8 OFF nothing goes on the wire; and "prima della fine della trasmissione precedente":
// a second SEND while 200 characters at 110 bps are going is ignored.
TEST(Pl110FreePort, ASendWithFreePortOffOrDuringATransmissionIsIgnored) {
    FreePortRun r = freePortRun();
    ASSERT_TRUE(r.run.net) << r.run.error.toStdString();
    r.write("V0", 2);
    r.set("I1", true);
    r.run.net->runUntil(50'000);
    EXPECT_TRUE(r.run.records.empty());
    EXPECT_FALSE(r.station->engine().bit(r.at("SM0.6")));
    // 110 bps (code 0), 8,O,1 (code 1): SM78 = 0x110.
    r.set("I1", false);
    r.write("SM78", 0x110);
    r.write("V0", 200);
    r.run.net->runUntil(60'000);
    r.set("I1", true);
    r.run.net->runUntil(70'000);
    ASSERT_EQ(r.run.records.size(), 1u);
    EXPECT_EQ(r.run.records[0].bytes.size(), 200);
    EXPECT_TRUE(r.station->engine().bit(r.at("SM0.6")));
    r.set("I1", false);
    r.run.net->runUntil(80'000);
    r.set("I1", true);
    r.run.net->runUntil(100'000);
    EXPECT_EQ(r.run.records.size(), 1u); // ignored
    EXPECT_TRUE(r.station->engine().bit(r.at("SM0.6")));
    // 200 characters of 11 bits at 110 bps: 20 s.
    r.run.net->runUntil(20'100'000);
    EXPECT_FALSE(r.station->engine().bit(r.at("SM0.6")));
}

// SEND of more characters than the buffer holds is an operation error that sends nothing.
TEST(Pl110FreePort, ASendBeyondTheBufferIsAnOperationError) {
    FreePortRun r = freePortRun();
    ASSERT_TRUE(r.run.net) << r.run.error.toStdString();
    r.write("V0", 300);
    r.set("I2", true);
    r.set("I1", true);
    r.run.net->runUntil(50'000);
    EXPECT_TRUE(r.run.records.empty());
    ASSERT_FALSE(r.station->engine().runtimeErrors().empty());
    EXPECT_TRUE(r.station->engine().runtimeErrors().front().message.contains(QLatin1String("300")));
}

// Free-port OFF again: the port's protocol is back, and its MODBUS slave answers a master.
TEST(Pl110FreePort, TheProtocolAnswersAgainWhenFreePortEnds) {
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
         {QStringLiteral("p.il"), QStringLiteral("; target: pl110\nLD SM0.0\nMOV 321 V0\n"
                                                 "LD I1\nMOV 296 SM78\nLDN I1\nMOV 0 SM78\n"
                                                 "END\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station *pl = r.net->station(QStringLiteral("pl"));
    auto at = [&](const char *d) {
        return std::get<model::Address>(model::parseAddress(pl->target(), QString::fromLatin1(d)));
    };
    pl->engine().setBit(at("I1"), true); // 0x128: free-port at 19200 8,E,1
    r.net->runUntil(300'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D100")) >> 8, 0xA); // no response
    // What the MBUS sent landed in the PL110's receive buffer instead.
    EXPECT_GT(pl->engine().value(at("SM79")), 0);
    pl->engine().setBit(at("I1"), false);
    r.net->runUntil(600'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 321);
}

// Without a network the port is connected to nothing: SEND still takes its time on the line.
TEST(Pl110FreePort, WithoutANetworkSendTakesItsLineTime) {
    FreePortRun r = freePortRun();
    ASSERT_TRUE(r.run.net) << r.run.error.toStdString();
    r.station->engine().attachPorts(nullptr);
    r.write("V0", 100);
    r.set("I2", true);
    r.run.net->runUntil(20'000);
    r.set("I1", true);
    r.run.net->runUntil(30'000);
    EXPECT_TRUE(r.station->engine().bit(r.at("SM0.6")));
    // 100 characters of 11 bits at 19200 bps: 57.3 ms.
    r.run.net->runUntil(80'000);
    EXPECT_TRUE(r.station->engine().bit(r.at("SM0.6")));
    r.run.net->runUntil(90'000);
    EXPECT_FALSE(r.station->engine().bit(r.at("SM0.6")));
    EXPECT_TRUE(r.run.records.empty());
}
