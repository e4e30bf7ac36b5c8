// The comms planner and drivers (issue 12): for each protocol, the frames and bytes on the
// wire of a refresh of 200 scattered devices, against the least the protocol allows for that
// set, computed here exactly by another method (a dynamic program over every address, not
// over the needed runs as the planner's is); and the time a refresh takes over a real
// pseudo-terminal with a responding peer, against the wire time of its bytes at 19200 bps.
// A pty has no baud rate: its time is what the software adds to the wire time.

#include "comms/driver/driver.h"
#include "comms/transport/pty_transport.h"
#include "model/target/target.h"
#include "tests/comms/fake_plc.h"
#include "tests/comms/pty_peer.h"

#include <QElapsedTimer>

#include <benchmark/benchmark.h>

#include <limits>
#include <map>
#include <random>

using namespace rung;
using namespace rung::comms;

namespace {

struct Case {
    const char *name;
    model::Family family;
    ProtocolKind protocol;
    int station;
    int bitsPerCharacter; // start + data + parity + stop at the protocol's usual frame
};

const Case kCases[] = {
    {"VigorLink", model::Family::Vigor, ProtocolKind::VigorLink, 0, 10},      // 7E1
    {"VigorModbusRtu", model::Family::Vigor, ProtocolKind::ModbusRtu, 1, 10}, // 8N1
    {"Pl110ModbusRtu", model::Family::Pl110, ProtocolKind::ModbusRtu, 1, 10}, // 8N1
    {"Cpm1HostLink", model::Family::Cpm1, ProtocolKind::HostLink, 0, 11},     // 7E2
};

std::unique_ptr<Driver> makeDriver(const Case &c, std::unique_ptr<Transport> transport) {
    QString error;
    return Driver::create(model::Target::get(c.family), c.protocol, std::move(transport), c.station,
                          {1000, 0, 5}, &error);
}

// 200 devices, scattered: an area the protocol maps, then an element of it, at random (fixed
// seed); timers and counters bring their contact and value (and PL110 presets) along.
std::vector<model::Address> scattered(const Driver &driver, int count) {
    const model::Target &t = driver.target();
    std::vector<int> areas;
    for (int a = 0; a < int(t.areas.size()); ++a) {
        const model::Area &area = t.area(a);
        if (area.last >= area.first &&
            driver.plan({model::Address{a, area.first, -1}}).unmapped.empty())
            areas.push_back(a);
    }
    std::mt19937 random(2026);
    std::vector<model::Address> out;
    while (int(out.size()) < count) {
        const int a = areas[random() % areas.size()];
        const model::Area &area = t.area(a);
        const model::Address address{a, area.first + int(random() % (area.last - area.first + 1)),
                                     -1};
        if (driver.plan({address}).unmapped.empty() &&
            std::find(out.begin(), out.end(), address) == out.end())
            out.push_back(address);
    }
    return out;
}

// The least bytes that read every needed unit: over every address of each segment, g[x] is
// the least cost of reading what is needed below x with frames that end at or before x; a
// frame may start and end anywhere except inside a value.
long long exactMinimum(const Driver::Plan &plan, ProtocolDriver &protocol,
                       const std::vector<UnitSpan> &segments) {
    std::map<model::ProtocolSpace, std::vector<UnitSpan>> needs;
    for (const auto &device : plan.placements)
        for (const auto &p : device)
            needs[p.source.space].push_back(p.source);
    long long total = 0;
    constexpr long long inf = std::numeric_limits<long long>::max() / 4;
    for (const UnitSpan &segment : segments) {
        std::vector<char> needed(std::size_t(segment.count), 0),
            inside(std::size_t(segment.count) + 1, 0);
        bool any = false;
        for (const UnitSpan &n : needs[segment.space]) {
            if (n.start < segment.start || n.end() > segment.end())
                continue;
            any = true;
            for (int u = n.start; u < n.end(); ++u)
                needed[std::size_t(u - segment.start)] = 1;
            for (int u = n.start + 1; u < n.end(); ++u)
                inside[std::size_t(u - segment.start)] = 1; // no frame boundary here
        }
        if (!any)
            continue;
        const int limit = protocol.maxReadUnits(segment.space);
        std::vector<long long> g(std::size_t(segment.count) + 1, inf);
        g[0] = 0;
        for (int x = 1; x <= segment.count; ++x) {
            if (!needed[std::size_t(x - 1)])
                g[std::size_t(x)] = g[std::size_t(x - 1)];
            if (inside[std::size_t(x)])
                continue;
            for (int s = x - 1; s >= std::max(0, x - limit); --s)
                if (!inside[std::size_t(s)] && g[std::size_t(s)] < inf)
                    g[std::size_t(x)] =
                        std::min(g[std::size_t(x)],
                                 g[std::size_t(s)] + protocol.readFrameBytes(segment.space, x - s));
        }
        total += g[std::size_t(segment.count)];
    }
    return total;
}

void BM_Plan200Scattered(benchmark::State &state) {
    const Case &c = kCases[state.range(0)];
    state.SetLabel(c.name);
    auto driver = makeDriver(c, std::make_unique<PtyTransport>(QStringLiteral("/dev/null")));
    const auto devices = scattered(*driver, 200);
    Driver::Plan plan;
    for (auto _ : state) {
        plan = driver->plan(devices);
        benchmark::DoNotOptimize(plan.reads.data());
    }
    const auto segments = mappedSegments(driver->target(), driver->protocol().map());
    const long long least = exactMinimum(plan, driver->protocol(), segments);
    long long naive = 0; // one frame per placement: what a driver without a planner sends
    for (const auto &device : plan.placements)
        for (const auto &p : device)
            naive += driver->protocol().readFrameBytes(p.source.space, p.source.count);
    state.counters["frames"] = double(plan.reads.size());
    state.counters["bytes"] = plan.bytes();
    state.counters["least_bytes"] = double(least);
    state.counters["ratio"] = double(plan.bytes()) / double(least);
    state.counters["unplanned_bytes"] = double(naive);
    state.counters["wire_ms_19200"] = plan.bytes() * c.bitsPerCharacter * 1000.0 / 19200.0;
    if (double(plan.bytes()) > 1.05 * double(least))
        state.SkipWithError("the plan is more than 1.05x the least the protocol allows");
}
BENCHMARK(BM_Plan200Scattered)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

void BM_RefreshOverPty(benchmark::State &state) {
    const Case &c = kCases[state.range(0)];
    state.SetLabel(c.name);
    test::FakeVigorPlc vigor;
    test::FakeModbusPlc modbus(c.station);
    test::FakeHostLinkPlc hostLink;
    const auto responder = c.protocol == ProtocolKind::VigorLink  ? vigor.responder()
                           : c.protocol == ProtocolKind::HostLink ? hostLink.responder()
                                                                  : modbus.responder();
    test::PtyPeer peer(responder, true);
    if (!peer.ok()) {
        state.SkipWithError(peer.error().toStdString().c_str());
        return;
    }
    auto driver = makeDriver(c, std::make_unique<PtyTransport>(peer.path()));
    QString error;
    if (!driver || !driver->link().open(&error)) {
        state.SkipWithError(error.toStdString().c_str());
        return;
    }
    const auto plan = driver->plan(scattered(*driver, 200));
    std::vector<std::int32_t> words(std::size_t(driver->layout()->wordCount()), 0);
    QElapsedTimer clock;
    clock.start();
    for (auto _ : state) {
        const DriverError e = driver->refresh(plan, words, nullptr);
        if (!e.ok()) {
            state.SkipWithError(e.message.toStdString().c_str());
            return;
        }
    }
    const double refreshMs = double(clock.nsecsElapsed()) / 1e6 / double(state.iterations());
    const double wireMs = plan.bytes() * c.bitsPerCharacter * 1000.0 / 19200.0;
    state.counters["frames"] = double(plan.reads.size());
    state.counters["bytes"] = plan.bytes();
    state.counters["wire_ms_19200"] = wireMs;
    // What the software adds to a refresh at 19200 bps, as a share of the wire time: the
    // time of one refresh over the pty (no baud rate) / the wire time of its bytes.
    state.counters["overhead_share"] = refreshMs / wireMs;
    // The refresh rate at 19200 bps as a share of what the wire allows for these frames
    // (wire time + what the software adds; a real PLC's turnaround is not counted).
    state.counters["rate_vs_wire"] = wireMs / (wireMs + refreshMs);
}
BENCHMARK(BM_RefreshOverPty)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace

BENCHMARK_MAIN();
