// The live overlay in the window (issue 11): the ladder and the instruction list fed by the
// real simulator session, the context menu that forces, releases and writes, the values
// under timers and boxes, the stale look of a source gone offline, repainting only the rungs
// that changed, the origin's label, and the menus in another language.

#include "app/gui/language.h"
#include "app/gui/simulation_controller.h"
#include "editor/il_editor.h"
#include "editor/ladder_painter.h"
#include "editor/watch_list_view.h"
#include "simulator/session.h"

#include "model/target/address.h"

#include <QApplication>
#include <QDockWidget>
#include <QHelpEvent>
#include <QInputDialog>
#include <QMenu>
#include <QPaintEvent>
#include <QSignalSpy>
#include <QTimer>
#include <QToolTip>

#include "tests/editor/fake_monitor_source.h"
#include "tests/editor/window_fixture.h"
#include "tests/eventually.h"

#include <gtest/gtest.h>

#include <functional>

using namespace rung;
using State = model::MonitorSource::RunState;

namespace {

struct Overlay : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        window.setSideBySide(false); // the ladder as wide as the window: its coils on screen
        // A window's first simulation opens its docks (Simulation, Inputs and Outputs) beside
        // the ladder: taken here and closed again, so the ladder keeps the width these tests
        // measure on.
        load("LD X0\nOUT Y0\nEND\n");
        if (sim()->run())
            sim()->stop();
        load("LD X1\nOUT Y1\nEND\n"); // stopped, an edit drops the session
        for (QDockWidget *dock : window.findChildren<QDockWidget *>())
            if (dock->objectName() != QLatin1String("problemsDock") &&
                dock->objectName() != QLatin1String("projectDock"))
                dock->close();
        QApplication::processEvents();
    }
    void TearDown() override {
        window.setSideBySide(false); // the next test's (QSettings), whatever this one did
        app::setLanguage(QStringLiteral("en"), false);
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    }
    app::SimulationController *sim() { return window.simulation(); }
    model::Address at(const char *device) {
        return std::get<model::Address>(
            model::parseAddress(window.document()->target(), QString::fromLatin1(device)));
    }
    // Runs the event loop until `done` holds.
    bool until(const std::function<bool()> &done) { return test::eventually(done); }
    // The newest snapshot once it satisfies `ready`; null after 5 s.
    std::shared_ptr<const model::Snapshot>
    waitFor(const std::function<bool(const model::Snapshot &)> &ready) {
        std::shared_ptr<const model::Snapshot> found;
        until([&] {
            if (sim()->session())
                if (auto s = sim()->session()->snapshot(); s && ready(*s))
                    found = s;
            return found != nullptr;
        });
        return found;
    }
    const model::RungOverlay::Output *coil(const model::RungOverlay &o, int row = 0) {
        return o.output(row);
    }
    // A menu entry by its text without the '&'.
    static QAction *entry(QMenu *menu, const QString &text) {
        for (QAction *a : menu->actions())
            if (QString(a->text()).remove(QLatin1Char('&')) == text)
                return a;
        return nullptr;
    }
    // Where a coil's centre is drawn in the viewport.
    QPoint coilCentre(int rung, int row = 0) {
        const QRect r = view->cellRectOnScreen({rung, row, view->metrics().gridColumns});
        return QPoint(static_cast<int>(r.left() + r.width() * 0.4),
                      static_cast<int>(r.top() + view->metrics().rowHeight * 0.55));
    }
    QColor pixel(QPoint at) { return view->viewport()->grab().toImage().pixelColor(at); }
    // Answers the next value dialog with `text`.
    void answerValueDialog(const QString &text) {
        QTimer::singleShot(0, [text] {
            auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget());
            ASSERT_NE(dialog, nullptr);
            EXPECT_EQ(dialog->objectName(), QStringLiteral("monitorValueDialog"));
            dialog->setTextValue(text);
            dialog->accept();
        });
    }
};

