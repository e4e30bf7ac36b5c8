// Tests > Record... online (app/gui/tests_panel_record.cpp): what a PLC did between Record...
// and Stop Recording..., its inputs and outputs as each refresh read them, becomes a scenario
// that passes on the program. The PLC is a virtual one on a pseudo-terminal, reached by the
// online session a user's Go Online makes.

#include "app/gui/tests_panel.h"
#include "comms/driver/online_session.h"
#include "editor/document.h"
#include "tests/cli/virtual_plc_fixture.h"

#include <QFile>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolButton>

#include <gtest/gtest.h>

#include <memory>

using namespace rung;
using rung::waits::kPatienceMs;

namespace {

QToolButton *buttonSaying(const QWidget &panel, const QString &text) {
    for (QToolButton *b : panel.findChildren<QToolButton *>())
        if (b->text() == text)
            return b;
    return nullptr;
}

} // namespace

TEST(TestsPanelAlone, RecordsWhatAnOnlinePlcDidAsAScenarioThatPasses) {
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    comms::slave::SlaveOptions options;
    options.protocol = model::ProtocolId::VigorLink;
    options.station = comms::defaultSettings(comms::ProtocolKind::VigorLink).station;
    test::VirtualPlcUnderTest plc("; target: vigor\nLD X0\nOUT Y0\nEND\n", options, false);
    ASSERT_TRUE(plc.ready());
    ASSERT_TRUE(plc.scanned());

    QTemporaryDir dir;
    editor::Document document;
    document.reset(vigor, QStringLiteral("VB"));
    ASSERT_TRUE(document.setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), nullptr));
    document.setPath(dir.filePath(QStringLiteral("follower.rung")));
    app::TestsPanel panel(&document);

    // Offline, Record... is the simulation's; online it starts a recording.
    QString error;
    EXPECT_FALSE(panel.startOnlineRecording(&error));
    EXPECT_EQ(error, QStringLiteral("Not online: go online to record what a PLC does"));
    comms::ConnectionSettings s = comms::defaultSettings(comms::ProtocolKind::VigorLink);
    s.port = plc.path;
    s.pollIntervalMs = 20;
    auto owned = std::make_unique<comms::OnlineSession>(vigor, s);
    comms::OnlineSession &session = *owned;
    panel.setOnlineSource([&]() -> model::MonitorSource * { return owned.get(); });
    session.connectToPlc();
    ASSERT_TRUE(QTest::qWaitFor(
        [&] { return session.connectionState() == comms::OnlineSession::ConnectionState::Online; },
        kPatienceMs));
    ASSERT_NE(buttonSaying(panel, QStringLiteral("Record...")), nullptr);
    ASSERT_TRUE(panel.startOnlineRecording(&error)) << error.toStdString();
    EXPECT_TRUE(panel.recordingOnline());
    EXPECT_NE(buttonSaying(panel, QStringLiteral("Stop Recording...")), nullptr);

    const model::Address x0 = std::get<model::Address>(model::parseAddress(vigor, u"X0"));
    const model::Address y0 = std::get<model::Address>(model::parseAddress(vigor, u"Y0"));
    const auto refreshes = [&] {
        const auto snapshot = session.snapshot();
        return snapshot ? snapshot->statistics.scans : 0;
    };
    const auto y0Is = [&](bool on) {
        const auto snapshot = session.snapshot();
        return snapshot && snapshot->valueKnown(y0) && snapshot->bit(y0) == on;
    };
    const auto someRefreshes = [&] {
        const quint64 now = refreshes();
        return QTest::qWaitFor([&] { return refreshes() >= now + 4; }, kPatienceMs);
    };
    ASSERT_TRUE(someRefreshes());
    session.writeBit(x0, true); // as a switch of the plant would
    ASSERT_TRUE(QTest::qWaitFor([&] { return y0Is(true); }, kPatienceMs));
    ASSERT_TRUE(someRefreshes());
    session.writeBit(x0, false);
    ASSERT_TRUE(QTest::qWaitFor([&] { return y0Is(false); }, kPatienceMs));
    ASSERT_TRUE(someRefreshes());

    const QString file = dir.filePath(QStringLiteral("recorded.rungtest"));
    QStringList notes;
    const QString text = panel.recordedText(file, &error, &notes);
    ASSERT_FALSE(text.isEmpty()) << error.toStdString();
    EXPECT_EQ(notes.size(), 1);
    // X0 switched on and off, Y0 seen following it; times as the refreshes saw them.
    const QString time = QStringLiteral("(\\d+(\\.\\d+)?)s");
    static const QRegularExpression shape(
        QStringLiteral("^# .*\nprogram follower.rung\nperiod 10ms\n\n"
                       "at %1 set X0=1\nat %1 expect Y0=1\nat %1 set X0=0\nat %1 expect Y0=0\n$")
            .arg(time));
    EXPECT_TRUE(shape.match(text).hasMatch()) << text.toStdString();
    // Going offline ends the recording but keeps it: the session goes, the scenario is the same
    // but for its last instant.
    panel.keepOnlineRecording();
    session.disconnectFromPlc();
    owned.reset();
    EXPECT_TRUE(panel.recordingOnline());
    EXPECT_NE(buttonSaying(panel, QStringLiteral("Stop Recording...")), nullptr);
    const QString kept = panel.recordedText(file, &error, &notes);
    EXPECT_TRUE(shape.match(kept).hasMatch()) << kept.toStdString();
    EXPECT_EQ(kept.section(QLatin1Char('\n'), 0, 6), text.section(QLatin1Char('\n'), 0, 6));
    {
        QFile out(file);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(text.toUtf8());
    }
    panel.stopOnlineRecording();
    EXPECT_FALSE(panel.recordingOnline());
    EXPECT_NE(buttonSaying(panel, QStringLiteral("Record...")), nullptr);
    // The scenario passes on the program it was recorded from.
    panel.refresh();
    QSignalSpy finished(&panel, &app::TestsPanel::runFinished);
    panel.run({file});
    ASSERT_TRUE(finished.wait(20000));
    ASSERT_EQ(panel.results().size(), 1u);
    EXPECT_TRUE(panel.results()[0].passed());
}

// The notes of a recording, shown when it is written: the file, then each note a sentence.
TEST(TestsPanelAlone, ARecordingsNotesReadAsSentencesUnderTheFile) {
    EXPECT_EQ(app::TestsPanel::recordingNotes(
                  QStringLiteral("/plant/tests/online.rungtest"),
                  {QStringLiteral("a change between two refreshes is not seen"),
                   QStringLiteral("the scenario runs at 10 ms scans")}),
              QStringLiteral("online.rungtest is written. What it does not hold:\n"
                             "\u2022 A change between two refreshes is not seen\n"
                             "\u2022 The scenario runs at 10 ms scans"));
}
