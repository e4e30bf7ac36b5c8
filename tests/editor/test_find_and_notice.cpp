// Find a device in the ladder (Ctrl+F, then F3 / Shift+F3 through every use, wrapping round),
// and the ladder's notice while the instruction list has errors: they show in both views.

#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"

#include <QLabel>
#include <QStatusBar>
#include <QTest>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

struct FindFixture : test::WindowFixture {
    int output = 0;
    void SetUp() override {
        WindowFixture::SetUp();
        load("LD X0\nOUT Y0\nLD Y0\nAND X0\nOUT Y1\nLD X1\nSET Y0\nEND\n");
        output = view->metrics().gridColumns;
        window.show();
        ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
        view->setCursor({0, 0, 0});
    }
};

} // namespace

TEST_F(FindFixture, F3WalksThroughEveryUseAndWrapsRound) {
    ASSERT_TRUE(window.findDevice(QStringLiteral("Y0"), false));
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, output})); // OUT Y0
    QTest::keyClick(view, Qt::Key_F3);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{1, 0, 0})); // LD Y0
    QTest::keyClick(view, Qt::Key_F3);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{2, 0, output})); // SET Y0
    QTest::keyClick(view, Qt::Key_F3);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, output})); // round again
    QTest::keyClick(view, Qt::Key_F3, Qt::ShiftModifier);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{2, 0, output})); // and back
    QTest::keyClick(view, Qt::Key_F3, Qt::ShiftModifier);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{1, 0, 0}));
}

TEST_F(FindFixture, ADeviceNobodyUsesOrNoDeviceAtAllLeavesTheCursorAndSaysWhy) {
    view->setCursor({1, 0, 1});
    EXPECT_FALSE(window.findDevice(QStringLiteral("X5"), false));
    EXPECT_EQ(view->cursor(), (editor::CellCursor{1, 0, 1}));
    EXPECT_EQ(window.statusBar()->currentMessage(),
              QStringLiteral("X5 is not used in the program"));
    EXPECT_FALSE(window.findDevice(QStringLiteral("X9"), false));
    EXPECT_EQ(window.statusBar()->currentMessage(), QStringLiteral("X9: X is numbered in octal"));
    EXPECT_EQ(view->cursor(), (editor::CellCursor{1, 0, 1}));
}

TEST_F(FindFixture, WhileTheListHasErrorsTheLadderSaysItShowsTheLastValidProgram) {
    EXPECT_TRUE(view->notice().isEmpty());
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y8\nEND\n"));
    window.applyListing();
    EXPECT_TRUE(view->notice().contains(QStringLiteral("line 2"))) << view->notice().toStdString();
    EXPECT_TRUE(view->notice().contains(QStringLiteral("last valid program")));
    auto *label = view->findChild<QLabel *>(QStringLiteral("ladderNotice"));
    ASSERT_NE(label, nullptr);
    EXPECT_TRUE(label->isVisible());
    EXPECT_EQ(window.document()->ladder().rungs.size(), 4u); // the last valid ladder
    // The notice is a band above the drawing, which moves down: no rung hides under it.
    const QRect band = label->geometry();
    EXPECT_GT(band.height(), 0);
    EXPECT_LE(band.bottom(), view->viewport()->geometry().top());
    EXPECT_EQ(band.width(), view->viewport()->width());
    // The list as typed has lines of its own: moving on the ladder selects none of them.
    window.ilEditor()->setSelection(0, 0, 0, 0);
    view->setFocus();
    view->setCursor({1, 0, 0});
    EXPECT_FALSE(window.ilEditor()->hasSelectedText());

    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y7\nEND\n"));
    window.applyListing();
    EXPECT_TRUE(view->notice().isEmpty());
    EXPECT_FALSE(label->isVisible());
    EXPECT_EQ(view->viewport()->geometry().top(), view->contentsRect().top()); // band gone
}
