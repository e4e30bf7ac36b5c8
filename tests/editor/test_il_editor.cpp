// The instruction-list editor: the lexer's styles per target and the operand form of the
// mnemonic on the cursor's line.

#include "editor/il_editor.h"

#include <QTest>

#include <gtest/gtest.h>

using namespace rung;
using editor::IlLexer;

namespace {

// The style of the first character of `word` in `line`.
int styleOf(const IlLexer &lexer, const QString &line, const QString &word) {
    const auto styles = lexer.styleLine(line);
    const qsizetype at = line.indexOf(word);
    return at < 0 ? -1 : styles[static_cast<std::size_t>(at)];
}

} // namespace

TEST(IlLexer, MnemonicDeviceConstantAndCommentOnVigor) {
    IlLexer lexer(model::Target::get(model::Family::Vigor));
    const QString line = QStringLiteral("TMR T0 K10 ; one second");
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("TMR")), IlLexer::Mnemonic);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("T0")), IlLexer::Device);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("K10")), IlLexer::Constant);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("one")), IlLexer::Comment);
}

TEST(IlLexer, StepNumbersAndTwoWordMnemonicsOnVpc) {
    IlLexer lexer(model::Target::get(model::Family::Vpc));
    const QString line = QStringLiteral("0002 LD NOT i03");
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("0002")), IlLexer::StepNumber);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("NOT")), IlLexer::Mnemonic);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("i03")), IlLexer::Device);
}

TEST(IlLexer, BcdConstantsAndChannelBitsOnCpm1) {
    IlLexer lexer(model::Target::get(model::Family::Cpm1));
    const QString line = QStringLiteral("TIM 000 #0150");
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("TIM")), IlLexer::Mnemonic);
    EXPECT_EQ(styleOf(lexer, line, QStringLiteral("#0150")), IlLexer::Constant);
    EXPECT_EQ(styleOf(lexer, QStringLiteral("OUT 010.00"), QStringLiteral("010.00")),
              IlLexer::Device);
}

TEST(IlLexer, AnUnknownMnemonicIsMarked) {
    IlLexer lexer(model::Target::get(model::Family::Vigor));
    EXPECT_EQ(styleOf(lexer, QStringLiteral("LDD X0"), QStringLiteral("LDD")), IlLexer::Error);
}

TEST(IlEditorHelp, TheCursorsLineShowsTheOperandFormOfItsMnemonic) {
    editor::IlEditor editor(model::Target::get(model::Family::Vigor));
    editor.setListing(QStringLiteral("LD X0\nTMR T0 K10\nEND\n"));
    editor.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    editor.setCursorPosition(1, 2);
    QCoreApplication::processEvents(); // Scintilla reports the move when it updates
    EXPECT_TRUE(editor.toolTip().startsWith(QStringLiteral("TMR ")))
        << editor.toolTip().toStdString();
    EXPECT_TRUE(editor.toolTip().contains(QStringLiteral("T0..T255")))
        << editor.toolTip().toStdString();
    editor.setCursorPosition(2, 0);
    QCoreApplication::processEvents();
    // An instruction without operands still says what it does.
    EXPECT_EQ(editor.toolTip(), QStringLiteral("END — End of the program"));
    editor.setCursorPosition(3, 0); // the empty line after END: nothing to explain
    QCoreApplication::processEvents();
    EXPECT_EQ(editor.toolTip(), QString());
}

TEST(IlEditorHelp, ASpaceAfterAMnemonicShowsItsOperandFormAsACallTip) {
    editor::IlEditor editor(model::Target::get(model::Family::Vigor));
    editor.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    editor.setFocus();
    QTest::keyClicks(&editor, QStringLiteral("TMR "));
    EXPECT_TRUE(editor.operandTipShown());
    editor.SendScintilla(QsciScintillaBase::SCI_CALLTIPCANCEL);
    QTest::keyClicks(&editor, QStringLiteral("T0 "));
    EXPECT_FALSE(editor.operandTipShown()); // an operand is there: no tip
    QTest::keyClick(&editor, Qt::Key_Return);
    QTest::keyClicks(&editor, QStringLiteral("FOO "));
    EXPECT_FALSE(editor.operandTipShown()); // not a mnemonic of the target
}

TEST(IlEditorNotes, AMessageIsBrokenAtSpacesIntoLinesThatFit) {
    const QString message =
        QStringLiteral("X8: X is numbered in octal; the digits 8 and 9 do not occur [OP001]");
    const QString wrapped = editor::IlEditor::wrapNote(message, 20);
    for (const QString &line : wrapped.split(QLatin1Char('\n'))) {
        EXPECT_LE(line.size(), 20) << line.toStdString();
        EXPECT_FALSE(line.isEmpty());
    }
    EXPECT_EQ(QString(wrapped).replace(QLatin1Char('\n'), QLatin1Char(' ')), message);
    EXPECT_EQ(editor::IlEditor::wrapNote(message, 200), message);
    // A word longer than the line stands alone rather than being cut.
    EXPECT_EQ(editor::IlEditor::wrapNote(QStringLiteral("a 0123456789 b"), 4),
              QStringLiteral("a\n0123456789\nb"));
}

