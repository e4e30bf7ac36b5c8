// Vigor RS (Vigor M/VB/VH communication manual, B-3-9): the manual's application example, verbatim,
// sends the frames the manual prints byte for byte and its reply check accepts the answer of the
// Computer Link station on the wire; and RS's flags and counts against a line device.

#include "network_fixture.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kExample = QStringLiteral(
    RUNG_SOURCE_DIR "/resources/examples/networks/non-protocol/non-protocol.rungnet");

QByteArray readFrame() {
    return hex("02 30 31 35 31 31 43 30 30 30 32 03 30 30");
}

} // namespace

TEST(NonProtocol, TheManualsExampleSendsItsFramesAndChecksTheReplies) {
    const NetRun r = runNetwork({}, {},
                                {QStringLiteral("--scans"), QStringLiteral("60"),
                                 QStringLiteral("--set"), QStringLiteral("left/VR1=120@0"),
                                 QStringLiteral("--set"), QStringLiteral("right/VR1=77@0"),
                                 QStringLiteral("--trace"), QStringLiteral("left/Y0,left/Y1")},
                                kExample);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    ASSERT_TRUE(r.error.isEmpty()) << r.error.toStdString();
    // Each PLC shows the other's VR1: the left D110 (its display), the right D1.
    EXPECT_EQ(value(*r.net, QStringLiteral("left"), QStringLiteral("D110")), 77);
    EXPECT_EQ(value(*r.net, QStringLiteral("right"), QStringLiteral("D1")), 120);
    // The frames B-3-9 prints: the read of D0 (1C00H) and the write's reply.
    std::vector<QByteArray> left, right;
    for (const TrafficRecord &t : r.records)
        (t.sender == QLatin1String("left/CP2") ? left : right).push_back(t.bytes);
    ASSERT_GE(left.size(), 2u);
    ASSERT_GE(right.size(), 2u);
    EXPECT_EQ(left[0], readFrame());
    // The write: "01" "61" "1C02" "02", D111 = 120 = 0078H low byte first, ETX and the sum.
    EXPECT_EQ(left[1], hex("02 30 31 36 31 31 43 30 32 30 32 37 38 30 30 03 44 32"));
    EXPECT_EQ(right[1], hex("06 30 31 36 31 30 30 03 32 42"));
    // The replies pass the program's own sum and error checks: Y0, Y1 never came ON.
    EXPECT_FALSE(r.trace.contains(QStringLiteral(",1,")));
    EXPECT_FALSE(r.trace.contains(QStringLiteral(",1\n")));
}

// A corrupted byte in the right PLC's reply (its 2nd frame on the wire, the reply to the
// read): the program's sum check fails and Y0 ("read communication fails") comes ON.
TEST(NonProtocol, ACorruptedReplyFailsTheProgramsSumCheck) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(kExample, &d, &error)) << error.toStdString();
    FaultDescription f;
    f.kind = FaultDescription::Kind::Corrupt;
    f.wire = QStringLiteral("w1");
    f.frame = 1;
    f.byte = 8; // a data digit: the value changes, its sum no longer matches
    f.mask = 0x01;
    d.faults.push_back(f);
    auto net = Network::build(d, listingLoader(), &error);
    ASSERT_TRUE(net) << error.toStdString();
    bool y0 = false;
    for (int row = 0; row < 20; ++row) {
        net->runUntil(qint64(row) * 10'000);
        y0 = y0 || bit(*net, QStringLiteral("left"), QStringLiteral("Y0"));
    }
    EXPECT_TRUE(y0);
}

namespace {

// A PLC whose RS sends D0.. (count D200) and receives into D100.. (count D201) when X0 rises;
// a line device answers "OK" + CR to "AB".
QByteArray rsNetwork(const QString &port, const QString &device) {
    return QStringLiteral(R"({
        "stations": [{"name": "plc", "program": "rs.il", "model": "VB",
                      "ports": {"CP2": %1}}],
        "devices": [%2],
        "wires": [["plc/CP2", "dev"]]
    })")
        .arg(port, device)
        .toUtf8();
}

