// Completion in the ladder's cell editor: mnemonics of the project's target, then the devices
// the program and the symbol table use; it follows a change of target.

#include "app/gui/main_window.h"
#include "editor/document.h"
#include "editor/il_editor.h"
#include "editor/ladder_view.h"
#include "model/target/address.h"

#include <QLineEdit>
#include <QTest>

#include "tests/editor/window_fixture.h"

#include <gtest/gtest.h>

using namespace rung;

using CellCompletion = test::WindowFixture;

TEST_F(CellCompletion, MnemonicsFirstThenTheDevicesInUse) {
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

TEST_F(CellCompletion, FollowsTheTargetOfTheOpenedProject) {
    window.newProject(model::Target::get(model::Family::Cpm1), QString());
    window.show();
    editor::LadderView *view = window.ladderView();
    view->openEditor(QString());
    QTest::keyClicks(view->inlineEditor(), QStringLiteral("T"));
    EXPECT_TRUE(view->completions().contains(QStringLiteral("TIM")));
    EXPECT_FALSE(view->completions().contains(QStringLiteral("TMR"))); // Vigor's
}

namespace {

// The item the open completion list has selected.
QString selectedItem(editor::IlEditor *il) {
    QByteArray buffer(256, '\0');
    il->SendScintilla(QsciScintillaBase::SCI_AUTOCGETCURRENTTEXT, static_cast<unsigned long>(0),
                      static_cast<void *>(buffer.data()));
    return QString::fromUtf8(buffer.constData());
}

} // namespace

TEST(IlCompletion, MnemonicsAtTheStartOfALineDevicesWithTheirNamesAfterIt) {
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
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    editor::IlEditor *il = window.ilEditor();
    il->setFocus();
    il->setCursorPosition(0, 0);
    QTest::keyClick(il, Qt::Key_Return);
    il->setCursorPosition(0, 0);

    QTest::keyClicks(il, QStringLiteral("AN"));
    ASSERT_TRUE(il->isListActive()); // the target's mnemonics
    EXPECT_TRUE(selectedItem(il).startsWith(QStringLiteral("AN")))
        << selectedItem(il).toStdString();
    il->cancelList();

    QTest::keyClicks(il, QStringLiteral("I X"));
    ASSERT_TRUE(il->isListActive()); // the devices of the project
    EXPECT_EQ(selectedItem(il), QStringLiteral("X0"));
    QTest::keyClick(il, Qt::Key_Down);
    QTest::keyClick(il, Qt::Key_Down);
    EXPECT_EQ(selectedItem(il), QStringLiteral("X5  Stop")); // the symbol's name beside it
    QTest::keyClick(il, Qt::Key_Return);
    EXPECT_FALSE(il->isListActive());
    EXPECT_EQ(il->text(0).trimmed(), QStringLiteral("ANI X5")); // only the device goes in

    // A constant is no device: no list.
    QTest::keyClick(il, Qt::Key_End);
    QTest::keyClicks(il, QStringLiteral(" K"));
    EXPECT_FALSE(il->isListActive());

    // A device typed in full, with no name to show, needs no list.
    QTest::keyClick(il, Qt::Key_Return);
    QTest::keyClicks(il, QStringLiteral("OUT Y"));
    EXPECT_TRUE(il->isListActive());
    QTest::keyClicks(il, QStringLiteral("1"));
    EXPECT_FALSE(il->isListActive());
    QTest::keyClick(il, Qt::Key_Return);
    QTest::keyClicks(il, QStringLiteral("LD X5")); // named, but typed in full: Return ends the line
    EXPECT_FALSE(il->isListActive());
}

TEST(IlCompletion, TheSecondWordOfAVpcMnemonicIsOffered) {
    app::MainWindow window;
    window.newProject(model::Target::get(model::Family::Vpc), QString());
    window.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
    editor::IlEditor *il = window.ilEditor();
    il->setFocus();
    il->setCursorPosition(0, 0);
    QTest::keyClick(il, Qt::Key_Return);
    il->setCursorPosition(0, 0);
    QTest::keyClicks(il, QStringLiteral("LD N"));
    ASSERT_TRUE(il->isListActive());
    EXPECT_EQ(selectedItem(il), QStringLiteral("NOT"));
}

TEST(DocumentDevices, UsedAndNamedDevicesInAddressOrder) {
    editor::Document document;
    document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
    std::vector<model::Diagnostic> errors;
    ASSERT_TRUE(
        document.setListing(QStringLiteral("LD X10\nOUT Y0\nLD X2\nOUT M7\nEND\n"), &errors));
    document.setSymbols({model::Symbol{
        std::get<model::Address>(model::parseAddress(document.target(), QStringLiteral("X3"))),
        QStringLiteral("Stop"), QString()}});
    EXPECT_EQ(document.knownDevices(),
              (QStringList{QStringLiteral("X2"), QStringLiteral("X3"), QStringLiteral("X10"),
                           QStringLiteral("Y0"), QStringLiteral("M7")}));
    EXPECT_TRUE(document.knownDevices(true).contains(QStringLiteral("X3  Stop")));
}
