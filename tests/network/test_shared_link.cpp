// Vigor CPU Link and Parallel Link (Vigor M/VB/VH communication manual, B-3-4, B-3-5): the
// manuals' application examples, verbatim (resources/examples/networks), each PLC showing
// what the manual says it shows; the status devices and network scan times of the manual's
// tables; and each under a fault.

#include "network_fixture.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kCpuLink =
    QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/cpu-link/cpu-link.rungnet");
const QString kParallel = QStringLiteral(
    RUNG_SOURCE_DIR "/resources/examples/networks/parallel-link/parallel-link.rungnet");

// The example network with its VR1s set and, when given, a fault added.
std::unique_ptr<Network> example(const QString &file, const std::vector<FaultDescription> &faults,
                                 const std::map<QString, int> &vr1) {
    NetworkDescription d;
    QString error;
    EXPECT_TRUE(readNetworkFile(file, &d, &error)) << error.toStdString();
    d.faults = faults;
    auto net = Network::build(d, listingLoader(), &error);
    EXPECT_TRUE(net) << error.toStdString();
    if (!net)
        return net;
    for (const auto &[station, value] : vr1) {
        Station *s = net->station(station);
        s->engine().writeWord(
            std::get<model::Address>(model::parseAddress(s->target(), QStringLiteral("VR1"))),
            value);
    }
    return net;
}

FaultDescription silent(const char *station, qint64 fromMs, qint64 toMs = -1) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Silent;
    f.station = QString::fromLatin1(station);
    f.fromMs = fromMs;
    f.toMs = toMs;
    return f;
}

const std::map<QString, int> kCpuVr1 = {{QStringLiteral("master"), 100},
                                        {QStringLiteral("slave1"), 150},
                                        {QStringLiteral("slave2"), 200}};

} // namespace

// B-3-4's example: "slave 1 shows the master's VR1, slave 2 shows slave 1's, the master shows
// slave 2's": each station's mode-1 area (D0.., D10.., D20..) reaches the others. Three
// stations in mode 1: a network scan of 11 ms (the manual's table), in D9201 and D9202; the
// master's settings in D9172, D9177, D9178, D9179.
TEST(CpuLink, TheManualsExampleSharesEachStationsArea) {
    auto net = example(kCpuLink, {}, kCpuVr1);
    ASSERT_TRUE(net);
    net->runUntil(100'000);
    const Network &n = *net;
    // What each display shows (D9081 names the register).
    EXPECT_EQ(value(n, QStringLiteral("slave1"), QStringLiteral("D9081")), 0);
    EXPECT_EQ(value(n, QStringLiteral("slave1"), QStringLiteral("D0")), 100);
    EXPECT_EQ(value(n, QStringLiteral("slave2"), QStringLiteral("D9081")), 10);
    EXPECT_EQ(value(n, QStringLiteral("slave2"), QStringLiteral("D10")), 150);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9081")), 20);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D20")), 200);
    for (const char *s : {"master", "slave1", "slave2"}) {
        const QString st = QString::fromLatin1(s);
        SCOPED_TRACE(s);
        EXPECT_EQ(value(n, st, QStringLiteral("D9201")), 11);
        EXPECT_EQ(value(n, st, QStringLiteral("D9202")), 11);
        EXPECT_EQ(value(n, st, QStringLiteral("D9172")), 5);
        EXPECT_EQ(value(n, st, QStringLiteral("D9177")), 2);
        EXPECT_EQ(value(n, st, QStringLiteral("D9178")), 1);
        EXPECT_EQ(value(n, st, QStringLiteral("D9179")), 3);
        for (const char *m : {"M9183", "M9184", "M9185"})
            EXPECT_FALSE(bit(n, st, QString::fromLatin1(m))) << m;
        EXPECT_EQ(value(n, st, QStringLiteral("D9212")), 0);
        EXPECT_EQ(value(n, st, QStringLiteral("D9213")), 0);
    }
}