TEST_F(Overlay, ToggleAnInputAndTheCoilIsEnergisedAfterOneScan) {
    load("LD X0\nOUT Y0\nEND\n");
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(sim()->singleScan());
    EXPECT_EQ(view->monitorSource(), sim()->session());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    ASSERT_TRUE(until([&] { return view->overlay(0).rows == 1; }));
    EXPECT_FALSE(coil(view->overlay(0))->on);
    EXPECT_FALSE(coil(view->overlay(0))->powered);
    EXPECT_NE(pixel(coilCentre(0)), editor::LadderPainter::energisedColor());

    sim()->session()->writeBit(at("X0"), true); // the input toggled
    ASSERT_TRUE(sim()->singleScan());           // one scan
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 2; }), nullptr);
    const model::RungOverlay o = view->overlay(0);
    EXPECT_TRUE(o.conducts(0, 0));
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_TRUE(coil(o)->powered);
    EXPECT_TRUE(coil(o)->on);
    // On screen: the coil is filled.
    ASSERT_TRUE(until([&] {
        return pixel(coilCentre(0)) == editor::LadderPainter::energisedColor();
    })) << pixel(coilCentre(0)).name().toStdString();
}

// A tooltip left open over a coil follows the scans: its value is the one on screen now,
// not the one of the moment it opened.
TEST_F(Overlay, AnOpenTooltipFollowsTheValues) {
    load("LD X0\nOUT Y0\nEND\n");
    window.resize(1200, 700);
    window.show();
    // Running before the tooltip opens: no state change of the simulation (which moves the
    // focus and closes tooltips) comes while it is up.
    ASSERT_TRUE(sim()->run());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans > 2; }), nullptr);
    ASSERT_TRUE(until([&] { return view->overlay(0).rows == 1; }));
    const QPoint centre = coilCentre(0);
    QHelpEvent hover(QEvent::ToolTip, centre, view->viewport()->mapToGlobal(centre));
    QApplication::sendEvent(view->viewport(), &hover);
    ASSERT_TRUE(QToolTip::isVisible());
    const QString before = QToolTip::text();
    ASSERT_TRUE(before.contains(QStringLiteral("OFF"))) << before.toStdString();
    sim()->session()->writeBit(at("X0"), true);
    EXPECT_TRUE(until([] {
        return QToolTip::text().contains(QStringLiteral("ON")) &&
               !QToolTip::text().contains(QStringLiteral("OFF"));
    })) << QToolTip::text().toStdString();
    QToolTip::hideText();
    sim()->stop();
}

TEST_F(Overlay, ForceAndReleaseFromTheContextMenu) {
    load("LD X0\nOUT Y0\nEND\n");
    window.show();
    // Without a source the entries are there, disabled.
    std::unique_ptr<QMenu> idle(view->monitorMenu({0, 0, 0}, nullptr));
    ASSERT_NE(idle, nullptr);
    ASSERT_NE(entry(idle.get(), QStringLiteral("Force X0 ON")), nullptr);
    EXPECT_FALSE(entry(idle.get(), QStringLiteral("Force X0 ON"))->isEnabled());

    ASSERT_TRUE(sim()->run());
    std::unique_ptr<QMenu> menu(view->monitorMenu({0, 0, 0}, nullptr));
    ASSERT_NE(menu, nullptr);
    QAction *force = entry(menu.get(), QStringLiteral("Force X0 ON"));
    ASSERT_NE(force, nullptr);
    EXPECT_TRUE(force->isEnabled());
    force->trigger();
    ASSERT_NE(
        waitFor([this](const model::Snapshot &s) { return s.forced(at("X0")) && s.bit(at("Y0")); }),
        nullptr);
    ASSERT_TRUE(until([&] { return view->overlay(0).isForced(0, 0); }));
    EXPECT_TRUE(view->overlay(0).conducts(0, 0));
    EXPECT_TRUE(until([&] {
        return window.statusBar()->currentMessage() == QStringLiteral("X0 forced ON");
    })) << window.statusBar()->currentMessage().toStdString();

    // The coil's menu: Y0.
    std::unique_ptr<QMenu> coilMenu(
        view->monitorMenu({0, 0, view->metrics().gridColumns}, nullptr));
    ASSERT_NE(coilMenu, nullptr);
    EXPECT_NE(entry(coilMenu.get(), QStringLiteral("Force Y0 OFF")), nullptr);

    entry(menu.get(), QStringLiteral("Release X0"))->trigger();
    ASSERT_NE(waitFor([this](const model::Snapshot &s) { return !s.forced(at("X0")); }), nullptr);
    ASSERT_TRUE(until([&] { return !view->overlay(0).isForced(0, 0); }));
    EXPECT_TRUE(until(
        [&] { return window.statusBar()->currentMessage() == QStringLiteral("X0 released"); }));
}