const char *kRs = "; target: vigor\n"
                  "LD X0\nPLS M0\n"
                  "LD M0\nSET M9122\n"
                  "LD M9000\nRS D0 D200 D100 D201\n"
                  "END\n";

NetRun rsRun(const QString &port, const QString &device, bool bytes8, int count, int receive) {
    NetRun r =
        runNetwork(rsNetwork(port, device), {{QStringLiteral("rs.il"), QString::fromLatin1(kRs)}});
    if (!r.net)
        return r;
    Station *s = r.net->station(QStringLiteral("plc"));
    auto at = [&](const char *d) {
        return std::get<model::Address>(model::parseAddress(s->target(), QString::fromLatin1(d)));
    };
    s->engine().setBit(at("M9161"), bytes8);
    s->engine().writeWord(at("D0"), bytes8 ? 'A' : ('B' << 8 | 'A'));
    s->engine().writeWord(at("D1"), bytes8 ? 'B' : 0);
    s->engine().writeWord(at("D200"), count);
    s->engine().writeWord(at("D201"), receive);
    s->engine().setBit(at("X0"), true);
    r.net->runUntil(300'000);
    return r;
}

const QString kLine = QStringLiteral(
    R"({"name": "dev", "kind": "line", "baud": 19200, "frame": "7E1",
        "answers": [{"expect": "41 42", "reply": "4F 4B 0D"}]})");
const QString kPort =
    QStringLiteral(R"({"application": "non-protocol", "baud": 19200, "frame": "7E1"})");

} // namespace

// 8-bit mode (M9161 ON): a byte a word, the low one; reception ends with n bytes, M9123 ON and
// D9123 their count; M9122 goes OFF when the last byte has left.
TEST(NonProtocol, EightBitModeSendsLowBytesAndReceivesNBytes) {
    const NetRun r = rsRun(kPort, kLine, true, 2, 3);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    ASSERT_FALSE(r.records.empty());
    EXPECT_EQ(r.records[0].bytes, QByteArray("AB"));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9122")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9123")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9129")));
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D9123")), 3);
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D100")), 'O');
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D101")), 'K');
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D102")), '\r');
}

// 16-bit mode: both bytes of a word, low first, m and n counting bytes; fewer bytes than n
// end with the time-out (D9129 = 0: 100 ms after the last one), M9129 and M9123 ON.
TEST(NonProtocol, SixteenBitModeAndTheTimeOut) {
    const NetRun r = rsRun(kPort, kLine, false, 2, 10);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_EQ(r.records[0].bytes, QByteArray("AB"));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9129")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9123")));
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D9123")), 3);
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D100")), 'K' << 8 | 'O');
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D101")), '\r');
}

// The port's start and end characters ("Start Char", "End Char"): added when sending, and the
// end character ends reception without being stored.
TEST(NonProtocol, StartAndEndCharacters) {
    const NetRun r = rsRun(QStringLiteral(R"({"application": "non-protocol", "baud": 19200,
                                         "frame": "7E1", "start": 2, "end": 13})"),
                           QStringLiteral(R"({"name": "dev", "kind": "line", "baud": 19200,
                            "frame": "7E1", "answers": [{"expect": "02 41 42 0D",
                            "reply": "02 4F 4B 0D"}]})"),
                           true, 2, 10);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_EQ(r.records[0].bytes, hex("02 41 42 0D"));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9123")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9129")));
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D9123")), 2);
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D101")), 'K');
}

// A device at another format (8N1 against the port's 7E1) sends characters the port reads
// with parity errors: M9063 and D9063 say so.
TEST(NonProtocol, AWrongFormatShowsACommunicationError) {
    const NetRun r = rsRun(kPort, QStringLiteral(R"({"name": "dev", "kind": "line", "baud": 19200,
                            "frame": "8N1", "answers": [{"expect": "41 42",
                            "reply": "CF 4B 0D"}]})"),
                           true, 2, 3);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_TRUE(bit(*r.net, QStringLiteral("plc"), QStringLiteral("M9063")));
    EXPECT_EQ(value(*r.net, QStringLiteral("plc"), QStringLiteral("D9063")), 6301);
}
