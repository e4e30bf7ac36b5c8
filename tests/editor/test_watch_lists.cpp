// Watch lists in the project dock: the device under the ladder cursor goes in with one undo
// step, Delete takes it out, and they are saved with the project.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"
#include "editor/watch_list_view.h"
#include "model/target/address.h"

#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "tests/editor/watch_rows.h"
#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

using WatchLists = test::WindowFixture;

TEST_F(WatchLists, TheDeviceUnderTheCursorIsAddedOnceAndRemovedWithDelete) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    window.show();
    editor::LadderView *view = window.ladderView();
    editor::WatchListView *watch = window.watchListView();
    view->setCursor({0, 0, 0});
    EXPECT_EQ(view->deviceAtCursor(), QStringLiteral("X0"));
    const int before = window.document()->undoStack()->count();
    watch->addDevice(view->deviceAtCursor());
    view->setCursor({0, 0, view->metrics().gridColumns});
    EXPECT_EQ(view->deviceAtCursor(), QStringLiteral("Y0"));
    watch->addDevice(view->deviceAtCursor());
    watch->addDevice(QStringLiteral("Y0")); // already there
    EXPECT_EQ(window.document()->undoStack()->count(), before + 2);
    const auto &lists = window.document()->project().watchLists;
    ASSERT_EQ(lists.size(), 1u);
    EXPECT_EQ(lists[0].devices, (QStringList{QStringLiteral("X0"), QStringLiteral("Y0")}));
    ASSERT_EQ(test::watchRows(watch), 1);
    EXPECT_EQ(test::watchRows(watch, 0), 2);

    watch->setCurrentIndex(test::watchIndex(watch, 0, 0));
    watch->setFocus();
    QTest::keyClick(watch, Qt::Key_Delete);
    EXPECT_EQ(window.document()->project().watchLists[0].devices,
              QStringList{QStringLiteral("Y0")});
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->project().watchLists[0].devices.size(), 2);

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("w.rung"));
    ASSERT_TRUE(window.saveTo(path));
    app::MainWindow again;
    ASSERT_TRUE(again.openFile(path, QString(), true));
    ASSERT_EQ(again.document()->project().watchLists.size(), 1u);
    EXPECT_EQ(again.document()->project().watchLists[0].devices.size(), 2);
    EXPECT_EQ(test::watchRows(again.watchListView(), 0), 2);
}

using ElementHelp = test::WindowFixture;

TEST_F(ElementHelp, HoveringAnElementNamesItsDeviceWithTheSymbolsNameAndComment) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    window.document()->setSymbols(
        {model::Symbol{std::get<model::Address>(
                           model::parseAddress(window.document()->target(), QStringLiteral("X0"))),
                       QStringLiteral("Start"), QStringLiteral("green button")}});
    editor::LadderView *view = window.ladderView();
    EXPECT_EQ(view->elementHelp({0, 0, 0}), QStringLiteral("X0 — Start: green button"));
    EXPECT_EQ(view->elementHelp({0, 0, view->metrics().gridColumns}), QStringLiteral("Y0"));
    EXPECT_TRUE(view->elementHelp({0, 0, 5}).isEmpty());
}