TEST_F(Overlay, TheMenuKeysOpenTheMenuAtTheCursor) {
    load("LD X0\nOUT Y0\nEND\n");
    showActive();
    view->setFocus();
    ASSERT_TRUE(sim()->run());
    view->setCursor({0, 0, 0});
    QTest::keyClick(view, Qt::Key_F10, Qt::ShiftModifier);
    auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
    ASSERT_NE(menu, nullptr);
    EXPECT_EQ(menu->objectName(), QStringLiteral("monitorMenu"));
    EXPECT_NE(entry(menu, QStringLiteral("Force X0 OFF")), nullptr);
    menu->close();
    EXPECT_EQ(sim()->runState(), State::Running) << "Shift+F10 is not F10 (Run)";
    // No action of the window takes Shift+F10.
    for (QAction *a : window.findChildren<QAction *>())
        for (const QKeySequence &key : a->shortcuts())
            EXPECT_NE(key, QKeySequence(Qt::SHIFT | Qt::Key_F10)) << a->text().toStdString();
}

TEST_F(Overlay, WriteAWordFromTheBoxsMenu) {
    load("LD X0\nMOV D0 D1\nEND\n");
    window.show();
    ASSERT_TRUE(sim()->run());
    const editor::CellCursor box{0, 0, view->metrics().gridColumns};
    std::unique_ptr<QMenu> menu(view->monitorMenu(box, nullptr));
    ASSERT_NE(menu, nullptr);
    QAction *write = entry(menu.get(), QStringLiteral("Write D0..."));
    ASSERT_NE(write, nullptr);
    EXPECT_NE(entry(menu.get(), QStringLiteral("Write D1...")), nullptr);
    answerValueDialog(QStringLiteral("1234"));
    write->trigger();
    ASSERT_NE(waitFor([this](const model::Snapshot &s) { return s.value(at("D0")) == 1234; }),
              nullptr);
    ASSERT_TRUE(until([&] {
        return coil(view->overlay(0))->value.contains(QStringLiteral("D0 = 1234"));
    })) << coil(view->overlay(0))->value.toStdString();
    EXPECT_TRUE(until([&] {
        return window.statusBar()->currentMessage() == QStringLiteral("D0 written: 1234");
    })) << window.statusBar()->currentMessage().toStdString();

    // Hexadecimal, then what is no number: said, nothing written.
    answerValueDialog(QStringLiteral("0x10"));
    write->trigger();
    ASSERT_NE(waitFor([this](const model::Snapshot &s) { return s.value(at("D0")) == 16; }),
              nullptr);
    answerValueDialog(QStringLiteral("twelve"));
    write->trigger();
    EXPECT_TRUE(window.statusBar()->currentMessage().startsWith(
        QStringLiteral("\"twelve\" is no value for D0")))
        << window.statusBar()->currentMessage().toStdString();
}

TEST_F(Overlay, ATimersValueStandsInItsBoxAndItsPresetIsWritten) {
    load("LD X0\nTMR T0 D10\nEND\n");
    window.resize(1200, 700);
    window.show();
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    const editor::CellCursor box{0, 0, view->metrics().gridColumns};
    std::unique_ptr<QMenu> menu(view->monitorMenu(box, nullptr));
    ASSERT_NE(menu, nullptr);
    QAction *preset = entry(menu.get(), QStringLiteral("Write Preset of T0..."));
    ASSERT_NE(preset, nullptr);
    ASSERT_TRUE(preset->isEnabled());
    answerValueDialog(QStringLiteral("50"));
    preset->trigger();
    ASSERT_NE(waitFor([this](const model::Snapshot &s) { return s.value(at("D10")) == 50; }),
              nullptr);
    EXPECT_TRUE(until([&] {
        return window.statusBar()->currentMessage() ==
               QStringLiteral("Preset of T0 written: 50 (in D10)");
    })) << window.statusBar()->currentMessage().toStdString();

    const QImage before = view->viewport()->grab().toImage();
    sim()->session()->writeBit(at("X0"), true);
    sim()->session()->runScans(31); // 300 ms of timing after the first scan that sees X0
    ASSERT_NE(waitFor([this](const model::Snapshot &s) { return s.value(at("T0")) == 3; }),
              nullptr);
    ASSERT_TRUE(until([&] {
        return coil(view->overlay(0))->value == QStringLiteral("3/50 ×0.1 s");
    })) << coil(view->overlay(0))->value.toStdString();
    // Drawn: the box's lower half (where the value stands) changed.
    const QRect r = view->cellRectOnScreen(box);
    const QRect lower(r.left(), r.top() + r.height() / 2, r.width(), r.height() / 2);
    ASSERT_TRUE(until(
        [&] { return view->viewport()->grab().toImage().copy(lower) != before.copy(lower); }));
}

