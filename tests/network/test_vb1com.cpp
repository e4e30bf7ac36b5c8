// The VB-1COM module (Vigor M/VB/VH communication manual, B-4): the manual's programming
// example 2 verbatim (resources/examples/networks/vb-1com), the module adding STX / ETX, the
// sum and the HEX <-> ASCII conversion, sends the frames the manual's Computer Link prints and
// takes the right PLC's answers; FROM / TO with digit groups and constants; a fault.

#include "network_fixture.h"

#include <algorithm>

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kVbOneCom =
    QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/vb-1com/vb-1com.rungnet");

std::unique_ptr<Network> vbOneCom(std::vector<TrafficRecord> *records,
                                  const std::vector<FaultDescription> &faults = {}) {
    NetworkDescription d;
    QString error;
    EXPECT_TRUE(readNetworkFile(kVbOneCom, &d, &error)) << error.toStdString();
    d.faults = faults;
    auto net = Network::build(d, listingLoader(), &error);
    EXPECT_TRUE(net) << error.toStdString();
    if (!net)
        return net;
    net->setTrafficSink([records](const TrafficRecord &t) { records->push_back(t); });
    for (const auto &[station, v] : {std::pair{"left", 120}, std::pair{"right", 77}}) {
        Station *s = net->station(QString::fromLatin1(station));
        s->engine().writeWord(
            std::get<model::Address>(model::parseAddress(s->target(), QStringLiteral("VR1"))), v);
    }
    return net;
}

} // namespace

// "Each PLC shows the other's VR1": the left D110 holds the right's 77, the right D1 the
// left's 120. The module's frames are the Computer Link read of D0 (the manual's own bytes,
// B-3-9) and the write of D1; its status word reports no error.
TEST(VbOneCom, TheManualsSecondExampleReadsAndWritesThroughTheModule) {
    std::vector<TrafficRecord> records;
    auto net = vbOneCom(&records);
    ASSERT_TRUE(net);
    net->runUntil(1'000'000);
    EXPECT_EQ(value(*net, QStringLiteral("left"), QStringLiteral("D110")), 77);
    EXPECT_EQ(value(*net, QStringLiteral("right"), QStringLiteral("D1")), 120);
    EXPECT_EQ(value(*net, QStringLiteral("left"), QStringLiteral("D108")), 0); // BFM #29
    std::vector<QByteArray> left, right;
    for (const TrafficRecord &t : records)
        (t.sender == QLatin1String("left/MODULE1") ? left : right).push_back(t.bytes);
    auto sent = [](const std::vector<QByteArray> &frames, const char *bytes) {
        return std::count(frames.begin(), frames.end(), hex(bytes));
    };
    // M9012 alternates the cycles: each frame goes out and is answered once a cycle.
    ASSERT_GE(left.size(), 4u);
    EXPECT_EQ(left.size(), right.size());
    const auto reads = sent(left, "02 30 31 35 31 31 43 30 30 30 32 03 30 30");
    // D111 = 120 = 0078H, low byte first: "7800".
    const auto writes = sent(left, "02 30 31 36 31 31 43 30 32 30 32 37 38 30 30 03 44 32");
    EXPECT_GE(reads, 2);
    EXPECT_GE(writes, 2);
    EXPECT_EQ(reads + writes, std::ptrdiff_t(left.size()));
    EXPECT_EQ(sent(right, "06 30 31 35 31 30 30 34 44 30 30 03 30 32"), reads);
    EXPECT_EQ(sent(right, "06 30 31 36 31 30 30 03 32 42"), writes);
}

// BFM #0 = 7096H sets the module's line: 19200 bps, 7 data bits, even parity, 1 stop bit.
TEST(VbOneCom, TheFormatWordSetsTheModulesLine) {
    std::vector<TrafficRecord> records;
    auto net = vbOneCom(&records);
    ASSERT_TRUE(net);
    net->runUntil(30'000);
    const StationPort *port =
        net->station(QStringLiteral("left"))->findPort(QStringLiteral("MODULE1"));
    ASSERT_TRUE(port);
    EXPECT_EQ(port->line().baud, 19200);
    EXPECT_EQ(model::frameFormatText(port->line()), QStringLiteral("7E1"));
}

// A corrupted byte in the right PLC's answer: the module's sum check fails, BFM #28 b3 and
// #29 = 4 ("receive sum error") show it in M33 and D108.
TEST(VbOneCom, ACorruptedAnswerIsTheModulesSumError) {
    FaultDescription f;
    f.kind = FaultDescription::Kind::Corrupt;
    f.wire = QStringLiteral("w1");
    f.frame = 1;
    f.byte = 8;
    std::vector<TrafficRecord> records;
    auto net = vbOneCom(&records, {f});
    ASSERT_TRUE(net);
    bool error = false;
    for (qint64 t = 10'000; t <= 200'000; t += 10'000) {
        net->runUntil(t);
        error = error || value(*net, QStringLiteral("left"), QStringLiteral("D108")) == 4;
    }
    EXPECT_TRUE(error);
}

// Without the module in the network, FROM / TO are an operation error that names it.
TEST(VbOneCom, AModuleThatIsNotThereIsAnOperationError) {
    NetRun r =
        runNetwork(R"({"stations": [{"name": "a", "program": "p.il", "model": "VB"}]})",
                   {{QStringLiteral("p.il"),
                     QStringLiteral("; target: vigor\nLD M9000\nFROM K1 K30 D0 K1\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(20'000);
    const auto &errors = r.net->station(QStringLiteral("a"))->engine().runtimeErrors();
    ASSERT_FALSE(errors.empty());
    EXPECT_TRUE(errors.front().message.contains(QStringLiteral("MODULE1")))
        << errors.front().message.toStdString();
}

// The module answers FROM with its model ID, K7030, at BFM #30.
TEST(VbOneCom, TheModelIdIs7030) {
    NetRun r =
        runNetwork(R"({"stations": [{"name": "a", "program": "p.il", "model": "VB",
                              "ports": {"MODULE1": {"application": "vb-1com"}}}]})",
                   {{QStringLiteral("p.il"),
                     QStringLiteral("; target: vigor\nLD M9000\nFROM K1 K30 D0 K1\nEND\n")}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(20'000);
    EXPECT_EQ(value(*r.net, QStringLiteral("a"), QStringLiteral("D0")), 7030);
}
