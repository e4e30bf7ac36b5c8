// A rung the instruction list cannot express (a reverse-current bridge) keeps a marked line in
// the list, which names it and why; editing the list around that line never drops the rung.

#include "editor/document.h"
#include "editor/il_editor.h"
#include "model/convert/convert.h"
#include "model/ladder/ladder_text.h"
#include "model/listing/il.h"
#include "tests/targets.h"

#include <QRegularExpression>

#include <gtest/gtest.h>

using namespace rung;

namespace {

// X2 joins the two branches between contacts: no listing can express it (PLC concepts (WPLSoft
// family) 1.8).
const char *kBridge = "LADDER vigor WIDTH 8\n"
                      "RUNG 1 ROWS 3 COLUMNS 3\n"
                      "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                      "|        |                 |\n"
                      "|        +-[ X2 ]-+        +\n"
                      "|                 |        |\n"
                      "|-[ X3 ]----------+-[ X4 ]-+\n";

using rung::testing::vigor;

model::Rung bridge() {
    model::Rung r =
        model::parseLadderText(vigor(), QString::fromLatin1(kBridge)).ladder.rungs.at(0);
    r.comment = QStringLiteral("Bridge");
    return r;
}

// Rung 1 "Start", rung 2 the bridge, rung 3 "Lamp", rung 4 END.
model::Project bridgeProject() {
    const model::ParseResult parsed = model::parseInstructionList(
        vigor(), QStringLiteral("; Start\nLD X10\nOUT Y10\n; Lamp\nLD X5\nOUT Y5\nEND\n"));
    model::Project p;
    p.target = &vigor();
    p.model = vigor().defaultModel().name;
    p.program = model::listToLadder(parsed.list).ladder;
    p.program.rungs.insert(p.program.rungs.begin() + 1, bridge());
    return p;
}

QString lineOf(const editor::Document &doc, int line) {
    return doc.listingText().split(QLatin1Char('\n')).value(line - 1);
}

} // namespace

TEST(ListPlaceholder, ARungTheListCannotExpressHasAMarkedLineInItsPlace) {
    editor::Document doc;
    doc.setProject(bridgeProject(), QString());
    const QStringList lines = doc.listingText().split(QLatin1Char('\n'));
    ASSERT_GE(lines.size(), 8);
    EXPECT_EQ(lines.mid(0, 3), (QStringList{"; Start", "LD X10", "OUT Y10"}));
    const QString placeholder = lines[3];
    EXPECT_TRUE(placeholder.startsWith(QLatin1String("; [[2:"))) << placeholder.toStdString();
    EXPECT_TRUE(placeholder.contains(QLatin1String("Rung 2 is not in the list: Reverse current")))
        << placeholder.toStdString();
    EXPECT_FALSE(model::placeholderKey(placeholder).isEmpty());
    EXPECT_EQ(lines.mid(4, 4), (QStringList{"; Lamp", "LD X5", "OUT Y5", "END"}));
    // The placeholder is its rung's line: the cursor and the rung's findings land on it.
    EXPECT_EQ(doc.firstLineOfRung(1), 4);
    EXPECT_EQ(doc.rungOfLine(4), 1);
    EXPECT_EQ(doc.firstLineOfRung(2), 5);
    EXPECT_EQ(doc.rungOfLine(6), 2);
    const auto rc =
        std::find_if(doc.diagnostics().begin(), doc.diagnostics().end(),
                     [](const model::Diagnostic &d) { return d.code == QLatin1String("RC001"); });
    ASSERT_NE(rc, doc.diagnostics().end());
    EXPECT_EQ(rc->location.rung, 1);
    // It reads as a placeholder in the list's own colours, not as a comment.
    editor::IlLexer lexer(vigor());
    EXPECT_EQ(lexer.styleLine(placeholder).front(), editor::IlLexer::Placeholder);
    EXPECT_EQ(lexer.styleLine(QStringLiteral("; [[2 not a placeholder")).front(),
              editor::IlLexer::Comment);
}

TEST(ListPlaceholder, EditingTheListAroundItKeepsTheRung) {
    editor::Document doc;
    doc.setProject(bridgeProject(), QString());
    const std::vector<model::Rung> before = doc.ladder().rungs;
    std::vector<model::Diagnostic> errors;
    // The list as shown, applied: nothing changes, no undo step.
    ASSERT_TRUE(doc.setListing(doc.listingText(), &errors));
    EXPECT_EQ(doc.ladder().rungs, before);
    EXPECT_EQ(doc.undoStack()->count(), 0);
    // A device changed in another rung: the bridge stays, between the same rungs.
    const QString shown = doc.listingText();
    QString typed = shown;
    typed.replace(QLatin1String("LD X5"), QLatin1String("LD X6"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    ASSERT_EQ(doc.ladder().rungs.size(), 4u);
    EXPECT_EQ(doc.ladder().rungs[1], bridge());
    EXPECT_EQ(doc.ladder().rungs[0], before[0]);
    EXPECT_NE(doc.ladder().rungs[2], before[2]);
    // The first rung's lines deleted from the text as typed (which still says "rung 2"):
    // the bridge is the first rung now.
    typed.remove(QLatin1String("; Start\nLD X10\nOUT Y10\n"));
    ASSERT_TRUE(doc.setListing(typed, &errors));
    ASSERT_EQ(doc.ladder().rungs.size(), 3u);
    EXPECT_EQ(doc.ladder().rungs[0], bridge());
    EXPECT_EQ(doc.firstLineOfRung(0), 1);
    // The placeholder line moved below the lamp: so does the rung.
    const QString placeholder = lineOf(doc, 1);
    QString moved = doc.listingText();
    moved.remove(placeholder + QLatin1Char('\n'));
    moved.replace(QLatin1String("OUT Y5\n"),
                  QLatin1String("OUT Y5\n") + placeholder + QLatin1Char('\n'));
    ASSERT_TRUE(doc.setListing(moved, &errors));
    ASSERT_EQ(doc.ladder().rungs.size(), 3u);
    EXPECT_EQ(doc.ladder().rungs[1], bridge());
    EXPECT_EQ(doc.ladder().rungs[0].comment, QStringLiteral("Lamp"));
    // Every step is undone to the program as opened.
    while (doc.undoStack()->canUndo())
        doc.undoStack()->undo();
    EXPECT_EQ(doc.ladder().rungs, before);
}

TEST(ListPlaceholder, ALineForARungOfAnotherProgramIsAnErrorNotALoss) {
    editor::Document doc;
    doc.setProject(bridgeProject(), QString());
    const std::vector<model::Rung> before = doc.ladder().rungs;
    QString typed = doc.listingText();
    typed.replace(QRegularExpression(QStringLiteral("\\[\\[2:[0-9a-f]+\\]\\]")),
                  QStringLiteral("[[2:000000]]"));
    std::vector<model::Diagnostic> errors;
    EXPECT_FALSE(doc.setListing(typed, &errors));
    ASSERT_EQ(errors.size(), 1u);
    EXPECT_EQ(errors[0].location.line, 4);
    EXPECT_EQ(errors[0].code, QStringLiteral("SYN001"));
    EXPECT_EQ(doc.ladder().rungs, before);
}
