// The online session: a PLC (a fake one behind the fake transport) as a MonitorSource.
// Every wait has a deadline; the PLC answers at once, so the tests take milliseconds.

#include "comms/driver/online_session.h"
#include "model/target/address.h"
#include "model/target/target.h"
#include "tests/comms/fake_plc.h"
#include "tests/eventually.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

namespace rung::comms::test {
namespace {

using RunState = model::MonitorSource::RunState;
using State = OnlineSession::ConnectionState;

using waits::eventually;
using waits::kPatienceMs;

model::Address address(const model::Target &t, const char *name) {
    return std::get<model::Address>(model::parseAddress(t, QString::fromLatin1(name)));
}

// The session's transport is made on its worker; the test keeps a pointer to script it.
struct Harness {
    const model::Target &target;
    std::mutex mutex;
    FakeTransport *port = nullptr; // the latest made, owned by the session's driver
    int made = 0;                  // transports made: a reconnect makes a new one
    std::function<void(FakeTransport &)> setUp;
    std::unique_ptr<OnlineSession> session;
    QObject reader;

    Harness(model::Family family, ConnectionSettings settings,
            std::function<void(FakeTransport &)> prepare)
        : target(model::Target::get(family))
        , setUp(std::move(prepare)) {
        settings.via = ConnectionSettings::Via::Serial;
        settings.port = QStringLiteral("/dev/ttyFAKE0");
        session = std::make_unique<OnlineSession>(target, settings, nullptr, [this] {
            auto t = std::make_unique<FakeTransport>(QStringLiteral("/dev/ttyFAKE0"));
            setUp(*t);
            std::lock_guard lock(mutex);
            port = t.get();
            ++made;
            return t;
        });
    }
    FakeTransport *transport() {
        std::lock_guard lock(mutex);
        return port;
    }
    // The transport made as the n-th (1-based), once it exists: the one before it is gone
    // with its driver after a disconnect, and must not be touched.
    FakeTransport *transportNumber(int n) {
        std::lock_guard lock(mutex);
        return made == n ? port : nullptr;
    }
    void watch(std::initializer_list<const char *> names) {
        std::vector<model::Address> devices;
        for (const char *n : names)
            devices.push_back(address(target, n));
        session->setWatched(&reader, devices);
    }
    std::shared_ptr<const model::Snapshot> snapshot() const { return session->snapshot(); }
    bool bit(const char *name) const {
        const auto s = snapshot();
        return s && s->bit(address(target, name));
    }
    std::int32_t value(const char *name) const {
        const auto s = snapshot();
        return s ? s->value(address(target, name)) : -99999;
    }
    // commandFinished for id: ok and the error text.
    std::pair<bool, QString> finish(model::MonitorSource::CommandId id, QSignalSpy &spy) {
        for (int k = 0;; ++k) {
            for (const auto &call : spy)
                if (call[0].value<model::MonitorSource::CommandId>() == id)
                    return {call[1].toBool(), call[2].toString()};
            if (!spy.wait(kPatienceMs))
                return {false, QStringLiteral("no commandFinished within the patience")};
        }
    }
};

ConnectionSettings pl110Settings() {
    ConnectionSettings s = defaultSettings(ProtocolKind::ModbusRtu);
    s.station = 1;
    s.link = {50, 1, 5};
    s.pollIntervalMs = 5;
    s.reconnectMinMs = 20;
    s.reconnectMaxMs = 80;
    return s;
}

// The Vigor Computer Link with a fast poll and a short patience, for a PLC that answers at once.
ConnectionSettings vigorSettings() {
    ConnectionSettings s = defaultSettings(ProtocolKind::VigorLink);
    s.link = {50, 1, 5};
    s.pollIntervalMs = 5;
    return s;
}

TEST(OnlineSession, PollsOnlyTheWatchedDevicesIntoTheSimulatorsSnapshotShape) {
    FakeModbusPlc plc;
    plc.setRegister(2010, 1234); // V10
    plc.setCoil(2400, true);     // Q1
    plc.setCoil(16000, true);    // SM0.0: RUN
    plc.setRegister(2100, 7);    // V100, not watched
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"V10", "Q1"});
    QSignalSpy states(h.session.get(), &OnlineSession::connectionStateChanged);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.value("V10") == 1234 && h.bit("Q1"); }));
    EXPECT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    EXPECT_EQ(h.session->runState(), RunState::Running);
    EXPECT_FALSE(h.snapshot()->stale);
    EXPECT_GT(h.snapshot()->statistics.scans, 0u); // refreshes, the online "scans"
    EXPECT_EQ(h.snapshot()->words.size(), std::size_t(h.session->layout()->wordCount()));
    EXPECT_EQ(h.value("V100"), 0); // not watched, not read
    // RUN / STOP through SM0.0; no MONITOR, no force.
    EXPECT_TRUE(h.session->abilities().setsMode);
    EXPECT_FALSE(h.session->abilities().monitorMode);
    EXPECT_FALSE(h.session->abilities().forces);
    // ... and the snapshot says which words the PLC answered for: a 0 nobody read is no value.
    EXPECT_TRUE(h.snapshot()->valueKnown(address(h.target, "V10")));
    EXPECT_TRUE(h.snapshot()->valueKnown(address(h.target, "Q1")));
    EXPECT_FALSE(h.snapshot()->valueKnown(address(h.target, "V100")));
    EXPECT_TRUE(h.session->errorText().isEmpty()) << h.session->errorText().toStdString();
    // The identity: PL110 words 0 and 1, read once.
    // Only V10 (register 2010), Q1 (coil 2400) and the RUN bit (coil 16000) were asked for.
    for (const auto &[function, start, count] : plc.requests()) {
        if (function == modbus::ReadHoldingRegisters && start == 0)
            continue; // the identity, words 0 and 1
        const bool v10 = function == modbus::ReadHoldingRegisters && start == 2010 && count == 1;
        const bool q1 = function == modbus::ReadCoils && start == 2400 && count == 1;
        const bool run = function == modbus::ReadCoils && start == 16000 && count == 1;
        EXPECT_TRUE(v10 || q1 || run) << function << " " << start << " " << count;
    }
    // Re-planned when the watched devices change.
    plc.setRegister(2020, 55);
    h.watch({"V10", "V20"});
    EXPECT_TRUE(eventually([&] { return h.value("V20") == 55; }));
    // A PL110 timer's preset is in the PT area (PL110 manual 2.1.9): read with the timer, known.
    h.watch({"T1"});
    EXPECT_TRUE(eventually([&] {
        const auto s = h.snapshot();
        return s && s->valueKnown(address(h.target, "T1")) &&
               s->setValueKnown(address(h.target, "T1"));
    }));
}

