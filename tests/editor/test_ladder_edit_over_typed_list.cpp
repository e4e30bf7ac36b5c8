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
    // Answers the next question with the button of this text; what it asked lands in *asked.
    void answer(const QString &button, QString *asked) {
        QTimer::singleShot(0, &window, [button, asked] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            *asked = box->text();
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
    ASSERT_TRUE(window.document()->listingText().contains(QStringLiteral("AND X2")))
        << window.document()->listingText().toStdString();
    EXPECT_EQ(il->text(), window.document()->listingText());
    il->setFocus();
    QTest::keyClick(il, Qt::Key_Z, Qt::ControlModifier);
    EXPECT_EQ(il->text(), kTyped);
}
