// The watch table: each row's word in decimal, signed, hexadecimal, binary or BCD (exact
// texts, saved with the project, one undo step), a symbol column, a force column, devices
// added by typing, by ranges in the target's numbering, and dropped from the ladder and the
// cross reference.

#include "fake_monitor_source.h"
#include "monitor_fixture.h"
#include "watch_rows.h"

#include "editor/cross_reference_view.h"
#include "editor/device_mime.h"
#include "editor/watch_list_view.h"
#include "editor/watch_panel.h"

#include <QDrag>
#include <QDropEvent>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeView>
#include <QTreeWidget>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;
using Column = editor::WatchListView::Column;
using model::ValueFormat;

namespace {

// The view's viewport events, which QAbstractItemView keeps protected.
struct DropTarget : editor::WatchListView {
    using editor::WatchListView::viewportEvent;
    using editor::WatchListView::WatchListView;
};

struct WatchTable : ::testing::Test {
    const model::Target &target = model::Target::get(model::Family::Vigor);
    editor::Document document;
    std::unique_ptr<editor::WatchListView> view;
    test::FakeMonitorSource source;

    void SetUp() override {
        document.reset(target, QStringLiteral("VB"));
        document.setWatchLists(
            {{QStringLiteral("W"),
              {QStringLiteral("D0"), QStringLiteral("X0"), QStringLiteral("C200")},
              {}}},
            QStringLiteral("watch"));
        view = std::make_unique<DropTarget>(&document);
        view->setMonitorSource(&source);
    }
    QModelIndex row(int k) { return test::watchIndex(view.get(), 0, k); }
    QString shown(int k, int column) { return test::watchText(view.get(), 0, k, column); }
    model::Address at(const char *device) {
        return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
    }
    void publish(const std::function<void(model::Snapshot &)> &fill) {
        ASSERT_TRUE(source.publishFilled(target, fill));
    }
    void setWord(model::Snapshot &s, const char *device, std::int32_t value) {
        s.words[static_cast<std::size_t>(s.layout->word(at(device)))] = value;
    }
};

} // namespace

TEST_F(WatchTable, AWordIsShownInTheRowsFormat) {
    publish([&](model::Snapshot &s) {
        setWord(s, "D0", -5);
        setWord(s, "C200", -1); // a 32-bit counter
    });
    EXPECT_EQ(shown(0, Column::ValueColumn), QStringLiteral("65531"));
    EXPECT_EQ(shown(0, Column::FormatColumn), QStringLiteral("Decimal"));
    const std::pair<ValueFormat, const char *> expected[] = {
        {ValueFormat::Signed, "-5"},
        {ValueFormat::Hex, "0xFFFB"},
        {ValueFormat::Binary, "1111 1111 1111 1011"},
        {ValueFormat::Decimal, "65531"},
    };
    for (const auto &[format, text] : expected) {
        view->setFormat(row(0), format);
        EXPECT_EQ(shown(0, Column::ValueColumn), QString::fromLatin1(text));
        EXPECT_EQ(shown(0, Column::FormatColumn), model::valueFormatName(format));
    }
    view->setFormat(row(0), ValueFormat::Bcd);
    publish([&](model::Snapshot &s) { setWord(s, "D0", 0x1234); });
    EXPECT_EQ(shown(0, Column::ValueColumn), QStringLiteral("1234"));
    publish([&](model::Snapshot &s) { setWord(s, "D0", 0x12A4); });
    EXPECT_EQ(shown(0, Column::ValueColumn), QStringLiteral("0x12A4 (not BCD)"));
    // A bit has no format; a 32-bit word keeps its width.
    EXPECT_EQ(shown(1, Column::FormatColumn), QString());
    view->setFormat(row(2), ValueFormat::Hex);
    publish([&](model::Snapshot &s) { setWord(s, "C200", -1); });
    EXPECT_TRUE(shown(2, Column::ValueColumn).startsWith(QStringLiteral("0xFFFFFFFF of ")))
        << shown(2, Column::ValueColumn).toStdString();
    // Saved with the project, each change one undo step.
    EXPECT_EQ(document.project().watchLists[0].format(QStringLiteral("D0")), ValueFormat::Bcd);
    document.undoStack()->undo();
    EXPECT_EQ(document.project().watchLists[0].format(QStringLiteral("C200")),
              ValueFormat::Decimal);
    EXPECT_EQ(document.undoStack()->undoText(), QStringLiteral("Show D0 as BCD"));
}

