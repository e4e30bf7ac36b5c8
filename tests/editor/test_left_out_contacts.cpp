// A contact on no path to an output (LD002) has no instruction in the list: a marked line
// before its rung's instructions names it, the warning points at that line, and editing the
// list keeps the contact in the ladder while the line stays (deleting the line lets it go).

#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "tests/targets.h"

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

using rung::testing::vigor;

model::Contact contact(const char *text) {
    QString why;
    const auto c = model::contactFromText(vigor(), QString::fromLatin1(text), &why);
    EXPECT_TRUE(c) << why.toStdString();
    return c.value_or(model::Contact{});
}

// Rung 1 "Start": LD X0 / OUT Y0 with X5 drawn in a second row, linked to nothing (LD002);
// rung 2: LD X1 / OUT Y1; rung 3: END.
model::Project strayProject() {
    const model::ParseResult parsed = model::parseInstructionList(
        vigor(), QStringLiteral("; Start\nLD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n"));
    EXPECT_TRUE(parsed.ok());
    model::Project p;
    p.target = &vigor();
    p.model = vigor().defaultModel().name;
    p.program = model::listToLadder(parsed.list).ladder;
    model::Rung &first = p.program.rungs.at(0);
    first.resize(2, first.columns);
    first.cell(1, 0).kind = model::CellKind::Contact;
    first.cell(1, 0).contact = contact("X5");
    return p;
}

const model::Diagnostic *find(const std::vector<model::Diagnostic> &ds, const char *code) {
    const auto it = std::find_if(ds.begin(), ds.end(), [code](const model::Diagnostic &d) {
        return d.code == QLatin1String(code);
    });
    return it == ds.end() ? nullptr : &*it;
}

QStringList linesOf(const editor::Document &doc) {
    return doc.listingText().split(QLatin1Char('\n'));
}

} // namespace

TEST(LeftOutContact, HasAMarkedLineThatItsWarningPointsAt) {
    editor::Document doc;
    doc.setProject(strayProject(), QString());
    const QStringList lines = linesOf(doc);
    ASSERT_GE(lines.size(), 6);
    EXPECT_EQ(lines[0], QStringLiteral("; Start"));
    const QString marker = lines[1];
    EXPECT_TRUE(marker.startsWith(QLatin1String("; [[1:"))) << marker.toStdString();
    EXPECT_TRUE(marker.contains(QLatin1String("@2,1]] Rung 1: X5 (row 2, column 1)")))
        << marker.toStdString();
    EXPECT_FALSE(model::placeholderKey(marker).isEmpty());
    EXPECT_EQ(lines.mid(2, 4), (QStringList{"LD X0", "OUT Y0", "LD X1", "OUT Y1"}));
    // The marker is no instruction, and it is its rung's line.
    EXPECT_LT(doc.printedListing().instructionAt(2), 0);
    EXPECT_EQ(doc.rungOfLine(2), 0);
    EXPECT_EQ(doc.firstLineOfRung(0), 1);
    EXPECT_EQ(doc.firstLineOfRung(1), 5);
    // LD002 lands on the marker, not on the rung's first line.
    const model::Diagnostic *ld002 = find(doc.diagnostics(), "LD002");
    ASSERT_NE(ld002, nullptr);
    EXPECT_EQ(ld002->location.row, 1);
    EXPECT_EQ(ld002->location.cell, 0);
    EXPECT_EQ(doc.lineOf(ld002->location), 2);
    // A finding on a listed cell lands on the line of the instruction written from it.
    EXPECT_EQ(doc.lineOf(model::Location{0, 0, 0, 0, doc.ladder().rungs[0].columns}), 4);
    EXPECT_EQ(doc.lineOf(model::Location{0, 0, 1, 0, 0}), 5);
    // The exported listing never holds the marker (the export refuses while LD002 stands,
    // and the document's own listing has no comment for it).
    for (const auto &[at, text] : doc.listing().list.comments)
        EXPECT_FALSE(text.contains(QLatin1String("[["))) << text.toStdString();
    // It reads as a placeholder in the list's colours.
    editor::IlLexer lexer(vigor());
    EXPECT_EQ(lexer.styleLine(marker).front(), editor::IlLexer::Placeholder);
}

