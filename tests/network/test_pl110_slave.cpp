// A PL110 port answering MODBUS RTU supervises its link (PL110 manual 2.1.2): its status word
// SM70 (COM1) has every bit at 1 once no correct packet with the PLC's address has come for
// the seconds SM75 sets, and 0 again with the next one. Here a Vigor VB's MBUS polls the
// PL110, then falls silent for three seconds.

#include "network_fixture.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

TEST(Pl110Slave, ItsStatusWordShowsAMasterThatFellSilentAndCameBack) {
    NetRun r = runNetwork(
        R"({"stations": [
        {"name": "vb", "program": "m.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 0}}},
        {"name": "pl", "program": "p.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus", "station": 1}}}],
        "wires": [["vb/CP2", "pl/COM1"]],
        "faults": [{"kind": "silent", "station": "vb", "from": 1000, "to": 4000}]})",
        {{QStringLiteral("m.il"),
          QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K1 D1001\n"
                         "MOV K1 D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K10 "
                         "D1005\nMOV K4 D1006\nMOV K2000 D1007\nLD M9000\nMBUS "
                         "D1000 D100\nEND\n")},
         {QStringLiteral("p.il"),
          QStringLiteral("; target: pl110\nLD SM0.1\nMOV 2 SM75\nLD SM0.0\nMOV 321 V0\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    auto status = [&] {
        return value(*r.net, QStringLiteral("pl"), QStringLiteral("SM70")) & 0xFFFF;
    };
    r.net->runUntil(500'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 321);
    EXPECT_EQ(status(), 0);
    r.net->runUntil(2'800'000); // silent since 1 s, less than SM75 = 2 s after the last request
    EXPECT_EQ(status(), 0);
    r.net->runUntil(3'200'000);
    EXPECT_EQ(status(), 0xFFFF);
    r.net->runUntil(4'500'000); // the master polls again from 4 s
    EXPECT_EQ(status(), 0);
}

// With no master on its line at all (two slaves), the word goes to all ones SM75's default 10 s
// after power-on.
TEST(Pl110Slave, NoMasterAtAllIsALostLinkAfterTheDefaultTenSeconds) {
    NetRun r = runNetwork(
        R"({"stations": [{"name": "pl", "program": "p.il", "target": "pl110",
            "ports": {"COM1": {"application": "modbus", "station": 1}}},
            {"name": "pl2", "program": "p.il", "target": "pl110",
            "ports": {"COM1": {"application": "modbus", "station": 2}}}],
            "wires": [["pl/COM1", "pl2/COM1"]]})",
        {{QStringLiteral("p.il"), QStringLiteral("; target: pl110\nLD SM0.0\nMOV 1 V0\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    auto status = [&] {
        return value(*r.net, QStringLiteral("pl"), QStringLiteral("SM70")) & 0xFFFF;
    };
    r.net->runUntil(9'900'000);
    EXPECT_EQ(status(), 0);
    r.net->runUntil(10'100'000);
    EXPECT_EQ(status(), 0xFFFF);
}

// SM77 of a slave port counts the requests for its station that came wrong (2.1.2: "errori
// conteggiati, ad esempio checksum errato"): the third frame on the bus, a request for station
// 1, has its fourth byte changed. The other PL110 on the bus (station 2), which hears every
// request and reply for station 1, counts nothing.
TEST(Pl110Slave, ARequestThatCameWrongIsCountedByItsStationOnly) {
    NetRun r = runNetwork(
        R"({"stations": [
        {"name": "vb", "program": "m.il", "model": "VB",
         "ports": {"CP2": {"application": "modbus", "station": 0}}},
        {"name": "pl", "program": "p.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus", "station": 1}}},
        {"name": "pl2", "program": "p.il", "target": "pl110",
         "ports": {"COM1": {"application": "modbus", "station": 2}}}],
        "wires": [{"name": "bus", "ends": ["vb/CP2", "pl/COM1", "pl2/COM1"]}],
        "faults": [{"kind": "corrupt", "wire": "bus", "frame": 2, "byte": 3}]})",
        {{QStringLiteral("m.il"),
          QStringLiteral("; target: vigor\nLD M9002\nMOV K1 D1000\nMOV K1 D1001\n"
                         "MOV K1 D1002\nMOV K1 D1003\nMOV K13 D1004\nMOV K10 "
                         "D1005\nMOV K4 D1006\nMOV K2000 D1007\nLD M9000\nMBUS "
                         "D1000 D100\nEND\n")},
         {QStringLiteral("p.il"), QStringLiteral("; target: pl110\nLD SM0.0\nMOV 321 V0\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(1'000'000);
    ASSERT_GE(r.records.size(), 3u);
    EXPECT_EQ(r.records[2].sender, QStringLiteral("vb/CP2")); // the request that came wrong
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("SM77")), 1);
    EXPECT_EQ(value(*r.net, QStringLiteral("pl2"), QStringLiteral("SM77")), 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D10")), 321); // and on it goes
}
