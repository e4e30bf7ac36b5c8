// The IDE's parts of issue 32: File > Compare With... (two ladders side by side, the lists,
// the report; next / previous change), File > Import / Export PLCopen XML, the Tests dock.

#include "app/gui/compare_window.h"
#include "app/gui/eliding_label.h"
#include "app/gui/main_window.h"
#include "app/gui/plcopen_exchange.h"
#include "app/gui/tests_panel.h"
#include "editor/compare_view.h"
#include "model/convert/convert.h"
#include "simulator/compiler.h"
#include "simulator/scenario_trace.h"

#include "tests/editor/window_fixture.h"
#include "tests/targets.h"
#include "tests/test_files.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTreeWidget>

#include <gtest/gtest.h>

using namespace rung;

namespace {

model::Project listedProject(const QString &text) {
    const model::Target &t = rung::testing::vigor();
    model::Project p;
    p.target = &t;
    p.model = t.defaultModel().name;
    p.program = model::listToLadder(model::parseInstructionList(t, text).list).ladder;
    return p;
}

QString rungsText(int n, int changed = -1) {
    QString text;
    for (int k = 0; k < n; ++k)
        text += QStringLiteral("LD X%1\n%2 M%3\nOUT Y%1\n")
                    .arg(k, 0, 8)
                    .arg(k == changed ? QStringLiteral("ANI") : QStringLiteral("AND"))
                    .arg(k);
    return text + QStringLiteral("END\n");
}

} // namespace

TEST(CompareWindow, ShowsBothLaddersTheListsAndTheReportAndStepsThroughTheChanges) {
    const model::Project a = listedProject(rungsText(8));
    model::Project b = listedProject(rungsText(8, 2));
    b.program.rungs.erase(b.program.rungs.begin() + 5);
    app::CompareWindow window(a, QStringLiteral("old.rung"), b, QStringLiteral("new"));
    editor::CompareView *view = window.ladder();
    EXPECT_EQ(view->changeCount(), 2); // rung 3 changed, rung 6 deleted
    // The first change is current from the start; Alt+Down goes on, Alt+Up back.
    EXPECT_EQ(view->current(), 2);
    window.show();
    window.activateWindow();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    QWidget *focus = QApplication::focusWidget() ? QApplication::focusWidget() : &window;
    QTest::keyClick(focus, Qt::Key_Down, Qt::AltModifier);
    EXPECT_EQ(view->current(), 5);
    EXPECT_EQ(view->comparison().rungs[5].status, model::RungStatus::Deleted);
    QTest::keyClick(focus, Qt::Key_Down, Qt::AltModifier);
    EXPECT_EQ(view->current(), 5); // no change after it
    QTest::keyClick(focus, Qt::Key_Up, Qt::AltModifier);
    EXPECT_EQ(view->current(), 2);
    // The list: a heading per rung, the changed instruction side by side with its sign.
    QTableWidget *list = window.listing();
    bool found = false;
    for (int r = 0; r < list->rowCount(); ++r)
        if (list->item(r, 1) && list->item(r, 1)->text() == QStringLiteral("AND M2")) {
            EXPECT_EQ(list->item(r, 2)->text(), QStringLiteral("ANI M2"));
            EXPECT_EQ(list->item(r, 0)->text(), QStringLiteral("~ changed"));
            found = true;
        }
    EXPECT_TRUE(found);
    // The list follows the current change.
    EXPECT_EQ(list->item(list->currentRow(), 1)->text(), QStringLiteral("rung 3"));
    EXPECT_TRUE(window.report()->toPlainText().contains(
        QStringLiteral("rung 3: changed\n    * contact changed: AND M2 -> ANI M2")));
}

