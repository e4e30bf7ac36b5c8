// Drawing with the mouse: a drag along a row lays wires over the empty cells, a drag down a
// column draws vertical links; each drag is one undo step.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QTest>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct MouseFixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        window.resize(1400, 900);
        window.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    }
    void drag(const editor::CellCursor &from, const editor::CellCursor &to) {
        const QPoint a = view->cellRectOnScreen(from).center();
        const QPoint b = view->cellRectOnScreen(to).center();
        QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, a);
        QTest::mouseMove(view->viewport(), (a + b) / 2);
        QTest::mouseMove(view->viewport(), b);
        QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, b);
    }
};

} // namespace

TEST_F(MouseFixture, DragAlongARowWiresTheEmptyCellsAroundAContact) {
    std::vector<model::Diagnostic> errors;
    // X0 in column 0, a branch X1 in row 1 column 0 that ends open: drag a wire to its end.
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    const int before = window.document()->undoStack()->count();
    drag({0, 0, 1}, {0, 0, 4});
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Draw a wire"));
    const model::Rung &rung = window.document()->ladder().rungs.front();
    for (int c = 1; c <= 4 && c < rung.columns; ++c)
        EXPECT_NE(rung.cell(0, c).kind, model::CellKind::Empty) << "column " << c;
    EXPECT_EQ(rung.cell(0, 0).kind, model::CellKind::Contact);    // never over an element
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n")); // same logic
}

TEST_F(MouseFixture, DragDownAColumnDrawsTheLinkThatMakesABranch) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    // An X1 contact under X0 (row 1, column 0) and a link at node 1 make X0 OR X1.
    view->setCursor({0, 1, 0});
    ASSERT_TRUE(view->enterInstruction(QStringLiteral("LD X1")));
    const int before = window.document()->undoStack()->count();
    drag({0, 0, 1}, {0, 1, 1});
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Draw a vertical link"));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
    window.document()->undoStack()->undo();
    EXPECT_NE(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
}

TEST_F(MouseFixture, AClickIsNotADrag) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    const int before = window.document()->undoStack()->count();
    drag({0, 0, 2}, {0, 0, 2});
    EXPECT_EQ(window.document()->undoStack()->count(), before);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, 2}));
}

// The press moves the cursor to the clicked rung, which moves the spare editing row and shifts
// the layout under the mouse: the release must still be read as a click.
TEST_F(MouseFixture, AClickInARungBelowTheCursorChangesNothing) {
    std::vector<model::Diagnostic> errors;
    const QString program = QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n");
    ASSERT_TRUE(window.document()->setListing(program, &errors));
    view->setCursor({0, 0, 0});
    const int before = window.document()->undoStack()->count();
    const QPoint at = view->cellRectOnScreen({2, 0, 1}).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, at);
    EXPECT_EQ(listing(), program);
    EXPECT_EQ(window.document()->undoStack()->count(), before);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{2, 0, 1}));
}

TEST_F(MouseFixture, ADragInARungBelowTheCursorIsReadWhereItWasPressed) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n"), &errors));
    view->setCursor({0, 0, 0});
    drag({2, 0, 1}, {2, 0, 4}); // both points in the layout the press saw
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Draw a wire"));
    const model::Rung &rung = window.document()->ladder().rungs[2];
    EXPECT_EQ(rung.rows, 1); // no link into a new row
    for (int c = 1; c <= 4 && c < rung.columns; ++c)
        EXPECT_EQ(rung.cell(0, c).kind, model::CellKind::Wire) << "column " << c;
}

// A link drawn right of a row's last element widens the rung: the row's wire must go on to the
// coil through the new cells.
TEST_F(MouseFixture, ALinkBeyondTheLastElementKeepsTheCoilsCondition) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nAND X1\nOUT Y0\nLD X2\nOUT Y1\nEND\n"), &errors));
    const int columnsBefore = window.document()->ladder().rungs.front().columns;
    const int node = columnsBefore + 2;
    drag({0, 0, node}, {0, 1, node});
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Draw a vertical link"));
    const model::Rung &rung = window.document()->ladder().rungs.front();
    ASSERT_GE(rung.columns, node);
    for (int c = columnsBefore; c < rung.columns; ++c)
        EXPECT_EQ(rung.cell(0, c).kind, model::CellKind::Wire) << "column " << c;
    // Y0 keeps X0 AND X1 as its condition, and Y1 is untouched.
    const QString il = listing();
    EXPECT_TRUE(il.startsWith(QStringLiteral("LD X0\nAND X1\nOUT Y0\n"))) << il.toStdString();
    EXPECT_TRUE(il.contains(QStringLiteral("LD X2\nOUT Y1\n"))) << il.toStdString();
}
