// Keyboard editing as in GX Works / WPLSoft: function keys for every element kind (parallel
// and edge contacts too), Ctrl+F9 / Ctrl+F10 to delete wires and links, arrows, and
// Insert / Delete for cells, rows and rungs; every edit one undo step with its label.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QAbstractItemView>
#include <QCompleter>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTest>
#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct KeyboardFixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        showWithLadderFocused();
    }
    void start(model::Family family, const char *listing) {
        window.newProject(model::Target::get(family), QString());
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(window.document()->setListing(QString::fromLatin1(listing), &errors));
        window.document()->undoStack()->clear();
    }
    // A function key (with its modifiers), then the operand into the cell editor it opens.
    // ... and the editor closes: what was typed was taken.
    void type(Qt::Key key, Qt::KeyboardModifiers mods, const char *operand) {
        typeIntoCell(key, operand, mods);
        QLineEdit *edit = view->inlineEditor();
        ASSERT_FALSE(edit->isVisible())
            << edit->text().toStdString() << ": " << edit->toolTip().toStdString();
    }
    const model::Rung &rung(int i) {
        return window.document()->ladder().rungs[static_cast<std::size_t>(i)];
    }
    QUndoStack *undo() { return window.document()->undoStack(); }
};

} // namespace

TEST_F(KeyboardFixture, ShiftF5AndShiftF6PlaceContactsInParallelWithTheRowAbove) {
    type(Qt::Key_F5, Qt::NoModifier, "X0");
    type(Qt::Key_F7, Qt::NoModifier, "Y0");
    view->setCursor({0, 1, 0});
    type(Qt::Key_F5, Qt::ShiftModifier, "X1"); // "OR " is prefilled
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
    view->setCursor({0, 2, 0});
    type(Qt::Key_F6, Qt::ShiftModifier, "X2"); // "ORI "
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nORI X2\nOUT Y0\nEND\n"));
    // The contact and its link are one step.
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Place ORI X2"));
    undo()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
}

TEST_F(KeyboardFixture, AParallelContactAwayFromTheRailSpansTheCellAbove) {
    type(Qt::Key_F5, Qt::NoModifier, "X0");
    type(Qt::Key_F5, Qt::NoModifier, "X1");
    type(Qt::Key_F7, Qt::NoModifier, "Y0");
    view->setCursor({0, 1, 1});
    type(Qt::Key_F5, Qt::ShiftModifier, "M0");
    EXPECT_TRUE(rung(0).link(0, 1));
    EXPECT_TRUE(rung(0).link(0, 2));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nLD X1\nOR M0\nANB\nOUT Y0\nEND\n"));
}

TEST_F(KeyboardFixture, ShiftAndAltF7F8PlaceEdgeContacts) {
    type(Qt::Key_F7, Qt::ShiftModifier, "X0"); // LDP
    type(Qt::Key_F8, Qt::ShiftModifier, "X1"); // LDF, in series: ANDF
    type(Qt::Key_F7, Qt::NoModifier, "Y0");
    EXPECT_EQ(listing(), QStringLiteral("LDP X0\nANDF X1\nOUT Y0\nEND\n"));
    view->setCursor({0, 1, 0});
    type(Qt::Key_F7, Qt::AltModifier, "M0"); // ORP
    EXPECT_EQ(listing(), QStringLiteral("LDP X0\nORP M0\nANDF X1\nOUT Y0\nEND\n"));
}

TEST_F(KeyboardFixture, EdgeKeysFollowTheTarget) {
    // PL110 has P / N on the power flow in place of edge contacts.
    start(model::Family::Pl110, "LD I1\nOUT Q1\nEND\n");
    view->setCursor({0, 0, 1});
    QTest::keyClick(view, Qt::Key_F7, Qt::ShiftModifier);
    ASSERT_TRUE(view->inlineEditor()->isVisible());
    EXPECT_EQ(view->inlineEditor()->text(), QStringLiteral("P "));
    QTest::keyClick(view->inlineEditor(), Qt::Key_Escape);
    // CPM1 has neither: the key says so and opens nothing.
    start(model::Family::Cpm1, "LD 000.00\nOUT 010.00\nEND(01)\n");
    view->inlineEditor()->hide();
    QSignalSpy said(view, &editor::LadderView::message);
    QTest::keyClick(view, Qt::Key_F8, Qt::ShiftModifier);
    EXPECT_FALSE(view->inlineEditor()->isVisible());
    ASSERT_EQ(said.count(), 1);
    EXPECT_TRUE(said.at(0).at(0).toString().contains(QStringLiteral("CPM1")));
}

