// The status bar (target, model, program size in steps, cursor cell or line), the problems
// panel's title and empty state, and the ladder / list layout (tabs or side by side) that the
// next start remembers.

#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "editor/problems_view.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSplitter>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

using StatusBar = test::WindowFixture;

TEST_F(StatusBar, ShowsTargetModelStepsAndTheCursor) {
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
    load("LD X0\nAND X1\nOUT Y0\nEND\n");
    const model::ModelVariant *vb =
        model::Target::get(model::Family::Vigor).model(QStringLiteral("VB"));
    ASSERT_NE(vb, nullptr);
    const int limit = vb->programSteps > 0
                          ? vb->programSteps
                          : model::Target::get(model::Family::Vigor).limits.programSteps;
    EXPECT_TRUE(test::statusText(window).contains(QStringLiteral("Vigor VB")))
        << test::statusText(window).toStdString();
    EXPECT_TRUE(test::statusText(window).contains(QStringLiteral("4 / %1 steps").arg(limit)))
        << test::statusText(window).toStdString();

    window.ladderView()->setFocus();
    window.ladderView()->setCursor({0, 0, 1});
    EXPECT_TRUE(test::statusText(window).contains(QStringLiteral("Rung 1, row 1, column 2")))
        << test::statusText(window).toStdString();

    // In the list the cursor is a line and a column.
    auto *tabs = window.findChild<QTabWidget *>();
    ASSERT_NE(tabs, nullptr);
    tabs->setCurrentWidget(window.ilEditor());
    window.ilEditor()->setFocus();
    ASSERT_TRUE(window.ilEditor()->hasFocus());
    EXPECT_TRUE(test::statusText(window).startsWith(QStringLiteral("Line ")))
        << test::statusText(window).toStdString();
    // Scintilla reports the move when it updates its view, after the call.
    QSignalSpy moved(window.ilEditor(), &QsciScintilla::cursorPositionChanged);
    window.ilEditor()->setCursorPosition(1, 3);
    if (moved.isEmpty()) {
        ASSERT_TRUE(moved.wait(3000));
    }
    EXPECT_TRUE(test::statusText(window).contains(QStringLiteral("Line 2, column 4")))
        << test::statusText(window).toStdString();

    // Another target and model: the status bar follows.
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    EXPECT_TRUE(
        test::statusText(window).contains(model::Target::get(model::Family::Cpm1).displayName))
        << test::statusText(window).toStdString();
    EXPECT_TRUE(test::statusText(window).contains(QStringLiteral("1 / "))) // END
        << test::statusText(window).toStdString();
}

using ProblemsPanel = test::WindowFixture;

TEST_F(ProblemsPanel, TitleCountsTheFindingsAndAnEmptyListSaysSo) {
    auto *dock = window.findChild<QDockWidget *>(QStringLiteral("problemsDock"));
    ASSERT_NE(dock, nullptr);
    EXPECT_EQ(dock->windowTitle(), QStringLiteral("Problems"));
    // Y0 driven twice: a duplicate-coil warning at least.
    load("LD X0\nOUT Y0\nLD X1\nOUT Y0\nEND\n");
    const int warnings = window.problemsView()->count(model::Severity::Warning);
    const int errors = window.problemsView()->count(model::Severity::Error);
    ASSERT_GT(warnings + errors, 0);
    EXPECT_NE(dock->windowTitle(), QStringLiteral("Problems"));
    EXPECT_TRUE(dock->windowTitle().startsWith(QStringLiteral("Problems (")))
        << dock->windowTitle().toStdString();
    EXPECT_EQ(dock->windowTitle(), window.problemsView()->summary());
    // Columns wide enough for their headers even when short.
    editor::ProblemsView *problems = window.problemsView();
    const QFontMetrics fm(problems->font());
    EXPECT_GE(problems->columnWidth(0), fm.horizontalAdvance(QStringLiteral("Severity")));
    EXPECT_GE(problems->columnWidth(2), fm.horizontalAdvance(QStringLiteral("rung 10, row 2")));
}

