// The engine's command inbox: commands posted from any thread are applied by the engine's
// thread before its next scan, in order; each result is handed over by complete().

#include "real_target_sim.h"

#include "simulator/command_inbox.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

using namespace rung;
using namespace rung::simulator;
using Kind = model::DeviceCommand::Kind;

namespace {

struct Finished {
    quint64 id;
    bool ok;
    QString error;
};

struct InboxSim : test::RealTargetSim {
    InboxSim()
        : RealTargetSim(model::Family::Vigor, "LD X0\nOUT Y0\nLD M0\nOUT Y1\nEND")
        , inbox([this](quint64 id, bool ok, const QString &error) {
            finished.push_back({id, ok, error});
        }) {}
    // What a driver does before each scan.
    void step() {
        inbox.apply(*engine);
        inbox.complete();
        engine->scan();
    }
    void post(quint64 id, Kind kind, const char *device, qint64 value = 0) {
        inbox.post({id, model::DeviceCommand{kind, at(device), value}});
    }
    std::vector<Finished> finished; // the engine's thread alone writes it
    CommandInbox inbox;
};

} // namespace

TEST(CommandInbox, CommandsWaitForApplyThenCompleteInOrder) {
    InboxSim s;
    s.post(1, Kind::WriteWord, "D3", 5);
    s.post(2, Kind::WriteWord, "D3", 6);
    s.post(3, Kind::Force, "X0", 1);
    EXPECT_TRUE(s.inbox.pending());
    s.engine->scan();
    EXPECT_EQ(s.value("D3"), 0); // a scan alone applies nothing
    const auto applied = s.inbox.apply(*s.engine);
    EXPECT_EQ(applied.commands, 3);
    EXPECT_FALSE(applied.reset);
    EXPECT_FALSE(s.inbox.pending());
    EXPECT_EQ(s.value("D3"), 6);
    EXPECT_TRUE(s.finished.empty()); // results wait for complete()
    s.inbox.complete();
    s.engine->scan();
    EXPECT_TRUE(s.bit("Y0")); // the force was in place for this scan's input image
    ASSERT_EQ(s.finished.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(s.finished[k].id, k + 1);
        EXPECT_TRUE(s.finished[k].ok);
    }
}

TEST(CommandInbox, EveryKindOfCommandReachesTheEngine) {
    InboxSim s;
    s.post(1, Kind::WriteBit, "M0", 1);
    s.post(2, Kind::WriteSetValue, "T5", 30);
    s.post(3, Kind::Force, "X0", 1);
    s.step();
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_EQ(s.engine->setValue(s.at("T5")), 30);
    EXPECT_TRUE(s.bit("Y0"));
    s.post(4, Kind::Release, "X0");
    s.step();
    EXPECT_FALSE(s.bit("Y0"));
    s.post(5, Kind::Force, "X0", 1);
    s.post(6, Kind::ReleaseAll, "X0");
    s.step();
    EXPECT_FALSE(s.bit("Y0"));
    s.post(7, Kind::WriteWord, "D200", 9); // retentive
    s.post(8, Kind::WriteWord, "D0", 9);
    s.inbox.post({9, PowerCycle{}});
    s.step();
    EXPECT_EQ(s.value("D200"), 9);
    EXPECT_EQ(s.value("D0"), 0);
    ASSERT_EQ(s.finished.size(), 9u);
    for (const Finished &f : s.finished)
        EXPECT_TRUE(f.ok) << f.id << " " << f.error.toStdString();
}

TEST(CommandInbox, AFailedCommandSaysWhichDeviceAndWhy) {
    InboxSim s;
    s.post(1, Kind::WriteSetValue, "D7", 3); // a data register has no set value
    s.post(2, Kind::Force, "D7", 1);         // nor is it a bit
    s.step();
    ASSERT_EQ(s.finished.size(), 2u);
    for (const Finished &f : s.finished) {
        EXPECT_FALSE(f.ok);
        EXPECT_TRUE(f.error.contains(QLatin1String("D7"))) << f.error.toStdString();
    }
    EXPECT_NE(s.finished[0].error, s.finished[1].error);
}

TEST(CommandInbox, PostsFromAnotherThreadWhileTheEngineScans) {
    // The writer posts D10 = 1..n while this thread scans; every command completes once, in
    // order, and the last value stays. Run under ThreadSanitizer by scripts/test-sanitizers.sh.
    InboxSim s;
    constexpr int n = 2000;
    std::atomic<bool> posted{false};
    std::thread writer([&] {
        for (int k = 1; k <= n; ++k)
            s.post(static_cast<quint64>(k), Kind::WriteWord, "D10", k);
        posted = true;
    });
    for (int round = 0; round < 1000000 && (!posted.load() || s.inbox.pending()); ++round)
        s.step();
    writer.join();
    s.step();
    ASSERT_EQ(s.finished.size(), static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k)
        ASSERT_EQ(s.finished[static_cast<std::size_t>(k)].id, static_cast<quint64>(k + 1));
    EXPECT_EQ(s.value("D10"), n);
}

TEST(CommandInbox, ResetAfterAForceReleasesItAndKeepsThePeriod) {
    // Stop of a session: a force posted before the reset is released by it, one posted after
    // it stays; the reset itself (id 0) completes nothing.
    InboxSim s;
    s.engine->setPeriodMs(20);
    s.post(1, Kind::Force, "X0", 1);
    s.post(2, Kind::WriteWord, "D200", 9); // retentive: a power cycle would keep it
    s.inbox.post({0, Reset{}});
    s.post(3, Kind::Force, "M0", 1);
    const auto applied = s.inbox.apply(*s.engine);
    EXPECT_EQ(applied.commands, 4);
    EXPECT_TRUE(applied.reset);
    s.inbox.complete();
    s.engine->scan();
    EXPECT_FALSE(s.bit("Y0"));
    EXPECT_FALSE(s.engine->snapshot().forced(s.at("X0")));
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_EQ(s.value("D200"), 0);
    EXPECT_EQ(s.engine->statistics().scans, 1u);
    EXPECT_EQ(s.engine->statistics().timeMs, 20);
    ASSERT_EQ(s.finished.size(), 3u);
    EXPECT_EQ(s.finished[2].id, 3u);
}
