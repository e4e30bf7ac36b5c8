// A network simulated on a worker thread as the IDE runs it (network_session.h): each station a
// MonitorSource, a value written in one station arriving in another, the faults made while it
// runs, the traffic handed over in batches, stop building the network again.

#include "network/network_session.h"

#include "network_fixture.h"

#include "../eventually.h"

#include "model/target/target.h"

#include <QSignalSpy>

#include <gtest/gtest.h>

namespace rung::network::test {
namespace {

using waits::eventually;
using RunState = model::MonitorSource::RunState;

const QString kEasyLink =
    QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/easy-link/easy-link.rungnet");

struct SessionFixture {
    std::unique_ptr<NetworkSession> session;
    QString error;

    explicit SessionFixture(const QString &file = kEasyLink) {
        NetworkDescription d;
        EXPECT_TRUE(readNetworkFile(file, &d, &error)) << error.toStdString();
        session = NetworkSession::start(d, listingLoader(), &error);
        EXPECT_TRUE(session) << error.toStdString();
    }
    StationSource *station(const char *name) const {
        return session->station(QString::fromLatin1(name));
    }
    static model::Address at(const StationSource *s, const char *device) {
        const auto a = model::parseAddress(s->target(), QString::fromLatin1(device));
        EXPECT_TRUE(std::holds_alternative<model::Address>(a)) << device;
        return std::holds_alternative<model::Address>(a) ? std::get<model::Address>(a)
                                                         : model::Address{};
    }
    static qint64 value(const StationSource *s, const char *device) {
        const auto snapshot = s->snapshot();
        return snapshot ? snapshot->value(at(s, device)) : -1;
    }
    // Waits until the command is answered; its result.
    bool finish(StationSource *s, model::MonitorSource::CommandId id) const {
        bool done = false, ok = false;
        QObject::connect(s, &model::MonitorSource::commandFinished, s,
                         [&](model::MonitorSource::CommandId got, bool good, const QString &) {
                             if (got == id) {
                                 done = true;
                                 ok = good;
                             }
                         });
        EXPECT_TRUE(eventually([&] { return done; }));
        return ok;
    }
};

TEST(NetworkSession, EveryStationIsASourceStoppedAtTimeZero) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    ASSERT_EQ(f.session->stations().size(), 3u);
    EXPECT_EQ(f.station("master")->stationName(), QStringLiteral("master"));
    EXPECT_TRUE(f.station("s5")->programPath().endsWith(QStringLiteral("slave.il")));
    EXPECT_EQ(f.station("s2")->runState(), RunState::Stopped);
    EXPECT_EQ(f.session->runState(), RunState::Stopped);
    EXPECT_EQ(f.session->nowUs(), 0);
    ASSERT_EQ(f.session->wires().size(), 1u);
    EXPECT_EQ(f.session->wires()[0].ends,
              (QStringList{QStringLiteral("master/CP2"), QStringLiteral("s5/CP2"),
                           QStringLiteral("s2/CP2")}));
    EXPECT_TRUE(f.station("master")->snapshot());
}

// What a station's front panel shows beside its memory (PL110 manual 5.3, page 3: "il nome
// dell'applicazione ladder caricata, i protocolli associati alle porte seriali"): the station's
// program file's name and each port's application as the network's settings give it (the
// example's EXP1 a MODBUS master; COM1 and COM2, not named, their first application).
TEST(NetworkSession, AStationsPanelContextIsItsProgramsNameAndItsPortsApplications) {
    SessionFixture f(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/networks/pl110-exp/pl110-exp.rungnet"));
    ASSERT_TRUE(f.session);
    const model::PanelContext &c = f.station("pl")->panelContext();
    EXPECT_EQ(c.application, QStringLiteral("master"));
    std::map<QString, QString> ports;
    for (const model::PanelPort &p : c.ports)
        ports[p.port] = p.application ? QString::fromLatin1(p.application->id) : QString();
    EXPECT_EQ(ports,
              (std::map<QString, QString>{{QStringLiteral("COM1"), QStringLiteral("modbus")},
                                          {QStringLiteral("EXP1"), QStringLiteral("modbus-master")},
                                          {QStringLiteral("COM2"), QStringLiteral("modbus")}}));
}

// The Easy Link example's set 1 reads D10..D19 of station 5 into the master's D0..D9.
TEST(NetworkSession, AValueWrittenInOneStationArrivesInAnother) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *s5 = f.station("s5");
    StationSource *master = f.station("master");
    EXPECT_TRUE(f.finish(s5, s5->writeWord(SessionFixture::at(s5, "D10"), 1234)));
    EXPECT_EQ(SessionFixture::value(s5, "D10"), 1234);
    f.session->setSpeed(0);
    f.session->run();
    EXPECT_EQ(master->runState(), RunState::Running);
    EXPECT_TRUE(eventually([&] { return SessionFixture::value(master, "D0") == 1234; }));
    EXPECT_GT(f.session->nowUs(), 0);
}

TEST(NetworkSession, ASingleScanIsOnePeriodOfTheNetworkThenPaused) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    QSignalSpy states(f.session.get(), &NetworkSession::runStateChanged);
    f.session->singleScan();
    EXPECT_EQ(f.session->runState(), RunState::Stepping);
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(f.session->nowUs(), f.session->description().periodMs * 1000);
    EXPECT_EQ(f.station("master")->snapshot()->statistics.scans, 1u);
    f.session->runFor(100);
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(f.session->nowUs(), (f.session->description().periodMs + 100) * 1000);
    EXPECT_GE(states.count(), 4);
}

