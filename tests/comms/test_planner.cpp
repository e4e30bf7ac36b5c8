// The request planner: gaps bridged exactly when their units cost less than another frame,
// frames split at each protocol's limit and at the holes of its map, exact frames for known
// sets, and the optimum checked against every way of cutting small sets into frames.

#include "comms/driver/planner.h"
#include "tests/comms/driver_fixture.h"

#include <random>

namespace rung::comms {
void PrintTo(const UnitSpan &s, std::ostream *os) {
    *os << "{space " << int(s.space) << ", " << s.start << ", " << s.count << "}";
}
} // namespace rung::comms

namespace rung::comms::test {
namespace {

using model::Family;
using model::ProtocolSpace;

std::vector<UnitSpan> spans(const Driver::Plan &plan) {
    std::vector<UnitSpan> out;
    for (const PlannedRead &r : plan.reads)
        out.push_back(r.span);
    return out;
}

TEST(Planner, VigorLinkBridgesAGapOfUpToTwelveBytesAndNoMore) {
    // A 51h frame costs 24 bytes besides its data, a byte of data 2 (two hex digits): a gap of
    // 12 bytes costs as much as a frame, and then one frame is better (fewer frames).
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // D0 and D7: a gap of D1..D6, 12 bytes: one frame 1C00h..1C0Fh.
    EXPECT_EQ(spans(f.driver->plan(f.devices({"D0", "D7"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0x1C00, 16}}));
    // D0 and D8: 14 bytes of gap cost more than a frame: two.
    EXPECT_EQ(spans(f.driver->plan(f.devices({"D0", "D8"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0x1C00, 2},
                                     {ProtocolSpace::LinkBytes, 0x1C10, 2}}));
    EXPECT_EQ(f.driver->plan(f.devices({"D0", "D8"})).bytes(), 2 * (24 + 4));
}

TEST(Planner, VigorLinkSplitsAt128BytesWhereItCostsLeast) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // D0..D63 are 128 bytes, exactly one frame.
    std::vector<model::Address> all;
    for (int i = 0; i < 64; ++i)
        all.push_back(f.device(QStringLiteral("D%1").arg(i).toLatin1().constData()));
    EXPECT_EQ(spans(f.driver->plan(all)),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0x1C00, 128}}));
    // D0, D63, D64: 130 bytes do not fit; D0 alone and D63..D64 cost least.
    EXPECT_EQ(spans(f.driver->plan(f.devices({"D0", "D63", "D64"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0x1C00, 2},
                                     {ProtocolSpace::LinkBytes, 0x1C7E, 4}}));
}

TEST(Planner, BitsShareTheirByteAndAreasOfOneSpaceShareFrames) {
    FakeDriver f(Family::Vigor, ProtocolKind::VigorLink, 0);
    // X0..X7 are byte 0000h, Y0 byte 0040h: far apart, two frames; X0 and X7 one byte.
    EXPECT_EQ(spans(f.driver->plan(f.devices({"X0", "X7", "X10"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0, 2}}));
    // Y77 (byte 0047h) and M0 (0080h) are 57 bytes apart: two frames.
    EXPECT_EQ(f.driver->plan(f.devices({"Y77", "M0"})).reads.size(), 2u);
    // The last step relay byte (037Ch) and the first timer contact byte (0380h) are 3 bytes
    // apart, but 037Dh..037Fh hold nothing: a read never crosses them. (T0's value at
    // 1400h is a third frame.)
    EXPECT_EQ(spans(f.driver->plan(f.devices({"S999", "T0"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::LinkBytes, 0x037C, 1},
                                     {ProtocolSpace::LinkBytes, 0x0380, 1},
                                     {ProtocolSpace::LinkBytes, 0x1400, 2}}));
}

TEST(Planner, ModbusRtuBridgesUpToSixRegisters) {
    // RTU: 8 bytes of request, 5 of reply besides 2 a register: 6 registers of gap (12 bytes)
    // cost less than another frame (13), 7 more.
    FakeDriver f(Family::Vigor, ProtocolKind::ModbusRtu, 1);
    EXPECT_EQ(f.driver->plan(f.devices({"D0", "D7"})).reads.size(), 1u);
    EXPECT_EQ(f.driver->plan(f.devices({"D0", "D8"})).reads.size(), 2u);
    // Coils: 8 to a byte, so a gap of up to 8 * 13 coils is still cheaper than a frame.
    EXPECT_EQ(spans(f.driver->plan(f.devices({"Y0", "Y147"}))),
              (std::vector<UnitSpan>{{ProtocolSpace::Coils, 0, 104}}));
}

TEST(Planner, Pl110ReadsAtMost30WordsAFrame) {
    FakeDriver f(Family::Pl110, ProtocolKind::ModbusRtu, 1);
    std::vector<model::Address> run;
    for (int i = 0; i < 30; ++i)
        run.push_back(f.device(QStringLiteral("V%1").arg(i).toLatin1().constData()));
    EXPECT_EQ(spans(f.driver->plan(run)),
              (std::vector<UnitSpan>{{ProtocolSpace::HoldingRegisters, 2000, 30}}));
    // V0..V30 is 31 words: two frames, each within the limit.
    run.push_back(f.device("V30"));
    const auto plan = f.driver->plan(run);
    ASSERT_EQ(plan.reads.size(), 2u);
    for (const PlannedRead &r : plan.reads)
        EXPECT_LE(r.span.count, 30);
    // Bits have no such limit in the manual: I1..I200 is one read of coils.
    std::vector<model::Address> inputs;
    for (int i = 1; i <= 200; ++i)
        inputs.push_back(f.device(QStringLiteral("I%1").arg(i).toLatin1().constData()));
    EXPECT_EQ(spans(f.driver->plan(inputs)),
              (std::vector<UnitSpan>{{ProtocolSpace::Coils, 1600, 200}}));
}

TEST(Planner, HostLinkCountsThePartsOfALongReply) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    // 17 characters of command, 11 of reply besides 4 a word: 7 words of gap are bridged.
    EXPECT_EQ(f.driver->plan(f.devices({"DM 0000", "DM 0008"})).reads.size(), 1u);
    EXPECT_EQ(f.driver->plan(f.devices({"DM 0000", "DM 0009"})).reads.size(), 2u);
    // The cost of a frame is the codec's own: 1 word = 17 + 15; 31 words = two parts.
    auto &p = f.driver->protocol();
    EXPECT_EQ(p.readFrameBytes(ProtocolSpace::HostLinkDm, 1), 17 + 15);
    EXPECT_EQ(p.readFrameBytes(ProtocolSpace::HostLinkDm, 30), 17 + 11 + 120);
    EXPECT_EQ(p.readFrameBytes(ProtocolSpace::HostLinkDm, 31), 17 + 11 + 124 + 3 + 1);
}

// Every way of cutting the needed items into consecutive frames, for small sets: the planner
// must find the cheapest.
long long bruteForce(const std::vector<UnitSpan> &items, const ReadCosts &costs,
                     const std::vector<UnitSpan> &segments) {
    const std::size_t n = items.size();
    long long best = -1;
    for (unsigned cuts = 0; cuts < (1u << (n - 1)); ++cuts) {
        long long total = 0;
        bool ok = true;
        std::size_t first = 0;
        for (std::size_t k = 0; k < n && ok; ++k) {
            if (k + 1 < n && !(cuts & (1u << k)))
                continue;
            const UnitSpan span{items[first].space, items[first].start,
                                items[k].end() - items[first].start};
            ok = span.count <= costs.maxUnits(span.space) || first == k;
            // One segment holds the whole frame.
            bool inOne = first == k;
            for (const UnitSpan &s : segments)
                inOne = inOne ||
                        (s.space == span.space && span.start >= s.start && span.end() <= s.end());
            ok = ok && inOne;
            total += costs.frameBytes(span.space, span.count);
            first = k + 1;
        }
        if (ok && (best < 0 || total < best))
            best = total;
    }
    return best;
}

TEST(Planner, FindsTheCheapestCutOfRandomSetsForEveryProtocol) {
    std::mt19937 random(12);
    struct Case {
        Family family;
        ProtocolKind protocol;
        ProtocolSpace space;
        int from, to, width;
    };
    const Case cases[] = {
        {Family::Vigor, ProtocolKind::VigorLink, ProtocolSpace::LinkBytes, 0x1C00, 0x1D00, 2},
        {Family::Vigor, ProtocolKind::ModbusRtu, ProtocolSpace::HoldingRegisters, 0, 300, 1},
        {Family::Pl110, ProtocolKind::ModbusRtu, ProtocolSpace::HoldingRegisters, 2000, 2120, 1},
        {Family::Vigor, ProtocolKind::ModbusTcp, ProtocolSpace::Coils, 512, 3000, 1},
        {Family::Cpm1, ProtocolKind::HostLink, ProtocolSpace::HostLinkDm, 0, 200, 1},
    };
    for (const Case &c : cases) {
        FakeDriver f(c.family, c.protocol, 1);
        auto &p = f.driver->protocol();
        const ReadCosts costs{[&p](ProtocolSpace s) { return p.maxReadUnits(s); },
                              [&p](ProtocolSpace s, int n) { return p.readFrameBytes(s, n); }};
        const auto segments = mappedSegments(f.driver->target(), p.map());
        for (int round = 0; round < 40; ++round) {
            std::vector<int> starts;
            std::uniform_int_distribution<int> at(c.from, c.to - c.width);
            const int n = 2 + int(random() % 9);
            while (int(starts.size()) < n) {
                const int s = at(random) / c.width * c.width;
                if (std::find(starts.begin(), starts.end(), s) == starts.end())
                    starts.push_back(s);
            }
            std::sort(starts.begin(), starts.end());
            std::vector<UnitSpan> items;
            for (int s : starts)
                items.push_back({c.space, s, c.width});
            const auto plan = planReads(items, costs, segments);
            EXPECT_EQ(totalBytes(plan), bruteForce(items, costs, segments))
                << protocolName(c.protocol).toStdString() << " round " << round;
            for (const PlannedRead &r : plan)
                EXPECT_LE(r.span.count, costs.maxUnits(r.span.space));
        }
    }
}

TEST(Planner, ADeviceOutsideTheMapIsNamedNotRead) {
    FakeDriver f(Family::Cpm1, ProtocolKind::HostLink, 0);
    // DM 6656..6667 exist on the PLC but lie past the Host Link map's reach (RD / WD reach
    // DM 0000..1023 and 6144..6655; Omron CPM1/SRM1 programming manual W353, Host Link).
    const auto plan = f.driver->plan(f.devices({"DM 6660", "DM 0001"}));
    ASSERT_EQ(plan.unmapped.size(), 1u);
    EXPECT_TRUE(plan.unmapped.front().second.contains(QLatin1String("DM 6660")))
        << plan.unmapped.front().second.toStdString();
    EXPECT_EQ(plan.reads.size(), 1u);
}

} // namespace
} // namespace rung::comms::test