TEST_F(WatchTable, AValueTypedInTheRowsFormatIsWritten) {
    view->setFormat(row(0), ValueFormat::Hex);
    EXPECT_TRUE(view->writeValue(row(0), QStringLiteral("1F")));
    EXPECT_EQ(source.commands.back().value, 0x1F);
    view->setFormat(row(0), ValueFormat::Bcd);
    EXPECT_TRUE(view->writeValue(row(0), QStringLiteral("150")));
    EXPECT_EQ(source.commands.back().value, 0x150);
    view->setFormat(row(0), ValueFormat::Binary);
    EXPECT_TRUE(view->writeValue(row(0), QStringLiteral("1010")));
    EXPECT_EQ(source.commands.back().value, 10);
    QSignalSpy messages(view.get(), &editor::WatchListView::message);
    EXPECT_FALSE(view->writeValue(row(0), QStringLiteral("102")));
    ASSERT_EQ(messages.size(), 1);
    EXPECT_EQ(messages[0][0].toString(),
              QStringLiteral("\"102\" is no value for D0: type up to 16 binary digits (0 and 1)"));
    view->setFormat(row(0), ValueFormat::Signed);
    EXPECT_FALSE(view->writeValue(row(0), QStringLiteral("70000")));
    EXPECT_EQ(messages.back()[0].toString(),
              QStringLiteral("\"70000\" is no value for D0: a 16-bit word holds -32768..65535"));
}

TEST_F(WatchTable, SymbolAndForceColumns) {
    document.setSymbols(
        {model::Symbol{at("X0"), QStringLiteral("Start"), QStringLiteral("green")}});
    EXPECT_EQ(shown(1, Column::SymbolColumn), QStringLiteral("Start"));
    EXPECT_EQ(shown(1, Column::ForceColumn), QString());
    publish([&](model::Snapshot &s) {
        const model::BitRef r = s.layout->bit(at("X0"));
        s.words[static_cast<std::size_t>(r.word)] |= static_cast<std::int32_t>(r.mask);
        s.forceMask[static_cast<std::size_t>(r.word)] |= r.mask;
    });
    EXPECT_EQ(shown(1, Column::ForceColumn), QStringLiteral("ON"));
    EXPECT_EQ(shown(1, Column::ValueColumn), QStringLiteral("ON (forced)"));
}

TEST_F(WatchTable, RangesAreAddedInTheTargetsNumberingAsOneStep) {
    const int steps = document.undoStack()->count();
    ASSERT_TRUE(view->addDevices({QStringLiteral("X0..X17")}));
    EXPECT_EQ(document.undoStack()->count(), steps + 1);
    EXPECT_EQ(document.undoStack()->undoText(), QStringLiteral("Add X1..X17 to the watch list"));
    const QStringList devices = document.project().watchLists[0].devices;
    // X0 was there already; X1..X7, X10..X17 follow: 15 new rows.
    ASSERT_EQ(devices.size(), 3 + 15);
    EXPECT_EQ(devices[3 + 6], QStringLiteral("X7"));
    EXPECT_EQ(devices[3 + 7], QStringLiteral("X10"));
    EXPECT_EQ(devices.back(), QStringLiteral("X17"));
    EXPECT_EQ(test::watchRows(view.get(), 0), 18);
    // The source watches every row.
    EXPECT_EQ(source.watched().size(), 18u);
    // A part that is no range adds nothing and says why.
    QSignalSpy messages(view.get(), &editor::WatchListView::message);
    EXPECT_FALSE(view->addDevices({QStringLiteral("D0..D3"), QStringLiteral("X8")}));
    EXPECT_EQ(document.project().watchLists[0].devices.size(), 18);
    ASSERT_EQ(messages.size(), 1);
    EXPECT_TRUE(messages[0][0].toString().contains(QStringLiteral("octal")));
}

TEST_F(WatchTable, TheAddFieldTakesDevicesAndRangesWithCommas) {
    editor::WatchPanel panel(&document);
    QTest::keyClicks(panel.addField(), QStringLiteral("Y0, D10..D12"));
    QTest::keyClick(panel.addField(), Qt::Key_Return);
    EXPECT_EQ(document.project().watchLists[0].devices.mid(3),
              (QStringList{"Y0", "D10", "D11", "D12"}));
    EXPECT_TRUE(panel.addField()->text().isEmpty());
    QTest::keyClicks(panel.addField(), QStringLiteral("Q9"));
    QTest::keyClick(panel.addField(), Qt::Key_Return);
    EXPECT_EQ(panel.addField()->text(), QStringLiteral("Q9")); // kept, to be corrected
}

