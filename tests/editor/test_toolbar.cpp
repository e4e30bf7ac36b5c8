// The palette on the main toolbar: drawn icons (no icon theme on a plain desktop), the
// function key in every tooltip; a picked tool places its element where the cells are clicked,
// the Edit menu acts at the cursor as the keys do.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QAction>
#include <QCoreApplication>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QTest>
#include <QToolBar>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

#include <functional>
#include <map>

using namespace rung;

TEST(Toolbar, EveryButtonHasADrawnIconAndItsKeyInTheTooltip) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    const std::pair<const char *, const char *> tools[] = {{"Normally Open Contact", "F5"},
                                                           {"Normally Closed Contact", "F6"},
                                                           {"Parallel Contact", "Shift+F5"},
                                                           {"Rising-Edge Contact", "Shift+F7"},
                                                           {"Falling-Edge Contact", "Shift+F8"},
                                                           {"Coil", "F7"},
                                                           {"Instruction", "F8"},
                                                           {"Horizontal Wire", "F9"},
                                                           {"Vertical Link", "Shift+F9"},
                                                           {"New Project...", "Ctrl+N"},
                                                           {"Open...", "Ctrl+O"},
                                                           {"Save", "Ctrl+S"}};
    for (const auto &[text, key] : tools) {
        QAction *a = test::toolbarAction(window, QString::fromLatin1(text));
        ASSERT_NE(a, nullptr) << text;
        EXPECT_FALSE(a->icon().isNull()) << text;
        EXPECT_FALSE(a->icon().pixmap(24, 24).isNull()) << text;
        EXPECT_TRUE(a->toolTip().contains(QString::fromLatin1(key))) << a->toolTip().toStdString();
    }
}

TEST(Toolbar, APickedToolPlacesItsElementInEveryCellClickedUntilEsc) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    editor::LadderView *view = window.ladderView();
    QAction *select = test::toolbarAction(window, QStringLiteral("Select"));
    ASSERT_NE(select, nullptr);
    EXPECT_TRUE(select->isChecked());
    // Pick a tool, click a cell, type the operand: the element is there.
    auto pick = [&](const char *button) {
        QAction *a = test::toolbarAction(window, QString::fromLatin1(button));
        ASSERT_NE(a, nullptr) << button;
        a->trigger();
        EXPECT_TRUE(a->isChecked()) << button;
        EXPECT_FALSE(select->isChecked());
        EXPECT_FALSE(view->armedTool().isEmpty());
    };
    auto click = [&](int row, int column, const char *operand) {
        const QRect cell = view->cellRectOnScreen({0, row, column});
        ASSERT_TRUE(cell.isValid());
        QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
        QLineEdit *edit = view->inlineEditor();
        ASSERT_TRUE(edit->isVisible()) << operand;
        QTest::keyClicks(edit, QString::fromLatin1(operand));
        QTest::keyClick(edit, Qt::Key_Return);
    };
    pick("Normally Open Contact");
    click(0, 0, "X3");
    click(0, 1, "X5"); // the tool stays picked: a second contact in the next cell
    pick("Coil");
    click(0, 2, "Y2"); // any cell of the row: a coil goes to the output column
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X3\nAND X5\nOUT Y2\nEND\n"));
    // A parallel contact where the click is, on the row below.
    pick("Parallel Contact");
    click(1, 0, "M1");
    EXPECT_EQ(window.document()->listingText(),
              QStringLiteral("LD X3\nOR M1\nAND X5\nOUT Y2\nEND\n"));

    // Esc puts the tool away: a click only selects again.
    QTest::keyClick(view, Qt::Key_Escape);
    EXPECT_TRUE(view->armedTool().isEmpty());
    EXPECT_TRUE(select->isChecked());
    const QRect cell = view->cellRectOnScreen({0, 0, 1});
    QTest::mouseClick(view->viewport(), Qt::LeftButton, Qt::NoModifier, cell.center());
    EXPECT_FALSE(view->inlineEditor()->isVisible());
    EXPECT_EQ(view->cursor().column, 1);

    // So does a right click.
    pick("Normally Closed Contact");
    QTest::mouseClick(view->viewport(), Qt::RightButton, Qt::NoModifier, cell.center());
    EXPECT_TRUE(view->armedTool().isEmpty());
    EXPECT_TRUE(select->isChecked());
}

