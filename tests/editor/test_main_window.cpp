#include "app/gui/main_window.h"
#include "app/gui/symbol_table.h"
#include "editor/cross_reference_view.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include "model/ladder/ladder_text.h"

#include <QAction>
#include <QApplication>
#include <QClipboard>
#include <QFileInfo>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QTreeView>
#include <QUndoStack>

#include "tests/test_files.h"

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <optional>

using namespace rung;

namespace {

struct Fixture : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        showWithLadderFocused();
    }
    editor::LadderView *ladder() { return view; }
};

} // namespace

TEST_F(Fixture, FunctionKeysAndTypingPlaceContactsAndCoils) {
    EXPECT_EQ(listing(), QStringLiteral("END\n"));
    typeIntoCell(Qt::Key_F5, "X0"); // "LD " is prefilled
    typeIntoCell(Qt::Key_F6, "X1"); // "LDI "
    typeIntoCell(Qt::Key_F7, "Y0"); // "OUT "
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nANI X1\nOUT Y0\nEND\n"));
    // Typing a mnemonic with its operand into the selected cell, as the vendor tools allow.
    ladder()->setCursor({0, 1, 0});
    QTest::keyClicks(ladder(), QStringLiteral("L"));
    QLineEdit *edit = ladder()->inlineEditor();
    QTest::keyClicks(edit, QStringLiteral("D M5"));
    QTest::keyClick(edit, Qt::Key_Return);
    ladder()->setCursor({0, 0, 1});
    QTest::keyClick(ladder(), Qt::Key_F9, Qt::ShiftModifier); // link row 0 to row 1 at column 1
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR M5\nANI X1\nOUT Y0\nEND\n"));
}

TEST_F(Fixture, AWrongInstructionKeepsTheEditorOpenAndChangesNothing) {
    QTest::keyClick(ladder(), Qt::Key_F5);
    QTest::keyClicks(ladder()->inlineEditor(), QStringLiteral("X8"));
    QTest::keyClick(ladder()->inlineEditor(), Qt::Key_Return);
    EXPECT_TRUE(ladder()->inlineEditor()->isVisible());
    EXPECT_EQ(ladder()->inlineEditor()->toolTip(), QStringLiteral("X8: X is numbered in octal"));
    EXPECT_EQ(listing(), QStringLiteral("END\n"));
}

TEST_F(Fixture, EveryEditIsOneUndoStepWithALabel) {
    typeIntoCell(Qt::Key_F5, "X0");
    typeIntoCell(Qt::Key_F7, "Y0");
    QUndoStack *undo = window.document()->undoStack();
    ASSERT_EQ(undo->count(), 2);
    EXPECT_EQ(undo->text(0), QStringLiteral("Place LD X0"));
    EXPECT_EQ(undo->text(1), QStringLiteral("Place OUT Y0"));
    undo->undo();
    // The rung keeps its contact and loses its coil: not a complete circuit, so no listing yet.
    const model::Rung &rung = window.document()->ladder().rungs.front();
    EXPECT_EQ(rung.cell(0, 0).kind, model::CellKind::Contact);
    EXPECT_FALSE(rung.outputs[0].has_value());
    undo->undo();
    EXPECT_EQ(listing(), QStringLiteral("END\n"));
    undo->redo();
    undo->redo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
}

TEST_F(Fixture, EditingTheListRebuildsTheLadder) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nLD X1\nORB\nOUT Y0\nEND\n"));
    window.applyListing();
    const auto &rungs = window.document()->ladder().rungs;
    ASSERT_EQ(rungs.size(), 2u);
    EXPECT_EQ(rungs[0].rows, 2);
    // The ladder writes the canonical form back.
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->count(), 1);
}

