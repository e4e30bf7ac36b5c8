// Completion in the ladder's cell editor: mnemonics of the project's target, then the devices
// the program and the symbol table use; it follows a change of target.

#include "app/gui/main_window.h"
#include "editor/ladder_view.h"
#include "model/address.h"

#include <QLineEdit>
#include <QTest>

#include <gtest/gtest.h>

using namespace rung;

TEST(CellCompletion, MnemonicsFirstThenTheDevicesInUse) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(window.document()->setListing(
        QStringLiteral("LD X0\nAND X1\nOUT Y0\nLD M7\nOUT Y1\nEND\n"), &errors));
    window.document()->setSymbols(
        {model::Symbol{std::get<model::Address>(
                           model::parseAddress(window.document()->target(), QStringLiteral("X5"))),
                       QStringLiteral("Stop"), QString()}});
    window.show();
    editor::LadderView *view = window.ladderView();
    view->setCursor({1, 0, 1});
    view->openEditor(QString());
    QLineEdit *edit = view->inlineEditor();
    QTest::keyClicks(edit, QStringLiteral("AN"));
    EXPECT_TRUE(view->completions().contains(QStringLiteral("ANI")));
    EXPECT_TRUE(view->completions().contains(QStringLiteral("ANB")));
    QTest::keyClicks(edit, QStringLiteral("I X"));
    const QStringList devices = view->completions();
    for (const char *d : {"ANI X0", "ANI X1", "ANI X5", "ANI Y0", "ANI M7"})
        EXPECT_TRUE(devices.contains(QString::fromLatin1(d))) << d;
}

TEST(CellCompletion, FollowsTheTargetOfTheOpenedProject) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    window.show();
    editor::LadderView *view = window.ladderView();
    view->openEditor(QString());
    QTest::keyClicks(view->inlineEditor(), QStringLiteral("T"));
    EXPECT_TRUE(view->completions().contains(QStringLiteral("TIM")));
    EXPECT_FALSE(view->completions().contains(QStringLiteral("TMR"))); // Vigor's
}