// The exchange runs every network scan time: at 10 ms nothing has arrived, at 11 ms it has.
TEST(CpuLink, TheExchangeComesAtTheNetworkScanTime) {
    auto net = example(kCpuLink, {}, kCpuVr1);
    ASSERT_TRUE(net);
    net->runUntil(10'999);
    EXPECT_EQ(value(*net, QStringLiteral("slave1"), QStringLiteral("D0")), 0);
    net->runUntil(11'000);
    EXPECT_EQ(value(*net, QStringLiteral("slave1"), QStringLiteral("D0")), 100);
}

// The same mode with all eight stations: 31 ms (mode 1), and modes 2 and 3 with three
// stations: 15 ms and 24 ms, with their M areas (M1000.., M1064..).
TEST(CpuLink, NetworkScanTimesAndAreasPerMode) {
    auto programs = std::map<QString, QString>{
        {QStringLiteral("p.il"), QStringLiteral("; target: vigor\nEND\n")}};
    auto build = [&](int range, int slaves) {
        QString stations;
        QStringList ends;
        for (int k = 0; k <= slaves; ++k) {
            stations += QStringLiteral(R"(%1{"name": "s%2", "program": "p.il", "model": "VB",
                "ports": {"CP2": {"application": "cpu-link", "station": %2 %3}}})")
                            .arg(k ? QStringLiteral(",") : QString())
                            .arg(k)
                            .arg(k ? QString()
                                   : QStringLiteral(R"(, "slaves": %1, "range": %2)")
                                         .arg(slaves)
                                         .arg(range));
            ends << QStringLiteral("\"s%1/CP2\"").arg(k);
        }
        return runNetwork(QStringLiteral(R"({"stations": [%1], "wires": [[%2]]})")
                              .arg(stations, ends.join(QLatin1Char(',')))
                              .toUtf8(),
                          programs);
    };
    NetRun eight = build(1, 7);
    ASSERT_TRUE(eight.net) << eight.error.toStdString();
    eight.net->runUntil(100'000);
    EXPECT_EQ(value(*eight.net, QStringLiteral("s7"), QStringLiteral("D9201")), 31);
    NetRun two = build(2, 2);
    ASSERT_TRUE(two.net) << two.error.toStdString();
    Station *s1 = two.net->station(QStringLiteral("s1"));
    s1->engine().setBit(
        std::get<model::Address>(model::parseAddress(s1->target(), QStringLiteral("M1095"))), true);
    two.net->runUntil(100'000);
    EXPECT_EQ(value(*two.net, QStringLiteral("s0"), QStringLiteral("D9201")), 15);
    EXPECT_TRUE(bit(*two.net, QStringLiteral("s0"), QStringLiteral("M1095")));
    EXPECT_TRUE(bit(*two.net, QStringLiteral("s2"), QStringLiteral("M1095")));
    NetRun three = build(3, 2);
    ASSERT_TRUE(three.net) << three.error.toStdString();
    three.net->runUntil(100'000);
    EXPECT_EQ(value(*three.net, QStringLiteral("s2"), QStringLiteral("D9201")), 24);
}

// A silent slave 2: M9185 ("communication failed, slave 2") ON on every station, D9213 = 01H
// (time-out), its error count in D9205 growing; the master and slave 1 go on exchanging, and
// slave 2's area stops arriving. The failed station costs its time-out and retries (5 x 10 ms,
// 3 retries: 200 ms) in the network scan time. Back, it clears.
TEST(CpuLink, ASilentSlaveShowsItsFailureAndTheOthersGoOn) {
    auto net = example(kCpuLink, {silent("slave2", 0, 1000)}, kCpuVr1);
    ASSERT_TRUE(net);
    net->runUntil(500'000);
    const Network &n = *net;
    EXPECT_TRUE(bit(n, QStringLiteral("master"), QStringLiteral("M9185")));
    EXPECT_TRUE(bit(n, QStringLiteral("slave1"), QStringLiteral("M9185")));
    EXPECT_FALSE(bit(n, QStringLiteral("master"), QStringLiteral("M9184")));
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9213")), 1);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9212")), 0);
    EXPECT_GE(value(n, QStringLiteral("master"), QStringLiteral("D9205")), 2);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9201")), 211);
    EXPECT_EQ(value(n, QStringLiteral("slave1"), QStringLiteral("D0")), 100);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D20")), 0);
    net->runUntil(2'000'000);
    EXPECT_FALSE(bit(n, QStringLiteral("master"), QStringLiteral("M9185")));
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9213")), 0);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D20")), 200);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9202")), 211);
}

