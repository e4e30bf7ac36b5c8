// rungstudio [FILE] [--target T]: the arguments, and an instruction list opened with the
// target given on the command line.

#include "app/gui/command_line.h"
#include "app/gui/main_window.h"
#include "editor/il_editor.h"
#include "editor/problems_view.h"

#include <QFile>
#include <QStatusBar>
#include <QTemporaryDir>

#include "tests/test_files.h"

#include <gtest/gtest.h>

using namespace rung;

TEST(CommandLine, AFileAndATarget) {
    const app::GuiArguments a =
        app::parseGuiArguments({QStringLiteral("rungstudio"), QStringLiteral("prog.il"),
                                QStringLiteral("--target"), QStringLiteral("CPM1")});
    ASSERT_TRUE(a.ok()) << a.error.toStdString();
    EXPECT_EQ(a.file, QStringLiteral("prog.il"));
    EXPECT_EQ(a.target, QStringLiteral("cpm1"));
    EXPECT_TRUE(a.screenshot.isEmpty());
    const app::GuiArguments none = app::parseGuiArguments({QStringLiteral("rungstudio")});
    EXPECT_TRUE(none.ok());
    EXPECT_TRUE(none.file.isEmpty());
}

TEST(CommandLine, WhatCannotBeUsedSaysWhy) {
    const app::GuiArguments unknown = app::parseGuiArguments(
        {QStringLiteral("rungstudio"), QStringLiteral("p.il"), QStringLiteral("--target=s7")});
    EXPECT_EQ(unknown.error, QStringLiteral("Unknown target s7: use vpc, vigor, cpm1, pl110"));
    EXPECT_FALSE(app::parseGuiArguments({QStringLiteral("rungstudio"), QStringLiteral("a.rung"),
                                         QStringLiteral("b.rung")})
                     .ok());
    EXPECT_FALSE(
        app::parseGuiArguments({QStringLiteral("rungstudio"), QStringLiteral("--bogus")}).ok());
}

TEST(CommandLine, AnInstructionListOpensForTheTargetGiven) {
    QTemporaryDir dir;
    const QString path =
        test::writeFile(dir, QStringLiteral("prog.il"), "LD 000.01\nOUT 010.00\nEND(01)\n");
    const app::GuiArguments a = app::parseGuiArguments(
        {QStringLiteral("rungstudio"), path, QStringLiteral("--target"), QStringLiteral("cpm1")});
    ASSERT_TRUE(a.ok());
    app::MainWindow window;
    ASSERT_TRUE(window.openFile(a.file, a.target, true));
    EXPECT_EQ(window.document()->target().id, QStringLiteral("cpm1"));
    EXPECT_EQ(window.document()->listingText(), QStringLiteral("LD 000.01\nOUT 010.00\nEND(01)\n"));
    EXPECT_TRUE(window.document()->path().isEmpty()); // saving asks where: it is no project
    // A target given that cannot read CPM1 addresses wins: the text opens as written, with
    // the errors marked, and the ladder waits for a valid program.
    app::MainWindow other;
    ASSERT_TRUE(other.openFile(path, QStringLiteral("vigor"), true));
    EXPECT_EQ(other.document()->target().id, QStringLiteral("vigor"));
    EXPECT_EQ(other.ilEditor()->text(), QStringLiteral("LD 000.01\nOUT 010.00\nEND(01)\n"));
    EXPECT_EQ(other.document()->listingText(), QStringLiteral("END\n"));
    ASSERT_NE(other.problemsView()->diagnosticAt(0), nullptr);
    EXPECT_EQ(other.problemsView()->diagnosticAt(0)->location.line, 1);
}

// A project is its own target: one asked for that it is not is said, not ignored (as
// rungstudio-cli says it; model::openProgramFile chooses for both).
TEST(CommandLine, AProjectOfAnotherTargetThanTheOneGivenIsRefusedSayingWhy) {
    const QString example =
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/start-first-latch.rung");
    app::MainWindow window;
    EXPECT_FALSE(window.openFile(example, QStringLiteral("cpm1"), true));
    EXPECT_EQ(window.statusBar()->currentMessage(),
              example + QStringLiteral(" is a vigor project, not cpm1"));
    EXPECT_EQ(window.document()->target().id, model::Target::defaultTarget().id);
    ASSERT_TRUE(window.openFile(example, QStringLiteral("vigor"), true));
    EXPECT_EQ(window.document()->target().id, QStringLiteral("vigor"));
}