// A diagnostic's annotation under its line fits the view: narrowing the view wraps it onto
// more lines, widening it joins them again; nothing of the message is lost.
TEST(IlEditorNotes, AnnotationsWrapToTheWidthOfTheView) {
    editor::IlEditor editor(model::Target::get(model::Family::Vigor));
    editor.setListing(QStringLiteral("LD X8\nOUT Y0\nEND\n"));
    editor.resize(900, 300);
    editor.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    model::Diagnostic d;
    d.code = QStringLiteral("OP001");
    d.location.line = 1;
    d.location.column = 4;
    d.message = QStringLiteral("X8: X is numbered in octal, so the digits 8 and 9 never occur in "
                               "an address of the inputs of this PLC");
    editor.showDiagnostics({d});
    const QString full = d.message + QStringLiteral(" [OP001]");
    const auto lineCount = [&] { return editor.annotation(0).count(QLatin1Char('\n')) + 1; };
    const auto joined = [&] { return editor.annotation(0).replace(QLatin1Char('\n'), ' '); };
    EXPECT_EQ(joined(), full);
    const qsizetype wide = lineCount();
    editor.resize(260, 300);
    QCoreApplication::processEvents();
    EXPECT_GT(lineCount(), wide);
    EXPECT_EQ(joined(), full);
    for (const QString &line : editor.annotation(0).split(QLatin1Char('\n')))
        EXPECT_LE(line.size(), editor.noteColumns()) << line.toStdString();
    editor.resize(900, 300);
    QCoreApplication::processEvents();
    EXPECT_EQ(lineCount(), wide);
}

// Notes on thousands of lines are written hidden and shown at once: each shown annotation
// moved the scroll range and Qt queued an event for it (30,608 findings of a 10,000-rung
// program grew Qt's queue of posted events to 5 MB, which it keeps). The notes are all there
// and boxed afterwards.
TEST(IlEditorNotes, ThousandsOfNotesAreShownWithoutAnEventEach) {
    editor::IlEditor editor(model::Target::get(model::Family::Vigor));
    QString text;
    for (int i = 0; i < 1500; ++i)
        text += QStringLiteral("LD X0\nOUT Y%1\n").arg(i % 8);
    editor.setListing(text);
    editor.resize(900, 300);
    editor.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&editor));
    std::vector<model::Diagnostic> notes;
    for (int line = 1; line <= 3000; ++line) {
        model::Diagnostic d;
        d.code = QStringLiteral("DC001");
        d.location.line = line;
        d.message = QStringLiteral("a note on line %1").arg(line);
        notes.push_back(d);
    }
    struct Counter : QObject {
        int events = 0;
        bool eventFilter(QObject *, QEvent *) override {
            ++events;
            return false;
        }
    } counter;
    QCoreApplication::processEvents();
    qApp->installEventFilter(&counter);
    editor.showDiagnostics(notes);
    QCoreApplication::processEvents();
    qApp->removeEventFilter(&counter);
    EXPECT_LT(counter.events, 300); // one a note was over 3,000
    EXPECT_EQ(editor.annotationDisplay(), QsciScintilla::AnnotationBoxed);
    EXPECT_EQ(editor.annotation(0), QStringLiteral("a note on line 1 [DC001]"));
    EXPECT_EQ(editor.annotation(2999), QStringLiteral("a note on line 3000 [DC001]"));
}

// Replace Device starts from the device the caret is on in the list, as from the ladder's cell.
TEST(IlEditorDevice, TheDeviceAtTheCaretAsTheTargetWritesIt) {
    editor::IlEditor il(model::Target::get(model::Family::Vigor));
    il.setText(QStringLiteral("LD x1 ; start X7\nTMR T0 K10\nOUT Y0\n"));
    const auto at = [&il](int line, int index) {
        il.setCursorPosition(line, index);
        return il.deviceAtCaret();
    };
    EXPECT_EQ(at(0, 3), QStringLiteral("X1")); // on it, written as the target writes it
    EXPECT_EQ(at(0, 5), QStringLiteral("X1")); // just after it, where typing leaves the caret
    EXPECT_EQ(at(0, 0), QString());            // the mnemonic
    EXPECT_EQ(at(0, 15), QString());           // a device named in the comment is no operand
    EXPECT_EQ(at(1, 5), QStringLiteral("T0"));
    EXPECT_EQ(at(1, 8), QString()); // the constant K10
    EXPECT_EQ(at(2, 5), QStringLiteral("Y0"));
}

// The step numbers beside the lines: a line that loses its step (a comment now, a line with an
// error) shows none, and every number has the step numbers' style.
TEST(IlEditorSteps, NumbersFollowTheLinesAndAnOldOneGoes) {
    editor::IlEditor editor(model::Target::get(model::Family::Vigor));
    editor.setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    const auto margin = [&editor](int line) {
        const auto at = static_cast<unsigned long>(line);
        const long length =
            editor.SendScintilla(QsciScintillaBase::SCI_MARGINGETTEXT, at, static_cast<long>(0));
        QByteArray buffer(static_cast<qsizetype>(length) + 1, '\0');
        editor.SendScintilla(QsciScintillaBase::SCI_MARGINGETTEXT, at,
                             static_cast<void *>(buffer.data()));
        return QString::fromUtf8(buffer.constData());
    };
    editor.setStepNumbers({0, 1, 12345});
    EXPECT_EQ(margin(0), QStringLiteral("0000"));
    EXPECT_EQ(margin(1), QStringLiteral("0001"));
    EXPECT_EQ(margin(2), QStringLiteral("12345"));
    const long offset = editor.SendScintilla(QsciScintillaBase::SCI_MARGINGETSTYLEOFFSET);
    EXPECT_EQ(editor.SendScintilla(QsciScintillaBase::SCI_MARGINGETSTYLE, 1UL, 0L) + offset,
              editor::IlLexer::StepNumber);
    editor.setStepNumbers({-1, 0});
    EXPECT_EQ(margin(0), QString());
    EXPECT_EQ(margin(1), QStringLiteral("0000"));
    EXPECT_EQ(margin(2), QString()); // no step given for it
}
