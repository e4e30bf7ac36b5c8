// PL110 MOVTXT (PL110 manual 4.2.10, 2.1.16): a text in double quotes in the listing, the
// ladder, the project file and PLCopen XML, and the checks of a text that does not fit.

#include "model/checks/checks.h"
#include "model/checks/operand_rules.h"
#include "model/convert/convert.h"
#include "model/exchange/plcopen.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "model/project/project.h"
#include "tests/targets.h"

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

using rung::testing::pl110;

// 2.1.16: "Per scrivere "TESTO DISPLAY" nella riga 3 del display per esempio, nel programma
// ladder sarà sufficiente inserire la seguente bobina: MOVTXT (DISP42, 1 Char per word)
// "TESTO DISPLAY"". In the listing: D, characters per word, the text.
const char *const kManualExample = "LD SM0.0\nMOVTXT DISP42 1 \"TESTO DISPLAY\"\nEND\n";

ParseResult parse(const QString &text) {
    return parseInstructionList(pl110(), text);
}

std::vector<Diagnostic> found(const QString &text, const char *code) {
    const ParseResult r = parse(text);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errors.front().message.toStdString());
    std::vector<Diagnostic> out;
    CheckOptions options;
    options.source = &text;
    for (const Diagnostic &d : checkList(r.list, options))
        if (d.code == QLatin1String(code))
            out.push_back(d);
    return out;
}

} // namespace

TEST(Pl110Text, TheManualsExampleParsesWithItsTextWhole) {
    const ParseResult r = parse(QString::fromLatin1(kManualExample));
    ASSERT_TRUE(r.ok()) << r.errors.front().message.toStdString();
    ASSERT_EQ(r.list.instructions.size(), 3u);
    const Instruction &ins = r.list.instructions[1];
    EXPECT_EQ(ins.spec->mnemonic, QStringLiteral("MOVTXT"));
    ASSERT_EQ(ins.operands.size(), 3u);
    EXPECT_EQ(formatOperand(pl110(), ins.operands[0]), QStringLiteral("DISP42"));
    EXPECT_EQ(ins.operands[1].constant.value, 1);
    EXPECT_EQ(ins.operands[2].kind, Operand::Kind::String);
    EXPECT_EQ(ins.operands[2].text, QStringLiteral("TESTO DISPLAY"));
    EXPECT_EQ(printInstruction(pl110(), ins), QStringLiteral("MOVTXT DISP42 1 \"TESTO DISPLAY\""));
    EXPECT_EQ(formatOperand(pl110(), ins.operands[2]), QStringLiteral("\"TESTO DISPLAY\""));
}

// A text keeps what a comment or a separator would otherwise cut: ';', '//', ',', spaces
// at either end, and a quote written twice.
TEST(Pl110Text, QuotesHoldCommentMarksSpacesAndDoubledQuotes) {
    const ParseResult r = parse(QStringLiteral(
        "MOVTXT V0 1 \"A;B // C, D\" ; a comment\nMOVTXT V20 2 \"  SAY \"\"HI\"\"  \"\nEND"));
    ASSERT_TRUE(r.ok()) << r.errors.front().message.toStdString();
    EXPECT_EQ(r.list.instructions[0].operands[2].text, QStringLiteral("A;B // C, D"));
    EXPECT_EQ(r.list.instructions[0].comment, QStringLiteral("a comment"));
    EXPECT_EQ(r.list.instructions[1].operands[2].text, QStringLiteral("  SAY \"HI\"  "));
    const QString printed = printInstructionList(r.list);
    EXPECT_TRUE(printed.contains(QStringLiteral("MOVTXT V20 2 \"  SAY \"\"HI\"\"  \"")))
        << printed.toStdString();
    const ParseResult again = parse(printed);
    ASSERT_TRUE(again.ok());
    for (std::size_t i = 0; i < r.list.instructions.size(); ++i)
        EXPECT_TRUE(again.list.instructions[i].sameAs(r.list.instructions[i]));
}

// Longer than any device or constant: a text is read whole, however long, and a text too
// long for its words is the check's to say (below), not the parser's.
TEST(Pl110Text, ATextLongerThanAnOperandIsReadWhole) {
    const QString text(168, QLatin1Char('X'));
    const ParseResult r = parse(QStringLiteral("MOVTXT DISP0 1 \"%1\"\nEND").arg(text));
    ASSERT_TRUE(r.ok()) << r.errors.front().message.toStdString();
    EXPECT_EQ(r.list.instructions[0].operands[2].text, text);
}

