// The problems panel shows every finding once, by its documented code (docs/diagnostics.md):
// a typed list that cannot be drawn is checked whole as `rungstudio-cli check` checks it, a
// ladder that cannot be listed is not reported twice, and a fix of the typed list that reorders
// the program is one undo step.

#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"

#include "model/ladder/ladder_text.h"

#include <QUndoStack>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <set>

using namespace rung;

namespace {

struct Problems : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        window.show();
    }
    std::vector<model::Diagnostic> shown() {
        std::vector<model::Diagnostic> all;
        for (int i = 0; window.problemsView()->diagnosticAt(i); ++i)
            all.push_back(*window.problemsView()->diagnosticAt(i));
        return all;
    }
    const model::Diagnostic *shownWithCode(const char *code) {
        for (int i = 0; window.problemsView()->diagnosticAt(i); ++i)
            if (window.problemsView()->diagnosticAt(i)->code == QLatin1String(code))
                return window.problemsView()->diagnosticAt(i);
        return nullptr;
    }
    std::vector<model::Rung> programOf(const QString &text) {
        const model::ParseResult parsed =
            model::parseInstructionList(window.document()->target(), text);
        EXPECT_TRUE(parsed.ok());
        return model::listToLadder(parsed.list).ladder.rungs;
    }
};

std::string describe(const std::vector<model::Diagnostic> &all) {
    QStringList lines;
    for (const model::Diagnostic &d : all)
        lines << QStringLiteral("%1 %2:%3 rung %4 %5")
                     .arg(d.code)
                     .arg(d.location.line)
                     .arg(d.location.column)
                     .arg(d.location.rung)
                     .arg(d.message);
    return lines.join(QLatin1Char('\n')).toStdString();
}

} // namespace

TEST_F(Problems, ATypedListThatCannotBeDrawnShowsWhatCheckPrintsAndNoConversionCode) {
    const std::vector<model::Rung> program = window.document()->ladder().rungs;
    const QString typed = QStringLiteral("LD X0\nLD X1\nOUT Y0\nLD X2\nOUT X3\nLD X4\nOUT Y0");
    window.ilEditor()->setText(typed);
    window.applyListing();
    // The text stays as typed and the ladder keeps the last valid program.
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_EQ(window.document()->ladder().rungs, program);
    const std::vector<model::Diagnostic> all = shown();
    // What `rungstudio-cli check --target vigor` prints for this text, line:column and code:
    //   3:1 BL001 (OUT with two blocks open), 5:5 OP002 (at X3), 7:1 EN001, 7:1 DC001
    std::multiset<std::tuple<QString, int, int>> found;
    for (const model::Diagnostic &d : all) {
        EXPECT_FALSE(d.code.startsWith(QLatin1String("CV"))) << describe(all);
        found.emplace(d.code, d.location.line, d.location.column);
    }
    const std::multiset<std::tuple<QString, int, int>> printed = {
        {QStringLiteral("BL001"), 3, 1},
        {QStringLiteral("OP002"), 5, 5},
        {QStringLiteral("EN001"), 7, 1},
        {QStringLiteral("DC001"), 7, 1},
    };
    EXPECT_EQ(found, printed) << describe(all);

    // Once the text can be drawn, the ladder follows it and the panel has no BL001 left.
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    EXPECT_EQ(shownWithCode("BL001"), nullptr) << describe(shown());
    EXPECT_EQ(window.document()->ladder().rungs, programOf(QStringLiteral("LD X0\nOUT Y0\nEND\n")));
}

TEST_F(Problems, ALadderThatCannotBeListedShowsEachProblemOnce) {
    const char *open = "LADDER vigor WIDTH 8\n"
                       "RUNG 1 ROWS 2 COLUMNS 2\n"
                       "|-[ X0 ]---[ X1 ]-+(OUT Y0)\n"
                       "|\n"
                       "|         -[ X2 ]-+(OUT Y1)\n";
    const auto parsed =
        model::parseLadderText(window.document()->target(), QString::fromLatin1(open));
    ASSERT_TRUE(parsed.ok());
    ASSERT_FALSE(model::ladderToList(parsed.ladder).ok()); // the listing refuses the rung
    window.document()->replaceRungs(0, 0, parsed.ladder.rungs, QStringLiteral("paste"));
    const std::vector<model::Diagnostic> all = shown();
    ASSERT_NE(shownWithCode("LD001"), nullptr) << describe(all);
    std::set<std::pair<int, int>> rows; // (rung, row) of each LD001
    for (const model::Diagnostic &d : all) {
        EXPECT_FALSE(d.code.startsWith(QLatin1String("CV"))) << describe(all);
        if (d.code == QLatin1String("LD001")) {
            EXPECT_TRUE(rows.emplace(d.location.rung, d.location.row).second) << describe(all);
        }
    }
}

TEST_F(Problems, AReorderingFixOfTheTypedListIsOneUndoStep) {
    // An output read from the stack that can go before the MPS (FZ006): its fix reorders the
    // program. (FZ004 on a block with a branch keeps the order now: the rung's simplest form.)
    const QString typed =
        QStringLiteral("LD X0\nMPS\nLD X1\nLD X2\nORB\nANB\nOUT Y0\nMPP\nOUT Y1\nEND\n");
    window.ilEditor()->setText(typed);
    window.applyListing();
    const std::vector<model::Rung> before = window.document()->ladder().rungs;
    ASSERT_EQ(before, programOf(typed));
    const model::Diagnostic *fz006 = shownWithCode("FZ006");
    ASSERT_NE(fz006, nullptr) << describe(shown());
    ASSERT_TRUE(fz006->fix.has_value());
    const model::Diagnostic fix = *fz006;
    QUndoStack *stack = window.document()->undoStack();
    const int steps = stack->count();

    emit window.problemsView()->applyFix(fix);
    const QString fixed = window.ilEditor()->text();
    EXPECT_NE(fixed, typed);
    EXPECT_TRUE(fixed.startsWith(fix.fix->listing)) << fixed.toStdString();
    const std::vector<model::Rung> reordered = programOf(fixed);
    EXPECT_NE(reordered, before); // the output moved before the MPS
    EXPECT_EQ(window.document()->ladder().rungs, reordered);
    EXPECT_EQ(shownWithCode("FZ006"), nullptr);
    EXPECT_EQ(stack->count(), steps + 1);
    EXPECT_EQ(stack->undoText(), fix.fix->label);
    EXPECT_FALSE(fix.fix->label.isEmpty());

    stack->undo();
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_EQ(window.document()->ladder().rungs, before);
    EXPECT_EQ(stack->count(), steps + 1); // undo pushed nothing
    EXPECT_EQ(stack->redoText(), fix.fix->label);

    stack->redo();
    EXPECT_EQ(window.ilEditor()->text(), fixed);
    EXPECT_EQ(window.document()->ladder().rungs, reordered);
    EXPECT_EQ(stack->count(), steps + 1);
    EXPECT_EQ(stack->undoText(), fix.fix->label);
}