TEST(OnlineSession, WritesAreDoneWhenThePlcAcknowledgesAndRefusalsSayWhy) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    plc.refuseWritesAt(2011); // V11
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"V10"});
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    const auto ok = h.finish(h.session->writeWord(address(h.target, "V10"), -5), finished);
    EXPECT_TRUE(ok.first) << ok.second.toStdString();
    EXPECT_EQ(plc.reg(2010), 0xFFFB);
    EXPECT_TRUE(eventually([&] { return h.value("V10") == -5; }));
    const auto bit = h.finish(h.session->writeBit(address(h.target, "Q3"), true), finished);
    EXPECT_TRUE(bit.first) << bit.second.toStdString();
    EXPECT_TRUE(plc.coil(2402));
    plc.clearRequests();
    const auto refused = h.finish(h.session->writeWord(address(h.target, "V11"), 1), finished);
    EXPECT_FALSE(refused.first);
    EXPECT_TRUE(refused.second.contains(QLatin1String("V11"))) << refused.second.toStdString();
    EXPECT_TRUE(refused.second.contains(QLatin1String("illegal data address")))
        << refused.second.toStdString();
    int writes = 0;
    for (const auto &[function, start, count] : plc.requests())
        writes += function == modbus::WriteSingleRegister ? 1 : 0;
    EXPECT_EQ(writes, 1); // never sent again
    const auto force = h.finish(h.session->force(address(h.target, "Q1"), true), finished);
    EXPECT_FALSE(force.first);
    EXPECT_TRUE(force.second.contains(QLatin1String("cannot force"))) << force.second.toStdString();
    // The link is fine after a refusal.
    EXPECT_EQ(h.session->connectionState(), State::Online);
}

TEST(OnlineSession, RunAndStopThroughTheRunBitShowInTheRunState) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.session->runState() == RunState::Running; }));
    const auto stop = h.finish(h.session->setPlcMode(PlcMode::Stop), finished);
    EXPECT_TRUE(stop.first) << stop.second.toStdString();
    EXPECT_FALSE(plc.coil(16000));
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Stopped; }));
    EXPECT_EQ(h.session->plcMode(), PlcMode::Stop);
    const auto run = h.finish(h.session->setPlcMode(PlcMode::Run), finished);
    EXPECT_TRUE(run.first) << run.second.toStdString();
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Running; }));
}

