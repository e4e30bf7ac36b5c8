// The CLI never reports success on, or writes, less than the user's whole program: a project's
// list as typed with errors (pendingListing) is no clean check, and a listing that would leave
// contacts out is not written.

#include "model/project/project.h"

#include <QFile>
#include <QTemporaryDir>

#include "tests/cli/cli_run.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

using namespace rung;
using test::cli;

namespace {

// Contacts with no output on rung 1: the drawing holds them, a listing cannot.
const QByteArray kContactsOnly = "LADDER vigor WIDTH 8\n"
                                 "RUNG 1 ROWS 1 COLUMNS 2\n"
                                 "|-[ X0 ]---[ X1 ]-\n"
                                 "RUNG 2 ROWS 1 COLUMNS 1\n"
                                 "|-[ X2 ]--(OUT Y0)\n"
                                 "RUNG 3 ROWS 1 COLUMNS 0\n"
                                 "|-(END)\n";

// A Vigor project whose rungs are LD X0 / OUT Y0 / END and whose list as typed (saved with its
// error, as the IDE does) has X8 on line 3: X is octal on a Vigor.
QString projectWithTypedErrors(const QTemporaryDir &dir) {
    const QString listing =
        test::writeFile(dir, QStringLiteral("p.il"), "; target: vigor\nLD X0\nOUT Y0\nEND\n");
    const QString path = dir.filePath(QStringLiteral("p.rung"));
    EXPECT_EQ(cli({QStringLiteral("convert"), listing, QStringLiteral("--to"),
                   QStringLiteral("project"), QStringLiteral("-o"), path})
                  .code,
              0);
    auto project = model::loadProject(path, nullptr);
    EXPECT_TRUE(project);
    if (!project)
        return path;
    project->pendingListing = QStringLiteral("LD X0\nOUT Y0\nLD X8\nOUT Y1\nEND\n");
    EXPECT_TRUE(model::saveProject(*project, path, nullptr));
    return path;
}

} // namespace

TEST(CliWholeProgram, ConvertToAListingRefusesContactsItWouldLeaveOut) {
    QTemporaryDir dir;
    const QString ladder = test::writeFile(dir, QStringLiteral("c.ladder"), kContactsOnly);
    const QString out = dir.filePath(QStringLiteral("c.il"));
    const test::CliRun r = cli({QStringLiteral("convert"), ladder, QStringLiteral("--to"),
                                QStringLiteral("il"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("c.ladder:rung 1:1:1: warning: X0")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("[LD002]"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("nothing written"))) << r.err.toStdString();
    // Not even --force: the file would be a shorter program, not one with findings.
    EXPECT_EQ(cli({QStringLiteral("convert"), ladder, QStringLiteral("--to"), QStringLiteral("il"),
                   QStringLiteral("--force"), QStringLiteral("-o"), out})
                  .code,
              1);
    EXPECT_FALSE(QFile::exists(out));
    // A ladder text keeps the contacts: that conversion loses nothing.
    const test::CliRun drawn =
        cli({QStringLiteral("convert"), ladder, QStringLiteral("--to"), QStringLiteral("ladder")});
    EXPECT_EQ(drawn.code, 0) << drawn.err.toStdString();
    EXPECT_TRUE(drawn.out.contains(QStringLiteral("[ X1 ]")));
}

TEST(CliWholeProgram, CheckOfAProjectWithAListAsTypedWithErrorsIsNoSuccess) {
    QTemporaryDir dir;
    const QString path = projectWithTypedErrors(dir);
    const test::CliRun r = cli({QStringLiteral("check"), path});
    EXPECT_EQ(r.code, 1);
    // Where: the key of the project file, and the line and column in the typed text.
    EXPECT_TRUE(r.out.contains(path + QStringLiteral(":pendingListing:3:"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("X8"))) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("pendingListing"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("not in its program"))) << r.err.toStdString();
}

TEST(CliWholeProgram, ConvertOfAProjectWithAListAsTypedWithErrorsKeepsIt) {
    QTemporaryDir dir;
    const QString path = projectWithTypedErrors(dir);
    for (const char *to : {"il", "ladder"}) {
        const QString out = dir.filePath(QStringLiteral("out.") + QLatin1String(to));
        const test::CliRun r =
            cli({QStringLiteral("convert"), path, QStringLiteral("--to"), QLatin1String(to),
                 QStringLiteral("--force"), QStringLiteral("-o"), out});
        EXPECT_EQ(r.code, 1) << to;
        EXPECT_FALSE(QFile::exists(out)) << to;
        EXPECT_TRUE(r.err.contains(QStringLiteral("pendingListing"))) << r.err.toStdString();
        EXPECT_TRUE(r.err.contains(QStringLiteral(":pendingListing:3:"))) << r.err.toStdString();
    }
    // A project keeps the list as typed.
    const QString copy = dir.filePath(QStringLiteral("copy.rung"));
    EXPECT_EQ(cli({QStringLiteral("convert"), path, QStringLiteral("--to"),
                   QStringLiteral("project"), QStringLiteral("-o"), copy})
                  .code,
              0);
    const auto kept = model::loadProject(copy, nullptr);
    ASSERT_TRUE(kept);
    EXPECT_TRUE(kept->pendingListing.contains(QStringLiteral("LD X8")));
}

// A block that leaves the registers is a check error (issue 14: check and simulate agree), so
// convert writes nothing for it and says where; the corrected block converts.
TEST(CliWholeProgram, ConvertWritesNoBlockMoveThatLeavesItsArea) {
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, QStringLiteral("b.il"),
                                         "; target: vigor\nLD M9000\nBMOV D8190 D0 K10\nEND\n");
    const QString out = dir.filePath(QStringLiteral("b.ladder"));
    const test::CliRun r = cli({QStringLiteral("convert"), file, QStringLiteral("--to"),
                                QStringLiteral("ladder"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("b.il:3:6: error: BMOV uses D8190..D8199, but "
                                              "D8192 does not exist [OP005]")))
        << r.err.toStdString();
    const test::CliRun check = cli({QStringLiteral("check"), file});
    EXPECT_EQ(check.code, 1);
    const QString good = test::writeFile(dir, QStringLiteral("g.il"),
                                         "; target: vigor\nLD M9000\nBMOV D8182 D0 K10\nEND\n");
    const test::CliRun converted = cli({QStringLiteral("convert"), good, QStringLiteral("--to"),
                                        QStringLiteral("ladder"), QStringLiteral("-o"), out});
    EXPECT_EQ(converted.code, 0) << converted.err.toStdString();
    EXPECT_TRUE(QFile::exists(out));
}
