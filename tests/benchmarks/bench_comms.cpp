// The comms planner and drivers (issue 12): for each protocol, the frames and bytes on the
// wire of a refresh of 200 scattered devices, against the least the protocol allows for that
// set, computed here exactly by another method (a dynamic program over every address, not
// over the needed runs as the planner's is); and the time a refresh takes over a real
// pseudo-terminal with a responding peer, against the wire time of its bytes at 19200 bps.
// A pty has no baud rate: its time is what the software adds to the wire time.

#include "comms/driver/driver.h"
#include "comms/driver/online_session.h"
#include "comms/transport/pty_transport.h"
#include "model/target/target.h"
#include "tests/benchmarks/smoke.h"
#include "tests/comms/fake_plc.h"
#include "tests/comms/pty_peer.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <benchmark/benchmark.h>

#include <limits>
#include <map>
#include <random>
#include <thread>

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

// The fake PLC (the codecs' slave side) that answers the case's protocol.
struct FakePlcs {
    const Case &c;
    test::FakeVigorPlc vigor;
    test::FakeModbusPlc modbus;
    test::FakeHostLinkPlc hostLink;
    explicit FakePlcs(const Case &which)
        : c(which)
        , modbus(which.station) {}
    test::FakeTransport::Responder responder() {
        return c.protocol == ProtocolKind::VigorLink  ? vigor.responder()
               : c.protocol == ProtocolKind::HostLink ? hostLink.responder()
                                                      : modbus.responder();
    }
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
    FakePlcs plcs(c);
    test::PtyPeer peer(plcs.responder(), true);
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

// The first `count` elements of each area the protocol maps, area after area: the devices of
// a screenful of rungs, which come in runs (X0-X17, Y0-Y7, M100-M131, T0-T7, D0-D9).
std::vector<model::Address> clustered(const Driver &driver, int count) {
    const model::Target &t = driver.target();
    std::vector<model::Address> out;
    const int each = 8;
    for (int start = 0; int(out.size()) < count && start < 64; start += each)
        for (int a = 0; a < int(t.areas.size()) && int(out.size()) < count; ++a) {
            const model::Area &area = t.area(a);
            for (int e = area.first + start;
                 e <= area.last && e < area.first + start + each && int(out.size()) < count; ++e)
                if (driver.plan({model::Address{a, e, -1}}).unmapped.empty())
                    out.push_back({a, e, -1});
        }
    return out;
}

// Issue 13: with 100 devices on screen at 19200 bps, the online refresh rate against what the
// wire allows for the planned frames. The whole online path: an OnlineSession (its worker,
// planner, driver, link and the 20 ms poll interval of the connection panel) on a real
// pseudo-terminal, the virtual PLC answering as a PLC on a 19200 bps line could at the
// earliest (PtyWire). "wire_ms" is the time the planned frames take on that line at
// the least, the silences Modbus RTU asks for included; "rate_vs_wire" = wire_ms / the real
// time between refreshes (the limit is 0.9). Range: the protocol case, then 0 = 100 devices
// scattered at random (many short frames), 1 = 100 devices in runs (a screenful of rungs).
void BM_OnlineRefreshAt19200(benchmark::State &state) {
    const Case &c = kCases[state.range(0)];
    const bool inRuns = state.range(1) == 1;
    state.SetLabel(std::string(c.name) + (inRuns ? " 100 in runs" : " 100 scattered"));
    FakePlcs plcs(c);
    const bool rtu = c.protocol == ProtocolKind::ModbusRtu;
    test::PtyPeer peer(plcs.responder(), true, {19200, c.bitsPerCharacter, rtu ? 3.5 : 0.0});
    if (!peer.ok()) {
        state.SkipWithError(peer.error().toStdString().c_str());
        return;
    }
    // The plan the session will make, for its figures: the same devices and the run bit.
    auto planner = makeDriver(c, std::make_unique<PtyTransport>(peer.path()));
    std::vector<model::Address> devices =
        inRuns ? clustered(*planner, 100) : scattered(*planner, 100);
    std::vector<model::Address> planned = devices;
    if (planner->runStateDevice().valid())
        planned.push_back(planner->runStateDevice());
    std::sort(planned.begin(), planned.end());
    planned.erase(std::unique(planned.begin(), planned.end()), planned.end());
    const auto plan = planner->plan(planned);
    const double characterMs = c.bitsPerCharacter * 1000.0 / 19200.0;
    const double wireMs =
        (double(plan.bytes()) + (rtu ? 2 * 3.5 * double(plan.reads.size()) : 0.0)) * characterMs;

    ConnectionSettings settings = defaultSettings(c.protocol);
    settings.via = ConnectionSettings::Via::Pty;
    settings.port = peer.path();
    settings.station = c.station;
    settings.link.timeoutMs = 2000;
    OnlineSession session(model::Target::get(c.family), settings);
    QObject reader;
    session.setWatched(&reader, devices);
    session.connectToPlc();
    const auto refreshes = [&session] {
        const auto snapshot = session.snapshot();
        return snapshot ? snapshot->statistics.scans : quint64(0);
    };
    const auto waitFor = [&](quint64 count) {
        QElapsedTimer patience;
        patience.start();
        while (refreshes() < count) {
            if (patience.elapsed() > 20000)
                return false;
            std::this_thread::sleep_for(std::chrono::microseconds(200));
        }
        return true;
    };
    // The first refresh also reads the PLC's identity: start counting after it.
    if (!waitFor(1)) {
        state.SkipWithError(qPrintable(QStringLiteral("no refresh: ") + session.errorText()));
        return;
    }
    quint64 seen = refreshes();
    const quint64 counted = seen;
    QElapsedTimer clock;
    clock.start();
    for (auto _ : state) {
        if (!waitFor(seen + 1)) {
            state.SkipWithError(qPrintable(QStringLiteral("stopped: ") + session.errorText()));
            return;
        }
        seen = refreshes();
    }
    const double refreshMs = double(clock.nsecsElapsed()) / 1e6 / double(seen - counted);
    state.counters["frames"] = double(plan.reads.size());
    state.counters["bytes"] = plan.bytes();
    state.counters["wire_ms"] = wireMs;
    state.counters["refresh_ms"] = refreshMs;
    state.counters["rate_vs_wire"] = wireMs / refreshMs;
    session.disconnectFromPlc();
    if (bench::judgesTime() && wireMs / refreshMs < 0.9)
        state.SkipWithError("the refresh rate is under 90% of what the wire allows");
}
BENCHMARK(BM_OnlineRefreshAt19200)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Iterations(bench::times(5))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

int main(int argc, char **argv) {
    QCoreApplication app(argc, argv); // the online session posts to its owner's thread
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    return 0;
}
