// Selecting whole rungs with Shift+Up/Down (and Shift+click): copy, cut and delete act on the
// selection, each cut or delete one undo step.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QApplication>
#include <QClipboard>
#include <QTest>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct SelectionFixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        load("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n");
        showWithLadderFocused();
        view->setCursor({0, 0, 0});
    }
};

} // namespace

TEST_F(SelectionFixture, ShiftDownSelectsRungsAndAPlainMoveDropsTheSelection) {
    EXPECT_EQ(view->selectedRungs(), (std::pair<int, int>{0, 1}));
    QTest::keyClick(view, Qt::Key_Down, Qt::ShiftModifier); // row 0 -> the spare row
    QTest::keyClick(view, Qt::Key_Down, Qt::ShiftModifier); // -> rung 1
    EXPECT_EQ(view->selectedRungs(), (std::pair<int, int>{0, 2}));
    QTest::keyClick(view, Qt::Key_Down);
    EXPECT_EQ(view->selectedRungs().second, 1);
}

TEST_F(SelectionFixture, CopyTakesEverySelectedRungAsListingText) {
    view->selectRungs(0, 1);
    window.copyRung(false);
    EXPECT_EQ(QApplication::clipboard()->text(), QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\n"));
}

TEST_F(SelectionFixture, CutRemovesTheSelectionInOneUndoStep) {
    view->selectRungs(1, 2);
    const int before = window.document()->undoStack()->count();
    window.copyRung(true);
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    window.pasteRungs(); // back where they were, as one step too
    EXPECT_EQ(window.document()->undoStack()->count(), before + 2);
    window.document()->undoStack()->undo();
    window.document()->undoStack()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n"));
}

TEST_F(SelectionFixture, ShiftDeleteDeletesTheSelectedRungs) {
    view->selectRungs(0, 1);
    QTest::keyClick(view, Qt::Key_Delete, Qt::ShiftModifier);
    EXPECT_EQ(listing(), QStringLiteral("LD X2\nOUT Y2\nEND\n"));
    window.document()->undoStack()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n"));
}

TEST_F(SelectionFixture, ShiftClickExtendsTheSelection) {
    const QPoint third = view->cellRectOnScreen({2, 0, 0}).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::ShiftModifier, third);
    EXPECT_EQ(view->selectedRungs(), (std::pair<int, int>{0, 3}));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, third);
    EXPECT_EQ(view->selectedRungs(), (std::pair<int, int>{2, 1}));
}