TEST_F(Fixture, InvalidListKeepsTheLastLadderAndShowsTheError) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    window.ilEditor()->setText(QStringLiteral("LD X8\nOUT Y0\nEND\n"));
    window.applyListing();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    bool found = false;
    for (int i = 0; window.problemsView()->diagnosticAt(i); ++i)
        found = found || (window.problemsView()->diagnosticAt(i)->code == QLatin1String("SYN001") &&
                          window.problemsView()->diagnosticAt(i)->location.line == 1);
    EXPECT_TRUE(found);
}

// The other lines are checked while one does not parse: OUT X2 (an output to an input) is in
// the problems and marked in the list beside the syntax error of line 1.
TEST_F(Fixture, TheLinesThatParseAreCheckedWhileAnotherDoesNot) {
    window.ilEditor()->setText(QStringLiteral("LD X8\nOUT Y0\nLD X1\nOUT X2\nEND\n"));
    window.applyListing();
    QStringList found;
    for (int i = 0; const model::Diagnostic *d = window.problemsView()->diagnosticAt(i); ++i)
        found << QStringLiteral("%1@%2").arg(d->code).arg(d->location.line);
    EXPECT_EQ(found, (QStringList{QStringLiteral("SYN001@1"), QStringLiteral("OP002@4")}))
        << found.join(u' ').toStdString();
    EXPECT_NE(window.ilEditor()->markersAtLine(3), 0u); // line 4, 0-based
    EXPECT_TRUE(window.ilEditor()->annotation(3).contains(QStringLiteral("[OP002]")))
        << window.ilEditor()->annotation(3).toStdString();
}

TEST_F(Fixture, EditingTheListAfterAPauseNeedsNoExplicitApply) {
    QSignalSpy changed(window.document(), &editor::Document::programChanged);
    window.ilEditor()->setText(QStringLiteral("LD X2\nOUT Y2\nEND\n"));
    ASSERT_TRUE(changed.wait(3000)); // the 500 ms pause timer fires
    EXPECT_EQ(window.document()->ladder().rungs.size(), 2u);
}

TEST_F(Fixture, MouseClickSelectsTheCell) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    window.applyListing();
    const QRect cell = ladder()->cellRectOnScreen({0, 0, 1});
    QTest::mouseClick(ladder()->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
    EXPECT_EQ(ladder()->cursor(), (editor::CellCursor{0, 0, 1}));
}

TEST_F(Fixture, ProblemsNavigateToTheirPlace) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT X2\nEND\n"));
    window.applyListing();
    editor::ProblemsView *problems = window.problemsView();
    int row = -1;
    for (int i = 0; problems->diagnosticAt(i); ++i)
        if (problems->diagnosticAt(i)->code == QLatin1String("OP002"))
            row = i;
    ASSERT_GE(row, 0);
    QSignalSpy moved(ladder(), &editor::LadderView::cursorMoved);
    emit problems->activated(problems->model()->index(row, 0));
    EXPECT_EQ(ladder()->cursor().rung, 1);
}

TEST_F(Fixture, ReverseCurrentFixIsOneUndoStep) {
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
    auto find = [&]() -> const model::Diagnostic * {
        for (const model::Diagnostic &d : window.document()->diagnostics())
            if (d.code == QLatin1String("RC001"))
                return &d;
        return nullptr;
    };
    ASSERT_NE(find(), nullptr);
    const model::Diagnostic d = *find();
    ASSERT_TRUE(d.fix.has_value());
    const int before = window.document()->undoStack()->count();
    emit window.problemsView()->applyFix(d);
    EXPECT_EQ(find(), nullptr);
    EXPECT_EQ(window.document()->undoStack()->count(), before + 1);
    window.document()->undoStack()->undo();
    EXPECT_NE(find(), nullptr);
}