// At 19200 bps a refresh of a screenful of devices takes longer than the poll interval: the
// next one starts at once (the interval counts from the start of a refresh), so the wire, not
// a pause, sets the rate. Each answer here takes 150 ms, a refresh (V10 and the RUN bit, two
// frames) 300 ms, the interval 250 ms: one refresh after the other comes every ~300 ms, and
// would come every ~550 ms if the interval were a pause after each.
TEST(OnlineSession, ARefreshLongerThanThePollIntervalIsFollowedAtOnce) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    ConnectionSettings settings = pl110Settings();
    settings.link.timeoutMs = 2000;
    settings.pollIntervalMs = 250;
    Harness h(model::Family::Pl110, settings, [&](FakeTransport &t) {
        t.setResponder([answer = plc.responder()](const QByteArray &request) {
            // A slow wire is the stimulus: the answer's delay is the test's, not a wait.
            std::this_thread::sleep_for(std::chrono::milliseconds(150));
            return answer(request);
        });
    });
    h.watch({"V10"});
    h.session->connectToPlc();
    const auto refreshes = [&] {
        const auto snapshot = h.snapshot();
        return snapshot ? snapshot->statistics.scans : 0;
    };
    ASSERT_TRUE(eventually([&] { return h.session->statistics().framesPerRefresh == 2; }));
    // From the end of one refresh to the end of the next, twice.
    const auto first = refreshes();
    ASSERT_TRUE(eventually([&] { return refreshes() > first; }));
    QElapsedTimer clock;
    clock.start();
    ASSERT_TRUE(eventually([&] { return refreshes() > first + 2; }));
    const double periodMs = double(clock.elapsed()) / 2;
    EXPECT_GE(periodMs, 280);
    EXPECT_LT(periodMs, 425) << "a pause of the poll interval after each refresh";
}

TEST(OnlineSession, ALostLinkShowsAtOnceKeepsTheValuesStaleAndResumesByItself) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    plc.setRegister(2010, 42);
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"V10"});
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.value("V10") == 42; }));
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    // The USB adapter is pulled, and stays away for two tries.
    h.transport()->failOpens(2);
    h.transport()->unplug();
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Lost; }));
    EXPECT_EQ(h.session->runState(), RunState::Offline);
    EXPECT_TRUE(h.session->errorText().contains(QLatin1String("lost")))
        << h.session->errorText().toStdString();
    EXPECT_TRUE(h.session->errorText().contains(QLatin1String("/dev/ttyFAKE0")))
        << h.session->errorText().toStdString();
    ASSERT_TRUE(eventually([&] { return h.snapshot()->stale; }));
    EXPECT_EQ(h.value("V10"), 42); // the last value, kept
    // Back: the session finds it without being asked.
    plc.setRegister(2010, 43);
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    EXPECT_TRUE(eventually([&] { return h.value("V10") == 43 && !h.snapshot()->stale; }));
    EXPECT_TRUE(h.session->errorText().isEmpty()) << h.session->errorText().toStdString();
    EXPECT_EQ(h.session->runState(), RunState::Running);
    EXPECT_TRUE(eventually([&] { return h.session->statistics().reconnects == 1; }));
    EXPECT_GE(h.transport()->opens(), 3);
}

TEST(OnlineSession, APlcThatFallsSilentIsLostAndFoundAgain) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    plc.setSilent(true);
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Lost; }));
    EXPECT_TRUE(h.session->errorText().contains(QLatin1String("no reply")))
        << h.session->errorText().toStdString();
    // A write while the PLC is away is not done.
    const auto write = h.finish(h.session->writeWord(address(h.target, "V1"), 1), finished);
    EXPECT_FALSE(write.first);
    EXPECT_EQ(plc.reg(2001), 0);
    plc.setSilent(false);
    EXPECT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
}

