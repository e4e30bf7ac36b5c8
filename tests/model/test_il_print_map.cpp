#include "convert_test_util.h"
#include "random_program.h"

#include <gtest/gtest.h>

// The printer's line map (PrintedListing): the lines the parser gives the printed text, so the
// editor and the main window need not count comment lines themselves.

using namespace rung::model;
using rung::model::test::parse;

namespace {

// Every instruction of the printed text is on the line the map says, every other line is a
// comment, and the map runs both ways.
void expectMapMatchesTheText(const InstructionList &list, const PrintedListing &printed) {
    const ParseResult back = parseInstructionList(*list.target, printed.text);
    ASSERT_TRUE(back.ok()) << printed.text.toStdString();
    ASSERT_EQ(back.list.instructions.size(), list.instructions.size());
    ASSERT_EQ(printed.instructionLine.size(), list.instructions.size());
    ASSERT_EQ(printed.instructionOfLine.size(),
              static_cast<std::size_t>(printed.text.count(QLatin1Char('\n'))));
    for (std::size_t i = 0; i < list.instructions.size(); ++i) {
        EXPECT_EQ(printed.instructionLine[i], back.list.instructions[i].line) << i;
        EXPECT_EQ(printed.instructionAt(printed.instructionLine[i]), static_cast<int>(i));
        EXPECT_LE(printed.firstLine[i], printed.instructionLine[i]);
    }
    const QStringList lines = printed.text.split(QLatin1Char('\n'));
    for (int line = 1; line <= static_cast<int>(printed.instructionOfLine.size()); ++line)
        if (printed.instructionAt(line) < 0) {
            EXPECT_TRUE(lines[line - 1].startsWith(QLatin1Char(';'))) << line;
        }
    EXPECT_EQ(printed.instructionAt(0), -1);
    EXPECT_EQ(printed.instructionAt(static_cast<int>(printed.instructionOfLine.size()) + 1), -1);
}

} // namespace

TEST(PrintedListing, TheMapGivesTheLinesTheParserReads) {
    const InstructionList list = parse(
        Family::Vigor, QStringLiteral("; start rung\n; second line\nLD X0 // start\nOUT Y0\n"
                                      "// stop rung\nLD X1\nOUT Y1 ; lamp\nEND\n; trailing\n"));
    const PrintedListing printed = printListing(list);
    expectMapMatchesTheText(list, printed);
    EXPECT_EQ(printed.instructionLine, (std::vector<int>{3, 4, 6, 7, 8}));
    EXPECT_EQ(printed.firstLine, (std::vector<int>{1, 4, 5, 7, 8, 9}));
    EXPECT_EQ(printed.text, printInstructionList(list));
}

TEST(PrintedListing, StepNumbersDoNotMoveTheLines) {
    const InstructionList list =
        parse(Family::Vigor, QStringLiteral("; c\nLD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND\n"));
    PrintOptions o;
    o.stepNumbers = true;
    expectMapMatchesTheText(list, printListing(list, o));
}

// A comment holding a line break (a rung comment typed with one, a file with a bare CR) used
// to print as one "; " line followed by a line of text that is no comment: the editor showed
// it as code and every line number after it was one off from the count of comment entries.
TEST(PrintedListing, ALineBreakInsideACommentPrintsAsCommentLines) {
    InstructionList list =
        parse(Family::Vigor, QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND"));
    list.comments.emplace_back(0, QStringLiteral("first\rsecond"));
    list.comments.emplace_back(2, QStringLiteral("third\r\nfourth\nfifth"));
    list.instructions[1].comment = QStringLiteral("a\nb");
    const PrintedListing printed = printListing(list);
    expectMapMatchesTheText(list, printed);
    EXPECT_EQ(printed.instructionLine, (std::vector<int>{3, 4, 8, 9, 10}));
    // Counting one line per comment entry (the editor's old count) put LD X1 on line 6.
    EXPECT_EQ(printed.firstLine[2], 5);
    EXPECT_EQ(printed.text.count(QLatin1Char('\r')), 0);
}

// Over random programs of every target with rung comments from the ladder.
TEST(PrintedListing, RandomProgramsWithRungCommentsKeepTheirMap) {
    for (Family f : {Family::Vpc, Family::Vigor, Family::Cpm1, Family::Pl110}) {
        const Target &t = Target::get(f);
        for (std::uint64_t seed = 1; seed <= 50; ++seed) {
            ToLadderResult lad = listToLadder(parse(f, rung::testing::randomProgram(t, seed)));
            ASSERT_TRUE(lad.ok());
            for (std::size_t r = 0; r < lad.ladder.rungs.size(); r += 2)
                lad.ladder.rungs[r].comment = QStringLiteral("rung %1\nsecond line").arg(r);
            const ToListingResult back = ladderToList(lad.ladder);
            ASSERT_TRUE(back.ok());
            expectMapMatchesTheText(back.list, printListing(back.list));
        }
    }
}

// The document prints its listing with placeholder comments of its own: the comments given
// replace the list's, the instructions and their line map are the list's.
TEST(PrintedListing, CommentsGivenApartReplaceTheListsOwn) {
    const InstructionList list = parse(
        Family::Vigor, QStringLiteral("; the list's own\nLD X0\nOUT Y0\nLD X1\nOUT Y1\nEND\n"));
    const std::vector<std::pair<int, QString>> comments = {{0, QStringLiteral("first")},
                                                           {2, QStringLiteral("placeholder")},
                                                           {2, QStringLiteral("third")}};
    const PrintedListing printed = printListing(list, comments);
    EXPECT_EQ(printed.text, QStringLiteral("; first\nLD X0\nOUT Y0\n; placeholder\n; third\n"
                                           "LD X1\nOUT Y1\nEND\n"));
    EXPECT_EQ(printed.instructionLine, (std::vector<int>{2, 3, 6, 7, 8}));
    EXPECT_EQ(printed.firstLine, (std::vector<int>{1, 3, 4, 7, 8, 9}));
    InstructionList same = list;
    same.comments = comments;
    expectMapMatchesTheText(same, printed);
    EXPECT_EQ(printListing(list).text.count(QStringLiteral("the list's own")), 1);
}