TEST_F(Fixture, SaveAndOpenGiveTheSameProgram) {
    window.ilEditor()->setText(
        QStringLiteral("; pump\nLD X0\nOR X1\nANI X2\nOUT Y0\nTMR T0 K10\nEND\n"));
    window.applyListing();
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("pump.rung"));
    ASSERT_TRUE(window.saveTo(path));
    EXPECT_FALSE(window.document()->isModified());
    const QString before = listing();
    window.newProject(model::Target::get(model::Family::Vpc), QString());
    ASSERT_TRUE(window.openFile(path, QString(), true));
    EXPECT_EQ(listing(), before);
    EXPECT_EQ(window.document()->target().id, QStringLiteral("vigor"));
}

TEST_F(Fixture, UnreadableFileLeavesTheProgramAlone) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    QTemporaryDir dir;
    const QString path = test::writeFile(
        dir, QStringLiteral("broken.rung"),
        "{\"format\": \"rungstudio-project\", \"schema\": 1, \"target\": \"vigor\", \"rungs\": [");
    EXPECT_FALSE(window.openFile(path, QString(), true));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
}

// A device or a pipe has no size to ask: opening a listing or importing symbols from one
// stops at the limit instead of reading forever, and the program stays as it was.
TEST_F(Fixture, AnEndlessDeviceIsRefusedAtTheLimit) {
    if (!QFile::exists(QStringLiteral("/dev/zero")))
        GTEST_SKIP() << "no /dev/zero";
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    EXPECT_FALSE(window.openFile(QStringLiteral("/dev/zero"), QStringLiteral("vigor"), true));
    QString error;
    EXPECT_FALSE(window.symbolTable()->importCsv(QStringLiteral("/dev/zero"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("larger than 64 MB"))) << error.toStdString();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
}

// A listing names its PLC on the first line, as the command-line tool reads it too; one that
// names none opens for the PLC whose syntax it is written in: an exported CPM1 listing
// reopened in a window set for Vigor is a CPM1 program, not a page of errors.
TEST_F(Fixture, AListingOpensForTheTargetItNamesOrWhoseSyntaxItIs) {
    const QByteArray program = "LD 000.00\nOR 010.00\nAND NOT 000.01\nOUT 010.00\nEND(01)\n";
    for (const QByteArray &text : {"; target: cpm1\n" + program, program}) {
        app::MainWindow window;
        QTemporaryDir dir;
        const QString path = test::writeFile(dir, QStringLiteral("keep.il"), text);
        ASSERT_EQ(window.document()->target().family, model::Family::Vigor);
        ASSERT_TRUE(window.openFile(path, QString(), true));
        EXPECT_EQ(window.document()->target().family, model::Family::Cpm1) << text.constData();
        EXPECT_EQ(window.document()->ladder().rungs.size(), 2u);
    }
}

// A listing with errors is not refused: it opens as typed, its errors marked, so that the
// user can fix it where it is shown; the ladder follows once it is valid.
TEST_F(Fixture, AListingWithErrorsOpensAsTypedWithItsErrorsMarked) {
    QTemporaryDir dir;
    const QString text = QStringLiteral("; target: vigor\nLD X0\nOUT Y0\nLD X8\nOUT Y1\nEND\n");
    const QString path = test::writeFile(dir, QStringLiteral("broken.il"), text.toUtf8());
    ASSERT_TRUE(window.openFile(path, QString(), true));
    EXPECT_EQ(window.ilEditor()->text(), text);
    EXPECT_EQ(listing(), QStringLiteral("END\n")); // the ladder: a new, empty program
    EXPECT_TRUE(ladder()->notice().contains(QStringLiteral("line 4")))
        << ladder()->notice().toStdString();
    editor::ProblemsView *problems = window.problemsView();
    ASSERT_NE(problems->diagnosticAt(0), nullptr);
    EXPECT_EQ(problems->diagnosticAt(0)->location.line, 4);
    EXPECT_TRUE(problems->diagnosticAt(0)->message.contains(QStringLiteral("octal")));

    window.ilEditor()->setSelection(3, 4, 3, 5);
    window.ilEditor()->replaceSelectedText(QStringLiteral("7"));
    window.applyListing();
    EXPECT_TRUE(ladder()->notice().isEmpty());
    // The `; target:` line names the PLC; it is no comment of the first rung (issue 15).
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD X7\nOUT Y1\nEND\n"));
}

// An edit on the ladder while the list holds text with errors shows the ladder's program in
// the list; what was typed is one Ctrl+Z away in the list, and the status bar says so.
TEST_F(Fixture, TypedTextWithErrorsGivesWayToALadderEditButStaysInTheListsUndo) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    const QString typed = QStringLiteral("LD X0\nOUT Y0\nLD X9\nEND\n");
    window.ilEditor()->setText(typed);
    window.applyListing();
    ASSERT_EQ(window.ilEditor()->text(), typed);
    ladder()->setFocus();
    ladder()->setCursor({0, 0, 1});
    // Asked first (test_ladder_edit_over_typed_list.cpp): the user lets the list go.
    QTimer::singleShot(0, &window, [] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget()))
            for (QAbstractButton *b : box->buttons())
                if (b->text() == QStringLiteral("Replace the List"))
                    b->click();
    });
    typeIntoCell(Qt::Key_F5, "X1");
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.ilEditor()->text(), listing());
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QStringLiteral("Ctrl+Z")));
    window.ilEditor()->undo();
    EXPECT_EQ(window.ilEditor()->text(), typed);
}

