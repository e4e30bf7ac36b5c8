// What a new user met on the way (issue 15's rough edges): status messages that outlive what
// they were about, Replace Device starting empty, the Edit menu without the parallel NC and
// edge contacts, a missing END without its fix.

#include "../test_files.h"
#include "app/gui/main_window.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include <QAction>
#include <QApplication>
#include <QCoreApplication>
#include <QInputDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTest>
#include <QTimer>
#include <QToolBar>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <functional>

using namespace rung;

namespace {

// The text a QInputDialog opened by `run` starts with; the dialog is then cancelled.
QString dialogStartText(const std::function<void()> &run) {
    QString seen = QStringLiteral("<no dialog>");
    QTimer::singleShot(0, [&seen] {
        if (auto *dialog = qobject_cast<QInputDialog *>(QApplication::activeModalWidget())) {
            seen = dialog->textValue();
            dialog->reject();
        }
    });
    run();
    return seen;
}

// The window on screen and active: the palette, the dialogs and the keys need it.
struct Shown : test::WindowFixture {
    void SetUp() override {
        WindowFixture::SetUp();
        showActive();
    }
};
using MissingEnd = Shown;
using OpenListing = Shown;
using PlaceElement = Shown;
using ReplaceDevice = Shown;
using StatusMessages = Shown;

} // namespace

TEST_F(StatusMessages, ThePaletteHintGoesWithTheTool) {
    QAction *tool = test::toolbarAction(window, QStringLiteral("Normally Open Contact"));
    ASSERT_NE(tool, nullptr);
    tool->trigger();
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QLatin1String("click a cell")));
    QTest::keyClick(window.ladderView(), Qt::Key_Escape);
    EXPECT_TRUE(window.ladderView()->armedTool().isEmpty());
    EXPECT_EQ(window.statusBar()->currentMessage(), QString());
    // A message about something else stays when a tool is put away.
    tool->trigger();
    window.statusBar()->showMessage(QStringLiteral("Saved"));
    QTest::keyClick(window.ladderView(), Qt::Key_Escape);
    EXPECT_EQ(window.statusBar()->currentMessage(), QStringLiteral("Saved"));
}

TEST_F(StatusMessages, HasErrorsGoesOnceTheListIsFixed) {
    QTemporaryDir dir;
    const QString path = test::writeFile(dir, QStringLiteral("bad.il"), "LD X0\nOUT Y8\nEND\n");
    ASSERT_TRUE(window.openFile(path, QStringLiteral("vigor")));
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QLatin1String("bad.il has errors")))
        << window.statusBar()->currentMessage().toStdString();
    // Still wrong: the message stays.
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y9\nEND\n"));
    window.applyListing();
    EXPECT_TRUE(window.statusBar()->currentMessage().contains(QLatin1String("has errors")));
    window.ilEditor()->setText(QStringLiteral("LD X0\nOUT Y7\nEND\n"));
    window.applyListing();
    EXPECT_EQ(window.document()->ladder().rungs.size(), 2u);
    EXPECT_EQ(window.statusBar()->currentMessage(), QString());
}

TEST_F(ReplaceDevice, StartsFromTheDeviceUnderTheCursor) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X3\nOUT Y2\nEND\n"), &errors));
    QAction *replace = test::editMenuEntry(window, QStringLiteral("Replace Device..."));
    ASSERT_NE(replace, nullptr);
    window.ladderView()->setFocus();
    window.ladderView()->setCursor({0, 0, 0});
    EXPECT_EQ(dialogStartText([&] { replace->trigger(); }), QStringLiteral("X3"));
    // In the list: the device the caret is on.
    editor::IlEditor *il = window.ilEditor();
    if (!il->isVisible())
        window.setSideBySide(true);
    // The offscreen platform does not hand the activation back when a dialog closes, as a
    // desktop does: the window takes it back and the list the focus before each try.
    auto focusList = [&] {
        window.activateWindow();
        return QTest::qWaitForWindowActive(&window) &&
               (il->setFocus(), QTest::qWaitFor([&] { return il->hasFocus(); }));
    };
    ASSERT_TRUE(focusList());
    il->setCursorPosition(1, 5);
    EXPECT_EQ(dialogStartText([&] { replace->trigger(); }), QStringLiteral("Y2"));
    // Nothing under the cursor: an empty field, as before.
    ASSERT_TRUE(focusList());
    il->setCursorPosition(2, 1);
    EXPECT_EQ(dialogStartText([&] { replace->trigger(); }), QString());
}

