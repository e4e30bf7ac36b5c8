// The document's rung lines come from the printer's line map (model::PrintedListing): they
// are the lines the list editor shows, whatever the rung comments hold.

#include "editor/document.h"

#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace rung;

namespace {

// The listing's lines as the list editor shows them: \r\n, \r and \n all end a line.
QStringList shownLines(const QString &text) {
    return text.split(QRegularExpression(QStringLiteral("\\r\\n|\\r|\\n")));
}

} // namespace

// The editor used to count one line per rung comment entry: a comment with a bare CR (a
// project written elsewhere) shows as two lines, and every rung after it was placed one line
// too early.
TEST(DocumentLines, RungLinesAreTheLinesTheListShows) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(document.setListing(
        QStringLiteral("; start\nLD X0\nOUT Y0\n; stop\nLD X1\nOUT Y1\nLD X2\nOUT Y2\nEND\n"),
        &errors));
    ASSERT_EQ(document.ladder().rungs.size(), 4u);
    model::Rung first = document.ladder().rungs[0];
    first.comment = QStringLiteral("start\rwith a second line");
    document.setRung(0, first, QStringLiteral("Comment"));
    const QStringList lines = shownLines(document.listingText());
    const auto lineOf = [&](const QString &text) { return lines.indexOf(text) + 1; };
    EXPECT_EQ(document.firstLineOfRung(0), lineOf(QStringLiteral("; start")));
    EXPECT_EQ(document.firstLineOfRung(1), lineOf(QStringLiteral("; stop")));
    EXPECT_EQ(document.firstLineOfRung(2), lineOf(QStringLiteral("LD X2")));
    EXPECT_EQ(document.firstLineOfRung(3), lineOf(QStringLiteral("END")));
    EXPECT_EQ(document.rungOfLine(lineOf(QStringLiteral("OUT Y1"))), 1);
    EXPECT_EQ(document.rungOfLine(lineOf(QStringLiteral("; with a second line"))), 0);
    // Every line of code is an instruction of the map, every other line a comment.
    const auto &map = document.printedListing();
    for (int line = 1; line < static_cast<int>(lines.size()); ++line)
        EXPECT_EQ(map.instructionAt(line) >= 0, !lines[line - 1].startsWith(QLatin1Char(';')))
            << line;
}

// A finding of the listing checks sits on the element its instruction came from: the list marks
// that instruction's line, not the rung's first line, which is its comment (an OUT on an input
// was marked on "; a comment" and placed at "rung 1" only).
TEST(DocumentLines, AListingFindingIsOnItsInstructionsLineAndCell) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(document.setListing(QStringLiteral("; a comment\nLD X0\nOUT Y0\n"
                                                   "; another\nLD X1\nAND X2\nOUT X3\nEND\n"),
                                    &errors));
    const QStringList lines = shownLines(document.listingText());
    const auto lineOf = [&](const QString &text) { return lines.indexOf(text) + 1; };
    const auto &all = document.diagnostics();
    const auto op002 = std::find_if(all.begin(), all.end(), [](const model::Diagnostic &d) {
        return d.code == QLatin1String("OP002");
    });
    ASSERT_NE(op002, all.end());
    EXPECT_EQ(op002->location.rung, 1);
    EXPECT_EQ(op002->location.row, 0);
    EXPECT_EQ(op002->location.cell, document.ladder().rungs[1].columns) << "the output column";
    EXPECT_EQ(document.lineOf(op002->location), lineOf(QStringLiteral("OUT X3")));
}

// The list pane's values read the document's instructions without a copy: what it holds stays
// the listing it was given after an edit replaces the document's, and is the document's own
// until then.
TEST(DocumentLines, SharedInstructionsOutliveTheNextRefreshUnchanged) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(document.setListing(QStringLiteral("LD X0\nOUT Y0\nEND\n"), &errors));
    const auto held = document.sharedInstructions();
    ASSERT_TRUE(held);
    EXPECT_EQ(held.get(), &document.listing().list.instructions);
    ASSERT_TRUE(document.setListing(QStringLiteral("LD X0\nAND X1\nOUT Y0\nLD X2\nOUT Y2\nEND\n"),
                                    &errors));
    EXPECT_EQ(document.listing().list.instructions.size(), 6u);
    ASSERT_EQ(held->size(), 3u);
    EXPECT_EQ((*held)[1].spec->mnemonic, QStringLiteral("OUT"));
    EXPECT_NE(held.get(), &document.listing().list.instructions);
}
