// A run of cells in a row: Shift+Left/Right selects it; copy, cut, paste and Delete act on
// it, each cut, paste or delete one undo step.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QApplication>
#include <QClipboard>
#include <QMimeData>
#include <QTest>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct CellFixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        load("LD X0\nAND X1\nANI X2\nOUT Y0\nLD X3\nOUT Y1\nEND\n");
        showWithLadderFocused();
    }
};

} // namespace

TEST_F(CellFixture, ShiftRightSelectsARunOfCellsAndAPlainMoveDropsIt) {
    view->setCursor({0, 0, 0});
    QTest::keyClick(view, Qt::Key_Right, Qt::ShiftModifier);
    QTest::keyClick(view, Qt::Key_Right, Qt::ShiftModifier);
    const auto run = view->selectedCells();
    ASSERT_TRUE(run.valid());
    EXPECT_EQ(run.first, 0);
    EXPECT_EQ(run.last, 2);
    QTest::keyClick(view, Qt::Key_Left);
    EXPECT_FALSE(view->selectedCells().valid());
}

TEST_F(CellFixture, CopiedCellsPasteIntoAnotherRungAsOneStep) {
    view->setCursor({0, 0, 1});
    view->selectCells(1, 2); // X1, /X2
    window.copyRung(false);
    EXPECT_TRUE(QApplication::clipboard()->mimeData()->hasFormat(
        QStringLiteral("application/x-rungstudio-cells")));
    view->setCursor({1, 0, 1}); // after X3
    const int before = window.document()->undoStack()->count();
    window.pasteRungs();
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Paste cells"));
    EXPECT_EQ(
        listing(),
        QStringLiteral("LD X0\nAND X1\nANI X2\nOUT Y0\nLD X3\nAND X1\nANI X2\nOUT Y1\nEND\n"));
}

TEST_F(CellFixture, DeleteAndCutClearTheSelectedCellsInOneStep) {
    view->setCursor({0, 0, 1});
    view->selectCells(1, 2);
    const int before = window.document()->undoStack()->count();
    QTest::keyClick(view, Qt::Key_Delete);
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Delete cells"));
    window.document()->undoStack()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nAND X1\nANI X2\nOUT Y0\nLD X3\nOUT Y1\nEND\n"));
    view->setCursor({0, 0, 1});
    view->selectCells(1, 2);
    window.copyRung(true);
    EXPECT_EQ(window.document()->undoStack()->index(), before + 1); // the undone step is gone
    EXPECT_FALSE(listing().contains(QStringLiteral("AND X1")));
}