TEST_F(PlaceElement, TheEditMenuHasTheParallelClosedAndEdgeContacts) {
    auto place = [&](const char *entry, const char *operand) {
        QAction *a = test::editMenuEntry(window, QString::fromLatin1(entry));
        ASSERT_NE(a, nullptr) << entry;
        EXPECT_TRUE(a->text().contains(QLatin1Char('&'))) << entry;
        a->trigger();
        QCoreApplication::sendPostedEvents();
        QLineEdit *edit = window.ladderView()->inlineEditor();
        ASSERT_TRUE(edit->isVisible()) << entry;
        QTest::keyClicks(edit, QString::fromLatin1(operand));
        QTest::keyClick(edit, Qt::Key_Return);
    };
    place("Normally Open Contact", "X3");
    place("Coil", "Y2");
    window.ladderView()->setCursor({0, 1, 0});
    place("Parallel Normally Closed Contact", "X4");
    window.ladderView()->setCursor({0, 2, 0});
    place("Parallel Rising-Edge Contact", "X5");
    window.ladderView()->setCursor({0, 3, 0});
    place("Parallel Falling-Edge Contact", "X6");
    EXPECT_EQ(window.document()->listingText(),
              QStringLiteral("LD X3\nORI X4\nORP X5\nORF X6\nOUT Y2\nEND\n"));
    // Their keys are in the menu; the toolbar's palette stays as it was.
    EXPECT_EQ(
        test::editMenuEntry(window, QStringLiteral("Parallel Normally Closed Contact"))->shortcut(),
        QKeySequence(Qt::SHIFT | Qt::Key_F6));
    EXPECT_EQ(
        test::editMenuEntry(window, QStringLiteral("Parallel Rising-Edge Contact"))->shortcut(),
        QKeySequence(Qt::ALT | Qt::Key_F7));
    EXPECT_EQ(
        test::editMenuEntry(window, QStringLiteral("Parallel Falling-Edge Contact"))->shortcut(),
        QKeySequence(Qt::ALT | Qt::Key_F8));
    EXPECT_EQ(test::toolbarAction(window, QStringLiteral("Parallel Rising-Edge Contact")), nullptr);
}

TEST_F(MissingEnd, TheProblemOffersToAppendIt) {
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(QStringLiteral("LD X0\nOUT Y0\n"), &errors));
    const auto &ds = window.document()->diagnostics();
    const auto en = std::find_if(ds.begin(), ds.end(), [](const model::Diagnostic &d) {
        return d.code == QLatin1String("EN001");
    });
    ASSERT_NE(en, ds.end());
    ASSERT_TRUE(en->fix.has_value());
    const model::Diagnostic missing = *en;
    emit window.problemsView()->applyFix(missing);
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X0\nOUT Y0\nEND\n"));
    EXPECT_EQ(window.document()->undoStack()->undoText(), QStringLiteral("Append END"));
    window.document()->undoStack()->undo();
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X0\nOUT Y0\n"));
}

TEST_F(OpenListing, TheTargetLineIsReadNotMadeARungComment) {
    QTemporaryDir dir;
    const QString path = test::writeFile(
        dir, QStringLiteral("lamp.il"), "; target: cpm1\n; Lamp\nLD 000.00\nOUT 010.00\nEND(01)\n");
    ASSERT_TRUE(window.openFile(path));
    EXPECT_EQ(window.document()->target().id, QStringLiteral("cpm1"));
    ASSERT_FALSE(window.document()->ladder().rungs.empty());
    EXPECT_EQ(window.document()->ladder().rungs[0].comment, QStringLiteral("Lamp"));
    EXPECT_EQ(window.document()->listingText(),
              QStringLiteral("; Lamp\nLD 000.00\nOUT 010.00\nEND(01)\n"));
}