TEST(Pl110Text, MalformedTextsSayWhatAndWhere) {
    struct Case {
        const char *line;
        int column;
        const char *says;
    };
    const Case cases[] = {
        {"MOVTXT DISP0 1 \"OPEN", 16, "has no closing quote"},
        {"MOVTXT DISP0 1 TESTO", 16, "a text in double quotes is expected here"},
        {"MOV \"A\" V0", 5, "a text in quotes is not expected here"},
        {"MOVTXT DISP0 1", 14, "MOVTXT needs 3 operand"},
        {"\"LD\" I1", 1, "Unknown instruction"},
    };
    for (const Case &c : cases) {
        const ParseResult r = parse(QString::fromLatin1(c.line));
        ASSERT_FALSE(r.ok()) << c.line;
        EXPECT_EQ(r.errors.front().line, 1) << c.line;
        EXPECT_EQ(r.errors.front().column, c.column) << c.line;
        EXPECT_TRUE(r.errors.front().message.contains(QLatin1String(c.says)))
            << c.line << ": " << r.errors.front().message.toStdString();
    }
}

// 4.2.10: "ciascuna word dell'area di destinazione conterrà un solo carattere" /
// "due caratteri della stringa di partenza, iniziando dalla parte alta della word".
TEST(Pl110Text, TextWordsAreOneCharacterOrTwoHighByteFirst) {
    EXPECT_EQ(textWords(QStringLiteral("TESTO"), 1),
              (std::vector<std::int32_t>{'T', 'E', 'S', 'T', 'O'}));
    EXPECT_EQ(textWords(QStringLiteral("TESTO"), 2),
              (std::vector<std::int32_t>{('T' << 8) | 'E', ('S' << 8) | 'T', 'O' << 8}));
    EXPECT_EQ(textWords(QStringLiteral("25.0\u00b0C"), 1).at(4), 0xb0);
}

// The ladder draws the box with its text, and the list written from the ladder is the list
// read: IL -> ladder -> IL, and the ladder's own text form.
TEST(Pl110Text, TextTravelsThroughTheLadderAndItsTextForm) {
    const ParseResult r = parse(QString::fromLatin1(kManualExample));
    ASSERT_TRUE(r.ok());
    const ToLadderResult ladder = listToLadder(r.list);
    ASSERT_TRUE(ladder.ok());
    const LadderProgram &program = ladder.ladder;
    const ToListingResult back = ladderToList(program);
    ASSERT_TRUE(back.ok());
    EXPECT_EQ(printInstructionList(back.list), printInstructionList(r.list));
    const QString text = printLadderText(program);
    EXPECT_TRUE(text.contains(QStringLiteral("(MOVTXT DISP42 1 \"TESTO DISPLAY\")")))
        << text.toStdString();
    const LadderTextResult read = parseLadderText(pl110(), text);
    ASSERT_TRUE(read.ok()) << read.errors.front().message.toStdString();
    EXPECT_EQ(printInstructionList(ladderToList(read.ladder).list), printInstructionList(r.list));
}

// The project file keeps the text, quotes and all.
TEST(Pl110Text, TheProjectFileKeepsTheText) {
    const ParseResult r = parse(QStringLiteral("LD I1\nMOVTXT V0 2 \"A \"\"B\"\" ;C\"\nEND"));
    ASSERT_TRUE(r.ok());
    Project project;
    project.target = &pl110();
    project.program = listToLadder(r.list).ladder;
    ProjectError error;
    const std::optional<Project> loaded = projectFromJson(projectToJson(project), &error);
    ASSERT_TRUE(loaded) << error.message.toStdString();
    const ToListingResult list = ladderToList(loaded->program);
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(list.list.instructions[1].operands[2].text, QStringLiteral("A \"B\" ;C"));
}