TEST_F(WatchTable, DroppedDevicesBecomeRowsAndRowsDragOut) {
    // A drop reaches the view as the window system delivers it: through the viewport's event
    // (QApplication hands a drop only to the target of a drag under way, which a test has not).
    std::unique_ptr<QMimeData> data(
        editor::deviceMimeData({QStringLiteral("M5"), QStringLiteral("T1")}));
    QDragEnterEvent enter(QPoint(5, 5), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
    static_cast<DropTarget *>(view.get())->viewportEvent(&enter);
    EXPECT_TRUE(enter.isAccepted());
    QDropEvent drop(QPointF(5, 5), Qt::CopyAction, data.get(), Qt::LeftButton, Qt::NoModifier);
    static_cast<DropTarget *>(view.get())->viewportEvent(&drop);
    EXPECT_TRUE(drop.isAccepted());
    EXPECT_EQ(document.project().watchLists[0].devices.mid(3), (QStringList{"M5", "T1"}));
    // Rows dragged out carry their devices (to the timing chart).
    view->clearSelection();
    const auto select = QItemSelectionModel::Select | QItemSelectionModel::Rows;
    view->selectionModel()->select(row(3), select); // the order the selection is made in
    view->selectionModel()->select(row(0), select);
    std::unique_ptr<QMimeData> out(
        view->model()->mimeData(view->selectionModel()->selectedIndexes()));
    ASSERT_NE(out, nullptr);
    EXPECT_EQ(editor::devicesFromMime(out.get()), (QStringList{"D0", "M5"}));
}

using WatchDrag = test::WindowFixture;

TEST_F(WatchDrag, ADeviceDraggedOutOfTheLadderLandsInTheWatchTable) {
    load("LD X0\nOUT Y0\nEND\n");
    window.resize(1200, 800);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    // Press on X0's cell and leave the ladder with the button down: the ladder starts a drag
    // that carries X0. (The offscreen platform ends a drag at once without dropping it, so
    // the drag's own data is dropped on the table, as the window system would drop it.)
    const QPoint cell = view->cellRectOnScreen({0, 0, 0}).center();
    QTest::mousePress(view->viewport(), Qt::LeftButton, {}, cell);
    const QPointF outside(-40, cell.y());
    QMouseEvent move(QEvent::MouseMove, outside, view->viewport()->mapToGlobal(outside),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(view->viewport(), &move);
    auto *drag = view->findChild<QDrag *>();
    ASSERT_NE(drag, nullptr);
    ASSERT_NE(drag->mimeData(), nullptr);
    EXPECT_EQ(editor::devicesFromMime(drag->mimeData()), QStringList{QStringLiteral("X0")});
    editor::WatchListView *watch = window.watchListView();
    EXPECT_TRUE(watch->dropDevices(drag->mimeData(), watch->viewport()->rect().center()));
    const auto &lists = window.document()->project().watchLists;
    ASSERT_EQ(lists.size(), 1u);
    EXPECT_EQ(lists[0].devices, QStringList{QStringLiteral("X0")});
    // A drag that stays inside the ladder draws wires as before: no device drag.
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, cell);
}

TEST_F(WatchDrag, TheCrossReferenceDragsTheDeviceOfARowOrAUse) {
    load("LD X0\nOUT Y0\nLD X0\nOUT Y1\nEND\n");
    QTreeView *tree = window.crossReference()->tree();
    window.crossReferenceDevice()->setText(QStringLiteral("X0"));
    ASSERT_GE(tree->model()->rowCount(), 1);
    const QModelIndex device = tree->model()->index(0, 0);
    ASSERT_GE(tree->model()->rowCount(device), 2);
    tree->clearSelection();
    // a use: the device it is a use of
    tree->selectionModel()->select(tree->model()->index(1, 0, device),
                                   QItemSelectionModel::Select | QItemSelectionModel::Rows);
    std::unique_ptr<QMimeData> data(
        tree->model()->mimeData(tree->selectionModel()->selectedIndexes()));
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(editor::devicesFromMime(data.get()), QStringList{QStringLiteral("X0")});
    EXPECT_TRUE(window.watchListView()->addDevices(editor::devicesFromMime(data.get())));
}

TEST_F(WatchDrag, FormatsAreSavedWithTheProjectAndOldProjectsStillOpen) {
    window.watchListView()->addDevices({QStringLiteral("D0..D1")});
    window.watchListView()->setFormat(test::watchIndex(window.watchListView(), 0, 1),
                                      ValueFormat::Hex);
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("w.rung"));
    ASSERT_TRUE(window.saveTo(path));
    app::MainWindow again;
    ASSERT_TRUE(again.openFile(path, QString(), true));
    EXPECT_EQ(again.document()->project().watchLists[0].format(QStringLiteral("D1")),
              ValueFormat::Hex);
    EXPECT_EQ(test::watchText(again.watchListView(), 0, 1, Column::FormatColumn),
              QStringLiteral("Hexadecimal"));
    // A project of the examples, written before the formats, opens with decimal rows.
    app::MainWindow old;
    ASSERT_TRUE(
        old.openFile(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/traffic-light.rung"),
                     QString(), true));
}