TEST(Toolbar, TheEditMenuActsAtTheCursorAsTheKeysDo) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    // The menu's entries post their function key to the ladder, as if the user pressed it.
    auto place = [&](const char *entry, const char *operand) {
        QAction *a = test::editMenuEntry(window, QString::fromLatin1(entry));
        ASSERT_NE(a, nullptr) << entry;
        a->trigger();
        QCoreApplication::sendPostedEvents();
        QLineEdit *edit = window.ladderView()->inlineEditor();
        ASSERT_TRUE(edit->isVisible()) << entry;
        QTest::keyClicks(edit, QString::fromLatin1(operand));
        QTest::keyClick(edit, Qt::Key_Return);
    };
    place("Normally Open Contact", "X3");
    place("Normally Closed Contact", "X4");
    place("Coil", "Y2");
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X3\nANI X4\nOUT Y2\nEND\n"));
    window.ladderView()->setCursor({0, 1, 0});
    place("Parallel Contact", "M1");
    EXPECT_EQ(window.document()->listingText(),
              QStringLiteral("LD X3\nOR M1\nANI X4\nOUT Y2\nEND\n"));
}

// The menu shows each entry's key, as the vendor tools' menus do, and no key means two
// things: Qt would then run neither.
TEST(Toolbar, TheEditMenuShowsTheKeysAndNoKeyIsAmbiguous) {
    app::MainWindow window;
    const std::pair<const char *, QKeySequence> entries[] = {
        {"Normally Open Contact", QKeySequence(Qt::Key_F5)},
        {"Normally Closed Contact", QKeySequence(Qt::Key_F6)},
        {"Parallel Contact", QKeySequence(Qt::SHIFT | Qt::Key_F5)},
        {"Coil", QKeySequence(Qt::Key_F7)},
        {"Vertical Link", QKeySequence(Qt::SHIFT | Qt::Key_F9)},
        {"Insert Rung", QKeySequence(Qt::SHIFT | Qt::Key_Insert)},
        {"Delete Rung", QKeySequence(Qt::SHIFT | Qt::Key_Delete)},
        {"Insert Row", QKeySequence(Qt::CTRL | Qt::Key_Insert)},
        {"Delete Row", QKeySequence(Qt::CTRL | Qt::Key_Delete)},
        {"Replace Device...", QKeySequence(Qt::CTRL | Qt::Key_H)}};
    for (const auto &[text, key] : entries) {
        QAction *a = test::editMenuEntry(window, QString::fromLatin1(text));
        ASSERT_NE(a, nullptr) << text;
        EXPECT_EQ(a->shortcut(), key) << text;
        // The ladder's own keys: shown in the menu, handled by the ladder only, so F5 or
        // Shift+Delete typed in the list is the list's.
        if (key != QKeySequence(Qt::CTRL | Qt::Key_H)) {
            EXPECT_EQ(a->shortcutContext(), Qt::WidgetShortcut) << text;
        }
        EXPECT_TRUE(a->text().contains(QLatin1Char('&'))) << text << ": no access key";
    }
    for (const char *text : {"Import Symbols (CSV)...", "Export Symbols (CSV)..."}) {
        QAction *a = test::editMenuEntry(window, QString::fromLatin1(text));
        ASSERT_NE(a, nullptr) << text;
        EXPECT_TRUE(a->text().contains(QLatin1Char('&'))) << text << ": no access key";
    }
    std::map<QString, QString> seen;
    for (QAction *a : window.findChildren<QAction *>())
        for (const QKeySequence &key : a->shortcuts()) {
            const auto [it, fresh] =
                seen.emplace(key.toString(), QString(a->text()).remove(QLatin1Char('&')));
            EXPECT_TRUE(fresh) << key.toString().toStdString() << ": " << it->second.toStdString()
                               << " and " << a->text().toStdString();
        }
}