// The marks read without colour: a sign and words for every status, a pattern for each band.
TEST(CompareWindow, EveryStatusHasASignWordsAndAPattern) {
    for (model::RungStatus s :
         {model::RungStatus::Moved, model::RungStatus::Changed, model::RungStatus::MovedChanged,
          model::RungStatus::Inserted, model::RungStatus::Deleted}) {
        EXPECT_FALSE(editor::CompareView::statusMark(s).isEmpty());
        EXPECT_FALSE(editor::CompareView::statusText(s).isEmpty());
        EXPECT_NE(editor::CompareView::statusPattern(s), Qt::NoBrush);
    }
    // Inserted and deleted differ in more than colour.
    EXPECT_NE(editor::CompareView::statusPattern(model::RungStatus::Inserted),
              editor::CompareView::statusPattern(model::RungStatus::Deleted));
    EXPECT_NE(editor::CompareView::statusMark(model::RungStatus::Inserted),
              editor::CompareView::statusMark(model::RungStatus::Deleted));
}

TEST(CompareWindow, AFileOfAnotherPlcOrThatDoesNotReadIsRefusedWithTheReason) {
    QString error;
    EXPECT_FALSE(
        app::loadForComparison(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/cpm1/keep.rung"),
                               rung::testing::vigor(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("only programs of one PLC are compared")))
        << error.toStdString();
    QTemporaryDir dir;
    const QString bad = test::writeFile(dir, QStringLiteral("bad.il"), "LD X8\nOUT Y0\nEND\n");
    EXPECT_FALSE(app::loadForComparison(bad, rung::testing::vigor(), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("line 1, column 5"))) << error.toStdString();
    const auto ok = app::loadForComparison(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/flasher.rung"),
        rung::testing::vigor(), &error);
    ASSERT_TRUE(ok);
}

TEST(CompareWindow, TheFileMenuHasCompareAndPlcopen) {
    app::MainWindow window;
    for (const char *entry : {"Compare With...", "Import PLCopen XML...", "Export PLCopen XML..."})
        EXPECT_NE(test::menuAction(window, QString::fromLatin1(entry)), nullptr) << entry;
}

// The import dialog: devices proposed for the variables no rule maps, what the target cannot
// take listed, nothing left out until the user says so.
TEST(PlcopenImportDialog, ProposesDevicesAndLeavesNothingOutUnasked) {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/pump.xml"));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    const QByteArray xml = f.readAll();
    app::PlcopenImportDialog dialog(xml, QStringLiteral("pump.xml"), rung::testing::vigor());
    QTableWidget *devices = dialog.devices();
    ASSERT_EQ(devices->rowCount(), 2);
    EXPECT_EQ(devices->item(0, 0)->text(), QStringLiteral("delay"));
    EXPECT_EQ(devices->item(0, 3)->text(), QStringLiteral("T0"));
    EXPECT_EQ(devices->item(1, 3)->text(), QStringLiteral("M0"));
    EXPECT_EQ(dialog.issues()->count(), 0);
    EXPECT_TRUE(dialog.canImport());
    // Another device typed for `latched`: it is the one imported.
    devices->item(1, 3)->setText(QStringLiteral("M100"));
    dialog.accept();
    EXPECT_EQ(dialog.result(), QDialog::Accepted);
    const QString listing = model::printInstructionList(
        model::ladderToList(dialog.project().program).list, {false, false});
    EXPECT_TRUE(listing.contains(QStringLiteral("LD T0\nSET M100\n"))) << listing.toStdString();

    // For the CPM1 the comparison has no contact: listed, and Import waits for the tick.
    app::PlcopenImportDialog omron(xml, QStringLiteral("pump.xml"), rung::testing::vigor());
    omron.targetBox()->setCurrentIndex(omron.targetBox()->findData(rung::testing::cpm1().id));
    ASSERT_GE(omron.issues()->count(), 1);
    EXPECT_TRUE(omron.issues()->item(0)->text().contains(QStringLiteral("block GT")));
    EXPECT_FALSE(omron.canImport());
    // A timer and a work bit of the CPM1 proposed (its work bits are bits of channels).
    EXPECT_EQ(omron.devices()->item(0, 3)->text(), QStringLiteral("TIM 000"));
    EXPECT_EQ(omron.devices()->item(1, 3)->text(), QStringLiteral("200.00"));
    omron.leaveOut()->setChecked(true);
    EXPECT_TRUE(omron.canImport());
}

// An IEC counter imported as the PLC's, which stops at its set value: the dialog says so.
TEST(PlcopenImportDialog, SaysWhatIsImportedButWorksOtherwise) {
    QFile f(QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/foreign/openplc-7-segments.xml"));
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    app::PlcopenImportDialog dialog(f.readAll(), QStringLiteral("plc.xml"), rung::testing::vigor());
    // The devices proposed are taken: the counter is imported as CNT C0.
    EXPECT_FALSE(dialog.notes()->isHidden());
    EXPECT_TRUE(dialog.notes()->text().contains(
        QStringLiteral("CTU (CTU0) is imported as Vigor's CNT: Vigor's CNT stops counting at its "
                       "set value")))
        << dialog.notes()->text().toStdString();
    app::PlcopenImportDialog pump(
        [] {
            QFile p(QStringLiteral(RUNG_TEST_DATA_DIR "/plcopen/pump.xml"));
            return p.open(QIODevice::ReadOnly) ? p.readAll() : QByteArray();
        }(),
        QStringLiteral("pump.xml"), rung::testing::vigor());
    EXPECT_TRUE(pump.notes()->isHidden());
}

namespace {

const QByteArray kLatchProject = R"({
    "format": "rungstudio-project", "schema": 1, "target": "vigor", "model": "VB",
    "rungs": [
        { "rows": 2, "columns": 2, "cells": [["X0", "/X1"], ["Y0", ""]],
          "links": [[0, 0], [0, 1]], "outputs": [[0, "OUT Y0"]] },
        { "rows": 1, "columns": 0, "cells": [[]], "links": [], "outputs": [[0, "END"]] }
    ]
})";

} // namespace