TEST(OnlineSession, DisconnectAndDestructionDoNotWaitForASilentPlc) {
    FakeModbusPlc plc;
    plc.setSilent(true);
    ConnectionSettings s = pl110Settings();
    s.link = {5000, 3, 5}; // a patient link: 20 s before it would give up on its own
    Harness h(model::Family::Pl110, s, [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.transport() && h.transport()->writes() > 0; }));
    QElapsedTimer clock;
    clock.start();
    h.session->disconnectFromPlc();
    EXPECT_LT(clock.elapsed(), 50); // returns at once
    EXPECT_TRUE(
        eventually([&] { return h.session->connectionState() == State::Disconnected; }, 2000));
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] {
        FakeTransport *again = h.transportNumber(2);
        return again && again->writes() > 0;
    }));
    clock.restart();
    h.session.reset(); // the worker is waiting for the PLC
    EXPECT_LT(clock.elapsed(), 2000);
}

TEST(OnlineSession, CommandsWhileNotConnectedFailAtOnce) {
    Harness h(model::Family::Pl110, pl110Settings(), [](FakeTransport &) {});
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    const auto r = h.finish(h.session->writeWord(address(h.target, "V1"), 1), finished);
    EXPECT_FALSE(r.first);
    EXPECT_TRUE(r.second.contains(QLatin1String("not connected"))) << r.second.toStdString();
    EXPECT_EQ(h.transport(), nullptr); // no port was even opened
}

// What the connection panel offers per family comes from the target tables' maps.
TEST(OnlineSession, EachFamilyIsReachedByTheProtocolsItsTableMaps) {
    using K = ProtocolKind;
    const auto of = [](model::Family f) { return protocolsOf(model::Target::get(f)); };
    EXPECT_EQ(of(model::Family::Vigor), (std::vector<K>{K::VigorLink, K::ModbusRtu, K::ModbusTcp}));
    EXPECT_EQ(of(model::Family::Pl110), (std::vector<K>{K::ModbusRtu, K::ModbusTcp}));
    EXPECT_EQ(of(model::Family::Cpm1), (std::vector<K>{K::HostLink}));
    EXPECT_TRUE(of(model::Family::Vpc).empty()); // its link protocol is not published
}

TEST(OnlineSession, SettingsThatCannotWorkFailWithTheReason) {
    ConnectionSettings s = pl110Settings();
    s.station = 0;
    Harness h(model::Family::Pl110, s, [](FakeTransport &) {});
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Failed; }));
    EXPECT_TRUE(h.session->errorText().contains(QLatin1String("broadcast")))
        << h.session->errorText().toStdString();
}

TEST(OnlineSession, HostLinkSwitchesToMonitorToWriteSaysSoAndShowsItsForces) {
    FakeHostLinkPlc plc;
    plc.setWord(model::ProtocolSpace::HostLinkDm, 5, 0x1234);
    ConnectionSettings s = defaultSettings(ProtocolKind::HostLink);
    s.link = {50, 1, 5};
    s.pollIntervalMs = 5;
    s.modePollMs = 20;
    Harness h(model::Family::Cpm1, s, [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"DM 0005", "010.00"});
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    QSignalSpy notices(h.session.get(), &OnlineSession::notice);
    QSignalSpy identity(h.session.get(), &OnlineSession::identityChanged);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.value("DM 0005") == 0x1234; }));
    ASSERT_TRUE(eventually([&] { return h.session->plcMode() == PlcMode::Run; }));
    // The mode and the run state reach the owner thread as two posts.
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Running; }));
    EXPECT_TRUE(eventually([&] { return identity.count() > 0; }));
    EXPECT_EQ(h.session->identity().model, QStringLiteral("model code 12h"));
    // Host Link commands every mode and forces.
    EXPECT_TRUE(h.session->abilities().setsMode);
    EXPECT_TRUE(h.session->abilities().monitorMode);
    EXPECT_TRUE(h.session->abilities().forces);
    const auto w = h.finish(h.session->writeWord(address(h.target, "DM 0005"), 99), finished);
    EXPECT_TRUE(w.first) << w.second.toStdString();
    EXPECT_EQ(plc.word(model::ProtocolSpace::HostLinkDm, 5), 99);
    ASSERT_TRUE(eventually([&] { return notices.count() > 0; }));
    EXPECT_TRUE(notices[0][0].toString().contains(QLatin1String("MONITOR")));
    EXPECT_EQ(plc.mode(), hostlink::Mode::Monitor);
    EXPECT_TRUE(eventually([&] { return h.session->plcMode() == PlcMode::Monitor; }));
    EXPECT_EQ(h.session->runState(), RunState::Running); // MONITOR runs the program
    const auto force = h.finish(h.session->force(address(h.target, "010.00"), true), finished);
    EXPECT_TRUE(force.first) << force.second.toStdString();
    EXPECT_EQ(plc.forced().size(), 1u);
    EXPECT_TRUE(eventually(
        [&] { return h.snapshot() && h.snapshot()->forced(address(h.target, "010.00")); }));
    const auto stop = h.finish(h.session->setPlcMode(PlcMode::Program), finished);
    EXPECT_TRUE(stop.first) << stop.second.toStdString();
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Stopped; }));
}

