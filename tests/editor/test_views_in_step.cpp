// The ladder and the list side by side as one program: step addresses in the list's margin,
// the cursor following from one view to the other, reverse-current cells marked on the
// ladder; and what the next start remembers (dock layout, language).

#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"

#include <QDockWidget>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

QString marginText(editor::IlEditor *il, int line) {
    const long length = il->SendScintilla(QsciScintillaBase::SCI_MARGINGETTEXT,
                                          static_cast<unsigned long>(line), static_cast<long>(0));
    QByteArray buffer(static_cast<qsizetype>(length) + 1, '\0');
    il->SendScintilla(QsciScintillaBase::SCI_MARGINGETTEXT, static_cast<unsigned long>(line),
                      static_cast<void *>(buffer.data()));
    return QString::fromUtf8(buffer.constData());
}

} // namespace

using ListMargin = test::WindowFixture;

TEST_F(ListMargin, EachInstructionShowsItsStepAddressMultiStepInstructionsCounted) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND\n"), &errors));
    const auto &ins = window.document()->listing().list.instructions;
    ASSERT_EQ(ins.size(), 5u);
    const auto &vigor = window.document()->target();
    ASSERT_GT(model::instructionSteps(vigor, ins[1]), 1); // a timer with its set value
    editor::IlEditor *il = window.ilEditor();
    const QString text = il->text();
    // Find each instruction's line in the listing text and read the margin beside it.
    for (const model::Instruction &i : ins) {
        const QString printed = model::printInstruction(vigor, i);
        int line = -1;
        for (int l = 0; l < il->lines(); ++l)
            if (il->text(l).simplified() == printed.simplified())
                line = l;
        ASSERT_GE(line, 0) << printed.toStdString();
        EXPECT_EQ(marginText(il, line), QStringLiteral("%1").arg(i.step, 4, 10, QLatin1Char('0')))
            << printed.toStdString();
    }
    EXPECT_EQ(ins[2].step, ins[1].step + model::instructionSteps(vigor, ins[1]));
    EXPECT_EQ(ins[0].step, 0);
}

// While the typed list has an error, its lines that parse keep their step numbers.
TEST_F(ListMargin, StepNumbersStayWhileTheListHasErrors) {
    editor::IlEditor *il = window.ilEditor();
    const QString typed = QStringLiteral("LD X0\nTMR T0 K10\nLD X8\nOUT Y0\nEND\n");
    il->setText(typed);
    window.applyListing();
    ASSERT_EQ(il->text(), typed);
    // TMR takes three steps; the line that cannot be read takes none.
    EXPECT_EQ(marginText(il, 0), QStringLiteral("0000"));
    EXPECT_EQ(marginText(il, 1), QStringLiteral("0001"));
    EXPECT_EQ(marginText(il, 3), QStringLiteral("0004"));
    EXPECT_EQ(marginText(il, 4), QStringLiteral("0005"));
    EXPECT_TRUE(marginText(il, 2).isEmpty()); // the line with the error has none
}

using ViewsInStep = test::WindowFixture;

TEST_F(ViewsInStep, SelectingARungSelectsItsLinesAndTheListCursorSelectsItsRung) {
    window.setSideBySide(true); // both views visible, as a user would work
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nOUT Y0\nLD X1\nAND X2\nOUT Y1\nLDI X3\nOUT Y2\nEND\n"), &errors));
    editor::Document *doc = window.document();
    editor::IlEditor *il = window.ilEditor();

    window.ladderView()->setFocus();
    window.ladderView()->setCursor({1, 0, 0});
    int fromLine = 0, fromIndex = 0, toLine = 0, toIndex = 0;
    il->getSelection(&fromLine, &fromIndex, &toLine, &toIndex);
    EXPECT_EQ(fromLine + 1, doc->firstLineOfRung(1));
    EXPECT_EQ(toLine + 1, doc->firstLineOfRung(2)); // up to the next rung's first line
    EXPECT_TRUE(il->selectedText().contains(QStringLiteral("AND X2")));
    EXPECT_FALSE(il->selectedText().contains(QStringLiteral("X3")));

    // And back: the list's cursor on a line of the third rung puts the ladder there.
    il->setFocus();
    ASSERT_TRUE(il->hasFocus());
    QSignalSpy moved(window.ladderView(), &editor::LadderView::cursorMoved);
    il->setCursorPosition(doc->firstLineOfRung(2), 0); // 0-based: the rung's second line
    if (moved.isEmpty()) {
        ASSERT_TRUE(moved.wait(3000));
    }
    EXPECT_EQ(window.ladderView()->cursor().rung, 2);
}

TEST_F(ViewsInStep, ReverseCurrentCellsAreMarkedOnTheLadder) {
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    const char *bridge = "LADDER vigor WIDTH 8\n"
                         "RUNG 1 ROWS 3 COLUMNS 3\n"
                         "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                         "|        |                 |\n"
                         "|        +-[ X2 ]-+        +\n"
                         "|                 |        |\n"
                         "|-[ X3 ]----------+-[ X4 ]-+\n";
    auto parsed = model::parseLadderText(model::Target::get(model::Family::Vigor),
                                         QString::fromLatin1(bridge));
    ASSERT_TRUE(parsed.ok());
    window.document()->replaceRungs(0, 0, parsed.ladder.rungs, QStringLiteral("paste"));
    const model::Diagnostic *rc = nullptr;
    for (const model::Diagnostic &d : window.document()->diagnostics())
        if (d.code == QLatin1String("RC001"))
            rc = &d;
    ASSERT_NE(rc, nullptr);
    ASSERT_FALSE(rc->related.empty());

    editor::LadderView *view = window.ladderView();
    view->setCursor({0, 2, 2}); // the cursor away from the marked cells
    const QImage image = view->viewport()->grab().toImage();
    const QColor mark(0xfd, 0xe2, 0xe2);
    std::set<std::pair<int, int>> marked;
    for (const model::Location &l : rc->related)
        marked.insert({l.row, l.cell});
    // A marked cell has the mark's tint in a corner; an unmarked one does not.
    const auto tinted = [&](int row, int column) {
        const QRect r = view->cellRectOnScreen({0, row, column});
        const QPoint corner = r.topLeft() + QPoint(2, 2); // viewport coordinates
        return image.pixelColor(corner * image.devicePixelRatio()) == mark;
    };
    for (const auto &[row, column] : marked)
        EXPECT_TRUE(tinted(row, column)) << "row " << row << " column " << column;
    int unmarkedSeen = 0;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column)
            if (!marked.count({row, column}) && !(row == 2 && column == 2)) {
                EXPECT_FALSE(tinted(row, column)) << "row " << row << " column " << column;
                ++unmarkedSeen;
            }
    EXPECT_GT(unmarkedSeen, 0);
}

TEST(NextStart, TheDockLayoutIsRemembered) {
    QSettings().remove(QStringLiteral("window/state"));
    {
        app::MainWindow window;
        window.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
        auto *problems = window.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
        ASSERT_NE(problems, nullptr);
        EXPECT_TRUE(problems->isVisible());
        problems->hide();
        window.close();
    }
    {
        app::MainWindow next;
        next.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&next));
        auto *problems = next.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
        ASSERT_NE(problems, nullptr);
        EXPECT_FALSE(problems->isVisible());
        problems->show();
        next.close();
    }
    QSettings().remove(QStringLiteral("window/state"));
}