// The Tests dock finds the project's scenarios, runs them on a worker and shows each
// expectation; the program run is the one in the window, unsaved edits included.
TEST(TestsPanel, FindsRunsAndReportsTheProjectsScenarios) {
    QTemporaryDir dir;
    const QString project = test::writeFile(dir, QStringLiteral("latch.rung"), kLatchProject);
    test::writeFile(dir, QStringLiteral("ok.rungtest"),
                    "program latch.rung\nat 0s set X0=1\nat 100ms set X0=0\nat 1s expect Y0=1\n");
    test::writeFile(dir, QStringLiteral("bad.rungtest"), "program latch.rung\nat 1s expect Y0=1\n");
    test::writeFile(dir, QStringLiteral("other.rungtest"),
                    "program elsewhere.rung\nat 1s expect Y0=1\n");
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(project, QString(), true));
    auto *panel = window.findChild<app::TestsPanel *>();
    ASSERT_NE(panel, nullptr);
    ASSERT_EQ(panel->scenarios().size(), 2); // not the one of another program
    // Where the panel looks, said in words with the folder (whole in the tooltip).
    auto *folder = panel->findChild<app::ElidingLabel *>();
    ASSERT_NE(folder, nullptr);
    EXPECT_EQ(folder->fullText(),
              QStringLiteral("Scenario tests (.rungtest) that name this project, in %1 and below")
                  .arg(QDir::toNativeSeparators(dir.path())));
    QSignalSpy finished(panel, &app::TestsPanel::runFinished);
    panel->run();
    ASSERT_TRUE(finished.wait(20000));
    ASSERT_EQ(panel->results().size(), 2u);
    const auto byName = [panel](const char *name) {
        return *std::find_if(panel->results().begin(), panel->results().end(),
                             [name](const simulator::ScenarioResult &r) {
                                 return r.file.endsWith(QLatin1String(name));
                             });
    };
    EXPECT_TRUE(byName("ok.rungtest").passed());
    EXPECT_EQ(byName("bad.rungtest").failures.size(), 1u);
    QTreeWidget *tree = panel->tree();
    ASSERT_EQ(tree->topLevelItemCount(), 2);
    EXPECT_TRUE(tree->topLevelItem(0)->text(1).startsWith(QStringLiteral("FAILED")));
    EXPECT_TRUE(tree->topLevelItem(1)->text(1).startsWith(QStringLiteral("passed")));
    // A dock of the window, listed in the View menu as the other panels.
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("testsDock"));
    ASSERT_NE(dock, nullptr);
    EXPECT_EQ(dock->windowTitle(), QStringLiteral("Tests"));
}