TEST(OnlineSession, AVigorOnTheComputerLinkShowsItsBitsWordsAndRunState) {
    FakeVigorPlc plc;
    plc.setByte(0x03E0, 0x01); // M9000: ON while the PLC runs
    plc.setByte(0x0081, 0x04); // M10
    plc.setByte(0x1C0A, 0x39); // D5 = 3039h, low byte first
    plc.setByte(0x1C0B, 0x30);
    Harness h(model::Family::Vigor, vigorSettings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"M10", "D5", "Y0", "T0"});
    QSignalSpy finished(h.session.get(), &model::MonitorSource::commandFinished);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.bit("M10") && h.value("D5") == 0x3039; }));
    // A timer's current value is read; its set value lives in the program, where the link
    // cannot reach it, and the snapshot says it is not known (the overlay shows the box's K).
    EXPECT_TRUE(h.snapshot()->valueKnown(address(h.target, "T0")));
    EXPECT_FALSE(h.snapshot()->setValueKnown(address(h.target, "T0")));
    // The link reads the mode (M9000) but cannot set it, and forces nothing.
    EXPECT_FALSE(h.session->abilities().setsMode);
    EXPECT_FALSE(h.session->abilities().monitorMode);
    EXPECT_FALSE(h.session->abilities().forces);
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Running; }));
    // Y0 ON with 70h; the refresh shows it.
    const auto on = h.finish(h.session->writeBit(address(h.target, "Y0"), true), finished);
    EXPECT_TRUE(on.first) << on.second.toStdString();
    EXPECT_EQ(plc.byte(0x0040), 0x01);
    EXPECT_TRUE(eventually([&] { return h.bit("Y0"); }));
    // The PLC goes to STOP (M9000 off): Stopped. RUN / STOP cannot be commanded over the link.
    plc.setByte(0x03E0, 0x00);
    EXPECT_TRUE(eventually([&] { return h.session->runState() == RunState::Stopped; }));
    const auto run = h.finish(h.session->setPlcMode(PlcMode::Run), finished);
    EXPECT_FALSE(run.first);
    EXPECT_TRUE(run.second.contains(QLatin1String("RUN / STOP"))) << run.second.toStdString();
}

// A device with no address in the protocol, watched after the connection is up, is said
// at once (the state stays Online): the warning does not wait for a reconnect. Watched
// before or after is a race between the window and the worker, so both orders are tried.
TEST(OnlineSession, ADeviceWithNoAddressWatchedWhileOnlineIsSaidAndUnsaidWhenDropped) {
    FakeHostLinkPlc plc;
    ConnectionSettings s = defaultSettings(ProtocolKind::HostLink);
    s.link = {50, 1, 5};
    s.pollIntervalMs = 5;
    Harness h(model::Family::Cpm1, s, [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    h.watch({"DM 0005"});
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.session->connectionState() == State::Online; }));
    ASSERT_TRUE(eventually([&] { return h.snapshot() && h.snapshot()->statistics.scans > 1; }));
    EXPECT_TRUE(h.session->errorText().isEmpty()) << h.session->errorText().toStdString();
    h.watch({"DM 0005", "TR 0"});
    ASSERT_TRUE(eventually([&] { return h.session->errorText().contains(QLatin1String("TR 0")); }))
        << h.session->errorText().toStdString();
    EXPECT_EQ(h.session->connectionState(), State::Online);
    h.watch({"DM 0005"});
    EXPECT_TRUE(eventually([&] { return h.session->errorText().isEmpty(); }))
        << h.session->errorText().toStdString();
}

