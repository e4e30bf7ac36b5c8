// Vigor Easy Link (Vigor M/VB/VH communication manual, B-3-3): the manual's programming example,
// verbatim, on a network whose slaves answer with the product's Computer Link responder; and each
// fault the issue names, shown by the working area's status codes as the manual lists them.

#include "network_fixture.h"

#include "comms/protocol/vigor_link_master.h"

using namespace rung;
using namespace rung::network;
using namespace rung::network::test;

namespace {

const QString kDir = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/easy-link/");

QByteArray easyLink(const QString &faults = QString(), int s5Baud = 19200) {
    return QStringLiteral(R"({
        "stations": [
            {"name": "master", "program": "master.il", "model": "VB",
             "ports": {"CP2": {"application": "easy-link", "station": 0, "baud": 19200}}},
            {"name": "s5", "program": "slave.il", "model": "VB",
             "ports": {"CP2": {"application": "computer-link", "station": 5, "baud": %1}}},
            {"name": "s2", "program": "slave.il", "model": "VB",
             "ports": {"CP2": {"application": "computer-link", "station": 2, "baud": 19200}}}
        ],
        "wires": [["master/CP2", "s5/CP2", "s2/CP2"]]
        %2
    })")
        .arg(s5Baud)
        .arg(faults.isEmpty() ? QString() : QStringLiteral(", \"faults\": [%1]").arg(faults))
        .toUtf8();
}

NetRun easyLinkRun(const QString &faults = QString(), int s5Baud = 19200, int rows = 60) {
    return runNetwork(easyLink(faults, s5Baud), {},
                      {QStringLiteral("--scans"), QString::number(rows), QStringLiteral("--set"),
                       QStringLiteral("s5/D10=123@0"), QStringLiteral("--set"),
                       QStringLiteral("s5/D19=-7@0"), QStringLiteral("--set"),
                       QStringLiteral("master/M0=1@0"), QStringLiteral("--set"),
                       QStringLiteral("master/M29=1@0"), QStringLiteral("--trace"),
                       QStringLiteral("master/D0,master/D9,master/M9199,hex:master/D100")},
                      kDir + QStringLiteral("test.rungnet"));
}

std::vector<int> column(const QString &trace, int k) {
    std::vector<int> out;
    const QStringList lines = trace.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QString cell = lines[i].split(QLatin1Char(','))[k];
        out.push_back(cell.startsWith(QLatin1Char('#')) ? cell.mid(1).toInt(nullptr, 16)
                                                        : cell.toInt());
    }
    return out;
}

} // namespace

// Set 1 reads D10..D19 of station 5 into D0..D9; set 2 writes M0..M29 to M100..M129 of
// station 2; M9199 is ON for one scan each time both have run.
TEST(EasyLink, TheManualsExampleReadsAndWritesItsTwoSets) {
    const NetRun r = easyLinkRun();
    ASSERT_TRUE(r.net) << r.error.toStdString();
    ASSERT_TRUE(r.error.isEmpty()) << r.error.toStdString();
    EXPECT_EQ(value(*r.net, QStringLiteral("master"), QStringLiteral("D0")), 123);
    EXPECT_EQ(value(*r.net, QStringLiteral("master"), QStringLiteral("D9")), -7);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M100")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M129")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M128")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M130")));       // past the set
    EXPECT_EQ(value(*r.net, QStringLiteral("master"), QStringLiteral("D100")), 0); // normal
    // M9199: one scan ON per completed table, never two in a row.
    const std::vector<int> done = column(r.trace, 4);
    int pulses = 0;
    for (std::size_t k = 0; k < done.size(); ++k) {
        pulses += done[k];
        if (k > 0) {
            EXPECT_FALSE(done[k] && done[k - 1]) << "row " << k;
        }
    }
    EXPECT_GE(pulses, 2);
    // The first frame is the Computer Link read the product's codec makes: station 5, 51h,
    // D10 at link byte 1C14h, 20 bytes.
    ASSERT_FALSE(r.records.empty());
    comms::vigor::Request read;
    read.station = 5;
    read.command = comms::vigor::Command::Read;
    read.address = 0x1C14;
    read.length = 20;
    EXPECT_EQ(r.records.front().bytes, comms::vigor::encodeRequest(read));
    EXPECT_EQ(r.records.front().sender, QStringLiteral("master/CP2"));
    // The slave's answer: its D10 = 123 (007Bh) low byte first.
    EXPECT_TRUE(r.records[1].bytes.startsWith(QByteArray("\x06"
                                                         "05510"
                                                         "07B00",
                                                         10)));
}