// A corrupted exchange with slave 1 (the wire's 2nd exchange: master 0, slave 1): D9212 = 05H
// ("check sum error") for that network scan, then 00H again.
TEST(CpuLink, ACorruptedExchangeShowsTheSumError) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Corrupt;
    f.wire = QStringLiteral("w1");
    f.frame = 1;
    auto net = example(kCpuLink, {f}, kCpuVr1);
    ASSERT_TRUE(net);
    net->runUntil(11'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D9212")), 5);
    EXPECT_TRUE(bit(*net, QStringLiteral("master"), QStringLiteral("M9184")));
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D9204")), 1);
    net->runUntil(400'000);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D9212")), 0);
    EXPECT_EQ(value(*net, QStringLiteral("master"), QStringLiteral("D9204")), 1);
    EXPECT_EQ(value(*net, QStringLiteral("slave2"), QStringLiteral("D10")), 150);
}

// No frame of CPU Link goes on a wire: the traffic says what was exchanged, with no bytes.
TEST(CpuLink, TheTrafficCarriesNoInventedFrame) {
    NetRun r = runNetwork({}, {}, {}, kCpuLink);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(50'000);
    ASSERT_FALSE(r.records.empty());
    for (const TrafficRecord &t : r.records) {
        EXPECT_TRUE(t.bytes.isEmpty());
        EXPECT_FALSE(t.note.isEmpty());
    }
}

// B-3-5's example at high speed: the master's D490 reaches the slave, the slave's D500 the
// master ("each PLC shows the other's VR1"); M9070 / M9071 say which is which, M9072 that the
// link is normal, M9162 the high speed the master chose.
TEST(ParallelLink, TheManualsExampleExchangesTheHighSpeedAreas) {
    auto net =
        example(kParallel, {}, {{QStringLiteral("master"), 90}, {QStringLiteral("slave"), 180}});
    ASSERT_TRUE(net);
    net->runUntil(200'000);
    const Network &n = *net;
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D9081")), 500);
    EXPECT_EQ(value(n, QStringLiteral("master"), QStringLiteral("D500")), 180);
    EXPECT_EQ(value(n, QStringLiteral("slave"), QStringLiteral("D9081")), 490);
    EXPECT_EQ(value(n, QStringLiteral("slave"), QStringLiteral("D490")), 90);
    EXPECT_TRUE(bit(n, QStringLiteral("master"), QStringLiteral("M9070")));
    EXPECT_FALSE(bit(n, QStringLiteral("master"), QStringLiteral("M9071")));
    EXPECT_TRUE(bit(n, QStringLiteral("slave"), QStringLiteral("M9071")));
    EXPECT_FALSE(bit(n, QStringLiteral("slave"), QStringLiteral("M9070")));
    for (const char *s : {"master", "slave"}) {
        EXPECT_TRUE(bit(n, QString::fromLatin1(s), QStringLiteral("M9072"))) << s;
        EXPECT_TRUE(bit(n, QString::fromLatin1(s), QStringLiteral("M9162"))) << s;
        EXPECT_FALSE(bit(n, QString::fromLatin1(s), QStringLiteral("M9063"))) << s;
    }
}

// The communication time: 14 ms at 19200 bps plus both scans (10 ms each): the first exchange
// at 34 ms.
TEST(ParallelLink, TheCommunicationTimeAddsBothScans) {
    auto net =
        example(kParallel, {}, {{QStringLiteral("master"), 90}, {QStringLiteral("slave"), 180}});
    ASSERT_TRUE(net);
    net->runUntil(33'999);
    EXPECT_EQ(value(*net, QStringLiteral("slave"), QStringLiteral("D490")), 0);
    net->runUntil(34'000);
    EXPECT_EQ(value(*net, QStringLiteral("slave"), QStringLiteral("D490")), 90);
}

// Low (normal) speed: M800..M899 and D490..D499 one way, M900..M999 and D500..D509 the other.
TEST(ParallelLink, NormalSpeedExchangesTheWholeAreas) {
    const std::map<QString, QString> programs = {
        {QStringLiteral("m.il"), QStringLiteral("; target: vigor\nLD M9000\nOUT M899\nMOV K7 "
                                                "D499\nEND\n")},
        {QStringLiteral("s.il"),
         QStringLiteral("; target: vigor\nLD M9000\nOUT M900\nMOV K9 D509\nEND\n")}};
    NetRun r = runNetwork(R"({"stations": [
        {"name": "m", "program": "m.il", "model": "VB",
         "ports": {"CP2": {"application": "parallel-link", "role": "master", "speed": "low"}}},
        {"name": "s", "program": "s.il", "model": "VB",
         "ports": {"CP2": {"application": "parallel-link", "role": "slave"}}}],
        "wires": [["m/CP2", "s/CP2"]]})",
                          programs);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(200'000);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s"), QStringLiteral("M899")));
    EXPECT_EQ(value(*r.net, QStringLiteral("s"), QStringLiteral("D499")), 7);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("m"), QStringLiteral("M900")));
    EXPECT_EQ(value(*r.net, QStringLiteral("m"), QStringLiteral("D509")), 9);
    EXPECT_FALSE(bit(*r.net, QStringLiteral("m"), QStringLiteral("M9162")));
}

// A cut wire: M9072 goes OFF and M9063 ("parallel operation ... error, PLC keeps running")
// ON; nothing is exchanged and both PLCs keep scanning.
TEST(ParallelLink, ACutWireShowsTheErrorAndThePlcsKeepRunning) {
    FaultDescription cut;
    cut.kind = FaultDescription::Kind::Cut;
    cut.wire = QStringLiteral("w1");
    auto net =
        example(kParallel, {cut}, {{QStringLiteral("master"), 90}, {QStringLiteral("slave"), 180}});
    ASSERT_TRUE(net);
    net->runUntil(200'000);
    for (const char *s : {"master", "slave"}) {
        EXPECT_FALSE(bit(*net, QString::fromLatin1(s), QStringLiteral("M9072"))) << s;
        EXPECT_TRUE(bit(*net, QString::fromLatin1(s), QStringLiteral("M9063"))) << s;
    }
    EXPECT_EQ(value(*net, QStringLiteral("slave"), QStringLiteral("D490")), 0);
    EXPECT_EQ(net->station(QStringLiteral("master"))->engine().statistics().scans, 20u);
}