TEST(OnlineSession, StatisticsAndTheTrafficTapReachTheOwner) {
    FakeModbusPlc plc;
    plc.setCoil(16000, true);
    Harness h(model::Family::Pl110, pl110Settings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    QSignalSpy traffic(h.session.get(), &OnlineSession::trafficAvailable);
    QSignalSpy stats(h.session.get(), &OnlineSession::statisticsChanged);
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return traffic.count() > 0 && stats.count() > 0; }));
    const LinkStatistics s = h.session->statistics();
    EXPECT_GT(s.requests, 0u);
    EXPECT_GT(s.replies, 0u);
    EXPECT_GT(s.refreshes, 0u);
    EXPECT_GT(s.bytesSent, 0u);
    quint64 next = 0;
    const auto records = h.session->traffic(0, &next);
    ASSERT_GE(records.size(), 2u);
    EXPECT_EQ(records[0].direction, TrafficRecord::Direction::Sent);
    EXPECT_EQ(records[1].direction, TrafficRecord::Direction::Received);
    EXPECT_GT(next, 1u);
}

} // namespace
} // namespace rung::comms::test

namespace rung::comms::test {
namespace {

// Online, the timing chart draws the PLC's values refresh by refresh, as it draws a
// simulation scan by scan: the session keeps the history of the devices asked for, each from
// the first refresh that read it (a word not read yet holds a 0 the PLC never said), and a
// trigger marks the refresh where it became true (the PLC does not stop for it).
TEST(OnlineSession, KeepsAHistoryOfTheChartsDevicesRefreshByRefresh) {
    FakeVigorPlc plc;
    plc.setByte(0x03E0, 0x01); // M9000: RUN
    plc.setByte(0x1C0A, 0x39); // D5 = 3039h, low byte first
    plc.setByte(0x1C0B, 0x30);
    Harness h(model::Family::Vigor, vigorSettings(),
              [&](FakeTransport &t) { t.setResponder(plc.responder()); });
    const model::Address m10 = address(h.target, "M10");
    const model::Address d5 = address(h.target, "D5");
    ASSERT_TRUE(h.session->watchHistory(m10));
    ASSERT_TRUE(h.session->watchHistory(d5));
    model::Trigger rises;
    rises.device = m10;
    rises.kind = model::Trigger::Kind::Rises;
    rises.action = model::Trigger::Action::Stop; // as the chart asks: online it only marks
    ASSERT_TRUE(h.session->setTrigger(rises));
    QSignalSpy triggered(h.session.get(), &model::MonitorSource::triggered);
    h.watch({"M10", "D5"});
    h.session->connectToPlc();
    ASSERT_TRUE(eventually([&] { return h.value("D5") == 0x3039; }));
    plc.setByte(0x0081, 0x04); // M10 ON
    ASSERT_TRUE(eventually([&] { return h.bit("M10"); }));
    plc.setByte(0x0081, 0x00); // and OFF again
    ASSERT_TRUE(eventually([&] { return !h.bit("M10"); }));
    ASSERT_TRUE(eventually([&] { return triggered.count() == 1; }));
    EXPECT_EQ(h.session->runState(), RunState::Running);

    std::vector<model::HistoryRecorder::Change> bit;
    std::vector<model::HistoryRecorder::Change> word;
    std::vector<model::HistoryRecorder::Mark> marks;
    h.session->readHistory([&](const model::HistoryRecorder &r) {
        bit = r.changes(m10, 0, std::numeric_limits<qint64>::max());
        word = r.changes(d5, 0, std::numeric_limits<qint64>::max());
        marks = r.marks();
    });
    // D5's first value is the PLC's, not the 0 before it was read.
    ASSERT_FALSE(word.empty());
    EXPECT_EQ(word.front().value, 0x3039);
    EXPECT_EQ(word.size(), 1u);
    // M10: OFF, ON, OFF, refresh numbers and times since the connection rising.
    ASSERT_EQ(bit.size(), 3u);
    EXPECT_EQ(bit[0].value, 0);
    EXPECT_EQ(bit[1].value, 1);
    EXPECT_EQ(bit[2].value, 0);
    EXPECT_LT(bit[0].scan, bit[1].scan);
    EXPECT_LT(bit[1].scan, bit[2].scan);
    EXPECT_LE(bit[1].timeMs, bit[2].timeMs);
    ASSERT_EQ(marks.size(), 1u);
    EXPECT_EQ(marks[0].scan, bit[1].scan);
    EXPECT_EQ(triggered[0][0].value<quint64>(), bit[1].scan);
    // A device the image has no word for is refused, as by the simulation.
    EXPECT_FALSE(h.session->watchHistory(model::Address{}));
}

} // namespace
} // namespace rung::comms::test