// Bits that start inside a link byte go one by one (70h / 71h), whole bytes with 61h: no
// other bit of the slave is written (M96..M99 and M130.. stay as the slave has them).
TEST(EasyLink, BitsOutsideTheSetAreNotTouched) {
    NetRun r = runNetwork(easyLink(), {}, {}, kDir + QStringLiteral("test.rungnet"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    Station *s2 = r.net->station(QStringLiteral("s2"));
    for (const char *d : {"M99", "M130", "M131"})
        s2->engine().setBit(
            std::get<model::Address>(model::parseAddress(s2->target(), QString::fromLatin1(d))),
            true);
    r.net->runUntil(400'000);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M99")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M130")));
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M131")));
    EXPECT_FALSE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M100")));
    int bitFrames = 0, byteFrames = 0;
    for (const TrafficRecord &t : r.records) {
        if (t.sender != QLatin1String("master/CP2") || t.bytes.size() < 5)
            continue;
        bitFrames += t.bytes.mid(3, 2) == "70" || t.bytes.mid(3, 2) == "71";
        byteFrames += t.bytes.mid(3, 2) == "61";
    }
    EXPECT_GT(bitFrames, 0);
    EXPECT_GT(byteFrames, 0);
}

// A cut wire: no slave answers; each set ends at its first time-out (D9129 = 0: 100 ms after
// the request's last byte, seen at the next END) with status A and the station in S2's lower
// byte: 05 from 110 ms, 02 once set 2 has timed out too (220 ms); the table still completes
// (M9199) and the simulation goes on.
TEST(EasyLink, ACutWireShowsNoResponseA) {
    const NetRun r = easyLinkRun(QStringLiteral(R"({"kind": "cut", "wire": "w1", "from": 0})"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    const std::vector<int> status = column(r.trace, 5);
    EXPECT_EQ(status[5], 0);       // before the first time-out (100 ms after the request)
    EXPECT_EQ(status[12], 0x0A05); // station 5 did not answer
    EXPECT_EQ(status[25], 0x0A02); // nor station 2
    EXPECT_EQ(value(*r.net, QStringLiteral("master"), QStringLiteral("D0")), 0);
    int pulses = 0;
    for (int v : column(r.trace, 4))
        pulses += v;
    EXPECT_GE(pulses, 2);
}

// A silent station: its set times out (A, station 5), the other set runs; S2 keeps the error
// until a whole table runs clean, and shows 0 again once the station is back.
TEST(EasyLink, ASilentStationShowsAAndTheOthersRun) {
    const NetRun r = easyLinkRun(
        QStringLiteral(R"({"kind": "silent", "station": "s5", "from": 0, "to": 300})"), 19200, 80);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    const std::vector<int> status = column(r.trace, 5);
    EXPECT_EQ(status[20], 0x0A05);
    EXPECT_TRUE(bit(*r.net, QStringLiteral("s2"), QStringLiteral("M129"))); // set 2 ran
    EXPECT_EQ(status.back(), 0); // back after 300 ms: a clean table clears S2
    EXPECT_EQ(value(*r.net, QStringLiteral("master"), QStringLiteral("D0")), 123);
}

// A corrupted byte in the request: the slave answers with its sum error (11h), which is an
// abnormal communication, status B.
TEST(EasyLink, ACorruptedByteShowsAbnormalB) {
    const NetRun r = easyLinkRun(
        QStringLiteral(R"({"kind": "corrupt", "wire": "w1", "frame": 0, "byte": 3, "xor": 1})"),
        19200, 10);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_EQ(column(r.trace, 5)[4], 0x0B05);
    ASSERT_GE(r.records.size(), 2u);
    EXPECT_FALSE(r.records[0].note.isEmpty()); // the traffic says which byte was changed
    EXPECT_EQ(r.records[1].bytes.mid(5, 2), QByteArray("11")); // the slave's sum error
}

// Station 5 at 9600 bps on a 19200 bps line reads other characters: it never answers (A).
TEST(EasyLink, AMismatchedBaudRateShowsA) {
    const NetRun r = easyLinkRun(QString(), 9600, 20);
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_EQ(column(r.trace, 5)[15], 0x0A05);
}

// A wrong table: a device type the manual does not list is status 4, found before anything
// is sent; the other set still runs.
TEST(EasyLink, AWrongDeviceTypeShowsStatus4) {
    NetRun r = runNetwork(easyLink(), {},
                          {QStringLiteral("--scans"), QStringLiteral("30"), QStringLiteral("--set"),
                           QStringLiteral("master/D1006=7@1"), QStringLiteral("--trace"),
                           QStringLiteral("hex:master/D100")},
                          kDir + QStringLiteral("test.rungnet"));
    ASSERT_TRUE(r.net) << r.error.toStdString();
    EXPECT_EQ(column(r.trace, 2).back(), 0x0405); // the set is read again in the next table
    EXPECT_TRUE(r.net->station(QStringLiteral("master"))->engine().runtimeErrors().empty());
}