namespace {

// The window's action with this shortcut, as the user reaches it.
QAction *actionWithShortcut(QWidget &window, const QKeySequence &key) {
    for (QAction *a : window.findChildren<QAction *>())
        if (a->shortcuts().contains(key))
            return a;
    return nullptr;
}

// Leaves work unsaved in a window that never closes, as a crash does: its recovery file is
// orphaned when the window goes. The program came from `original` when that is not empty.
void crashWithUnsavedWork(const QString &original, const QString &listing) {
    app::MainWindow crashed;
    crashed.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    if (!original.isEmpty()) {
        ASSERT_TRUE(crashed.saveTo(original));
    }
    crashed.ilEditor()->setText(listing);
    crashed.applyListing();
    ASSERT_TRUE(crashed.document()->isModified());
    crashed.writeRecovery();
    ASSERT_TRUE(QFileInfo::exists(crashed.recoveryPath()));
    // While its instance runs, its work is no other window's to recover.
    app::MainWindow other;
    EXPECT_NE(other.recoveryPath(), crashed.recoveryPath());
    EXPECT_FALSE(other.offerRecovery(false));
}

} // namespace

TEST_F(Fixture, RecoveryBringsBackUnsavedWork) {
    QTemporaryDir dir;
    const QString original = dir.filePath(QStringLiteral("plant.rung"));
    crashWithUnsavedWork(original, QStringLiteral("LD X5\nOUT Y5\nEND\n"));
    app::MainWindow other;
    other.show();
    ASSERT_TRUE(other.offerRecovery(false));
    EXPECT_EQ(other.document()->listingText(), QStringLiteral("LD X5\nOUT Y5\nEND\n"));
    // The recovered work is in no file yet: modified, with its original file to save to.
    EXPECT_TRUE(other.document()->isModified());
    EXPECT_TRUE(other.isWindowModified());
    EXPECT_EQ(other.document()->path(), original);
    EXPECT_TRUE(QFileInfo::exists(other.recoveryPath()));
    EXPECT_FALSE(app::MainWindow().offerRecovery(false)); // recovered once only
    // Closing asks to save; Cancel keeps the window and the recovery file.
    bool asked = false;
    QTimer::singleShot(0, &other, [&asked] {
        if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
            asked = true;
            box->button(QMessageBox::Cancel)->click();
        }
    });
    EXPECT_FALSE(other.close());
    EXPECT_TRUE(asked);
    EXPECT_TRUE(QFileInfo::exists(other.recoveryPath()));
    // Save writes the original file, and the recovery file goes.
    QAction *save = actionWithShortcut(other, QKeySequence::Save);
    ASSERT_NE(save, nullptr);
    save->trigger();
    EXPECT_FALSE(other.document()->isModified());
    EXPECT_FALSE(QFileInfo::exists(other.recoveryPath()));
    app::MainWindow reopened;
    ASSERT_TRUE(reopened.openFile(original, QString(), true));
    EXPECT_EQ(reopened.document()->listingText(), QStringLiteral("LD X5\nOUT Y5\nEND\n"));
}