TEST(NetworkSession, StopBuildsTheNetworkAgainAtPowerOn) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *s5 = f.station("s5");
    StationSource *master = f.station("master");
    f.finish(s5, s5->writeWord(SessionFixture::at(s5, "D10"), 77));
    f.session->setSpeed(0);
    f.session->run();
    ASSERT_TRUE(eventually([&] { return SessionFixture::value(master, "D0") == 77; }));
    f.session->stop();
    EXPECT_EQ(master->runState(), RunState::Stopped);
    EXPECT_TRUE(eventually([&] {
        return f.session->nowUs() == 0 && SessionFixture::value(master, "D0") == 0 &&
               SessionFixture::value(s5, "D10") == 0;
    }));
}

TEST(NetworkSession, TrafficComesInBatchesWithItsWireAndSender) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    QSignalSpy told(f.session.get(), &NetworkSession::trafficAvailable);
    f.session->runFor(200);
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] { return told.count() > 0; }));
    const std::vector<TrafficRecord> records = f.session->takeTraffic();
    ASSERT_FALSE(records.empty());
    EXPECT_EQ(records.front().wire, QStringLiteral("w1"));
    EXPECT_EQ(records.front().sender, QStringLiteral("master/CP2"));
    EXPECT_LE(records.back().startUs, f.session->nowUs());
    bool startedOver = true;
    EXPECT_TRUE(f.session->takeTraffic(&startedOver).empty()); // taken once
    EXPECT_FALSE(startedOver);
    // Stop builds the network again: the next frames are the new network's, and say so.
    f.session->stop();
    f.session->runFor(100);
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    const auto fresh = f.session->takeTraffic(&startedOver);
    EXPECT_TRUE(startedOver);
    ASSERT_FALSE(fresh.empty());
    EXPECT_LE(fresh.back().startUs, 100'000);
    f.session->takeTraffic(&startedOver);
    EXPECT_FALSE(startedOver);
}

TEST(NetworkSession, ACutWireStopsTheDataAndMarksTheTrafficUntilItIsJoinedAgain) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *s5 = f.station("s5");
    StationSource *master = f.station("master");
    f.session->runFor(200);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    f.session->takeTraffic();
    f.session->setWireCut(QStringLiteral("w1"), true);
    EXPECT_TRUE(f.session->wireCut(QStringLiteral("w1")));
    f.finish(s5, s5->writeWord(SessionFixture::at(s5, "D10"), 55));
    f.session->runFor(300);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(SessionFixture::value(master, "D0"), 0);
    const auto cut = f.session->takeTraffic();
    ASSERT_FALSE(cut.empty());
    for (const TrafficRecord &r : cut)
        EXPECT_TRUE(r.note.contains(QStringLiteral("cut"))) << r.note.toStdString();

    f.session->setWireCut(QStringLiteral("w1"), false);
    EXPECT_FALSE(f.session->wireCut(QStringLiteral("w1")));
    f.session->runFor(300);
    EXPECT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(SessionFixture::value(master, "D0"), 55);
}

