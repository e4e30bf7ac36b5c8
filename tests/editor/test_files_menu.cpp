// File > Examples (the manuals' examples of every target, opened as untitled copies) and
// File > Open Recent (remembered in the settings for the next start).

#include "app/gui/main_window.h"

#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

TEST(FilesMenu, ExamplesForEveryTargetOpenAsUntitledCopies) {
    app::MainWindow window;
    QMenu *examples = test::submenu(window, QStringLiteral("Examples"));
    ASSERT_NE(examples, nullptr);
    QStringList targets;
    for (QAction *sub : examples->actions()) {
        ASSERT_NE(sub->menu(), nullptr);
        targets << sub->text();
        ASSERT_FALSE(sub->menu()->actions().isEmpty()) << sub->text().toStdString();
        for (QAction *example : sub->menu()->actions()) {
            example->trigger();
            EXPECT_EQ(window.document()->target().displayName, sub->text())
                << example->text().toStdString();
            EXPECT_GT(window.document()->ladder().rungs.size(), 1u);
            EXPECT_TRUE(window.document()->path().isEmpty()); // Save asks where
            EXPECT_FALSE(window.document()->isModified());
        }
    }
    for (model::Family f : model::Target::families())
        EXPECT_TRUE(targets.contains(model::Target::get(f).displayName))
            << model::Target::get(f).displayName.toStdString();
}

// Titles to read, not file names: the resource "vigor/traffic-light.rung" is "Traffic light",
// "cpm1/difu-difd.rung" names its two instructions as the manual writes them.
TEST(FilesMenu, ExamplesHaveReadableTitles) {
    app::MainWindow window;
    QMenu *examples = test::submenu(window, QStringLiteral("Examples"));
    ASSERT_NE(examples, nullptr);
    QStringList titles;
    for (QAction *sub : examples->actions())
        for (QAction *example : sub->menu()->actions())
            titles << example->text();
    EXPECT_TRUE(titles.contains(QStringLiteral("Traffic light"))) << titles.join(',').toStdString();
    EXPECT_TRUE(titles.contains(QStringLiteral("DIFU / DIFD"))) << titles.join(',').toStdString();
    for (const QString &title : titles)
        EXPECT_FALSE(title.contains(QLatin1Char('-')) && !title.contains(QLatin1Char(' ')))
            << title.toStdString();
}

TEST(FilesMenu, RecentFilesAreRememberedNewestFirst) {
    QSettings().remove(QStringLiteral("files/recent"));
    QTemporaryDir dir;
    const QString a = dir.filePath(QStringLiteral("a.rung"));
    const QString b = dir.filePath(QStringLiteral("b.rung"));
    {
        app::MainWindow window;
        window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        ASSERT_TRUE(window.saveTo(a));
        ASSERT_TRUE(window.saveTo(b));
        ASSERT_TRUE(window.openFile(a, QString(), true));
    }
    app::MainWindow next; // the next start
    QMenu *recent = test::submenu(next, QStringLiteral("Open Recent"));
    ASSERT_NE(recent, nullptr);
    ASSERT_GE(recent->actions().size(), 2);
    EXPECT_EQ(recent->actions().at(0)->text(), QStringLiteral("a.rung"));
    EXPECT_EQ(recent->actions().at(1)->text(), QStringLiteral("b.rung"));
    recent->actions().at(1)->trigger();
    EXPECT_EQ(next.document()->path(), b);
    QSettings().remove(QStringLiteral("files/recent"));
}
