// Opening a program file and choosing its target: one function for File > Open and every
// command of rungstudio-cli (model/project/program_file.h).

#include "model/project/program_file.h"
#include "tests/targets.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace rung::model;

namespace {

QString write(const QTemporaryDir &dir, const char *name, const char *text) {
    const QString path = dir.filePath(QString::fromLatin1(name));
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(text);
    return path;
}

struct Opened {
    std::optional<ProgramFile> file;
    QString error;
    QString targetId() const { return file && file->target ? file->target->id : QString(); }
};

Opened open(const QString &path, const char *asked = "", const char *fallback = "") {
    ProgramFileOptions options;
    options.target = QString::fromLatin1(asked);
    options.fallbackTarget = QString::fromLatin1(fallback);
    Opened o;
    o.file = openProgramFile(path, programFileKind(path), options, &o.error);
    return o;
}

} // namespace

TEST(ProgramFile, TheKindFollowsTheName) {
    EXPECT_EQ(programFileKind(QStringLiteral("a/b.rung")), ProgramFileKind::Project);
    EXPECT_EQ(programFileKind(QStringLiteral("b.RUNG")), ProgramFileKind::Project);
    EXPECT_EQ(programFileKind(QStringLiteral("b.ladder")), ProgramFileKind::LadderText);
    EXPECT_EQ(programFileKind(QStringLiteral("b.il")), ProgramFileKind::Listing);
    EXPECT_EQ(programFileKind(QStringLiteral("b.txt")), ProgramFileKind::Listing);
    EXPECT_EQ(programFileKind(QStringLiteral("b")), ProgramFileKind::Listing);
}

TEST(ProgramFile, AListingsTargetIsAskedElseDeclaredElseReadFromItsSyntax) {
    QTemporaryDir dir;
    const QString declared = write(dir, "d.il", "; target: cpm1\nLD 000.00\nOUT 010.00\nEND(01)\n");
    EXPECT_EQ(open(declared).targetId(), QStringLiteral("cpm1"));
    EXPECT_EQ(open(declared, "vigor").targetId(), QStringLiteral("vigor"));
    const QString bare = write(dir, "b.il", "LD 000.00\nOUT 010.00\nEND(01)\n");
    // With a target in hand (the IDE's project), the one whose syntax reads it.
    EXPECT_EQ(open(bare, "", "vigor").targetId(), QStringLiteral("cpm1"));
    EXPECT_EQ(open(bare, "", "vigor").file->text,
              QStringLiteral("LD 000.00\nOUT 010.00\nEND(01)\n"));
    // Without one (the command line), none: the caller asks which.
    const Opened none = open(bare);
    ASSERT_TRUE(none.file.has_value()) << none.error.toStdString();
    EXPECT_EQ(none.file->target, nullptr);
}

TEST(ProgramFile, ALadderTextNamesItsTargetAndOneWithoutReadsAsTheFirstFamily) {
    QTemporaryDir dir;
    const QString drawn = write(dir, "d.ladder", "LADDER pl110 WIDTH 8\n");
    EXPECT_EQ(open(drawn).targetId(), QStringLiteral("pl110"));
    EXPECT_EQ(open(drawn, "vigor").targetId(), QStringLiteral("vigor"));
    // No LADDER line: its reader says so, for whichever target.
    const QString headless = write(dir, "h.ladder", "RUNG 1\n");
    EXPECT_EQ(open(headless, "", "cpm1").targetId(), QStringLiteral("cpm1"));
    EXPECT_EQ(open(headless).targetId(), Target::get(Target::families().front()).id);
}

TEST(ProgramFile, AProjectIsItsOwnTargetAndAnotherAskedIsAnError) {
    QTemporaryDir dir;
    Project project;
    project.target = &rung::testing::vigor();
    project.model = project.target->defaultModel().name;
    project.program.target = project.target;
    const QString path = dir.filePath(QStringLiteral("p.rung"));
    ProjectError saveError;
    ASSERT_TRUE(saveProject(project, path, &saveError)) << saveError.message.toStdString();
    const Opened opened = open(path, "", "cpm1");
    ASSERT_TRUE(opened.file.has_value()) << opened.error.toStdString();
    EXPECT_EQ(opened.file->project.target, &rung::testing::vigor());
    EXPECT_TRUE(opened.file->text.isEmpty());
    EXPECT_EQ(open(path, "vigor").targetId(), QStringLiteral("vigor"));
    const Opened other = open(path, "cpm1");
    EXPECT_FALSE(other.file.has_value());
    EXPECT_EQ(other.error, path + QStringLiteral(" is a vigor project, not cpm1"));
}

TEST(ProgramFile, AnUnknownTargetIsNamedWithWhoNamedIt) {
    QTemporaryDir dir;
    const QString path = write(dir, "s.il", "; target: s7\nLD X0\n");
    const Opened declared = open(path, "", "vigor");
    EXPECT_FALSE(declared.file.has_value());
    EXPECT_EQ(declared.error,
              path + QStringLiteral(": unknown target s7 (vpc, vigor, cpm1, pl110)"));
    const Opened asked = open(path, "s5");
    EXPECT_EQ(asked.error, QStringLiteral("unknown target s5 (vpc, vigor, cpm1, pl110)"));
}

TEST(ProgramFile, ATextOverTheLimitOrMissingIsAnErrorThatNamesIt) {
    QTemporaryDir dir;
    const QString big = write(dir, "big.il", "; target: vigor\nLD X0\nOUT Y0\nEND\n");
    ProgramFileOptions options;
    options.maxBytes = 8;
    QString error;
    EXPECT_FALSE(openProgramFile(big, ProgramFileKind::Listing, options, &error).has_value());
    EXPECT_TRUE(error.contains(big)) << error.toStdString();
    const QString missing = dir.filePath(QStringLiteral("missing.il"));
    EXPECT_FALSE(open(missing, "vigor").file.has_value());
    EXPECT_TRUE(open(missing, "vigor").error.contains(missing));
}