TEST_F(KeyboardFixture, CtrlF9AndCtrlF10DeleteAWireAndALink) {
    type(Qt::Key_F5, Qt::NoModifier, "X0");
    QTest::keyClick(view, Qt::Key_F9); // a wire in column 1
    type(Qt::Key_F7, Qt::NoModifier, "Y0");
    view->setCursor({0, 1, 0});
    type(Qt::Key_F5, Qt::ShiftModifier, "X1");
    ASSERT_EQ(rung(0).cell(0, 1).kind, model::CellKind::Wire);
    ASSERT_TRUE(rung(0).link(0, 1));
    const int before = undo()->count();

    view->setCursor({0, 0, 1});
    QTest::keyClick(view, Qt::Key_F9, Qt::ControlModifier);
    EXPECT_EQ(rung(0).cell(0, 1).kind, model::CellKind::Empty);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Delete a wire"));
    // On a contact Ctrl+F9 deletes nothing and says why.
    view->setCursor({0, 0, 0});
    QSignalSpy said(view, &editor::LadderView::message);
    QTest::keyClick(view, Qt::Key_F9, Qt::ControlModifier);
    EXPECT_EQ(said.count(), 1);
    EXPECT_EQ(rung(0).cell(0, 0).kind, model::CellKind::Contact);
    EXPECT_EQ(undo()->count(), before + 1);

    view->setCursor({0, 0, 1}); // the link at the left node of column 1
    QTest::keyClick(view, Qt::Key_F10, Qt::ControlModifier);
    EXPECT_FALSE(rung(0).link(0, 1));
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Delete a vertical link"));
    EXPECT_EQ(undo()->count(), before + 2);
    undo()->undo();
    undo()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
}

TEST_F(KeyboardFixture, InsertAndDeleteActOnCellsRowsAndRungs) {
    start(model::Family::Vigor, "LD X0\nOR X3\nAND X1\nOUT Y0\nLD X2\nOUT Y1\nEND\n");
    ASSERT_EQ(rung(0).rows, 2);
    const QString original = listing();

    view->setCursor({0, 0, 1});
    QTest::keyClick(view, Qt::Key_Insert); // a cell before X1
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Insert a cell"));
    EXPECT_EQ(rung(0).cell(0, 2).kind, model::CellKind::Contact);
    undo()->undo();

    view->setCursor({0, 1, 0});
    QTest::keyClick(view, Qt::Key_Insert, Qt::ControlModifier);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Insert a row"));
    EXPECT_EQ(rung(0).rows, 3);
    undo()->undo();

    view->setCursor({1, 0, 0});
    QTest::keyClick(view, Qt::Key_Insert, Qt::ShiftModifier);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Insert rung"));
    EXPECT_EQ(window.document()->ladder().rungs.size(), 4u);
    undo()->undo();
    EXPECT_EQ(listing(), original);

    view->setCursor({0, 0, 1});
    QTest::keyClick(view, Qt::Key_Delete);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Delete"));
    EXPECT_EQ(rung(0).cell(0, 1).kind, model::CellKind::Empty);
    undo()->undo();

    view->setCursor({0, 1, 0});
    QTest::keyClick(view, Qt::Key_Delete, Qt::ControlModifier);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Delete a row"));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nLD X2\nOUT Y1\nEND\n"));
    undo()->undo();

    view->setCursor({1, 0, 0});
    QTest::keyClick(view, Qt::Key_Delete, Qt::ShiftModifier);
    EXPECT_EQ(undo()->undoText(), QStringLiteral("Delete rung"));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X3\nAND X1\nOUT Y0\nEND\n"));
    undo()->undo();
    EXPECT_EQ(listing(), original);
    EXPECT_EQ(undo()->index(), 0);
}

TEST_F(KeyboardFixture, ArrowsMoveThroughRowsTheSpareRowAndRungs) {
    start(model::Family::Vigor, "LD X0\nOR X3\nAND X1\nOUT Y0\nLD X2\nOUT Y1\nEND\n");
    view->setCursor({0, 0, 0});
    QSignalSpy moved(view, &editor::LadderView::cursorMoved);
    QTest::keyClick(view, Qt::Key_Right);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, 1}));
    QTest::keyClick(view, Qt::Key_Down);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 1, 1}));
    QTest::keyClick(view, Qt::Key_Down); // the spare row under the rung, for a new branch
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 2, 1}));
    QTest::keyClick(view, Qt::Key_Down);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{1, 0, 1}));
    QTest::keyClick(view, Qt::Key_Up); // back to the last row of the rung above
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 1, 1}));
    QTest::keyClick(view, Qt::Key_End);
    EXPECT_EQ(view->cursor().column, view->metrics().gridColumns);
    QTest::keyClick(view, Qt::Key_Home);
    EXPECT_EQ(view->cursor().column, 0);
    EXPECT_EQ(moved.count(), 7);
}

TEST_F(KeyboardFixture, ReturnCommitsEvenWhileTheCompletionListIsOpen) {
    start(model::Family::Vigor, "LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n");
    view->setCursor({1, 0, 1});
    QTest::keyClick(view, Qt::Key_F5);
    QLineEdit *edit = view->inlineEditor();
    QTest::keyClicks(edit, QStringLiteral("X0")); // "LD X0" is offered: the list is open
    ASSERT_TRUE(edit->completer()->popup()->isVisible());
    QTest::keyClick(edit, Qt::Key_Return);
    EXPECT_FALSE(edit->isVisible());
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD X1\nAND X0\nOUT Y1\nEND\n"));
}