TEST_F(Fixture, RecoveryIsOfferedBeforeTheCommandLinesFile) {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("asked.il"));
    {
        QFile out(file);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write("LD X1\nOUT Y1\nEND\n");
    }
    crashWithUnsavedWork(QString(), QStringLiteral("LD X6\nOUT Y6\nEND\n"));
    app::MainWindow recovering;
    recovering.start(file, QString(), false); // the user recovers: the recovered work wins
    EXPECT_EQ(recovering.document()->listingText(), QStringLiteral("LD X6\nOUT Y6\nEND\n"));
    EXPECT_TRUE(recovering.document()->isModified());
    EXPECT_TRUE(recovering.document()->path().isEmpty()); // no original file: Save As
    app::MainWindow plain;                                // nothing left to recover: the file opens
    plain.start(file, QString(), false);
    EXPECT_EQ(plain.document()->listingText(), QStringLiteral("LD X1\nOUT Y1\nEND\n"));
}

// Process ids repeat between runs (in containers the program often gets the same one): work
// left under this process's id by an earlier run is neither taken over nor lost.
TEST_F(Fixture, AnEarlierRunsRecoveryUnderTheSamePidIsOfferedNotOverwritten) {
    QTemporaryDir dir;
    const QString saved = dir.filePath(QStringLiteral("earlier.rung"));
    QString next; // the name the next window would take: one number further on
    {
        app::MainWindow earlier;
        earlier.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        earlier.ilEditor()->setText(QStringLiteral("LD X7\nOUT Y7\nEND\n"));
        earlier.applyListing();
        ASSERT_TRUE(earlier.saveTo(saved));
        const QString base = earlier.recoveryPath().chopped(5);
        const qsizetype dash = base.lastIndexOf(QLatin1Char('-'));
        next = base.left(dash + 1) + QString::number(base.mid(dash + 1).toInt() + 1) +
               QStringLiteral(".rung");
    }
    ASSERT_TRUE(QFile::copy(saved, next)); // left by an earlier run with this process id
    app::MainWindow window;
    EXPECT_NE(window.recoveryPath(), next);
    window.writeRecovery();
    ASSERT_TRUE(window.offerRecovery(false));
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X7\nOUT Y7\nEND\n"));
}

TEST_F(Fixture, CopyAndPasteRungsAlsoAsListingText) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    ladder()->setCursor({0, 0, 0});
    window.copyRung(false);
    EXPECT_EQ(QApplication::clipboard()->text(),
              QStringLiteral("LD X0\nOUT Y1\n").replace(QLatin1String("Y1"), QLatin1String("Y0")));
    window.pasteRungs();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD X0\nOUT Y0\nEND\n"));
    // Plain listing text from another program pastes as rungs too.
    QApplication::clipboard()->setText(QStringLiteral("LD X1\nANI X2\nOUT Y3\n"));
    ladder()->setCursor({2, 0, 0});
    window.pasteRungs();
    EXPECT_EQ(listing(),
              QStringLiteral("LD X0\nOUT Y0\nLD X0\nOUT Y0\nLD X1\nANI X2\nOUT Y3\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->text(window.document()->undoStack()->count() - 1),
              QStringLiteral("Paste rung"));
}