TEST(NetworkSession, ASilentStationSendsNothingAndTheCorruptedFrameIsMarked) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    f.session->setSilent(QStringLiteral("s5"), true);
    EXPECT_TRUE(f.session->silent(QStringLiteral("s5")));
    f.session->corruptNextFrame(QStringLiteral("w1"), 1, 0x04);
    f.session->runFor(300);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    const auto records = f.session->takeTraffic();
    ASSERT_FALSE(records.empty());
    EXPECT_TRUE(records.front().note.contains(QStringLiteral("corrupted")))
        << records.front().note.toStdString();
    bool silenced = false;
    for (const TrafficRecord &r : records) {
        if (r.sender == QStringLiteral("s5/CP2"))
            silenced = silenced || r.note.contains(QStringLiteral("silent"));
    }
    EXPECT_TRUE(silenced);
    // Stop forgets the faults made by hand.
    f.session->stop();
    EXPECT_FALSE(f.session->silent(QStringLiteral("s5")));
}

TEST(NetworkSession, ASlavesPortAtAnotherBaudRateLeavesTheMasterWithoutItsData) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *s5 = f.station("s5");
    StationSource *master = f.station("master");
    f.session->setBaud(QStringLiteral("s5/CP2"), 9600);
    EXPECT_EQ(f.session->baudSet(QStringLiteral("s5/CP2")), 9600);
    f.finish(s5, s5->writeWord(SessionFixture::at(s5, "D10"), 31));
    f.session->runFor(1000);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(SessionFixture::value(master, "D0"), 0);
    // LINK's working area: the master heard no answer it could read from station 5.
    EXPECT_NE(SessionFixture::value(master, "D100") >> 8, 0);
    f.session->stop();
    EXPECT_EQ(f.session->baudSet(QStringLiteral("s5/CP2")), 0);
    f.finish(s5, s5->writeWord(SessionFixture::at(s5, "D10"), 31));
    f.session->runFor(1000);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_EQ(SessionFixture::value(master, "D0"), 31);
}

// Vigor's D200.. are latched (retentive); D0.. clear at a power cycle.
TEST(NetworkSession, APowerCycleKeepsTheLatchedRegistersAndTheClock) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *s2 = f.station("s2");
    f.session->runFor(50);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    f.finish(s2, s2->writeWord(SessionFixture::at(s2, "D0"), 5));
    f.finish(s2, s2->writeWord(SessionFixture::at(s2, "D200"), 7));
    f.session->powerCycle();
    f.session->runFor(10);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] { return SessionFixture::value(s2, "D0") == 0; }));
    EXPECT_EQ(SessionFixture::value(s2, "D200"), 7);
    EXPECT_EQ(f.session->nowUs(), 60'000);
}

// Power flow for the overlay: recorded by the station on screen only.
TEST(NetworkSession, OnlyTheStationShownRecordsPowerFlow) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    f.session->setPowerFlowStation(QStringLiteral("master"));
    f.session->runFor(30);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_FALSE(f.station("master")->snapshot()->powerFlow.empty());
    EXPECT_TRUE(f.station("s5")->snapshot()->powerFlow.empty());
    f.session->setPowerFlowStation(QStringLiteral("s5"));
    f.session->runFor(30);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    EXPECT_TRUE(eventually([&] { return !f.station("s5")->snapshot()->powerFlow.empty(); }));
    EXPECT_TRUE(f.station("master")->snapshot()->powerFlow.empty());
}

TEST(NetworkSession, AStationKeepsTheHistoryOfItsDevices) {
    SessionFixture f;
    ASSERT_TRUE(f.session);
    StationSource *master = f.station("master");
    const model::Address d1001 = SessionFixture::at(master, "D1001");
    EXPECT_TRUE(master->watchHistory(d1001));
    f.session->runFor(50);
    ASSERT_TRUE(eventually([&] { return f.session->runState() == RunState::Paused; }));
    std::optional<std::int32_t> first, later;
    std::optional<quint64> from;
    master->readHistory([&](const model::HistoryRecorder &h) {
        from = h.knownFrom(d1001);
        first = h.valueAtScan(d1001, 1);
        later = h.valueAtTime(d1001, 40);
    });
    ASSERT_TRUE(from);
    EXPECT_EQ(*from, 1u);
    EXPECT_EQ(first, 5); // MOV K5 D1001 at the first scan
    EXPECT_EQ(later, 5);
}

TEST(NetworkSession, ANetworkThatDoesNotBuildSaysWhy) {
    NetworkDescription d;
    QString error;
    ASSERT_TRUE(parseNetwork(R"({"stations": [{"name": "a", "program": "missing.il"}]})",
                             QStringLiteral("/tmp/x.rungnet"), &d, &error));
    EXPECT_FALSE(NetworkSession::start(d, listingLoader(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("missing.il"))) << error.toStdString();
}

} // namespace
} // namespace rung::network::test
