// The ladder edited while the instruction list holds typed text with errors: the list takes the
// ladder's program only when the user chose so, and Ctrl+Z in the list brings the text back.

#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"

#include <QApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

namespace {

// X is octal on a Vigor: X8 is no device, the list's line 4 is wrong.
const auto kProgram = QStringLiteral("LD X0\nOUT Y0\nEND\n");
const auto kTyped = QStringLiteral("LD X0\nOUT Y0\nLD X1\nOUT X8\nEND\n");

struct LadderEditOverTypedList : test::WindowFixture {
    editor::IlEditor *il = window.ilEditor();
    void SetUp() override {
        WindowFixture::SetUp();
        load(kProgram);
        window.setSideBySide(true); // both views in sight, as a user works with them
        showActive();
    }
    // Types the lines before END in the list, as a user does, and lets the program catch up.
    void typeInTheList() {
        il->setFocus();
        il->setCursorPosition(2, 0); // at END
        for (const char *line : {"LD X1", "OUT X8"}) {
            QTest::keyClicks(il, QString::fromLatin1(line));
            QTest::keyClick(il, Qt::Key_Return);
        }
        ASSERT_EQ(il->text(), kTyped);
        window.applyListing(); // what the typing pause does
        ASSERT_GT(window.problemsView()->count(model::Severity::Error), 0);
    }
    // A ladder edit: a contact X2 placed in series after X0.
    void editTheLadder() {
        view->setFocus();
        view->setCursor({0, 0, 1});
        typeIntoCell(Qt::Key_F5, "X2");
    }
    // Answers the next question with the button of this text; what it asked lands in *asked,
    // and the text of its default button in *byDefault.
    void answer(const QString &button, QString *asked, QString *byDefault = nullptr) {
        QTimer::singleShot(0, &window, [button, asked, byDefault] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            *asked = box->text();
            if (byDefault && box->defaultButton())
                *byDefault = box->defaultButton()->text();
            for (QAbstractButton *b : box->buttons())
                if (b->text().remove(QLatin1Char('&')) == button) {
                    b->click();
                    return;
                }
            box->reject();
        });
    }
};

} // namespace

TEST_F(LadderEditOverTypedList, CtrlZInTheListBringsTheTypedTextBack) {
    typeInTheList();
    QString asked;
    answer(QStringLiteral("Replace the List"), &asked);
    editTheLadder();
    // Asked first, naming the list's first error.
    EXPECT_TRUE(asked.contains(QStringLiteral("line 4"))) << asked.toStdString();
    EXPECT_TRUE(asked.contains(QStringLiteral("X8"))) << asked.toStdString();
    ASSERT_TRUE(window.document()->listingText().contains(QStringLiteral("AND X2")))
        << window.document()->listingText().toStdString();
    EXPECT_EQ(il->text(), window.document()->listingText());
    il->setFocus();
    QTest::keyClick(il, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(il->text(), kTyped);
}

TEST_F(LadderEditOverTypedList, CancelLeavesBothViewsAndTheTypedTextAsTheyWere) {
    typeInTheList();
    const int steps = window.document()->undoStack()->count();
    const quint64 revision = window.document()->rungsRevision();
    QString asked;
    QString byDefault;
    answer(QStringLiteral("Cancel"), &asked, &byDefault);
    editTheLadder();
    EXPECT_TRUE(asked.contains(QStringLiteral("line 4"))) << asked.toStdString();
    EXPECT_EQ(byDefault.remove(QLatin1Char('&')), QStringLiteral("Cancel"));
    EXPECT_EQ(il->text(), kTyped);
    EXPECT_EQ(window.document()->listingText(), kProgram); // the ladder as it was
    EXPECT_EQ(window.document()->rungsRevision(), revision);
    EXPECT_EQ(window.document()->undoStack()->count(), steps); // no step pushed
    EXPECT_GT(window.problemsView()->count(model::Severity::Error), 0);
}

// Typed within the typing pause, not yet checked: the edit asks all the same.
TEST_F(LadderEditOverTypedList, TextTypedJustNowIsAskedForToo) {
    il->setFocus();
    il->setCursorPosition(2, 0);
    QTest::keyClicks(il, QStringLiteral("OUT X8"));
    QTest::keyClick(il, Qt::Key_Return);
    QString asked;
    answer(QStringLiteral("Cancel"), &asked);
    editTheLadder();
    EXPECT_TRUE(asked.contains(QStringLiteral("line 3"))) << asked.toStdString();
    EXPECT_EQ(il->text(), QStringLiteral("LD X0\nOUT Y0\nOUT X8\nEND\n"));
    EXPECT_EQ(window.document()->listingText(), kProgram);
}

// Edit > Redo of a ladder step would replace the list as typed too: asked the same way.
TEST_F(LadderEditOverTypedList, RedoOfALadderStepAsksFirst) {
    editTheLadder();
    QUndoStack *stack = window.document()->undoStack();
    stack->undo();
    ASSERT_EQ(window.document()->listingText(), kProgram);
    typeInTheList();
    const int index = stack->index();
    QAction *redo = test::editMenuEntry(window, QStringLiteral("Redo Place LD X2"));
    ASSERT_NE(redo, nullptr);
    QString asked;
    answer(QStringLiteral("Cancel"), &asked);
    redo->trigger();
    EXPECT_TRUE(asked.contains(QStringLiteral("line 4"))) << asked.toStdString();
    EXPECT_EQ(stack->index(), index);
    EXPECT_EQ(il->text(), kTyped);
    answer(QStringLiteral("Replace the List"), &asked);
    redo->trigger();
    EXPECT_EQ(stack->index(), index + 1);
    EXPECT_TRUE(il->text().contains(QStringLiteral("AND X2")));
}

// Without typed errors nothing is asked: the list simply follows the ladder.
TEST_F(LadderEditOverTypedList, AListWithoutErrorsFollowsWithoutAQuestion) {
    QString asked;
    answer(QStringLiteral("Cancel"), &asked);
    editTheLadder();
    EXPECT_TRUE(asked.isEmpty()) << asked.toStdString();
    EXPECT_TRUE(il->text().contains(QStringLiteral("AND X2")));
}