TEST_F(Overlay, AConstantPresetIsNoWriteButSaysWhy) {
    load("LD X0\nTMR T0 K50\nEND\n");
    window.show();
    ASSERT_TRUE(sim()->run());
    std::unique_ptr<QMenu> menu(view->monitorMenu({0, 0, view->metrics().gridColumns}, nullptr));
    ASSERT_NE(menu, nullptr);
    QAction *preset = entry(menu.get(), QStringLiteral("Write Preset of T0..."));
    ASSERT_NE(preset, nullptr);
    EXPECT_FALSE(preset->isEnabled());
    EXPECT_EQ(preset->toolTip(), QStringLiteral("The preset of T0 is the constant K50 of the "
                                                "program: change it in the program"));
    EXPECT_NE(entry(menu.get(), QStringLiteral("Force T0 ON")), nullptr) << "its done bit";
}

TEST_F(Overlay, TheInstructionListShowsEachLinesResultAndValues) {
    load("LD X0\nAND X1\nOUT Y0\nLD X0\nTMR T0 K50\nLD T0\nOUT Y1\nEND\n");
    window.setSideBySide(true);
    window.resize(1300, 700);
    window.show();
    editor::IlEditor *il = window.ilEditor();
    ASSERT_EQ(il->text(), listing());
    EXPECT_FALSE(il->monitoredLine(0).has_value());
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    sim()->session()->writeBit(at("X0"), true);
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 2; }), nullptr);
    const int ld = window.document()->printedListing().instructionLine[0] - 1;
    const int and_ = window.document()->printedListing().instructionLine[1] - 1;
    ASSERT_TRUE(il->monitoredLine(ld).has_value());
    EXPECT_EQ(il->monitoredLine(ld)->result, std::optional<bool>(true));
    EXPECT_EQ(il->monitoredLine(ld)->text, QStringLiteral("X0 = ON"));
    EXPECT_EQ(il->monitoredLine(and_)->result, std::optional<bool>(false));
    EXPECT_EQ(il->monitoredLine(and_)->text, QStringLiteral("X1 = OFF"));
    const auto &lines = window.document()->printedListing().instructionLine;
    ASSERT_GE(lines.size(), 6u);
    EXPECT_EQ(il->monitoredLine(lines[4] - 1)->text, QStringLiteral("T0 0/50 ×0.1 s"));
    EXPECT_EQ(il->monitoredLine(lines[5] - 1)->text, QStringLiteral("T0 = OFF")) << "its done bit";
    const QString text = il->text();
    // Drawn beside the line, in the overlay's blue (the filled square of LD X0's result).
    const QImage image = il->viewport()->grab().toImage();
    const long pos =
        il->SendScintilla(QsciScintillaBase::SCI_POSITIONFROMLINE, static_cast<unsigned long>(ld));
    const int y =
        static_cast<int>(il->SendScintilla(QsciScintillaBase::SCI_POINTYFROMPOSITION, 0UL, pos));
    const int h = static_cast<int>(il->SendScintilla(QsciScintillaBase::SCI_TEXTHEIGHT, 0UL));
    bool blue = false;
    for (int x = 0; x < image.width() && !blue; ++x)
        for (int dy = 0; dy < h && !blue; ++dy)
            blue = image.pixelColor(x, y + dy) == editor::LadderPainter::energisedColor();
    EXPECT_TRUE(blue) << "no result mark on the line of LD X0";
    EXPECT_EQ(il->text(), text) << "the text is untouched";
    EXPECT_FALSE(il->isUndoAvailable()) << "and so is its undo";

    // The line's menu forces its device.
    std::unique_ptr<QMenu> menu(il->monitorMenu(and_, nullptr));
    ASSERT_NE(menu, nullptr);
    entry(menu.get(), QStringLiteral("Force X1 ON"))->trigger();
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(
        waitFor([this](const model::Snapshot &s) { return s.forced(at("X1")) && s.bit(at("Y0")); }),
        nullptr);
    EXPECT_TRUE(il->monitoredLine(and_)->forced);
    EXPECT_EQ(il->monitoredLine(and_)->result, std::optional<bool>(true));
}

