// The CPM1's peripheral port in a network (docs/network.md, "The CPM1's peripheral port"): Host
// Link answered from the station's image at its scan's end, as the other families' slave ports
// answer, on virtual time; the front panel's COMM lamp lit while the port carries bytes and dark
// after; the wiring checks know Host Link's units.

#include "network_fixture.h"

#include "network/check.h"
#include "network/devices.h"
#include "network/network_history.h"

#include "model/image/panel_view.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const char *kCpm1 = "; target: cpm1\nLD 253.13\nMOV(21) #1234 DM0000\nEND(01)\n";

// A host on the CPM1's peripheral port: a line device at the port's Host Link defaults
// (9600 bps 7E2), whose frames the test puts on the wire.
NetRun hostAndCpm1() {
    return runNetwork(R"({"stations": [{"name": "plc", "program": "c.il", "model": "CPM1-20CDR",
                              "ports": {"PERIPHERAL": {"application": "host-link", "station": 0}}}],
                          "devices": [{"name": "host", "kind": "line", "baud": 9600,
                                       "frame": "7E2"}],
                          "wires": [["plc/PERIPHERAL", "host"]]})",
                      {{QStringLiteral("c.il"), QString::fromLatin1(kCpm1)}});
}

// The station's COMM lamp for a snapshot of it, as the IDE's front panel draws it.
bool commLit(const Station &plc, const model::Snapshot &snapshot,
             model::MonitorSource::RunState state = model::MonitorSource::RunState::Running) {
    const model::PanelView v =
        model::panelView(plc.target(), plc.model(), {&snapshot, state, false, 0});
    for (const model::PanelLampView &l : v.lamps)
        if (l.label == QLatin1String("COMM"))
            return l.lit;
    ADD_FAILURE() << "no COMM lamp";
    return false;
}

// ... for its snapshot now.
bool commLit(const Station &plc) {
    return commLit(plc, plc.snapshot());
}

} // namespace

// "@00RD0000000157*" (read DM 0000, one word; C-mode, Omron's public Host Link documentation)
// put on the wire at 100 ms: its 17 characters at 9600 bps 7E2 (11 bits each) arrive at 119.5
// ms, the station answers at the end of its next scan (120 ms) from its image, 1234 (its MOV);
// the reply's 15 characters leave by 137.2 ms. COMM (Omron CPM1 guide 2.1: "Világít - A PLC
// kommunikál") is dark before, lit from the scan that saw the request, and dark 0.2 s (our
// hold) after the reply's last character.
TEST(Cpm1PeripheralPort, AnswersHostLinkAtTheScansEndAndCommIsLitWhileItCarriesFrames) {
    NetRun r = hostAndCpm1();
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station &plc = *r.net->station(QStringLiteral("plc"));
    auto *host = dynamic_cast<LineDevice *>(r.net->endpoint(QStringLiteral("host")));
    ASSERT_NE(host, nullptr);
    ASSERT_TRUE(r.net->runUntil(100000));
    EXPECT_FALSE(commLit(plc)) << "nothing on the port yet";
    r.net->inject(host, "@00RD0000000157*\r");
    ASSERT_TRUE(r.net->runUntil(119000));
    EXPECT_FALSE(commLit(plc)) << "the request is still coming";
    ASSERT_TRUE(r.net->runUntil(120000));
    EXPECT_TRUE(commLit(plc)) << "the request came before this scan";
    ASSERT_TRUE(r.net->runUntil(140000));
    EXPECT_EQ(host->received(), QByteArray("@00RD00123452*\r"));
    ASSERT_EQ(r.records.size(), 2u);
    EXPECT_EQ(r.records[1].sender, QStringLiteral("plc/PERIPHERAL"));
    EXPECT_EQ(r.records[1].startUs, 120000) << "answered at the scan's end";
    const qint64 lastByte = r.records[1].endUs;
    EXPECT_EQ(plc.snapshot().communicatedUs, lastByte);
    ASSERT_TRUE(r.net->runUntil(330000));
    EXPECT_LT(330000 - lastByte, 200000);
    EXPECT_TRUE(commLit(plc)) << "within 0.2 s of the reply's last character";
    ASSERT_TRUE(r.net->runUntil(340000));
    EXPECT_GE(340000 - lastByte, 200000);
    EXPECT_FALSE(commLit(plc)) << "0.2 s after: the PLC is not communicating";

    // A command for another unit is not answered, but the port carried it: COMM lights.
    r.net->inject(host, "@01RD0000000156*\r");
    ASSERT_TRUE(r.net->runUntil(400000));
    EXPECT_EQ(r.records.size(), 3u) << "no reply";
    EXPECT_TRUE(commLit(plc));
}

