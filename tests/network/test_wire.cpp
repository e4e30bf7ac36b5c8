// The wire: characters across mismatched lines (uart.h), wire time at baud and format, the
// network file's errors, collisions.

#include "network_fixture.h"

#include "network/devices.h"
#include "network/uart.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

model::SerialSettings line(int baud, const char *frame) {
    model::SerialSettings s;
    s.baud = baud;
    model::parseFrameFormat(QString::fromLatin1(frame), &s);
    return s;
}

} // namespace

TEST(Uart, TheSameLineCarriesTheBytes) {
    const Received r = acrossLine("\x02"
                                  "0551\x03",
                                  line(19200, "8N1"), line(19200, "8N1"));
    EXPECT_EQ(r.bytes, QByteArray("\x02"
                                  "0551\x03"));
    EXPECT_EQ(r.errors, 0);
}

// 7E1 read as 8N1 at the same rate: ten bits a character either way; the parity bit arrives
// as bit 7 (even parity: set when the seven bits have an odd number of ones).
TEST(Uart, SevenEvenOneReadAsEightNoneOneKeepsTheParityAsBit7) {
    const Received r =
        acrossLine(QByteArray("\x30\x31\x43", 3), line(19200, "7E1"), line(19200, "8N1"));
    EXPECT_EQ(r.bytes, QByteArray("\x30\xB1\xC3", 3));
    EXPECT_EQ(r.errors, 0);
}

// 8N1 read as 7E1: bit 7 is taken as the parity bit; where it is wrong, a parity error.
TEST(Uart, EightNoneReadAsSevenEvenChecksBit7AsParity) {
    const Received r = acrossLine(QByteArray("\x41\xC1", 2), line(9600, "8N1"), line(9600, "7E1"));
    EXPECT_EQ(r.bytes, QByteArray("\x41\x41", 2));
    EXPECT_EQ(r.errors, 1);
}

// Another baud rate: other characters, with framing errors; never the bytes sent.
TEST(Uart, AnotherBaudRateReadsOtherCharacters) {
    const QByteArray sent = hex("02 30 31 35 31 31 43 30 30 30 32 03 30 30");
    const Received slow = acrossLine(sent, line(19200, "7E1"), line(9600, "7E1"));
    EXPECT_NE(slow.bytes, sent);
    EXPECT_GT(slow.errors, 0);
    EXPECT_LT(slow.bytes.size(), sent.size());
    const Received fast = acrossLine(sent, line(9600, "7E1"), line(19200, "7E1"));
    EXPECT_NE(fast.bytes, sent);
    EXPECT_GT(fast.errors, 0);
}

TEST(Uart, WireTimeCountsEveryBitOfEveryCharacter) {
    EXPECT_EQ(wireTimeUs(14, line(19200, "7E1")), 7292); // 140 bits
    EXPECT_EQ(wireTimeUs(8, line(9600, "8E2")), 10000);  // 8 x 12 bits
    EXPECT_EQ(wireTimeUs(1, line(38400, "8N1")), 261);
}

TEST(NetworkFile, ErrorsSayWhatWhereAndWhy) {
    auto error = [](const char *json) {
        NetworkDescription d;
        QString e;
        EXPECT_FALSE(parseNetwork(QByteArray(json), QStringLiteral("n.rungnet"), &d, &e));
        return e.toStdString();
    };
    EXPECT_EQ(error("{"),
              "n.rungnet: line 1, column 2: the file is not valid JSON (unterminated object)");
    EXPECT_EQ(error(R"({"stations": []})"),
              "n.rungnet: stations: a network needs at least one station");
    EXPECT_EQ(
        error(R"({"stations": [{"name": "a b", "program": "p.il"}]})"),
        "n.rungnet: stations[0].name: \"a b\" is no name (letters, digits, _ and -, at most 32)");
    EXPECT_EQ(
        error(
            R"({"stations": [{"name": "a", "program": "p.il"}, {"name": "a", "program": "p.il"}]})"),
        "n.rungnet: stations[1].name: a second \"a\"; names are unique");
    EXPECT_EQ(error(R"({"stations": [{"name": "a", "program": "p.il", "prog": 1}]})"),
              "n.rungnet: stations[0].prog: unknown key (this object takes: name, program, target, "
              "model, period, ports, comment)");
    EXPECT_EQ(error(R"({"stations": [{"name": "a", "program": "p.il"}], "wires": [["a/CP2"]]})"),
              "n.rungnet: wires[0]: a wire joins at least two ends");
    EXPECT_EQ(
        error(R"({"stations": [{"name": "a", "program": "p.il"}], "faults": [{"kind": "fire"}]})"),
        "n.rungnet: faults[0].kind: \"fire\" is no fault (cut, silent, corrupt)");
}

