// Rows longer than the target's contacts per line (Vigor: 11) fold into blocks below, with
// continuation marks, as the vendor editor draws them; the cursor and the mouse follow.

#include "editor/document.h"
#include "editor/ladder_painter.h"
#include "editor/ladder_view.h"

#include <QTest>

#include <gtest/gtest.h>

using namespace rung;

namespace {

// X0..X15 (octal) in series, M0 in parallel to the whole chain, then X14: 15 columns.
const char *kWide = "LD X0\nAND X1\nAND X2\nAND X3\nAND X4\nAND X5\nAND X6\nAND X7\nAND X10\n"
                    "AND X11\nAND X12\nAND X13\nAND X14\nAND X15\nOR M0\nAND X14\nOUT Y0\n"
                    "LD X1\nOUT Y1\nEND\n";

struct FoldFixture : ::testing::Test {
    editor::Document document;
    std::unique_ptr<editor::LadderView> view;
    void SetUp() override {
        document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(document.setListing(QString::fromLatin1(kWide), &errors));
        ASSERT_EQ(document.ladder().rungs.front().columns, 15);
        view = std::make_unique<editor::LadderView>(&document);
        view->resize(1300, 800);
        view->show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(view.get()));
    }
};

} // namespace

TEST_F(FoldFixture, AWideRungTakesTwoBlocksAndTheDrawingKeepsTheTargetsWidth) {
    const editor::LadderMetrics m = view->metrics();
    EXPECT_EQ(m.shownColumns(), 11);
    const model::Rung &wide = document.ladder().rungs[0];
    const model::Rung &narrow = document.ladder().rungs[1];
    EXPECT_EQ(m.blocks(wide), 2);
    EXPECT_EQ(m.blocks(narrow), 1);
    EXPECT_DOUBLE_EQ(m.width(), m.gutter + 11 * m.cellWidth + m.outputWidth +
                                    editor::LadderMetrics::kRightMargin);
    // Two blocks of two rows with a spare line between them.
    EXPECT_DOUBLE_EQ(m.rungHeight(wide) - m.commentBlock(wide) - m.rungGap, 5 * m.rowHeight);

    editor::LadderPainter painter(document.project(), m);
    const QRectF x13 = painter.cellRect(wide, 0, 11); // first cell of the second block
    const QRectF x0 = painter.cellRect(wide, 0, 0);
    EXPECT_DOUBLE_EQ(x13.left(), x0.left());
    EXPECT_DOUBLE_EQ(x13.top() - x0.top(), 3 * m.rowHeight);
    // The output sits beside the last block.
    EXPECT_DOUBLE_EQ(painter.outputRect(wide, 0).top(), x13.top());
}

TEST_F(FoldFixture, TheCursorWalksIntoTheNextBlockAndOnToTheOutput) {
    view->setFocus();
    view->setCursor({0, 0, 10});
    QTest::keyClick(view.get(), Qt::Key_Right);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, 11}));
    view->setCursor({0, 0, 21}); // the end of the second block
    QTest::keyClick(view.get(), Qt::Key_Right);
    EXPECT_EQ(view->cursor().column, view->metrics().gridColumns); // the output column
    // A one-block rung goes from its eleventh column straight to the output.
    view->setCursor({1, 0, 10});
    QTest::keyClick(view.get(), Qt::Key_Right);
    EXPECT_EQ(view->cursor().column, view->metrics().gridColumns);
    QTest::keyClick(view.get(), Qt::Key_Left);
    EXPECT_EQ(view->cursor().column, 10);
}

TEST_F(FoldFixture, AClickInTheSecondBlockSelectsThatCell) {
    const QPoint at = view->cellRectOnScreen({0, 1, 12}).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, at);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 1, 12}));
    const QPoint out = view->cellRectOnScreen({0, 0, view->metrics().gridColumns}).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, out);
    EXPECT_EQ(view->cursor(), (editor::CellCursor{0, 0, view->metrics().gridColumns}));
}