// Two Host Link slaves answering the same unit on one wire both answer each command: `check`
// says so, as it does for Computer Link and MODBUS stations.
TEST(Cpm1PeripheralPort, TwoPortsAnsweringTheSameUnitOnOneWireAreAWiringError) {
    NetRun r = runNetwork(
        R"({"stations": [{"name": "a", "program": "c.il", "ports": {"PERIPHERAL": {"station": 3}}},
                         {"name": "b", "program": "c.il", "ports": {"PERIPHERAL": {"station": 3}}},
                         {"name": "c", "program": "c.il", "ports": {"PERIPHERAL": {"station": 4}}}],
            "wires": [["a/PERIPHERAL", "b/PERIPHERAL", "c/PERIPHERAL"]]})",
        {{QStringLiteral("c.il"), QString::fromLatin1(kCpm1)}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    const std::vector<NetworkFinding> findings = checkNetwork(*r.net);
    QStringList texts;
    for (const NetworkFinding &f : findings)
        texts << f.message;
    EXPECT_TRUE(texts.contains(
        QStringLiteral("a/PERIPHERAL and b/PERIPHERAL both answer Host Link station 3")))
        << texts.join(QLatin1Char('\n')).toStdString();
    EXPECT_FALSE(texts.join(QLatin1Char('\n')).contains(QStringLiteral("c/PERIPHERAL")));
}

// A unit outside Host Link's 00..31 is refused where and why, as every port setting.
TEST(Cpm1PeripheralPort, AUnitOutsideTheTableIsRefusedWithWhere) {
    NetRun r = runNetwork(
        R"({"stations": [{"name": "a", "program": "c.il", "ports": {"PERIPHERAL": {"station": 32}}}]})",
        {{QStringLiteral("c.il"), QString::fromLatin1(kCpm1)}});
    EXPECT_FALSE(r.net);
    EXPECT_TRUE(r.error.contains(QStringLiteral("stations[0].ports.PERIPHERAL.station")))
        << r.error.toStdString();
}

// The network's history (network_history.h) keeps what the COMM lamp showed: moving the chart's
// cursor to an earlier instant shows the lamp as it was then (the network paused), lit while
// the request and its reply were on the port and within the 0.2 s after, dark before and after;
// across keys and the changes between them.
TEST(Cpm1PeripheralPort, TheHistoryShowsTheCommLampAsItWasAtEachInstant) {
    NetRun r = hostAndCpm1();
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station &plc = *r.net->station(QStringLiteral("plc"));
    auto *host = dynamic_cast<LineDevice *>(r.net->endpoint(QStringLiteral("host")));
    ASSERT_NE(host, nullptr);
    NetworkHistory history(NetworkHistory::Limits{64u << 20, 5});
    history.start(*r.net);
    std::vector<std::pair<qint64, bool>> live; // (instant, lit then)
    std::vector<qint64> communicated;
    for (qint64 us = 10000; us <= 400000; us += 10000) {
        // Between two keys (one each 6 instants here): the lamp's change read from the changes.
        if (us == 140000)
            r.net->inject(host, "@00RD0000000157*\r");
        ASSERT_TRUE(r.net->runUntil(us));
        history.record(*r.net, false);
        live.emplace_back(us, commLit(plc));
        communicated.push_back(plc.snapshot().communicatedUs);
    }
    // Keys and the changes between them both read.
    EXPECT_GT(history.window().keys, 1u);
    EXPECT_LT(history.window().keys, history.window().instants / 2);
    int lit = 0;
    for (std::size_t k = 0; k < live.size(); ++k) {
        const auto &[us, wasLit] = live[k];
        const std::optional<model::Snapshot> past = history.stationAt(0, us);
        ASSERT_TRUE(past) << us;
        EXPECT_EQ(past->communicatedUs, communicated[k]) << "at " << us << " us";
        EXPECT_EQ(commLit(plc, *past, model::MonitorSource::RunState::Paused), wasLit)
            << "at " << us << " us";
        lit += wasLit ? 1 : 0;
    }
    // The request arrives at 149.5 ms, is answered at the 150 ms scan, the reply's last
    // character leaves at 167.2 ms.
    const auto litAt = [&](qint64 us) { return live[std::size_t(us / 10000 - 1)].second; };
    EXPECT_FALSE(litAt(140000)) << "nothing on the port yet";
    EXPECT_TRUE(litAt(150000)) << "the request came";
    EXPECT_TRUE(litAt(360000)) << "within 0.2 s of the reply";
    EXPECT_FALSE(litAt(370000)) << "0.2 s after";
    EXPECT_EQ(lit, 22);
}
