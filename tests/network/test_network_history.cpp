// The history of a whole network (network_history.h): every station of every example network
// shown at a past instant is what it was at that instant while the network ran, word for
// word; commands between slices; the memory budget; the session recording it on its worker
// (NetworkSession.* runs under ThreadSanitizer) and a station's past as a read-only
// MonitorSource.

#include "network/history_arena.h"
#include "network/network_history.h"
#include "network/network_session.h"
#include "network/station_past_source.h"

#include "network_fixture.h"

#include "../eventually.h"

#include "model/listing/il.h"
#include "model/target/target.h"
#include "simulator/compiler.h"
#include "simulator/scan_writes.h"

#include <QDirIterator>

#include <gtest/gtest.h>

namespace rung::network::test {
namespace {

using waits::eventually;
using RunState = model::MonitorSource::RunState;

const QString kHistoryExamples = QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks");
const QString kHistoryEasyLink = kHistoryExamples + QStringLiteral("/easy-link/easy-link.rungnet");

// The networks File > Examples > Networks lists: every .rungnet under the examples.
QStringList historyExampleNetworks() {
    QStringList out;
    QDirIterator it(kHistoryExamples, {QStringLiteral("*.rungnet")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        out << it.next();
    out.sort();
    return out;
}

std::unique_ptr<Network> buildForHistory(const QString &file) {
    NetworkDescription d;
    QString error;
    EXPECT_TRUE(readNetworkFile(file, &d, &error)) << error.toStdString();
    std::unique_ptr<Network> net = Network::build(d, listingLoader(), &error);
    EXPECT_TRUE(net) << error.toStdString();
    return net;
}

model::Address historyAddress(const Station &s, const char *device) {
    const auto a = model::parseAddress(s.target(), QString::fromLatin1(device));
    EXPECT_TRUE(std::holds_alternative<model::Address>(a)) << device;
    return std::holds_alternative<model::Address>(a) ? std::get<model::Address>(a)
                                                     : model::Address{};
}

// What a view shows of a station: its words, forced bits, power flow and scan count.
struct SeenThen {
    std::vector<std::int32_t> words;
    std::vector<std::uint32_t> forceMask;
    std::vector<std::uint32_t> forceValue;
    std::vector<bool> flow;
    quint64 scans = 0;
    qint64 timeMs = 0;
    qint64 communicatedUs = -1; // the front panel's COMM lamp
    friend bool operator==(const SeenThen &, const SeenThen &) = default;
};

SeenThen seenThen(const model::Snapshot &s) {
    return {s.words,         s.forceMask,        s.forceValue,
            s.powerFlow,     s.statistics.scans, s.statistics.timeMs,
            s.communicatedUs};
}

SeenThen seenThen(const Station &s) {
    return seenThen(s.snapshot());
}

struct LiveInstant {
    qint64 us = 0;
    std::vector<SeenThen> stations;
};

LiveInstant captureLive(const Network &net) {
    LiveInstant l;
    l.us = net.nowUs();
    for (const auto &s : net.stations())
        l.stations.push_back(seenThen(*s));
    return l;
}

// Every instant recorded, and a moment between two, shows every station as it was then.
void expectHistoryShownAsLive(const NetworkHistory &history, const std::vector<LiveInstant> &live) {
    for (std::size_t k = 0; k < live.size(); ++k) {
        // A later instant at the same time (a command) is the one shown.
        if (k + 1 < live.size() && live[k + 1].us == live[k].us)
            continue;
        const auto shown = history.at(live[k].us);
        ASSERT_TRUE(shown) << "at " << live[k].us;
        ASSERT_EQ(shown->size(), live[k].stations.size());
        for (std::size_t s = 0; s < shown->size(); ++s)
            ASSERT_TRUE(seenThen((*shown)[s]) == live[k].stations[s])
                << "station " << s << " at " << live[k].us << " us";
        if (k + 1 < live.size() && live[k + 1].us > live[k].us + 1) {
            const qint64 between = (live[k].us + live[k + 1].us) / 2;
            const auto one = history.stationAt(0, between);
            ASSERT_TRUE(one);
            EXPECT_TRUE(seenThen(*one) == live[k].stations[0]) << "between, at " << between;
            EXPECT_EQ(history.instantAt(between), live[k].us);
        }
    }
}

// What wordValues must say of one word of one station, from the live instants after afterUs:
// the value at the first, then each instant at which it changed.
std::vector<NetworkHistory::WordValue> liveWordValues(const std::vector<LiveInstant> &live,
                                                      std::size_t station, std::size_t word,
                                                      qint64 afterUs) {
    std::vector<NetworkHistory::WordValue> out;
    for (std::size_t k = 0; k < live.size(); ++k) {
        if (live[k].us <= afterUs)
            continue;
        const SeenThen &s = live[k].stations[station];
        if (out.empty() || out.back().value != s.words[word])
            out.push_back({live[k].us, s.scans, s.timeMs, s.words[word]});
    }
    return out;
}

// Every word that changed of every station, read back one word at a time: whole, and going on
// from an instant in the middle.
void expectWordValuesAsLive(const NetworkHistory &history, const std::vector<LiveInstant> &live) {
    const qint64 middle = live[live.size() / 2].us;
    for (std::size_t s = 0; s < live.front().stations.size(); ++s)
        for (std::size_t w = 0; w < live.front().stations[s].words.size(); ++w) {
            const auto all = liveWordValues(live, s, w, -1);
            if (all.size() < 2)
                continue;
            NetworkHistory::WordValue newest;
            ASSERT_EQ(history.wordValues(s, w, -1, &newest), all)
                << "station " << s << " word " << w;
            EXPECT_EQ(newest.us, live.back().us);
            EXPECT_EQ(history.wordValues(s, w, middle), liveWordValues(live, s, w, middle))
                << "station " << s << " word " << w;
        }
    NetworkHistory::WordValue untouched{-7, 0, 0, 0};
    EXPECT_TRUE(history.wordValues(0, 0, live.back().us, &untouched).empty());
    EXPECT_EQ(untouched.us, -7);
}

// Busy programs: each of three stations in CPU Link counts 59 registers up every scan, at
// steps of its own, and toggles a bit: 27 registers spread over its whole image, two side by
// side, 30 side by side (the history keeps neighbours as one run).
std::unique_ptr<Network> busyNetwork() {
    std::map<QString, QString> programs;
    for (int k = 0; k < 3; ++k) {
        QString p = QStringLiteral("; target: vigor\nLDI M0\nOUT M0\nLD M9000\n");
        for (int r = 0; r < 59; ++r)
            p += QStringLiteral("ADD D%1 K%2 D%1\n")
                     .arg(r < 27   ? r * 130 + k
                          : r < 29 ? 3700 + r
                                   : 4000 + r)
                     .arg(r % 5 + k + 1);
        programs[QStringLiteral("p%1.il").arg(k)] = p + QStringLiteral("END\n");
    }
    NetworkDescription d;
    QString error;
    EXPECT_TRUE(parseNetwork(QByteArrayLiteral(R"({"stations": [
        {"name": "s0", "program": "p0.il", "model": "VB",
         "ports": {"CP2": {"application": "cpu-link", "station": 0, "slaves": 2, "range": 1}}},
        {"name": "s1", "program": "p1.il", "model": "VB",
         "ports": {"CP2": {"application": "cpu-link", "station": 1}}},
        {"name": "s2", "program": "p2.il", "model": "VB",
         "ports": {"CP2": {"application": "cpu-link", "station": 2}}}],
        "wires": [["s0/CP2", "s1/CP2", "s2/CP2"]]})"),
                             QStringLiteral("busy.rungnet"), &d, &error))
        << error.toStdString();
    std::unique_ptr<Network> net = Network::build(d, listingLoader(programs), &error);
    EXPECT_TRUE(net) << error.toStdString();
    return net;
}

} // namespace

TEST(NetworkHistory, EveryStationOfEveryExampleNetworkIsShownAsItWasAtEachInstant) {
    const QStringList files = historyExampleNetworks();
    ASSERT_GE(files.size(), 10);
    for (const QString &file : files) {
        SCOPED_TRACE(file.toStdString());
        std::unique_ptr<Network> net = buildForHistory(file);
        ASSERT_TRUE(net);
        const qint64 slice = std::max<qint64>(1, net->description().periodMs) * 1000;
        // Keys close together, so that rebuilds cross several of them.
        NetworkHistory history(NetworkHistory::Limits{256u << 20, 16});
        net->stations().front()->engine().setPowerFlowRecording(true);
        history.start(*net);
        std::vector<LiveInstant> live{captureLive(*net)};
        for (int k = 1; k <= 300; ++k) {
            if (k == 120) { // the user chose another station: its power flow from now on
                net->stations().front()->engine().setPowerFlowRecording(false);
                net->stations().back()->engine().setPowerFlowRecording(true);
            }
            net->runUntil(k * slice);
            history.record(*net, false);
            live.push_back(captureLive(*net));
        }
        expectHistoryShownAsLive(history, live);
        expectWordValuesAsLive(history, live);
        EXPECT_FALSE(history.at(-1));
        const NetworkHistory::Window w = history.window();
        EXPECT_EQ(w.firstUs, 0);
        EXPECT_EQ(w.lastUs, 300 * slice);
        EXPECT_EQ(w.instants, 301u);
        // Not a still picture: the stations' images changed while the network ran.
        bool changed = false;
        for (std::size_t s = 0; s < live.front().stations.size(); ++s)
            changed = changed || live.front().stations[s].words != live.back().stations[s].words;
        EXPECT_TRUE(changed);
    }
}

// Busy stations, every scan recorded: what is read back is what ran, scan by scan, every word
// of every station (keys far apart and close together).
TEST(NetworkHistory, BusyStationsAreShownAsTheyWereAtEveryScan) {
    for (const std::size_t keyEvery : {std::size_t(1000), std::size_t(7)}) {
        SCOPED_TRACE(keyEvery);
        std::unique_ptr<Network> net = busyNetwork();
        ASSERT_TRUE(net);
        NetworkHistory history(NetworkHistory::Limits{256u << 20, keyEvery});
        history.start(*net);
        std::vector<LiveInstant> live{captureLive(*net)};
        for (int k = 1; k <= 250; ++k) {
            net->runUntil(k * 10'000);
            history.record(*net, false);
            live.push_back(captureLive(*net));
        }
        // Busy indeed: 59 registers and a bit of each station changed in every scan, beside
        // what the CPU Link and the system words changed.
        for (std::size_t s = 0; s < 3; ++s) {
            std::size_t changed = 0;
            for (std::size_t w = 0; w < live[100].stations[s].words.size(); ++w)
                changed += live[100].stations[s].words[w] != live[101].stations[s].words[w];
            EXPECT_GE(changed, 60u) << s;
        }
        expectHistoryShownAsLive(history, live);
        expectWordValuesAsLive(history, live);
    }
}

// The Easy Link example's set 1 reads D10..D19 of station 5 into the master's D0..D9: a value
// written in s5 is seen arriving in the master, and the master's past before it arrived shows
// the old value.
TEST(NetworkHistory, AValueArrivingInAnotherStationIsShownAtTheInstantItArrived) {
    std::unique_ptr<Network> net = buildForHistory(kHistoryEasyLink);
    ASSERT_TRUE(net);
    Station &s5 = *net->station(QStringLiteral("s5"));
    Station &master = *net->station(QStringLiteral("master"));
    NetworkHistory history;
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    qint64 arrived = -1;
    for (int k = 1; k <= 200; ++k) {
        if (k == 50) { // a command between two slices, as the session applies it
            ASSERT_TRUE(s5.engine().writeWord(historyAddress(s5, "D10"), 1234));
            ASSERT_TRUE(s5.engine().force(historyAddress(s5, "Y0"), true));
            history.record(*net, true);
            live.push_back(captureLive(*net));
        }
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
        if (arrived < 0 && master.engine().value(historyAddress(master, "D0")) == 1234)
            arrived = net->nowUs();
    }
    ASSERT_GT(arrived, 500'000);
    expectHistoryShownAsLive(history, live);
    const std::size_t m = 0; // the master is the first station
    ASSERT_EQ(net->stations()[m].get(), &master);
    const auto then = history.stationAt(m, arrived);
    const auto before = history.stationAt(m, arrived - 10'000);
    ASSERT_TRUE(then && before);
    EXPECT_EQ(then->value(historyAddress(master, "D0")), 1234);
    EXPECT_NE(before->value(historyAddress(master, "D0")), 1234);
    // The command's instant, between the slices ending at 0.49 s and 0.5 s: the write and the
    // force, shown from 0.49 s on (in place of the slice's instant at that time).
    const auto written = history.stationAt(1, 490'000);
    ASSERT_TRUE(written);
    EXPECT_EQ(written->value(historyAddress(s5, "D10")), 1234);
    EXPECT_TRUE(written->forced(historyAddress(s5, "Y0")));
    const auto earlier = history.stationAt(1, 489'999);
    ASSERT_TRUE(earlier);
    EXPECT_NE(earlier->value(historyAddress(s5, "D10")), 1234);
    EXPECT_FALSE(earlier->forced(historyAddress(s5, "Y0")));
}

TEST(NetworkHistory, OverItsBudgetTheOldestGoAndTheRestIsShownExactly) {
    std::unique_ptr<Network> net = buildForHistory(kHistoryEasyLink);
    ASSERT_TRUE(net);
    // Room for a few keys of the three VBs and their changes: what the first 50 instants (a
    // key and the changes that run from it) take, four times.
    std::size_t key = 0;
    {
        std::unique_ptr<Network> probeNet = buildForHistory(kHistoryEasyLink);
        ASSERT_TRUE(probeNet);
        NetworkHistory probe(NetworkHistory::Limits{std::size_t(1) << 30, 50});
        probe.start(*probeNet);
        for (int k = 1; k < 50; ++k) {
            probeNet->runUntil(k * 10'000);
            probe.record(*probeNet, false);
        }
        key = probe.window().bytes;
    }
    NetworkHistory history(NetworkHistory::Limits{4 * key, 50});
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    for (int k = 1; k <= 600; ++k) {
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
    }
    const NetworkHistory::Window w = history.window();
    EXPECT_GT(w.firstUs, 0);
    EXPECT_EQ(w.lastUs, 6'000'000);
    EXPECT_LE(w.bytes, 4 * key);
    EXPECT_GE(w.keys, 2u);
    EXPECT_FALSE(history.at(w.firstUs - 1));
    std::vector<LiveInstant> kept;
    for (const LiveInstant &l : live)
        if (l.us >= w.firstUs)
            kept.push_back(l);
    EXPECT_EQ(kept.size(), w.instants);
    expectHistoryShownAsLive(history, kept);
}

TEST(NetworkSession, ItsWorkerRecordsTheHistoryOfEveryStationAndAPastStationIsReadOnly) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(readNetworkFile(kHistoryEasyLink, &d, &error)) << error.toStdString();
    std::unique_ptr<NetworkSession> session = NetworkSession::start(d, listingLoader(), &error);
    ASSERT_TRUE(session) << error.toStdString();
    StationSource *s5 = session->station(QStringLiteral("s5"));
    StationSource *master = session->station(QStringLiteral("master"));
    const auto address = [](const StationSource *s, const char *device) {
        return std::get<model::Address>(
            model::parseAddress(s->target(), QString::fromLatin1(device)));
    };
    bool written = false;
    QObject::connect(
        s5, &model::MonitorSource::commandFinished, s5,
        [&](model::MonitorSource::CommandId, bool ok, const QString &) { written = ok; });
    s5->writeWord(address(s5, "D10"), 4321);
    ASSERT_TRUE(eventually([&] { return written; }));
    std::shared_ptr<const NetworkHistory> history = session->history();
    session->setSpeed(0);
    session->runFor(2000);
    // Read while the worker records.
    std::size_t reads = 0;
    ASSERT_TRUE(eventually([&] {
        const NetworkHistory::Window w = history->window();
        if (!w.empty() && history->at(w.lastUs))
            ++reads;
        return session->runState() == RunState::Paused;
    }));
    EXPECT_GT(reads, 0u);
    const NetworkHistory::Window w = history->window();
    EXPECT_EQ(w.lastUs, 2'000'000);
    EXPECT_EQ(session->nowUs(), 2'000'000);
    // The newest instant is what the stations published last.
    ASSERT_TRUE(eventually(
        [&] { return master->snapshot() && master->snapshot()->statistics.timeMs == 2000; }));
    const auto now = history->at(w.lastUs);
    ASSERT_TRUE(now);
    for (std::size_t s = 0; s < session->stations().size(); ++s)
        EXPECT_EQ((*now)[s].words, session->stations()[s]->snapshot()->words) << s;
    // The master's D0 arrived some time after the start: before then the past shows 0.
    EXPECT_EQ(master->snapshot()->value(address(master, "D0")), 4321);
    StationPastSource past(history, 0, master);
    ASSERT_TRUE(past.show(10'000));
    EXPECT_EQ(past.snapshot()->value(address(master, "D0")), 0);
    EXPECT_EQ(past.snapshot()->statistics.timeMs, 10);
    ASSERT_TRUE(past.show(2'000'000));
    EXPECT_EQ(past.snapshot()->value(address(master, "D0")), 4321);
    EXPECT_EQ(past.runState(), RunState::Paused);
    // Read-only: a write is refused, and the live station keeps its value.
    QString refused;
    QObject::connect(&past, &model::MonitorSource::commandFinished, &past,
                     [&](model::MonitorSource::CommandId, bool ok, const QString &why) {
                         if (!ok)
                             refused = why;
                     });
    past.writeWord(address(master, "D0"), 1);
    ASSERT_TRUE(eventually([&] { return !refused.isEmpty(); }));
    EXPECT_TRUE(refused.contains(QStringLiteral("read-only")));
    EXPECT_FALSE(past.forceRefusal().isEmpty());
    // The chart's rows read the live station's recorder through it.
    EXPECT_TRUE(past.watchHistory(address(master, "D0")));
    // Stop starts the history again at power-on.
    session->stop();
    EXPECT_TRUE(eventually([&] {
        const NetworkHistory::Window after = history->window();
        return after.instants == 1 && after.lastUs == 0;
    }));
}

// What a station's program does not write, written between its scans, is recorded at the
// instant it was written (image_writes.h): the history compares only what the programs can
// write and what was marked. The PL110-Vigor example: the PL110's COM_2 writes its AI1 into
// the Vigor's D100 over MODBUS, a word the Vigor's program only shows.
TEST(NetworkHistory, AWordAMasterWritesIntoASlaveIsRecordedAtTheInstantItWasWritten) {
    std::unique_ptr<Network> net =
        buildForHistory(kHistoryExamples + QStringLiteral("/pl110-vigor/pl110-vigor.rungnet"));
    ASSERT_TRUE(net);
    Station &pl = *net->station(QStringLiteral("pl"));
    Station &vb = *net->station(QStringLiteral("vb"));
    const model::Address d100 = historyAddress(vb, "D100");
    const auto d100Word = static_cast<std::size_t>(vb.engine().layout().word(d100));
    const auto scanWrites = simulator::scanWrites(vb.engine().program());
    ASSERT_TRUE(scanWrites); // the Vigor's scan does not write it: the slave's side does
    for (const auto &[b, e] : *scanWrites)
        ASSERT_FALSE(b <= d100Word && d100Word < e);
    NetworkHistory history(NetworkHistory::Limits{256u << 20, 64});
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    qint64 arrived = -1;
    for (int k = 1; k <= 200; ++k) {
        if (k == 30 || k == 120) { // the analog input changes: a command, as the session's
            ASSERT_TRUE(pl.engine().writeWord(historyAddress(pl, "AI1"), k == 30 ? 1234 : 77));
            history.record(*net, true);
            live.push_back(captureLive(*net));
        }
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
        if (arrived < 0 && vb.engine().value(d100) == 1234)
            arrived = net->nowUs();
    }
    ASSERT_GT(arrived, 300'000);
    EXPECT_EQ(vb.engine().value(d100), 77);
    expectHistoryShownAsLive(history, live);
    expectWordValuesAsLive(history, live);
    const auto then = history.stationAt(1, arrived);
    const auto before = history.stationAt(1, arrived - 1);
    ASSERT_TRUE(then && before);
    EXPECT_EQ(then->value(d100), 1234);
    EXPECT_NE(before->value(d100), 1234);
}

// The CPU Link example: the master's VR1 (a command: the panel's knob) goes into its D0 by its
// program, and the link's exchange writes it into D0 of both slaves, whose programs only show
// it: recorded at the instant each slave received it.
TEST(NetworkHistory, AWordALinkExchangeWritesIsRecordedAtTheInstantItArrived) {
    std::unique_ptr<Network> net =
        buildForHistory(kHistoryExamples + QStringLiteral("/cpu-link/cpu-link.rungnet"));
    ASSERT_TRUE(net);
    Station &master = *net->station(QStringLiteral("master"));
    Station &slave1 = *net->station(QStringLiteral("slave1"));
    const model::Address d0 = historyAddress(slave1, "D0");
    const auto d0Word = static_cast<std::size_t>(slave1.engine().layout().word(d0));
    const auto scanWrites = simulator::scanWrites(slave1.engine().program());
    ASSERT_TRUE(scanWrites); // the slave's scan does not write it: the link does
    for (const auto &[b, e] : *scanWrites)
        ASSERT_FALSE(b <= d0Word && d0Word < e);
    NetworkHistory history(NetworkHistory::Limits{256u << 20, 64});
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    qint64 arrived = -1;
    for (int k = 1; k <= 200; ++k) {
        if (k == 30 || k == 120) {
            ASSERT_TRUE(
                master.engine().writeWord(historyAddress(master, "VR1"), k == 30 ? 555 : 77));
            history.record(*net, true);
            live.push_back(captureLive(*net));
        }
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
        if (arrived < 0 && slave1.engine().value(d0) == 555)
            arrived = net->nowUs();
    }
    ASSERT_GT(arrived, 300'000);
    EXPECT_EQ(slave1.engine().value(d0), 77);
    expectHistoryShownAsLive(history, live);
    expectWordValuesAsLive(history, live);
    const auto then = history.stationAt(1, arrived);
    const auto before = history.stationAt(1, arrived - 1);
    ASSERT_TRUE(then && before);
    EXPECT_EQ(then->value(d0), 555);
    EXPECT_NE(before->value(d0), 555);
}

// The history's memory (history_arena.h): what is allocated keeps its bytes; chunks go back
// once everything in them is freed, oldest first as the history drops its oldest instants or
// in any order, and the few kept come back for the next allocations.
TEST(HistoryArena, ChunksGoWhenEmptyAndAFewComeBackForTheNext) {
    HistoryArena arena;
    constexpr std::size_t kPieces = 3000; // 4 KB each: 6 chunks and more
    for (const bool oldestFirst : {true, false}) {
        SCOPED_TRACE(oldestFirst);
        std::vector<std::uint32_t *> pieces;
        for (std::size_t k = 0; k < kPieces; ++k) {
            auto *p = static_cast<std::uint32_t *>(arena.allocate(4096));
            std::fill_n(p, 1024, static_cast<std::uint32_t>(k));
            pieces.push_back(p);
        }
        EXPECT_GE(arena.chunksHeld(), 6u);
        const std::size_t held = arena.chunksHeld();
        for (std::size_t k = 0; k < kPieces; ++k)
            ASSERT_EQ(pieces[k][1023], k);
        for (std::size_t k = 0; k < kPieces; ++k)
            arena.deallocate(pieces[oldestFirst ? k : kPieces - 1 - k], 4096);
        EXPECT_LE(arena.chunksHeld(), 5u); // the current one and four kept
        // The same again takes the chunks kept first.
        for (std::size_t k = 0; k < kPieces; ++k)
            pieces[k] = static_cast<std::uint32_t *>(arena.allocate(4096));
        EXPECT_LE(arena.chunksHeld(), held + 1);
        for (std::size_t k = 0; k < kPieces; ++k)
            arena.deallocate(pieces[k], 4096);
    }
    // A large piece comes from the heap, not a chunk.
    const std::size_t before = arena.chunksHeld();
    void *large = arena.allocate(HistoryArena::kChunk);
    EXPECT_EQ(arena.chunksHeld(), before);
    arena.deallocate(large, HistoryArena::kChunk);
}

// A Host Link master (through a bridge, or here straight onto the port) forces a bit of the
// CPM1 (KS, in MONITOR mode): the forced bit and its value are shown from that instant on,
// though no command of the session's came between the slices.
QByteArray hostLinkFrame(const char *text) {
    QByteArray f = QByteArrayLiteral("@") + text;
    quint8 fcs = 0;
    for (const char c : f)
        fcs ^= quint8(c);
    return f + QByteArray::number(fcs, 16).rightJustified(2, '0').toUpper() + "*\r";
}

TEST(NetworkHistory, ABitAHostLinkMasterForcesIsRecordedForcedAtItsInstant) {
    std::unique_ptr<Network> net = buildForHistory(
        kHistoryExamples + QStringLiteral("/cpm1-host-link/cpm1-host-link.rungnet"));
    ASSERT_TRUE(net);
    Station &cpm1 = *net->station(QStringLiteral("cpm1"));
    StationPort *port = cpm1.findPort(QStringLiteral("PERIPHERAL"));
    ASSERT_TRUE(port);
    ASSERT_EQ(hostLinkFrame("00KSCIO 001000"), QByteArray("@00KSCIO 0010003C*\r"));
    const model::Address forced = historyAddress(cpm1, "010.00");
    NetworkHistory history(NetworkHistory::Limits{256u << 20, 1000});
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    qint64 seen = -1;
    for (int k = 1; k <= 120; ++k) {
        if (k == 20)
            port->deliver(hostLinkFrame("00SC02"), 0, net->nowUs()); // MONITOR
        if (k == 50)
            port->deliver(hostLinkFrame("00KSCIO 001000"), 0, net->nowUs());
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
        if (seen < 0 && cpm1.engine().snapshot().forced(forced))
            seen = net->nowUs();
    }
    ASSERT_GT(seen, 490'000);
    expectHistoryShownAsLive(history, live);
    const auto then = history.stationAt(0, seen);
    const auto before = history.stationAt(0, seen - 1);
    ASSERT_TRUE(then && before);
    EXPECT_TRUE(then->forced(forced));
    EXPECT_TRUE(then->bit(forced));
    EXPECT_FALSE(before->forced(forced));
}

// An online edit (a command, between slices): from then on the words the new program writes
// are recorded, not the old one's.
TEST(NetworkHistory, TheWordsANewProgramWritesAreRecordedAfterAnOnlineEdit) {
    std::unique_ptr<Network> net = busyNetwork();
    ASSERT_TRUE(net);
    Station &s1 = *net->station(QStringLiteral("s1"));
    const model::Target &t = s1.target();
    const model::ParseResult parsed = model::parseInstructionList(
        t, QStringLiteral("; target: vigor\nLD M9000\nADD D5000 K3 D5000\nMOV D5000 D6001\nEND\n"),
        s1.model());
    ASSERT_TRUE(parsed.ok());
    model::CheckOptions checks;
    checks.model = s1.model();
    const simulator::CompileResult edited = simulator::prepareProgram(parsed.list, checks);
    ASSERT_TRUE(edited.ok());
    NetworkHistory history(NetworkHistory::Limits{256u << 20, 1000});
    history.start(*net);
    std::vector<LiveInstant> live{captureLive(*net)};
    for (int k = 1; k <= 100; ++k) {
        if (k == 40) {
            ASSERT_EQ(s1.engine().replaceProgram(edited.program), simulator::EditApplied::Now);
            history.record(*net, true);
            live.push_back(captureLive(*net));
        }
        net->runUntil(k * 10'000);
        history.record(*net, false);
        live.push_back(captureLive(*net));
    }
    EXPECT_GT(s1.engine().value(historyAddress(s1, "D6001")), 100);
    expectHistoryShownAsLive(history, live);
    expectWordValuesAsLive(history, live);
}

} // namespace rung::network::test