TEST_F(Overlay, AListTypedItsOwnWayShowsValuesOnItsOwnLines) {
    load("LD X0\nOUT Y0\nEND\n");
    window.show();
    editor::IlEditor *il = window.ilEditor();
    // The same program with a comment line and other spacing: lines of its own.
    il->setText(QStringLiteral("; start\nLD   X0\nOUT  Y0\nEND\n"));
    window.applyListing();
    ASSERT_NE(il->text(), listing());
    ASSERT_TRUE(sim()->singleScan());
    ASSERT_NE(waitFor([](const model::Snapshot &s) { return s.statistics.scans == 1; }), nullptr);
    ASSERT_TRUE(il->monitoredLine(1).has_value());
    EXPECT_EQ(il->monitoredLine(1)->text, QStringLiteral("X0 = OFF"));
    EXPECT_FALSE(il->monitoredLine(0).has_value()) << "a comment line";
    // Typing moves the lines: no values until the list is applied again.
    il->insertAt(QStringLiteral("; more\n"), 0, 0);
    EXPECT_FALSE(il->monitoredLine(1).has_value());
}

// The overlay draws from any MonitorSource: a fake one here, gone offline (an online PLC that
// stopped answering): the last values stay, drawn stale.
TEST_F(Overlay, ASourceGoneOfflineIsDrawnStale) {
    load("LD X0\nOUT Y0\nEND\n");
    window.resize(1200, 700);
    window.show();
    test::FakeMonitorSource source;
    auto snapshot = source.blank(window.document()->target());
    const model::BitRef x0 = snapshot->layout->bit(at("X0"));
    const model::BitRef y0 = snapshot->layout->bit(at("Y0"));
    snapshot->words[static_cast<std::size_t>(x0.word)] |= static_cast<std::int32_t>(x0.mask);
    snapshot->words[static_cast<std::size_t>(y0.word)] |= static_cast<std::int32_t>(y0.mask);
    source.setState(State::Running);
    window.setMonitorSource(&source, app::MainWindow::MonitorOrigin::Online);
    source.publish(snapshot);
    ASSERT_TRUE(until([&] { return view->overlay(0).rows == 1 && coil(view->overlay(0))->on; }));
    EXPECT_FALSE(view->overlay(0).stale);
    EXPECT_TRUE(view->overlay(0).output(0)->powered) << "no power flow: the devices decide";
    ASSERT_TRUE(
        until([&] { return pixel(coilCentre(0)) == editor::LadderPainter::energisedColor(); }));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral("Online PLC")));

    source.setState(State::Offline);
    EXPECT_TRUE(view->overlay(0).stale);
    EXPECT_TRUE(coil(view->overlay(0))->on) << "the last value known stays";
    ASSERT_TRUE(
        until([&] { return pixel(coilCentre(0)) != editor::LadderPainter::energisedColor(); }));
    window.setMonitorSource(nullptr);
    EXPECT_EQ(view->overlay(0).rows, 0);
}

// A snapshot repaints the rungs whose overlay changed, and only them.
TEST_F(Overlay, ASnapshotRepaintsOnlyTheRungsThatChanged) {
    load("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n");
    window.resize(1200, 700);
    window.show();
    test::FakeMonitorSource source;
    source.setState(State::Running);
    auto snapshot = source.blank(window.document()->target());
    window.setMonitorSource(&source);
    source.publish(snapshot);
    ASSERT_TRUE(until([&] { return view->overlay(0).rows == 1; }));

    struct PaintSpy : QObject {
        QRegion painted;
        int paints = 0;
        bool eventFilter(QObject *, QEvent *event) override {
            if (event->type() == QEvent::Paint) {
                painted += static_cast<QPaintEvent *>(event)->region();
                ++paints;
            }
            return false;
        }
    } spy;
    view->viewport()->installEventFilter(&spy);
    // The window settles first (the origin's label shown, the layout that follows, the first
    // snapshot's frame; late on a loaded machine): 100 ms without a paint, within 3 s. A poll
    // for quiet: nothing tells that the window will not lay itself out once more.
    bool settled = false;
    for (int i = 0; i < 30 && !settled; ++i) {
        const int before = spy.paints;
        QTest::qWait(100);
        settled = spy.paints == before;
    }
    ASSERT_TRUE(settled) << "the view kept repainting";
    // A snapshot is shown when snapshotChanged reaches the view (it repaints the rungs that
    // changed then), and painted when the events it posted are delivered.
    QSignalSpy arrived(&source, &model::MonitorSource::snapshotChanged);
    const auto deliver = [&](std::shared_ptr<const model::Snapshot> s) {
        arrived.clear();
        source.publish(std::move(s));
        const bool reached = until([&] { return !arrived.isEmpty(); });
        QCoreApplication::processEvents();
        return reached;
    };
    spy.painted = QRegion();
    auto next = std::make_shared<model::Snapshot>(*snapshot);
    const model::BitRef x1 = next->layout->bit(at("X1"));
    next->words[static_cast<std::size_t>(x1.word)] |= static_cast<std::int32_t>(x1.mask);
    ASSERT_TRUE(deliver(next));
    ASSERT_TRUE(until([&] { return !spy.painted.isEmpty(); }));
    const QRect second = view->cellRectOnScreen({1, 0, 0});
    const QRect first = view->cellRectOnScreen({0, 0, 0});
    const QRect third = view->cellRectOnScreen({2, 0, 0});
    EXPECT_TRUE(spy.painted.intersects(second));
    EXPECT_FALSE(spy.painted.intersects(first)) << "rung 1 did not change";
    EXPECT_FALSE(spy.painted.intersects(third)) << "rung 3 did not change";

    // The same values again: nothing repainted.
    spy.painted = QRegion();
    ASSERT_TRUE(deliver(std::make_shared<model::Snapshot>(*next)));
    EXPECT_TRUE(spy.painted.isEmpty());
    view->viewport()->removeEventFilter(&spy);
    window.setMonitorSource(nullptr);
}

