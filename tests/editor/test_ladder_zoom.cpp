// Fit to width: beside the instruction list the ladder shrinks so the output column is never
// cut off; the user's own zoom ends it.

#include "app/gui/main_window.h"
#include "editor/document.h"
#include "editor/ladder_view.h"

#include <QAction>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>

#include <gtest/gtest.h>

using namespace rung;

TEST(LadderZoom, FitToWidthShrinksTheDrawingIntoANarrowViewButNeverEnlargesIt) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    editor::LadderView view(&document);
    view.resize(850, 400); // narrower than the drawing, wide enough to fit it readably
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    const double fullWidth = view.metrics().width();
    ASSERT_GT(fullWidth, view.viewport()->width()); // cut off at 100 %

    QSignalSpy changed(&view, &editor::LadderView::fitWidthChanged);
    view.setFitWidth(true);
    EXPECT_EQ(changed.count(), 1);
    EXPECT_LT(view.zoom(), 1.0);
    EXPECT_LE(view.metrics().width(), view.viewport()->width());

    view.resize(2400, 400); // wider than the drawing: stays at 100 %
    QCoreApplication::processEvents();
    EXPECT_DOUBLE_EQ(view.zoom(), 1.0);
    view.resize(static_cast<int>(fullWidth * 0.95), 400);
    QCoreApplication::processEvents();
    EXPECT_LT(view.zoom(), 1.0);
    EXPECT_LE(view.metrics().width(), view.viewport()->width());
}

// Side by side with the list on a small screen: the text stays readable (labels at 10 px or
// more, the names below them at 8 px or more) and the drawing scrolls instead.
TEST(LadderZoom, FitToWidthKeepsTheTextReadableAndScrollsInstead) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    editor::LadderView view(&document);
    view.resize(400, 400);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.setFitWidth(true);
    const editor::LadderMetrics m = view.metrics();
    // The sizes the painter draws with at this zoom: device labels and the small text (names,
    // comments, rung numbers).
    const editor::LadderMetrics::FontSizes sizes = m.fontSizes();
    EXPECT_GE(sizes.label, 10);
    EXPECT_GE(sizes.small, 9);
    EXPECT_LT(view.zoom(), 1.0); // it did shrink, as far as readable
    EXPECT_GT(m.width(), view.viewport()->width());
    EXPECT_GT(view.horizontalScrollBar()->maximum(), 0); // the rest is a scroll away
    EXPECT_TRUE(view.fitWidth());
}

TEST(LadderZoom, TheUsersZoomEndsFitToWidth) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    editor::LadderView view(&document);
    view.resize(600, 400);
    view.setFitWidth(true);
    QSignalSpy changed(&view, &editor::LadderView::fitWidthChanged);
    view.setZoom(1.5);
    EXPECT_FALSE(view.fitWidth());
    ASSERT_EQ(changed.count(), 1);
    EXPECT_FALSE(changed.front().front().toBool());
    EXPECT_DOUBLE_EQ(view.zoom(), 1.5);
    view.resize(500, 400); // no longer follows the width
    QCoreApplication::processEvents();
    EXPECT_DOUBLE_EQ(view.zoom(), 1.5);
}

TEST(LadderZoom, TheChoiceIsAViewMenuOptionRememberedForTheNextStart) {
    auto fitAction = [](app::MainWindow &w) -> QAction * {
        for (QAction *a : w.findChildren<QAction *>())
            if (a->text().remove(QLatin1Char('&')) == QStringLiteral("Fit Ladder to Width"))
                return a;
        return nullptr;
    };
    {
        app::MainWindow window;
        QAction *fit = fitAction(window);
        ASSERT_NE(fit, nullptr);
        fit->setChecked(true);
        EXPECT_TRUE(window.ladderView()->fitWidth());
        fit->setChecked(false);
        EXPECT_FALSE(window.ladderView()->fitWidth());
    }
    {
        app::MainWindow window;
        EXPECT_FALSE(window.ladderView()->fitWidth());
        EXPECT_FALSE(fitAction(window)->isChecked());
        window.ladderView()->setZoom(1.0);
        fitAction(window)->setChecked(true); // leave the default for the other tests
    }
    app::MainWindow again;
    EXPECT_TRUE(again.ladderView()->fitWidth());
}