TEST(NetworkFile, PortSettingsAreCheckedAgainstTheTargetsTables) {
    auto build = [](const char *ports) {
        const QByteArray json =
            QStringLiteral(R"({"stations": [{"name": "a", "program": "p.il",
            "model": "%1", "ports": %2}]})")
                .arg(QLatin1String(ports[0] == 'H' ? "VH" : "VB"), QLatin1String(ports + 1))
                .toUtf8();
        const NetRun r =
            runNetwork(json, {{QStringLiteral("p.il"), QStringLiteral("; target: vigor\nEND\n")}});
        return r.error.toStdString();
    };
    EXPECT_EQ(build(R"(B{"CP2": {"application": "easy-link", "baud": 12345}})"),
              "t.rungnet: stations[0].ports.CP2.baud: 12345 is not a rate of Easy Link (19200, "
              "4800, 9600, 38400)");
    EXPECT_EQ(build(R"(H{"CP2": {"application": "cpu-link"}})"),
              "t.rungnet: stations[0].ports.CP2.application: the Vigor VH has no CPU Link on CP2 "
              "(it has: computer-link, modbus, non-protocol)");
    EXPECT_EQ(build(R"(B{"CP9": {}})"),
              "t.rungnet: stations[0].ports.CP9: Vigor has no port CP9 (its ports: CP1, CP2, CP3, "
              "MODULE1, MODULE2, MODULE3, MODULE4, MODULE5, MODULE6, MODULE7, MODULE8, MODULE9, "
              "MODULE10, MODULE11, MODULE12, MODULE13, MODULE14, MODULE15, MODULE16)");
    EXPECT_EQ(build(R"(B{"CP2": {"application": "computer-link", "frame": "8N1"}})"),
              "t.rungnet: stations[0].ports.CP2.frame: Computer Link always uses 7E1");
    EXPECT_EQ(build(R"(B{"CP2": {"application": "computer-link", "slaves": 2}})"),
              "t.rungnet: stations[0].ports.CP2.slaves: Computer Link takes no setting \"slaves\"");
    EXPECT_EQ(build(R"(B{"CP2": {"application": "cpu-link", "station": 8}})"),
              "t.rungnet: stations[0].ports.CP2.station: needs a whole number from 0 to 7");
}

// Two stations sending at once on one wire: both frames are garbled for every receiver, and
// the traffic says so.
TEST(Wire, ACollisionGarblesBothFrames) {
    const char *sender = "; target: vigor\nLD M9002\nSET M9122\nLD M9000\nRS D0 K2 D100 K2\nEND\n";
    NetRun r = runNetwork(R"({"stations": [
            {"name": "a", "program": "s.il", "ports": {"CP2": {"application": "non-protocol"}}},
            {"name": "b", "program": "s.il", "ports": {"CP2": {"application": "non-protocol"}}}],
        "devices": [{"name": "dev", "kind": "line", "frame": "7E1"}],
        "wires": [["a/CP2", "b/CP2", "dev"]]})",
                          {{QStringLiteral("s.il"), QString::fromLatin1(sender)}});
    ASSERT_TRUE(r.net) << r.error.toStdString();
    r.net->runUntil(50'000);
    ASSERT_EQ(r.records.size(), 2u);
    EXPECT_FALSE(r.records[1].note.isEmpty());
    auto *dev = dynamic_cast<LineDevice *>(r.net->endpoint(QStringLiteral("dev")));
    ASSERT_TRUE(dev);
    EXPECT_EQ(dev->received(), QByteArray("\x7F\x7F\x7F\x7F", 4)); // inverted zeros, 7 bits
}