TEST_F(Overlay, TheWindowSaysWhichOriginItShows) {
    load("LD X0\nOUT Y0\nEND\n");
    window.show();
    auto *label = window.findChild<QLabel *>(QStringLiteral("monitorOrigin"));
    EXPECT_TRUE(label == nullptr || !label->isVisible());
    EXPECT_FALSE(window.windowTitle().contains(QStringLiteral("Simulation")));
    ASSERT_TRUE(sim()->run());
    EXPECT_EQ(window.monitorSource(), sim()->session());
    EXPECT_EQ(window.ilEditor()->monitorSource(), sim()->session());
    EXPECT_EQ(window.watchListView()->monitorSource(), sim()->session());
    label = window.findChild<QLabel *>(QStringLiteral("monitorOrigin"));
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->isVisible());
    EXPECT_EQ(label->text(), QStringLiteral("Simulation"));
    EXPECT_TRUE(window.windowTitle().contains(QStringLiteral(" — Simulation — ")))
        << window.windowTitle().toStdString();
    // Stopped, an edit drops the session: no values, no label (while it runs, an edit is an
    // online edit and the session goes on: test_simulation_debug.cpp).
    sim()->stop();
    load("LD X1\nOUT Y0\nEND\n");
    EXPECT_EQ(window.monitorSource(), nullptr);
    EXPECT_EQ(view->monitorSource(), nullptr);
    EXPECT_FALSE(label->isVisible());
    EXPECT_FALSE(window.windowTitle().contains(QStringLiteral("Simulation")));
}

TEST_F(Overlay, ALanguageSwitchRetranslatesTheMenusAndTheLabel) {
    load("LD X0\nOUT Y0\nEND\n");
    window.show();
    ASSERT_TRUE(sim()->run());
    ASSERT_TRUE(app::setLanguage(QStringLiteral("hu"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
    const QString force =
        QCoreApplication::translate("rung::editor::MonitorCommands", "Force %1 O&N")
            .arg(QStringLiteral("X0"));
    EXPECT_NE(force, QStringLiteral("Force X0 O&N")) << "no Hungarian text";
    std::unique_ptr<QMenu> menu(view->monitorMenu({0, 0, 0}, nullptr));
    ASSERT_NE(menu, nullptr);
    EXPECT_EQ(menu->actions().front()->text(), force);
    auto *label = window.findChild<QLabel *>(QStringLiteral("monitorOrigin"));
    ASSERT_NE(label, nullptr);
    EXPECT_EQ(label->text(), QCoreApplication::translate("rung::app::MainWindow", "Simulation"));
    EXPECT_NE(label->text(), QStringLiteral("Simulation"));
    ASSERT_TRUE(app::setLanguage(QStringLiteral("it"), false));
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
    std::unique_ptr<QMenu> italian(window.ilEditor()->monitorMenu(0, nullptr));
    ASSERT_NE(italian, nullptr);
    EXPECT_EQ(italian->actions().front()->text(),
              QCoreApplication::translate("rung::editor::MonitorCommands", "Force %1 O&N")
                  .arg(QStringLiteral("X0")));
}

} // namespace