TEST_F(Fixture, ReplaceDeviceEverywhereIsOneUndoStep) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nLD Y0\nAND X0\nOUT Y1\nEND\n"));
    window.applyListing();
    QString error;
    EXPECT_EQ(window.replaceDeviceEverywhere(QStringLiteral("X0"), QStringLiteral("X7"), &error),
              2);
    EXPECT_EQ(listing(), QStringLiteral("LD X7\nOUT Y0\nLD Y0\nAND X7\nOUT Y1\nEND\n"));
    EXPECT_EQ(window.replaceDeviceEverywhere(QStringLiteral("X0"), QStringLiteral("X8"), &error),
              -1);
    EXPECT_EQ(error, QStringLiteral("X8: X is numbered in octal"));
    // A word where the contacts need a bit: refused, said, nothing changed, no undo step.
    const int steps = window.document()->undoStack()->count();
    EXPECT_EQ(window.replaceDeviceEverywhere(QStringLiteral("X7"), QStringLiteral("D0"), &error),
              -1);
    EXPECT_EQ(error,
              QStringLiteral("D0 cannot replace X7 in rung 1: a bit device is expected there."));
    EXPECT_EQ(listing(), QStringLiteral("LD X7\nOUT Y0\nLD Y0\nAND X7\nOUT Y1\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->count(), steps);
    window.document()->undoStack()->undo();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nLD Y0\nAND X0\nOUT Y1\nEND\n"));
}

TEST_F(Fixture, CrossReferenceListsEveryUse) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nLD Y0\nAND X0\nOUT Y1\nEND\n"));
    window.applyListing();
    window.crossReferenceDevice()->setText(QStringLiteral("Y0"));
    const QAbstractItemModel *rows = window.crossReference()->tree()->model();
    ASSERT_EQ(rows->rowCount(), 1); // the device, its uses below it
    const QModelIndex y0 = rows->index(0, 0);
    ASSERT_EQ(rows->rowCount(y0), 2);
    EXPECT_EQ(rows->index(0, 2, y0).data().toString(), QStringLiteral("coil"));
    EXPECT_EQ(rows->index(1, 0, y0).data().toString(), QStringLiteral("rung 2"));
    EXPECT_EQ(rows->index(1, 2, y0).data().toString(), QStringLiteral("contact"));
}

TEST_F(Fixture, SymbolsImportFromCsvAndShowByName) {
    QTemporaryDir dir;
    const QString path =
        test::writeFile(dir, QStringLiteral("symbols.csv"),
                        "device,name,comment\nX0,Start,\"green, big\"\nY0,Pump,\n");
    QString error;
    ASSERT_TRUE(window.symbolTable()->importCsv(path, &error)) << error.toStdString();
    const auto &symbols = window.document()->project().symbols;
    ASSERT_EQ(symbols.size(), 2u);
    EXPECT_EQ(symbols[0].comment, QStringLiteral("green, big"));
    QFile bad(dir.filePath(QStringLiteral("bad.csv")));
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
    bad.write("X9,Oops,\n");
    bad.close();
    EXPECT_FALSE(window.symbolTable()->importCsv(bad.fileName(), &error));
    EXPECT_TRUE(error.endsWith(QStringLiteral("line 1: X9: X is numbered in octal")));
    window.document()->undoStack()->undo();
    EXPECT_TRUE(window.document()->project().symbols.empty());
}

