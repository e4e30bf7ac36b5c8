// The window's layout (app/gui/layout_controller.h) without the Rung Studio window: a plain
// main window with the docks by their names, two pages for the ladder and the list.

#include "app/gui/layout_controller.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QScreen>
#include <QSettings>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>

#include <gtest/gtest.h>

#include <memory>

using namespace rung;

namespace {

void forgetLayout() {
    for (const char *key : {"window/geometry", "window/state", "view/sideBySide", "view/split"})
        QSettings().remove(QString::fromLatin1(key));
}

// The docks of dock_layout.h, each with a label; the inputs and outputs hidden, as the window
// keeps them until a simulation starts.
struct LayoutAlone {
    QMainWindow window;
    QLabel *ladder = new QLabel(QStringLiteral("ladder"));
    QLabel *listing = new QLabel(QStringLiteral("list"));
    app::LayoutController layout{&window, ladder, listing, &window};
    QMenu view;

    // `frontPanel`: with the Front Panel dock (hidden until a simulation, as the window has
    // it); without it, the docks of a window before it came.
    explicit LayoutAlone(bool frontPanel = false) {
        for (const char *name : {"projectDock", "crossReferenceDock", "ioDock", "simulationDock",
                                 "scanDebuggerDock", "connectionDock", "problemsDock", "watchDock",
                                 "timingChartDock", "testsDock", "frontPanelDock"}) {
            if (!frontPanel && QLatin1String(name) == QLatin1String("frontPanelDock"))
                continue;
            auto *d = new QDockWidget(QString::fromLatin1(name), &window);
            d->setObjectName(QString::fromLatin1(name));
            d->setWidget(new QLabel(QString::fromLatin1(name)));
            window.addDockWidget(Qt::BottomDockWidgetArea, d);
        }
        dock("ioDock")->hide();
        if (frontPanel)
            dock("frontPanelDock")->hide();
        layout.addActions(&view);
    }
    QDockWidget *dock(const char *name) {
        return window.findChild<QDockWidget *>(QString::fromLatin1(name));
    }
    QAction *action(const char *name) {
        return view.findChild<QAction *>(QString::fromLatin1(name));
    }
    bool together(const char *a, const char *b) {
        return window.tabifiedDockWidgets(dock(a)).contains(dock(b));
    }
    void settle() {
        for (int k = 0; k < 5; ++k)
            QApplication::processEvents();
    }
};

} // namespace

// A first start (nothing saved): editing docks left, findings below the ladder, each group
// as tabs (the offscreen screen is narrow: the live docks join the left column).
TEST(LayoutControllerAlone, AFirstStartGroupsTheDocks) {
    forgetLayout();
    LayoutAlone f;
    ASSERT_FALSE(f.layout.wideScreen());
    f.layout.restore();
    f.window.show();
    f.settle();
    EXPECT_EQ(f.window.dockWidgetArea(f.dock("projectDock")), Qt::LeftDockWidgetArea);
    EXPECT_EQ(f.window.dockWidgetArea(f.dock("problemsDock")), Qt::BottomDockWidgetArea);
    EXPECT_TRUE(f.together("projectDock", "crossReferenceDock"));
    EXPECT_TRUE(f.together("projectDock", "simulationDock"));
    EXPECT_TRUE(f.together("projectDock", "connectionDock"));
    EXPECT_TRUE(f.together("problemsDock", "watchDock"));
    EXPECT_TRUE(f.together("problemsDock", "timingChartDock"));
    EXPECT_TRUE(f.together("problemsDock", "testsDock"));
    EXPECT_FALSE(f.dock("ioDock")->isVisible());
    // The window fits the screen it is on.
    const QRect screen = f.window.screen()->availableGeometry();
    EXPECT_LE(f.window.width(), screen.width());
    EXPECT_LE(f.window.height(), screen.height());
    // The docks' tab bars keep whole titles and scroll rather than cutting them.
    const QList<QTabBar *> bars = f.window.findChildren<QTabBar *>(Qt::FindDirectChildrenOnly);
    ASSERT_FALSE(bars.isEmpty());
    for (QTabBar *bar : bars) {
        EXPECT_EQ(bar->elideMode(), Qt::ElideNone);
        EXPECT_TRUE(bar->usesScrollButtons());
    }
}

