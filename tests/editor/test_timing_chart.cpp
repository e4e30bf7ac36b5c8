// The timing chart on a real simulation: its CSV for the start/stop latch of PLC concepts
// (WPLSoft family) 1.9 (the example project) equals the known trace, a trigger stops the simulation
// at the scan where its condition became true, cursors snap to scans and say the time between them,
// devices come in typed, as ranges and dropped, and the PNG and SVG exports are files that read
// back.

#include "monitor_fixture.h"

#include "editor/device_mime.h"
#include "editor/timing_canvas.h"
#include "editor/timing_chart.h"

#include "model/project/project.h"

#include <QDropEvent>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTextStream>

#include <gtest/gtest.h>

using namespace rung;

namespace {

QString readAll(const QString &path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly | QIODevice::Text)) << path.toStdString();
    return QString::fromUtf8(f.readAll());
}

} // namespace

TEST(TimingChart, TheCsvOfTheStartFirstLatchEqualsTheKnownTrace) {
    // The example project (PLC concepts (WPLSoft family) 1.9 example 2), driven with the
    // stimulus of the golden trace tests/data/sim/vigor_start_first_latch.il: --set X1=1@1
    // --set X1=0@2 --set X2=1@4 --set X1=1@5 --set X2=0@6 --set X1=0@7 (once n scans have run),
    // 8 scans. One CSV, one meaning: the chart's rows are the trace's, less those where nothing
    // changed.
    test::MonitorFixture f;
    model::ProjectError error;
    const auto project = model::loadProject(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/start-first-latch.rung"), &error);
    ASSERT_TRUE(project.has_value()) << error.message.toStdString();
    f.document.setProject(*project, QString());
    f.startSession();
    editor::TimingChart chart(&f.document);
    chart.resize(900, 200);
    chart.setMonitorSource(f.session.get());
    ASSERT_TRUE(
        chart.addDevices({QStringLiteral("X1"), QStringLiteral("X2"), QStringLiteral("Y1")}));
    const std::vector<std::tuple<quint64, const char *, bool>> stimuli{
        {1, "X1", true}, {2, "X1", false}, {4, "X2", true},
        {5, "X1", true}, {6, "X2", false}, {7, "X1", false}};
    for (quint64 scan = 0; scan < 8; ++scan) {
        for (const auto &[at, device, on] : stimuli)
            if (at == scan)
                f.session->writeBit(f.at(device), on);
        f.scan();
    }
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("latch.csv"));
    QString why;
    ASSERT_TRUE(chart.exportTo(path, QStringLiteral("csv"), &why)) << why.toStdString();
    const QStringList trace =
        readAll(QStringLiteral(RUNG_TEST_DATA_DIR "/sim/vigor_start_first_latch.csv"))
            .split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_EQ(trace.size(), 9); // the header and 8 scans
    QString changes = trace[0] + QLatin1Char('\n');
    for (qsizetype k = 1; k < trace.size(); ++k)
        if (k == 1 ||
            trace[k].section(QLatin1Char(','), 2) != trace[k - 1].section(QLatin1Char(','), 2))
            changes += trace[k] + QLatin1Char('\n');
    EXPECT_EQ(readAll(path), changes);
    EXPECT_EQ(changes.count(QLatin1Char('\n')), 8); // scan 4 changed nothing
}

TEST(TimingChart, ATriggerStopsTheSimulationAtTheScanWhereItBecameTrue) {
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"),
            "LD M9000\nADD D10 K1 D10\nEND\n");
    editor::TimingChart chart(&f.document);
    chart.resize(900, 200);
    chart.setMonitorSource(f.session.get());
    ASSERT_TRUE(chart.addDevices({QStringLiteral("D10")}));
    QSignalSpy cursor(&chart, &editor::TimingChart::cursorMoved);
    ASSERT_TRUE(chart.armTrigger(QStringLiteral("D10 > 100"), model::Trigger::Action::Stop));
    f.session->setSpeed(0); // as fast as the engine goes
    f.session->run();
    ASSERT_TRUE(test::eventually([&] { return cursor.count() == 1; }));
    EXPECT_EQ(f.session->runState(), model::MonitorSource::RunState::Paused);
    EXPECT_EQ(f.scans(), 101u);
    EXPECT_EQ(f.session->snapshot()->value(f.at("D10")), 101);
    // Cursor A on that scan, and the chart says what happened.
    EXPECT_EQ(cursor.at(0).at(0).toInt(), 0);
    EXPECT_EQ(cursor.at(0).at(1).toULongLong(), 101u);
    EXPECT_EQ(cursor.at(0).at(2).toLongLong(), 1010);
    EXPECT_EQ(chart.canvas()->cursorTime(0), 1010);
    const QString readout = chart.findChild<QLabel *>(QStringLiteral("timingReadout"))->text();
    EXPECT_TRUE(readout.contains(QStringLiteral("D10 > 100 at 1.010 s (scan 101)")))
        << readout.toStdString();
    // A trigger that is no condition is refused with the reason.
    QSignalSpy messages(&chart, &editor::TimingChart::message);
    EXPECT_FALSE(chart.armTrigger(QStringLiteral("D10 soars"), model::Trigger::Action::Mark));
    ASSERT_EQ(messages.size(), 1);
    EXPECT_TRUE(messages[0][0].toString().startsWith(QStringLiteral("Trigger not armed: ")));
}