TEST_F(Fixture, FuzzyFormsOfTheTypedListOfferTheirCanonicalRewriteAsOneStep) {
    const QString typed =
        QStringLiteral("LD X0\nLD X1\nORB\nOUT Y0\nLD    X2   ; as typed\nOUT Y1\nEND\n");
    window.ilEditor()->setText(typed);
    window.applyListing();
    EXPECT_EQ(window.ilEditor()->text(), typed);             // the text stays as the user wrote it
    EXPECT_EQ(window.document()->ladder().rungs.size(), 3u); // and the ladder follows it
    editor::ProblemsView *problems = window.problemsView();
    // A copy: the panel's findings are replaced when the fix refreshes it.
    std::optional<model::Diagnostic> fuzzy;
    for (int i = 0; problems->diagnosticAt(i); ++i)
        if (problems->diagnosticAt(i)->code == QLatin1String("FZ002"))
            fuzzy = *problems->diagnosticAt(i);
    ASSERT_TRUE(fuzzy.has_value());
    EXPECT_EQ(fuzzy->severity, model::Severity::Warning);
    EXPECT_TRUE(fuzzy->location.onListing());
    ASSERT_TRUE(fuzzy->fix.has_value());
    const int programSteps = window.document()->undoStack()->count();

    emit problems->applyFix(model::Diagnostic(*fuzzy));
    EXPECT_EQ(window.ilEditor()->text(),
              QStringLiteral("LD X0\nOR X1\nOUT Y0\nLD    X2   ; as typed\nOUT Y1\nEND\n"));
    for (int i = 0; problems->diagnosticAt(i); ++i)
        EXPECT_FALSE(problems->diagnosticAt(i)->code.startsWith(QLatin1String("FZ")));
    // The program did not change, only its text; the fix is still one step of Edit > Undo
    // under its own label, and of the list's own undo (Ctrl+Z in the list).
    const QString fixed = window.ilEditor()->text();
    QUndoStack *stack = window.document()->undoStack();
    EXPECT_EQ(stack->count(), programSteps + 1);
    EXPECT_EQ(stack->undoText(), fuzzy->fix->label);
    stack->undo();
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_EQ(window.document()->ladder().rungs.size(), 3u);
    stack->redo();
    EXPECT_EQ(window.ilEditor()->text(), fixed);
    window.ilEditor()->undo();
    EXPECT_EQ(window.ilEditor()->text(), typed);
    // The lines were changed behind the step's back: it goes rather than overwrite them.
    stack->undo();
    EXPECT_EQ(window.ilEditor()->text(), typed);
    EXPECT_EQ(stack->count(), programSteps);
}

// Undo right after typing in the list takes back what was typed, even before the pause that
// applies it; the step is named like any edit of the list.
TEST_F(Fixture, UndoRightAfterTypingInTheListTakesTheTypingBack) {
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    window.applyListing();
    ASSERT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    QAction *undo = nullptr;
    QAction *redo = nullptr;
    for (QAction *a : window.findChildren<QAction *>()) {
        if (a->shortcut() == QKeySequence(QKeySequence::Undo))
            undo = a;
        if (a->shortcut() == QKeySequence(QKeySequence::Redo))
            redo = a;
    }
    ASSERT_TRUE(undo && redo);
    EXPECT_EQ(undo->text(), QStringLiteral("&Undo Edit instruction list"));

    window.ilEditor()->setFocus();
    window.ilEditor()->setCursorPosition(1, 0);
    QTest::keyClicks(window.ilEditor(), QStringLiteral("AND X1"));
    QTest::keyClick(window.ilEditor(), Qt::Key_Return);
    ASSERT_EQ(window.ilEditor()->text(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n")); // not applied yet
    undo->trigger();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.ilEditor()->text(), listing());
    EXPECT_EQ(redo->text(), QStringLiteral("&Redo Edit instruction list"));
    redo->trigger();
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));

    // Typing the program cannot follow yet (an error) is taken back in the list itself; the
    // program's steps stay as they are.
    const int steps = window.document()->undoStack()->index();
    window.ilEditor()->setCursorPosition(2, 0);
    QTest::keyClicks(window.ilEditor(), QStringLiteral("ORB"));
    QTest::keyClick(window.ilEditor(), Qt::Key_Return);
    window.applyListing(); // the pause passed: the list shows the error
    EXPECT_EQ(listing(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    EXPECT_TRUE(undo->isEnabled());
    undo->trigger();
    EXPECT_EQ(window.ilEditor()->text(), QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->index(), steps);
}