// PLCopen XML: MOVTXT is a block of the PL110's own, its text an IEC STRING literal, and the
// file reads back to the same instruction.
TEST(Pl110Text, PlcopenWritesTheTextAsAStringAndReadsItBack) {
    const ParseResult r = parse(QStringLiteral("LD I1\nMOVTXT V0 1 \"IT'S $5\"\nEND"));
    ASSERT_TRUE(r.ok());
    Project project;
    project.target = &pl110();
    project.model = QStringLiteral("PL110-2A");
    project.program = listToLadder(r.list).ladder;
    const PlcopenExport xml = exportPlcopen(project, QStringLiteral("text"));
    EXPECT_TRUE(xml.xml.contains("'IT$'S $$5'")) << xml.xml.toStdString();
    const PlcopenImport back = importPlcopen(xml.xml, pl110(), pl110().model("PL110-2A"));
    ASSERT_TRUE(back.complete()) << (back.issues.empty()
                                         ? std::string("unmapped")
                                         : back.issues.front().message.toStdString());
    const ToListingResult list = ladderToList(back.project->program);
    ASSERT_TRUE(list.ok());
    EXPECT_EQ(printInstructionList(list.list), printInstructionList(r.list));
}

// A text too long for its words says how long, from where to where, and which word is
// missing; at the text's column.
TEST(Pl110Text, ATextLongerThanItsAreaSaysWhatAndWhere) {
    const auto d = found(QStringLiteral("LD I1\nMOVTXT DISP160 1 \"TESTO DISPLAY\"\nEND"), "OP005");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].severity, Severity::Error);
    EXPECT_EQ(d[0].location.line, 2);
    EXPECT_EQ(d[0].location.column, 18);
    EXPECT_EQ(d[0].message, QStringLiteral("the text of MOVTXT (length 13) is stored in "
                                           "DISP160..DISP172, but DISP168 does not exist: the "
                                           "text is too long for its place"));
    // Two characters a word take half the words: 13 characters in V343..V349.
    EXPECT_TRUE(found(QStringLiteral("MOVTXT V343 2 \"TESTO DISPLAY\"\nEND"), "OP005").empty());
    const auto two = found(QStringLiteral("MOVTXT V344 2 \"TESTO DISPLAY\"\nEND"), "OP005");
    ASSERT_EQ(two.size(), 1u);
    EXPECT_TRUE(two[0].message.contains(QStringLiteral("V344..V350, but V350")));
}

TEST(Pl110Text, CharactersThatDoNotFitOrDoNotShowAreNamed) {
    // Beyond a byte: an error, the character and its place in the text.
    const auto big = found(QStringLiteral("MOVTXT V0 1 \"TEMP \u2103\"\nEND"), "OP005");
    ASSERT_EQ(big.size(), 1u);
    EXPECT_TRUE(big[0].message.contains(QStringLiteral("'\u2103' (character 6)")))
        << big[0].message.toStdString();
    // Into the display: a tab is drawn as a space (a warning); the degree sign of 5.4's page
    // is shown. Into V the same text is any byte a program may want.
    const auto tab = found(QStringLiteral("MOVTXT DISP0 1 \"A\tB 25\u00b0C\"\nEND"), "OP007");
    ASSERT_EQ(tab.size(), 1u);
    EXPECT_EQ(tab[0].severity, Severity::Warning);
    EXPECT_EQ(tab[0].location.column, 16);
    EXPECT_EQ(tab[0].message, QStringLiteral("the display shows \\x09 of the text of MOVTXT as a "
                                             "space: it draws the character codes 32..126, "
                                             "160..255"));
    EXPECT_TRUE(found(QStringLiteral("MOVTXT V0 1 \"A\tB\"\nEND"), "OP007").empty());
    // Two characters a word do not fit a display character of 8 bits.
    const auto packed = found(QStringLiteral("MOVTXT DISP0 2 \"AB\"\nEND"), "OP005");
    ASSERT_EQ(packed.size(), 1u);
    EXPECT_EQ(packed[0].message, QStringLiteral("MOVTXT stores two characters a word, but DISP0 "
                                                "holds 8 bits a word: write 1 character per word"));
    // 1 or 2 characters a word, nothing else.
    const auto three = found(QStringLiteral("MOVTXT V0 3 \"AB\"\nEND"), "OP005");
    ASSERT_EQ(three.size(), 1u);
    EXPECT_EQ(three[0].message,
              QStringLiteral("the characters per word of MOVTXT must be 1 or 2, not 3"));
}
