// The PL110 example networks (resources/examples/networks/pl110-*) as they ship, and each under
// a fault: what the PL110 manual's markers show (2.1.2: SM70 / SM80 status bits, SM76 / SM86
// time-outs, SM77 / SM87 errors, SM79 characters received), the simulation going on. Their
// traces and traffic byte for byte are NetworkGolden.EveryExampleRunsAsRecorded's.

#include "network_fixture.h"

#include "network/devices.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

QString pl110Example(const char *name) {
    return QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/%1/%1.rungnet")
        .arg(QLatin1String(name));
}

std::unique_ptr<Network> pl110ExampleWith(const char *name, const FaultDescription &fault,
                                          QString *error) {
    NetworkDescription d;
    if (!readNetworkFile(pl110Example(name), &d, error))
        return nullptr;
    d.faults.push_back(fault);
    return Network::build(d, listingLoader(), error);
}

FaultDescription pl110Fault(FaultDescription::Kind kind, const char *wireOrStation,
                            qint64 fromMs = 0, qint64 toMs = -1) {
    FaultDescription f;
    f.kind = kind;
    if (kind == FaultDescription::Kind::Silent)
        f.station = QString::fromLatin1(wireOrStation);
    else
        f.wire = QString::fromLatin1(wireOrStation);
    f.fromMs = fromMs;
    f.toMs = toMs;
    return f;
}

} // namespace

// 4.2.21's EXP settings: V0..V9 get the slave's 10000..10009, its coils 10003..10010 get V10's
// bits 0..7 (165 = 1010 0101b).
TEST(Pl110Examples, TheManualsExpSettingsReadAndWrite) {
    NetRun r = runNetwork({}, {}, {}, pl110Example("pl110-exp"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(500'000);
    for (int k = 0; k < 10; ++k)
        EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("V%1").arg(k)), 100 + k);
    auto *slave = dynamic_cast<ModbusSlaveDevice *>(r.net->endpoint(QStringLiteral("slave")));
    ASSERT_NE(slave, nullptr);
    const int bits[] = {1, 0, 1, 0, 0, 1, 0, 1};
    for (int k = 0; k < 8; ++k)
        EXPECT_EQ(slave->coils.at(10003 + k), bits[k]) << k;
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("SM80")), 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("SM86")), 0);
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("SM87")), 0);
}

// A silent slave: both queries time out, SM86 counts, after SM85 (10) in a row EXP_1 and EXP_2
// show in SM80 bits 0 and 1; the PLC keeps scanning and the bits clear when it answers again.
TEST(Pl110Examples, TheExpExampleUnderASilentSlave) {
    QString error;
    auto net = pl110ExampleWith(
        "pl110-exp", pl110Fault(FaultDescription::Kind::Silent, "slave", 0, 3000), &error);
    ASSERT_TRUE(net) << error.toStdString();
    net->runUntil(2'900'000);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("SM80")), 3);
    EXPECT_GE(value(*net, QStringLiteral("pl"), QStringLiteral("SM86")), 20);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("V0")), 0);
    EXPECT_EQ(net->station(QStringLiteral("pl"))->engine().statistics().scans, 290u);
    net->runUntil(3'500'000);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("SM80")), 0);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("V9")), 109);
}

// The scale's answer lands in COM1_RX and is copied to V0..V9 each second; SM0.6 while "W" CR
// goes out.
TEST(Pl110Examples, TheFreePortExampleReadsTheScale) {
    NetRun r = runNetwork({}, {}, {}, pl110Example("pl110-free-port"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(3'000'000);
    const QByteArray weight("+0012.5kg\r");
    for (int k = 0; k < weight.size(); ++k)
        EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("V%1").arg(k)), weight[k]);
    EXPECT_GE(value(*r.net, QStringLiteral("pl"), QStringLiteral("V20")), 2);
    ASSERT_FALSE(r.records.empty());
    EXPECT_EQ(r.records[0].bytes, hex("57 0D"));
}

// A cut line: "W" CR reaches nobody, SM79 stays 0 and V20 stops counting; the PLC goes on and
// reads the scale again once the line is whole.
TEST(Pl110Examples, TheFreePortExampleUnderACutLine) {
    QString error;
    auto net = pl110ExampleWith("pl110-free-port",
                                pl110Fault(FaultDescription::Kind::Cut, "line", 0, 2500), &error);
    ASSERT_TRUE(net) << error.toStdString();
    net->runUntil(2'400'000);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("SM79")), 0);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("V20")), 0);
    net->runUntil(4'000'000);
    EXPECT_GE(value(*net, QStringLiteral("pl"), QStringLiteral("V20")), 1);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("V0")), '+');
}

// The PL110 reads the Vigor's VR1 and writes its AI1 to the Vigor's display register D100.
TEST(Pl110Examples, APl110MasterAndAVigorSlave) {
    NetRun r = runNetwork({}, {},
                          {QStringLiteral("--scans"), QStringLiteral("30"), QStringLiteral("--set"),
                           QStringLiteral("pl/AI1=512@0"), QStringLiteral("--set"),
                           QStringLiteral("vb/VR1=200@0"), QStringLiteral("--trace"),
                           QStringLiteral("pl/V0,vb/D100")},
                          pl110Example("pl110-vigor"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    ASSERT_TRUE(r.error.isEmpty()) << r.error.toStdString();
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("V0")), 200);
    EXPECT_EQ(value(*r.net, QStringLiteral("vb"), QStringLiteral("D100")), 512);
    EXPECT_EQ(value(*r.net, QStringLiteral("pl"), QStringLiteral("SM70")), 0);
}

// A corrupted byte in the Vigor's reply: one CRC error in SM77, no status bit (SM75 is 10), and
// the next poll reads.
TEST(Pl110Examples, APl110MasterAndAVigorSlaveUnderACorruptedByte) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(pl110Example("pl110-vigor"), &d, &error)) << error.toStdString();
    FaultDescription f = pl110Fault(FaultDescription::Kind::Corrupt, "rs485");
    f.frame = 1; // the Vigor's first reply
    f.byte = 3;
    d.faults.push_back(f);
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    Station *vb = net->station(QStringLiteral("vb"));
    vb->engine().writeWord(
        std::get<model::Address>(model::parseAddress(vb->target(), QStringLiteral("VR1"))), 99);
    net->runUntil(300'000);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("SM77")), 1);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("SM70")), 0);
    EXPECT_EQ(value(*net, QStringLiteral("pl"), QStringLiteral("V0")), 99);
}