// The chart of a failed expectation: the run again with its devices recorded, the failing
// instant in the history.
// A .rungtest opened (File > Open, the command line, a double-click in a file manager) opens
// the program it names, in the scenario's folder, with the scenario chosen in the Tests dock.
TEST(TestsPanel, OpeningAScenarioOpensItsProgramWithTheScenarioChosen) {
    QTemporaryDir dir;
    const QString project = test::writeFile(dir, QStringLiteral("latch.rung"), kLatchProject);
    test::writeFile(dir, QStringLiteral("a.rungtest"), "program latch.rung\nat 1s expect Y0=0\n");
    const QString scenario = test::writeFile(dir, QStringLiteral("b.rungtest"),
                                             "program latch.rung\nat 1s expect Y0=1\n");
    const QString orphan =
        test::writeFile(dir, QStringLiteral("orphan.rungtest"), "at 1s expect Y0=1\n");
    app::MainWindow window;
    window.show();
    ASSERT_TRUE(window.openFile(scenario, QString(), true));
    EXPECT_EQ(QFileInfo(window.document()->path()).canonicalFilePath(),
              QFileInfo(project).canonicalFilePath());
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("testsDock"));
    ASSERT_NE(dock, nullptr);
    EXPECT_TRUE(dock->isVisible());
    auto *panel = window.findChild<app::TestsPanel *>();
    ASSERT_NE(panel, nullptr);
    ASSERT_NE(panel->tree()->currentItem(), nullptr);
    EXPECT_EQ(panel->tree()->currentItem()->text(0), QStringLiteral("b.rungtest"));
    // One that names no program opens nothing and says why, with its name.
    EXPECT_FALSE(window.openFile(orphan, QString(), true));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("orphan.rungtest")))
        << window.statusBar()->currentMessage().toStdString();
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("program FILE")));
    EXPECT_EQ(QFileInfo(window.document()->path()).canonicalFilePath(),
              QFileInfo(project).canonicalFilePath());
}

TEST(TestsPanel, AFailedExpectationsRunIsRecordedForTheChart) {
    const model::ParseResult parsed =
        model::parseInstructionList(rung::testing::vigor(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    const auto program = simulator::compileProgram(parsed.list).program;
    std::vector<simulator::ScenarioError> errors;
    const simulator::Scenario s = simulator::parseScenario(
        QStringLiteral("program x.il\nat 500ms set X0=1\nat 1s expect Y0=0\n"), QStringLiteral("x"),
        &errors);
    const model::Address y0 =
        std::get<model::Address>(model::parseAddress(rung::testing::vigor(), u"Y0"));
    simulator::ScenarioTrace trace(s, program, {y0});
    ASSERT_EQ(trace.result().failures.size(), 1u);
    EXPECT_EQ(trace.result().failures[0].timeMs, 1000);
    std::optional<std::int32_t> before;
    std::optional<std::int32_t> after;
    trace.readHistory([&](const model::HistoryRecorder &h) {
        before = h.valueAtTime(y0, 400);
        after = h.valueAtTime(y0, 600);
    });
    EXPECT_EQ(before, 0);
    EXPECT_EQ(after, 1);
    EXPECT_EQ(trace.snapshot()->statistics.timeMs, 1010);
}