// Before, any edit of the list rebuilt every rung from the text and the stray contact was gone
// without a word.
TEST(LeftOutContact, EditingAnotherRungKeepsIt) {
    editor::Document doc;
    doc.setProject(strayProject(), QString());
    const std::vector<model::Rung> before = doc.ladder().rungs;
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(doc.setListing(doc.listingText(), &errors));
    EXPECT_EQ(doc.ladder().rungs, before);
    EXPECT_EQ(doc.undoStack()->count(), 0);
    QString typed = doc.listingText();
    typed.replace(QLatin1String("LD X1"), QLatin1String("LD X2"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    ASSERT_EQ(doc.ladder().rungs.size(), 3u);
    EXPECT_EQ(doc.ladder().rungs[0], before[0]); // the drawing as it was, X5 and all
    EXPECT_NE(doc.ladder().rungs[1], before[1]);
    ASSERT_NE(find(doc.diagnostics(), "LD002"), nullptr);
    // The rung's comment edited in the list: the drawing stays, with the new comment.
    typed = doc.listingText();
    typed.replace(QLatin1String("; Start"), QLatin1String("; Start button"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    EXPECT_EQ(doc.ladder().rungs[0].comment, QStringLiteral("Start button"));
    EXPECT_EQ(doc.ladder().rungs[0].cell(1, 0).kind, model::CellKind::Contact);
}

TEST(LeftOutContact, EditingItsOwnRungKeepsItAtItsCellOrInANewRow) {
    editor::Document doc;
    doc.setProject(strayProject(), QString());
    std::vector<model::Diagnostic> errors;
    // X0 becomes X3: the second row is free, X5 goes back to row 2, column 1.
    QString typed = doc.listingText();
    typed.replace(QLatin1String("LD X0"), QLatin1String("LD X3"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    const model::Rung &first = doc.ladder().rungs.at(0);
    ASSERT_GE(first.rows, 2);
    EXPECT_EQ(first.cell(0, 0).contact.operands, contact("X3").operands);
    EXPECT_EQ(first.cell(1, 0).kind, model::CellKind::Contact);
    EXPECT_EQ(first.cell(1, 0).contact.operands, contact("X5").operands);
    // A branch typed where X5 stood: X5 moves to a row of its own below, still on no path.
    typed = doc.listingText();
    typed.replace(QLatin1String("LD X3\n"), QLatin1String("LD X3\nOR X4\n"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    const model::Rung &branched = doc.ladder().rungs.at(0);
    ASSERT_EQ(branched.rows, 3);
    EXPECT_EQ(branched.cell(1, 0).contact.operands, contact("X4").operands);
    EXPECT_EQ(branched.cell(2, 0).contact.operands, contact("X5").operands);
    const model::Diagnostic *ld002 = find(doc.diagnostics(), "LD002");
    ASSERT_NE(ld002, nullptr);
    EXPECT_EQ(ld002->location.row, 2);
    EXPECT_TRUE(
        linesOf(doc).join(QLatin1Char('\n')).contains(QLatin1String("X5 (row 3, column 1)")));
}

TEST(LeftOutContact, DeletingItsLineLetsItGoAsOneUndoStep) {
    editor::Document doc;
    doc.setProject(strayProject(), QString());
    const std::vector<model::Rung> before = doc.ladder().rungs;
    QStringList lines = linesOf(doc);
    lines.removeAt(1);
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(doc.setListing(lines.join(QLatin1Char('\n')), &errors));
    EXPECT_EQ(find(doc.diagnostics(), "LD002"), nullptr);
    for (const model::Cell &c : doc.ladder().rungs.at(0).cells)
        EXPECT_FALSE(c.kind == model::CellKind::Contact &&
                     c.contact.operands == contact("X5").operands);
    ASSERT_EQ(doc.undoStack()->count(), 1);
    doc.undoStack()->undo();
    EXPECT_EQ(doc.ladder().rungs, before);
}

TEST(LeftOutContact, ALineWithNoRungBelowIsAnErrorNotALoss) {
    editor::Document doc;
    doc.setProject(strayProject(), QString());
    const std::vector<model::Rung> before = doc.ladder().rungs;
    QStringList lines = linesOf(doc);
    const QString marker = lines.takeAt(1);
    while (!lines.isEmpty() && lines.back().isEmpty())
        lines.removeLast();
    lines << marker; // after END
    std::vector<model::Diagnostic> errors;
    EXPECT_FALSE(doc.setListing(lines.join(QLatin1Char('\n')), &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].location.line, lines.size());
    EXPECT_TRUE(errors[0].message.contains(QLatin1String("X5"))) << errors[0].message.toStdString();
    EXPECT_EQ(doc.ladder().rungs, before);
}

// In the window: the warning's annotation stands under the marker line, and double-clicking
// it in Problems goes to the contact.
using LeftOutContactWindow = test::WindowFixture;

TEST_F(LeftOutContactWindow, TheListShowsTheWarningOnTheMarkedLine) {
    window.document()->setProject(strayProject(), QString());
    QApplication::processEvents();
    const QStringList lines = linesOf(*window.document());
    ASSERT_TRUE(lines[1].contains(QLatin1String("X5")));
    EXPECT_FALSE(window.ilEditor()->annotation(1).isEmpty());
    EXPECT_TRUE(window.ilEditor()->annotation(0).isEmpty());
    EXPECT_TRUE(window.ilEditor()->annotation(2).isEmpty());
}