TEST(TimingChart, AMarkingTriggerFindsMomentsAlreadyRecorded) {
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"), "LD X0\nOUT Y0\nEND\n");
    editor::TimingChart chart(&f.document);
    chart.setMonitorSource(f.session.get());
    ASSERT_TRUE(chart.addDevices({QStringLiteral("Y0")}));
    for (const bool on : {false, true, false, true}) {
        f.session->writeBit(f.at("X0"), on);
        f.scan();
    }
    ASSERT_TRUE(chart.armTrigger(QStringLiteral("Y0 rises"), model::Trigger::Action::Mark));
    // Found in the history: Y0 rose after scans 2 and 4. Nothing stopped.
    EXPECT_EQ(f.session->runState(), model::MonitorSource::RunState::Paused);
    QTemporaryDir dir;
    QString why;
    ASSERT_TRUE(chart.exportTo(dir.filePath(QStringLiteral("y.csv")), QStringLiteral("csv"), &why));
    EXPECT_EQ(readAll(dir.filePath(QStringLiteral("y.csv"))),
              QStringLiteral("scan,time_ms,Y0\n1,10,0\n2,20,1\n3,30,0\n4,40,1\n"));
}

TEST(TimingChart, CursorsSnapToScansAndSayTheTimeBetweenThem) {
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"), "LD X0\nOUT Y0\nEND\n");
    editor::TimingChart chart(&f.document);
    chart.setMonitorSource(f.session.get());
    f.session->runScans(60);
    ASSERT_TRUE(test::eventually([&] { return f.scans() == 60; }));
    f.settle();
    QSignalSpy cursor(&chart, &editor::TimingChart::cursorMoved);
    chart.placeCursor(0, 123);
    chart.placeCursor(1, 457);
    EXPECT_EQ(chart.canvas()->cursorTime(0), 120);
    EXPECT_EQ(chart.canvas()->cursorTime(1), 460);
    ASSERT_EQ(cursor.count(), 2);
    EXPECT_EQ(cursor.at(0).at(1).toULongLong(), 12u); // the scan that ends at 120 ms
    EXPECT_EQ(cursor.at(1).at(1).toULongLong(), 46u);
    const QString readout = chart.findChild<QLabel *>(QStringLiteral("timingReadout"))->text();
    EXPECT_TRUE(readout.contains(QStringLiteral("B − A: 0.340 s (34 scan")))
        << readout.toStdString();
}

TEST(TimingChart, DevicesComeTypedAsRangesAndDropped) {
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"), "LD X0\nOUT Y0\nEND\n");
    editor::TimingChart chart(&f.document);
    chart.setMonitorSource(f.session.get());
    ASSERT_TRUE(chart.addDevices({QStringLiteral("X0..X3"), QStringLiteral("D0")}));
    ASSERT_EQ(chart.channels().size(), 5u);
    EXPECT_TRUE(chart.channels()[0].bit);
    EXPECT_FALSE(chart.channels()[4].bit);
    std::unique_ptr<QMimeData> data(
        editor::deviceMimeData({QStringLiteral("Y0"), QStringLiteral("X0")}));
    QDropEvent drop(QPointF(50, 50), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
    // As the window system delivers it (QApplication hands a drop only to a drag under way).
    static_cast<QObject *>(chart.canvas())->event(&drop);
    EXPECT_TRUE(drop.isAccepted());
    ASSERT_EQ(chart.channels().size(), 6u); // X0 was there
    EXPECT_EQ(chart.channels().back().device, QStringLiteral("Y0"));
    chart.removeChannel(0);
    EXPECT_EQ(chart.channels().front().device, QStringLiteral("X1"));
    QSignalSpy messages(&chart, &editor::TimingChart::message);
    EXPECT_FALSE(chart.addDevices({QStringLiteral("X9")}));
    ASSERT_EQ(messages.size(), 1);
}

TEST(TimingChart, PngAndSvgExportsAreFilesThatReadBack) {
    test::MonitorFixture f;
    f.start(model::Target::get(model::Family::Vigor), QStringLiteral("VB"),
            "LD M9000\nADD D0 K1 D0\nLD M9012\nOUT Y0\nEND\n");
    editor::TimingChart chart(&f.document);
    chart.resize(900, 200);
    chart.setMonitorSource(f.session.get());
    ASSERT_TRUE(chart.addDevices({QStringLiteral("Y0"), QStringLiteral("D0")}));
    f.session->runScans(30);
    ASSERT_TRUE(test::eventually([&] { return f.scans() == 30; }));
    f.settle();
    QTemporaryDir dir;
    QString why;
    const QString png = dir.filePath(QStringLiteral("chart.png"));
    const QString svg = dir.filePath(QStringLiteral("chart.svg"));
    ASSERT_TRUE(chart.exportTo(png, QStringLiteral("png"), &why)) << why.toStdString();
    ASSERT_TRUE(chart.exportTo(svg, QStringLiteral("svg"), &why)) << why.toStdString();
    QImage image(png);
    ASSERT_FALSE(image.isNull());
    EXPECT_GE(image.width(), 900);
    EXPECT_GE(image.height(), chart.canvas()->contentHeight());
    QSvgRenderer renderer(svg);
    EXPECT_TRUE(renderer.isValid());
    EXPECT_TRUE(readAll(svg).contains(QStringLiteral("D0")));
    EXPECT_FALSE(
        chart.exportTo(dir.filePath(QStringLiteral("missing/x.png")), QStringLiteral("png"), &why));
    EXPECT_FALSE(why.isEmpty());
}