// Side by side the two pages share a splitter, both in sight; as tabs one is in front. The
// View menu's entry and the setting follow, and the next start comes back so.
TEST(LayoutControllerAlone, SideBySideIsTheMenusAndTheNextStartsToo) {
    forgetLayout();
    {
        LayoutAlone f;
        f.layout.restore();
        f.window.show();
        QAction *side = f.action("sideBySideAction");
        ASSERT_NE(side, nullptr);
        EXPECT_FALSE(side->isChecked());
        auto *tabs = f.window.centralWidget()->findChild<QTabWidget *>();
        ASSERT_NE(tabs, nullptr);
        EXPECT_EQ(tabs->count(), 2);
        EXPECT_EQ(tabs->tabText(0), QStringLiteral("Ladder"));
        EXPECT_EQ(tabs->tabText(1), QStringLiteral("Instruction List"));
        f.layout.showPage(f.listing);
        EXPECT_TRUE(f.listing->isVisible());
        EXPECT_FALSE(f.ladder->isVisible());

        side->trigger(); // as from the menu
        EXPECT_TRUE(f.layout.sideBySide());
        auto *split = f.window.centralWidget()->findChild<QSplitter *>();
        ASSERT_NE(split, nullptr);
        EXPECT_EQ(f.ladder->parentWidget(), split);
        EXPECT_EQ(f.listing->parentWidget(), split);
        EXPECT_TRUE(f.ladder->isVisible());
        EXPECT_TRUE(f.listing->isVisible());
        EXPECT_FALSE(tabs->isVisible());
        EXPECT_TRUE(QSettings().value(QStringLiteral("view/sideBySide")).toBool());
        f.layout.setSideBySide(false); // from the code: the menu's entry follows
        EXPECT_FALSE(side->isChecked());
        EXPECT_EQ(tabs->count(), 2);
        EXPECT_TRUE(tabs->isVisible());
        f.layout.setSideBySide(true);
        f.layout.save();
    }
    LayoutAlone next;
    next.layout.restore();
    EXPECT_TRUE(next.layout.sideBySide());
    EXPECT_TRUE(next.action("sideBySideAction")->isChecked()); // the menu says so too
    forgetLayout();
}

// What the user arranged is the next start's: a closed dock stays closed, a moved one where
// it went.
TEST(LayoutControllerAlone, TheNextStartRestoresTheDocks) {
    forgetLayout();
    {
        LayoutAlone f;
        f.layout.restore();
        f.window.show();
        f.settle();
        f.dock("watchDock")->close();
        f.window.addDockWidget(Qt::RightDockWidgetArea, f.dock("timingChartDock"));
        f.settle();
        f.layout.save();
    }
    LayoutAlone next;
    next.layout.restore();
    next.window.show();
    next.settle();
    EXPECT_FALSE(next.dock("watchDock")->isVisible());
    EXPECT_EQ(next.window.dockWidgetArea(next.dock("timingChartDock")), Qt::RightDockWidgetArea);
    EXPECT_TRUE(next.dock("problemsDock")->isVisible());
    forgetLayout();
}

// A layout saved by a window before the Front Panel dock (layout version 2): restored as it
// was, the new dock would be left where it was added, alone below the findings, not a tab
// beside the run controls or the terminals where dock_layout.h puts it. Such a layout is not
// restored (kDockLayoutVersion 3): the first start's groups come instead.
TEST(LayoutControllerAlone, ALayoutSavedBeforeTheFrontPanelPutsItsDockWhereItBelongs) {
    forgetLayout();
    {
        LayoutAlone before;
        before.layout.restore();
        before.window.show();
        before.settle();
        QSettings().setValue(QStringLiteral("window/state"), before.window.saveState(2));
    }
    LayoutAlone next(true);
    next.layout.restore();
    next.window.show();
    next.settle();
    next.dock("frontPanelDock")->show(); // the first simulation shows it
    next.settle();
    EXPECT_FALSE(next.dock("frontPanelDock")->isFloating());
    // (Asked of the front panel: a hidden dock, the terminals here, lists no tabs.)
    EXPECT_TRUE(next.together("frontPanelDock", "simulationDock") ||
                next.together("frontPanelDock", "ioDock"))
        << "the front panel is a tab beside the run controls or the terminals";
    forgetLayout();
}

// View > Reset Window Layout: a dock closed, floated or moved by accident comes back to its
// first place; a dock the user has open (the inputs and outputs of a simulation) stays open.
TEST(LayoutControllerAlone, ResetWindowLayoutBringsEveryDockBack) {
    forgetLayout();
    LayoutAlone f;
    f.layout.restore();
    f.window.show();
    f.settle();
    f.dock("projectDock")->close();
    f.dock("watchDock")->setFloating(true);
    f.window.addDockWidget(Qt::RightDockWidgetArea, f.dock("problemsDock"));
    f.dock("ioDock")->show();
    f.settle();
    ASSERT_EQ(f.window.dockWidgetArea(f.dock("problemsDock")), Qt::RightDockWidgetArea);

    QAction *reset = f.action("resetLayoutAction");
    ASSERT_NE(reset, nullptr);
    EXPECT_FALSE(reset->text().isEmpty());
    reset->trigger();
    f.settle();
    EXPECT_TRUE(f.dock("projectDock")->isVisible());
    EXPECT_EQ(f.window.dockWidgetArea(f.dock("projectDock")), Qt::LeftDockWidgetArea);
    EXPECT_FALSE(f.dock("watchDock")->isFloating());
    EXPECT_TRUE(f.together("problemsDock", "watchDock"));
    EXPECT_EQ(f.window.dockWidgetArea(f.dock("problemsDock")), Qt::BottomDockWidgetArea);
    EXPECT_TRUE(f.together("projectDock", "crossReferenceDock"));
    EXPECT_TRUE(f.dock("ioDock")->isVisible());
    EXPECT_EQ(f.window.dockWidgetArea(f.dock("ioDock")), Qt::LeftDockWidgetArea);
    // In front: the project and the problems, as at a first start.
    EXPECT_FALSE(f.dock("projectDock")->visibleRegion().isEmpty());
    EXPECT_FALSE(f.dock("problemsDock")->visibleRegion().isEmpty());
    forgetLayout();
}