TEST(ViewLayout, SideBySideOrTabsIsTheUsersChoiceRememberedForTheNextStart) {
    QSettings().remove(QStringLiteral("view/sideBySide"));
    {
        app::MainWindow window;
        window.show();
        // Tabs by default.
        EXPECT_EQ(qobject_cast<QSplitter *>(window.ladderView()->parentWidget()), nullptr);
        QAction *side = test::menuAction(window, QStringLiteral("Ladder and List Side by Side"));
        ASSERT_NE(side, nullptr);
        EXPECT_FALSE(side->isChecked());
        side->trigger();
        auto *split = qobject_cast<QSplitter *>(window.ladderView()->parentWidget());
        ASSERT_NE(split, nullptr);
        EXPECT_EQ(window.ilEditor()->parentWidget(), split);
        EXPECT_TRUE(window.ladderView()->isVisible());
        EXPECT_TRUE(window.ilEditor()->isVisible());
    }
    {
        app::MainWindow next; // as on the next start
        next.show();
        EXPECT_NE(qobject_cast<QSplitter *>(next.ladderView()->parentWidget()), nullptr);
        QAction *side = test::menuAction(next, QStringLiteral("Ladder and List Side by Side"));
        ASSERT_NE(side, nullptr);
        EXPECT_TRUE(side->isChecked());
        side->trigger(); // back to tabs
        EXPECT_EQ(qobject_cast<QSplitter *>(next.ladderView()->parentWidget()), nullptr);
    }
    app::MainWindow last;
    EXPECT_EQ(qobject_cast<QSplitter *>(last.ladderView()->parentWidget()), nullptr);
    QSettings().remove(QStringLiteral("view/sideBySide"));
}

// Side by side, the list gets room for its comment lines, and the user's split is kept.
TEST(ViewLayout, TheSplitBetweenLadderAndListIsRemembered) {
    QSettings().setValue(QStringLiteral("view/sideBySide"), true);
    QSettings().remove(QStringLiteral("view/split"));
    QList<int> chosen;
    {
        app::MainWindow window;
        window.show();
        auto *split = qobject_cast<QSplitter *>(window.ladderView()->parentWidget());
        ASSERT_NE(split, nullptr);
        const QList<int> sizes = split->sizes();
        ASSERT_EQ(sizes.size(), 2);
        EXPECT_GE(sizes[1] * 3, sizes[0]) << sizes[0] << " " << sizes[1]; // not a sliver
        split->setSizes({sizes[0] + sizes[1] - 300, 300});
        chosen = split->sizes();
        window.close();
    }
    app::MainWindow next;
    next.show();
    auto *split = qobject_cast<QSplitter *>(next.ladderView()->parentWidget());
    ASSERT_NE(split, nullptr);
    EXPECT_EQ(split->sizes(), chosen);
    QSettings().remove(QStringLiteral("view/sideBySide"));
    QSettings().remove(QStringLiteral("view/split"));
}

// The docks tabbed beside the ladder at 1366x768 (project, cross reference, terminals,
// simulation) show their whole titles, scrolled when they do not fit: Qt's own tab bars cut
// them to "P..." and "Si...", which no one can tell apart.
TEST(DockTabs, TitlesAreWholeAt1366x768) {
    app::MainWindow window;
    window.resize(1366, 768);
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    for (const char *name : {"ioDock", "simulationDock", "crossReferenceDock"}) {
        auto *dock = window.findChild<QDockWidget *>(QString::fromLatin1(name));
        ASSERT_NE(dock, nullptr) << name;
        dock->show();
    }
    QApplication::processEvents();
    int tabs = 0;
    for (QTabBar *bar : window.findChildren<QTabBar *>(Qt::FindDirectChildrenOnly)) {
        if (!bar->isVisible())
            continue;
        EXPECT_EQ(bar->elideMode(), Qt::ElideNone);
        for (int i = 0; i < bar->count(); ++i, ++tabs)
            EXPECT_GE(bar->tabRect(i).width(),
                      bar->fontMetrics().horizontalAdvance(bar->tabText(i)))
                << bar->tabText(i).toStdString();
    }
    EXPECT_GE(tabs, 4); // the left column's four
}

// A dock closed with its x comes back from a menu: each of the window's docks has its entry
// (View, or the Simulation menu for the run controls and the scan debugger), and View > Reset
// Window Layout brings a closed one back too.
TEST_F(StatusBar, EveryDockOpensAgainFromAMenu) {
    QList<QAction *> entries;
    for (QMenu *menu : window.menuBar()->findChildren<QMenu *>())
        entries += menu->actions();
    const QList<QDockWidget *> docks = window.findChildren<QDockWidget *>();
    ASSERT_GE(docks.size(), 10);
    for (QDockWidget *dock : docks)
        EXPECT_TRUE(entries.contains(dock->toggleViewAction())) << dock->objectName().toStdString();
    auto *project = window.findChild<QDockWidget *>(QStringLiteral("projectDock"));
    window.show();
    project->close();
    ASSERT_FALSE(project->isVisible());
    QAction *reset = window.menuBar()->findChild<QAction *>(QStringLiteral("resetLayoutAction"));
    ASSERT_NE(reset, nullptr);
    reset->trigger();
    EXPECT_TRUE(project->isVisible());
}
