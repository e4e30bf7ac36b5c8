#pragma once

// The main window as the GUI tests meet it: a new Vigor VB program, and the few things the
// tests do with it (load a listing, type into a cell, find a menu entry, read the status bar).

#include "app/gui/eliding_label.h"
#include "app/gui/main_window.h"
#include "app/gui/recovery.h"
#include "editor/ladder_view.h"
#include "tests/eventually.h"

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>

#include <functional>

namespace rung::test {

using waits::eventually;
using waits::kPatienceMs;

// An entry of one of the menu bar's menus (or one of their submenus), by its text without
// the access-key '&'; nullptr when there is none.
inline QAction *menuAction(const QMainWindow &window, const QString &text) {
    for (QAction *top : window.menuBar()->actions())
        if (top->menu())
            for (QAction *a : top->menu()->actions()) {
                if (a->text().remove(QLatin1Char('&')) == text)
                    return a;
                if (a->menu())
                    for (QAction *inner : a->menu()->actions())
                        if (inner->text().remove(QLatin1Char('&')) == text)
                            return inner;
            }
    return nullptr;
}

// A menu entry picked as the user picks it (Language > Magyar): triggered, then the queued
// work it starts and the language change it posts carried out.
inline void pickMenuEntry(QMainWindow &window, const char *name) {
    QAction *entry = menuAction(window, QString::fromUtf8(name));
    ASSERT_NE(entry, nullptr) << name;
    entry->trigger();
    QCoreApplication::processEvents();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
    QCoreApplication::processEvents();
}

// A button of the toolbars, by its text without the access-key '&'; nullptr when there is none.
inline QAction *toolbarAction(const QMainWindow &window, const QString &text) {
    for (QToolBar *bar : window.findChildren<QToolBar *>())
        for (QAction *a : bar->actions())
            if (QString(a->text()).remove(QLatin1Char('&')) == text)
                return a;
    return nullptr;
}

// An entry of the Edit menu or of its submenus (at any depth), by its text without the '&'.
inline QAction *editMenuEntry(const QMainWindow &window, const QString &text) {
    std::function<QAction *(QMenu *)> find = [&](QMenu *menu) -> QAction * {
        for (QAction *e : menu->actions()) {
            if (QString(e->text()).remove(QLatin1Char('&')) == text)
                return e;
            if (e->menu())
                if (QAction *inner = find(e->menu()))
                    return inner;
        }
        return nullptr;
    };
    for (QAction *m : window.menuBar()->actions())
        if (m->menu() && m->text() == QStringLiteral("&Edit"))
            return find(m->menu());
    return nullptr;
}

inline QMenu *submenu(const QMainWindow &window, const QString &title) {
    QAction *a = menuAction(window, title);
    return a ? a->menu() : nullptr;
}

// The status bar's permanent texts, joined by '|'.
inline QString statusText(const QMainWindow &window) {
    QStringList texts;
    for (QLabel *label : window.statusBar()->findChildren<QLabel *>())
        if (auto *elided = qobject_cast<app::ElidingLabel *>(label))
            texts << elided->fullText(); // what the label says whatever the window's width
        else
            texts << label->text();
    return texts.join(QLatin1Char('|'));
}

// A recovery folder of the test's own while it lives: a window that recovered work keeps it in
// a recovery file of its own, orphaned when the window goes, and the next test's windows
// would be offered it (a hang when the whole binary runs in one process).
struct OwnRecoveryFolder {
    QTemporaryDir folder;
    QString before = app::RecoveryFile::directory();
    OwnRecoveryFolder() { app::RecoveryFile::setDirectory(folder.path()); }
    ~OwnRecoveryFolder() { app::RecoveryFile::setDirectory(before); }
    OwnRecoveryFolder(const OwnRecoveryFolder &) = delete;
    OwnRecoveryFolder &operator=(const OwnRecoveryFolder &) = delete;
};

struct WindowFixture : ::testing::Test {
    OwnRecoveryFolder recoveryFolder; // before the window: its recovery file goes there
    app::MainWindow window;
    editor::LadderView *view = window.ladderView();

    void SetUp() override {
        window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    }
    // The program from an instruction list that must be valid.
    void load(const QString &listing) {
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(window.document()->setListing(listing, &errors))
            << listing.toStdString()
            << (errors.empty() ? std::string() : errors.front().message.toStdString());
    }
    void load(const char *listing) { load(QString::fromLatin1(listing)); }
    void showWithLadderFocused() {
        window.show();
        view->setFocus();
    }
    QString listing() { return window.document()->listingText(); }
    // On screen and active, as a user meets it: focus, dialogs and key presses behave so.
    void showActive() {
        window.show();
        window.activateWindow();
        EXPECT_TRUE(QTest::qWaitForWindowActive(&window));
    }
    // A function key (with its modifiers), then the operand into the cell editor it opens.
    void typeIntoCell(Qt::Key key, const char *operand, Qt::KeyboardModifiers mods = {}) {
        QTest::keyClick(view, key, mods);
        QLineEdit *edit = view->inlineEditor();
        ASSERT_TRUE(edit->isVisible()) << "key " << key;
        QTest::keyClicks(edit, QString::fromLatin1(operand));
        QTest::keyClick(edit, Qt::Key_Return);
    }
};

} // namespace rung::test
