// The palette on the main toolbar: drawn icons (no icon theme on a plain desktop), the
// function key in every tooltip, and a click does what the key does.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"

#include <QAction>
#include <QCoreApplication>
#include <QLineEdit>
#include <QTest>
#include <QToolBar>

#include <gtest/gtest.h>

using namespace rung;

namespace {

QAction *toolbarAction(app::MainWindow &window, const QString &text) {
    for (QToolBar *bar : window.findChildren<QToolBar *>())
        for (QAction *a : bar->actions())
            if (a->text().remove(QLatin1Char('&')) == text)
                return a;
    return nullptr;
}

} // namespace

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
        QAction *a = toolbarAction(window, QString::fromLatin1(text));
        ASSERT_NE(a, nullptr) << text;
        EXPECT_FALSE(a->icon().isNull()) << text;
        EXPECT_FALSE(a->icon().pixmap(24, 24).isNull()) << text;
        EXPECT_TRUE(a->toolTip().contains(QString::fromLatin1(key))) << a->toolTip().toStdString();
    }
}

TEST(Toolbar, PaletteButtonsPlaceWhatTheirKeysPlace) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    // The buttons post their function key to the ladder, as if the user had pressed it.
    auto place = [&](const char *button, const char *operand) {
        QAction *a = toolbarAction(window, QString::fromLatin1(button));
        ASSERT_NE(a, nullptr) << button;
        a->trigger();
        QCoreApplication::sendPostedEvents();
        QLineEdit *edit = window.ladderView()->inlineEditor();
        ASSERT_TRUE(edit->isVisible()) << button;
        QTest::keyClicks(edit, QString::fromLatin1(operand));
        QTest::keyClick(edit, Qt::Key_Return);
    };
    place("Normally Open Contact", "X3");
    place("Normally Closed Contact", "X4");
    place("Coil", "Y2");
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD X3\nANI X4\nOUT Y2\nEND\n"));
    // The buttons with modifiers post them too: a parallel contact below the first one.
    window.ladderView()->setCursor({0, 1, 0});
    place("Parallel Contact", "M1");
    EXPECT_EQ(window.document()->listingText(),
              QStringLiteral("LD X3\nOR M1\nANI X4\nOUT Y2\nEND\n"));
}
