#include "app/cli/cli.h"
#include "app/cli/cli_language.h"

#include "model/project/project.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTranslator>

#include "tests/cli/cli_run.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

#include <memory>

namespace {

using rung::test::cli;
using rung::test::CliRun;

QString write(const QTemporaryDir &dir, const QString &name, const QByteArray &content) {
    return rung::test::writeFile(dir, name, content);
}

} // namespace

TEST(CliCheck, PrintsOneLinePerFindingWithPlaceSeverityAndCode) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("dup.il"),
                               "LD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND(01)\n");
    const CliRun r =
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("cpm1")});
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(
        r.out,
        QStringLiteral(
            "%1:4:1: error: 010.00 is driven twice; a coil may be driven only once (the first "
            "is on line 2) [DC001]\n")
            .arg(file));
}

TEST(CliCheck, ExitsZeroWhenThereAreOnlyWarnings) {
    QTemporaryDir dir;
    const QString file =
        write(dir, QStringLiteral("w.il"), "; target: vigor\nLD X0\nOUT Y0\nLD X1\nOUT Y0\nEND\n");
    const CliRun r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.contains(QStringLiteral(":5:1: warning: ")));
}

TEST(CliCheck, SyntaxErrorsHaveLineAndColumn) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("bad.il"), "LD X0\nOUT Y8\nEND\n");
    const CliRun r =
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vigor")});
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out,
              QStringLiteral("%1:2:6: error: Y8: Y is numbered in octal [SYN001]\n").arg(file));
}

// The lines that parse are checked beside the one that does not, as in the editor.
TEST(CliCheck, TheLinesThatParseAreCheckedBesideASyntaxError) {
    QTemporaryDir dir;
    const QString file =
        write(dir, QStringLiteral("bad.il"), "LD X8\nOUT Y0\nLD X1\nOUT X2\nEND\n");
    const CliRun r =
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vigor")});
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out,
              QStringLiteral("%1:1:5: error: X8: X is numbered in octal [SYN001]\n"
                             "%1:4:5: error: X2 cannot be written: the program only reads it "
                             "(inputs) [OP002]\n")
                  .arg(file));
}

// A rung whose X2 would carry power right to left (RC001 at rung 1, row 1, column 4).
constexpr char kBridgeLadder[] = "LADDER vigor WIDTH 8\n"
                                 "RUNG 1 ROWS 3 COLUMNS 3\n"
                                 "|-[ X0 ]-+----------[ X1 ]-+(OUT Y0)\n"
                                 "|        |                 |\n"
                                 "|        +-[ X2 ]-+        +\n"
                                 "|                 |        |\n"
                                 "|-[ X3 ]----------+-[ X4 ]-+\n";

TEST(CliCheck, LadderFindingsNameTheRung) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("bridge.ladder"), kBridgeLadder);
    const CliRun r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral("%1:rung 1:1:4: error: Reverse current").arg(file)))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("[RC001]")));
}

TEST(CliCheck, ModelNarrowsTheRanges) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("v.il"), "LD i00\nOUT o20\nEND\n");
    EXPECT_EQ(
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vpc")})
            .code,
        0);
    const CliRun r =
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vpc"),
             QStringLiteral("--model"), QStringLiteral("VPC2416")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(
        QStringLiteral("v.il:2:6: error: o20 is beyond VPC2416's outputs o00..o15")));
}

TEST(CliUsage, ErrorsExitTwo) {
    EXPECT_EQ(cli({}).code, 2);
    EXPECT_EQ(cli({QStringLiteral("frobnicate")}).code, 2);
    EXPECT_EQ(cli({QStringLiteral("check")}).code, 2);
    const CliRun missing = cli({QStringLiteral("check"), QStringLiteral("/nonexistent/x.il"),
                                QStringLiteral("--target"), QStringLiteral("vigor")});
    EXPECT_EQ(missing.code, 2);
    EXPECT_TRUE(missing.err.contains(QStringLiteral("/nonexistent/x.il")));
    QTemporaryDir dir;
    const QString noTarget = write(dir, QStringLiteral("n.il"), "LD X0\nOUT Y0\n");
    const CliRun r = cli({QStringLiteral("check"), noTarget});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--target")));
    EXPECT_EQ(cli({QStringLiteral("--help")}).code, 0);
}

TEST(CliConvert, ListingToLadderToProjectAndBack) {
    QTemporaryDir dir;
    const QByteArray listing = "LD X0\nOR X1\nLD X2\nOR X3\nANB\nOUT Y0\nEND\n";
    const QString il = write(dir, QStringLiteral("p.il"), listing);
    const QString ladder = dir.filePath(QStringLiteral("p.ladder"));
    const QString project = dir.filePath(QStringLiteral("p.rung"));
    ASSERT_EQ(
        cli({QStringLiteral("convert"), il, QStringLiteral("--target"), QStringLiteral("vigor"),
             QStringLiteral("--to"), QStringLiteral("ladder"), QStringLiteral("-o"), ladder})
            .code,
        0);
    ASSERT_EQ(cli({QStringLiteral("convert"), ladder, QStringLiteral("--to"),
                   QStringLiteral("project"), QStringLiteral("-o"), project})
                  .code,
              0);
    const CliRun back =
        cli({QStringLiteral("convert"), project, QStringLiteral("--to"), QStringLiteral("il")});
    EXPECT_EQ(back.code, 0);
    EXPECT_EQ(back.out, QString::fromLatin1(listing));
}

TEST(CliConvert, FromOverridesTheExtension) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("prog.txt"), "LD X0\nOUT Y0\nEND\n");
    const CliRun r = cli({QStringLiteral("convert"), file, QStringLiteral("--from"),
                          QStringLiteral("il"), QStringLiteral("--target"), QStringLiteral("vigor"),
                          QStringLiteral("--to"), QStringLiteral("ladder")});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("LADDER vigor WIDTH")));
}

TEST(CliConvert, RefusesToWriteWhatHasErrors) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("e.il"), "LD X0\nANB\nOUT Y0\n");
    const QString out = dir.filePath(QStringLiteral("e.rung"));
    const CliRun r =
        cli({QStringLiteral("convert"), file, QStringLiteral("--target"), QStringLiteral("vigor"),
             QStringLiteral("--to"), QStringLiteral("project"), QStringLiteral("-o"), out});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out));
    EXPECT_TRUE(r.err.contains(QStringLiteral("e.il:2:1: error:")));
}

TEST(CliBinary, TheInstalledToolRunsTheSameCommands) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("b.il"), "LD X0\nOUT X1\nEND\n");
    QProcess p;
    p.start(QStringLiteral(RUNG_CLI_PATH),
            {QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vigor")});
    ASSERT_TRUE(p.waitForFinished(30000));
    EXPECT_EQ(p.exitCode(), 1);
    EXPECT_TRUE(QString::fromUtf8(p.readAllStandardOutput()).contains(QStringLiteral("[OP002]")));
}

#ifdef RUNG_QM_DIR
// The tool follows the locale like other command-line tools; the C locale of scripts keeps
// English. What it should print is what the same command prints with the catalogue loaded.
TEST(CliBinary, SpeaksTheLanguageOfTheLocale) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("l.il"), "LD X0\nOUT X1\n");
    const QStringList args{QStringLiteral("check"), file, QStringLiteral("--target"),
                           QStringLiteral("vigor")};
    const auto runBinary = [&](const QString &lang) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"LC_ALL", "LC_MESSAGES", "LANGUAGE"})
            env.remove(QString::fromLatin1(name));
        env.insert(QStringLiteral("LANG"), lang);
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(RUNG_CLI_PATH), args);
        EXPECT_TRUE(p.waitForFinished(30000));
        EXPECT_EQ(p.exitCode(), 1);
        return QString::fromUtf8(p.readAllStandardOutput());
    };
    std::unique_ptr<QCoreApplication> app;
    int argc = 1;
    char arg0[] = "test_cli";
    char *argv[] = {arg0, nullptr};
    if (!QCoreApplication::instance())
        app = std::make_unique<QCoreApplication>(argc, argv);
    const auto runWith = [&](const QString &language) {
        QTranslator translator;
        EXPECT_TRUE(translator.load(QStringLiteral(RUNG_QM_DIR "/rungstudio_") + language));
        QCoreApplication::installTranslator(&translator);
        const QString out = cli(args).out;
        QCoreApplication::removeTranslator(&translator);
        return out;
    };

    const QString english = cli(args).out;
    ASSERT_TRUE(english.contains(QStringLiteral("[OP002]")));
    ASSERT_TRUE(english.contains(QStringLiteral("[EN001]")));
    EXPECT_EQ(runBinary(QStringLiteral("C")).toStdString(), english.toStdString());
    for (const QString &language : {QStringLiteral("hu"), QStringLiteral("it")}) {
        const QString expected = runWith(language);
        EXPECT_NE(expected.toStdString(), english.toStdString()) << language.toStdString();
        EXPECT_TRUE(expected.contains(QStringLiteral("[OP002]")));
        EXPECT_EQ(runBinary(language + QStringLiteral("_") + language.toUpper() +
                            QStringLiteral(".UTF-8"))
                      .toStdString(),
                  expected.toStdString());
    }
}

// --lang picks the language whatever the locale says; what it should print is again what the
// same command prints with that catalogue loaded.
TEST(CliBinary, LangPicksTheLanguageOverTheLocale) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("g.il"), "LD X0\nOUT X1\n");
    const QStringList args{QStringLiteral("check"), file, QStringLiteral("--target"),
                           QStringLiteral("vigor")};
    const auto runBinary = [&](const QStringList &options, const QString &lang, int *code) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"LC_ALL", "LC_MESSAGES", "LANGUAGE"})
            env.remove(QString::fromLatin1(name));
        env.insert(QStringLiteral("LANG"), lang);
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(RUNG_CLI_PATH), options);
        EXPECT_TRUE(p.waitForFinished(30000));
        *code = p.exitCode();
        return QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
    };
    std::unique_ptr<QCoreApplication> app;
    int argc = 1;
    char arg0[] = "test_cli";
    char *argv[] = {arg0, nullptr};
    if (!QCoreApplication::instance())
        app = std::make_unique<QCoreApplication>(argc, argv);
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(RUNG_QM_DIR "/rungstudio_hu")));
    QCoreApplication::installTranslator(&translator);
    const QString hungarian = cli(args).out;
    QCoreApplication::removeTranslator(&translator);
    const QString english = cli(args).out;
    ASSERT_NE(hungarian, english);
    int code = 0;
    EXPECT_EQ(runBinary(QStringList{QStringLiteral("--lang"), QStringLiteral("hu")} + args,
                        QStringLiteral("C"), &code)
                  .toStdString(),
              hungarian.toStdString());
    EXPECT_EQ(code, 1);
    EXPECT_EQ(runBinary(args + QStringList{QStringLiteral("--lang=en")},
                        QStringLiteral("it_IT.UTF-8"), &code)
                  .toStdString(),
              english.toStdString());
    const QString wrong =
        runBinary(QStringList{QStringLiteral("--lang"), QStringLiteral("de")} + args,
                  QStringLiteral("C"), &code);
    EXPECT_EQ(code, 2);
    EXPECT_TRUE(wrong.contains(QStringLiteral("--lang must be one of en, hu, it")))
        << wrong.toStdString();
}

// The place of a finding on the ladder ("rung 1:1:4") speaks the language of --lang too.
TEST(CliBinary, LangTranslatesTheRungOfAFindingsPlace) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("bridge.ladder"), kBridgeLadder);
    const auto run = [&](const char *lang) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        for (const char *name : {"LC_ALL", "LC_MESSAGES", "LANGUAGE"})
            env.remove(QString::fromLatin1(name));
        env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(RUNG_CLI_PATH), {QStringLiteral("--lang"), QString::fromLatin1(lang),
                                                QStringLiteral("check"), file});
        EXPECT_TRUE(p.waitForFinished(30000));
        EXPECT_EQ(p.exitCode(), 1);
        return QString::fromUtf8(p.readAllStandardOutput());
    };
    const QString english = run("en");
    EXPECT_TRUE(english.contains(file + QStringLiteral(":rung 1:1:4: error: ")))
        << english.toStdString();
    const QString hungarian = run("hu");
    EXPECT_TRUE(hungarian.contains(file + QStringLiteral(":létrafok 1:1:4: hiba: ")))
        << hungarian.toStdString();
    EXPECT_FALSE(hungarian.contains(QStringLiteral(":rung "))) << hungarian.toStdString();
    const QString italian = run("it");
    EXPECT_TRUE(italian.contains(file + QStringLiteral(":segmento 1:1:4: errore: ")))
        << italian.toStdString();
    EXPECT_FALSE(italian.contains(QStringLiteral(":rung "))) << italian.toStdString();
}

// The C locale gets English with its plural forms, not the "(s)" of the source text.
TEST(CliBinary, EnglishInTheCLocaleHasItsPluralForms) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("p.il"), "LD X0\nOUT\nEND\n");
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char *name : {"LC_ALL", "LC_MESSAGES", "LANGUAGE"})
        env.remove(QString::fromLatin1(name));
    env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(RUNG_CLI_PATH),
            {QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("vigor")});
    ASSERT_TRUE(p.waitForFinished(30000));
    const QString out = QString::fromUtf8(p.readAllStandardOutput());
    EXPECT_TRUE(out.contains(QStringLiteral("needs 1 operand:"))) << out.toStdString();
    EXPECT_FALSE(out.contains(QStringLiteral("operand(s)"))) << out.toStdString();
}
#endif

TEST(Examples, EveryExampleProjectLoadsAndHasNoError) {
    int count = 0;
    for (const char *target : {"vpc", "vigor", "cpm1", "pl110"}) {
        QDir dir(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/") +
                 QString::fromLatin1(target));
        for (const QString &name : dir.entryList({QStringLiteral("*.rung")})) {
            const CliRun r = cli({QStringLiteral("check"), dir.filePath(name)});
            EXPECT_EQ(r.code, 0) << name.toStdString() << "\n"
                                 << r.out.toStdString() << r.err.toStdString();
            ++count;
        }
    }
    EXPECT_GE(count, 12);
}

TEST(CliUsage, HelpListsEveryCommandAndVersionNamesTheTool) {
    const CliRun help = cli({QStringLiteral("--help")});
    EXPECT_EQ(help.code, 0);
    for (const char *command :
         {"check FILE", "convert FILE", "simulate FILE", "serve FILE", "read  --target",
          "write (the same", "record --pc", "terminal --port"})
        EXPECT_TRUE(help.out.contains(QLatin1String(command))) << command;
    // Asked after a command, help is help, not an unknown option.
    for (const char *command : {"serve", "read", "record", "terminal", "check"}) {
        const CliRun after = cli({QLatin1String(command), QStringLiteral("--help")});
        EXPECT_EQ(after.code, 0) << command << after.err.toStdString();
        EXPECT_EQ(after.out, help.out) << command;
    }
    const CliRun version = cli({QStringLiteral("--version")});
    EXPECT_EQ(version.code, 0);
    EXPECT_TRUE(QRegularExpression(QStringLiteral("^rungstudio-cli \\d+\\.\\d+\\.\\d+\n$"))
                    .match(version.out)
                    .hasMatch())
        << version.out.toStdString();
}

TEST(CliCheck, BrokenProjectIsAnIoErrorWithTheReason) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("bad.rung"),
                               "{\"format\": \"rungstudio-project\", \"schema\": 1,\n\"target\": ");
    const CliRun r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.startsWith(QStringLiteral("bad.rung: Line 2, column 11 (byte 56): the file "
                                                "is not valid JSON")))
        << r.err.toStdString();
}

// ---- check: every finding by its documented code --------------------------------------------

namespace {

CliRun checkText(const QTemporaryDir &dir, const char *name, const QByteArray &content,
                 const char *target = nullptr) {
    QStringList args{QStringLiteral("check"), write(dir, QString::fromLatin1(name), content)};
    if (target)
        args << QStringLiteral("--target") << QString::fromLatin1(target);
    return cli(args);
}

// The codes of the printed findings, in order.
QStringList codes(const QString &out) {
    static const QRegularExpression re(QStringLiteral("\\[(\\w+)\\]$"),
                                       QRegularExpression::MultilineOption);
    QStringList found;
    for (auto it = re.globalMatch(out); it.hasNext();)
        found << it.next().captured(1);
    return found;
}

} // namespace

TEST(CliCheck, AListingThatCannotBeDrawnGetsEveryFindingByItsDocumentedCode) {
    QTemporaryDir dir;
    const CliRun r =
        checkText(dir, "bl.il", "LD X0\nLD X1\nOUT Y0\nLD X2\nOUT X3\nLD X4\nOUT Y0\n", "vigor");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(codes(r.out), (QStringList{QStringLiteral("BL001"), QStringLiteral("OP002"),
                                         QStringLiteral("EN001"), QStringLiteral("DC001")}))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("bl.il:3:1: error: ")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("[CV"))) << r.out.toStdString();
}

TEST(CliCheck, StackAndConditionProblemsHaveTheirOwnCodes) {
    QTemporaryDir dir;
    QByteArray deep = "LD X0\n";
    for (int i = 1; i <= 9; ++i)
        deep += "MPS\nAND X" + QByteArray::number(i, 8) + "\n";
    deep += "OUT Y0\n";
    for (int i = 1; i <= 9; ++i)
        deep += "MPP\nOUT Y" + QByteArray::number(i, 8) + "\n";
    deep += "END\n";
    const struct {
        const char *program;
        QStringList codes;
    } cases[] = {
        {deep.constData(), {QStringLiteral("ST001")}},
        {"LD X0\nMPP\nOUT Y0\nEND\n", {QStringLiteral("ST002")}},
        {"OUT Y0\nEND\n", {QStringLiteral("OC001")}},
        {"LD X0\nMPS\nAND X1\nOUT Y0\nEND\n", {QStringLiteral("ST003")}},
    };
    for (const auto &c : cases) {
        const CliRun r = checkText(dir, "s.il", c.program, "vigor");
        EXPECT_EQ(r.code, 1);
        EXPECT_EQ(codes(r.out), c.codes) << c.program << "\n" << r.out.toStdString();
    }
    // and where there is nothing to find, nothing
    const CliRun clean =
        checkText(dir, "c.il", "LD X0\nMPS\nAND X1\nOUT Y0\nMPP\nOUT Y1\nEND\n", "vigor");
    EXPECT_EQ(clean.code, 0);
    EXPECT_EQ(clean.out, QString());
}

TEST(CliCheck, AnOpenBranchOfALadderIsLD001) {
    QTemporaryDir dir;
    const CliRun r = checkText(dir, "open.ladder",
                               "LADDER vigor WIDTH 8\n"
                               "RUNG 1 ROWS 2 COLUMNS 2\n"
                               "|-[ X0 ]---[ X1 ]--(OUT Y0)\n"
                               "|\n"
                               "|         -[ X2 ]--(OUT Y1)\n"
                               "RUNG 2 ROWS 1 COLUMNS 0\n"
                               "|-(END)\n");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(codes(r.out), (QStringList{QStringLiteral("LD002"), QStringLiteral("LD001")}))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("open.ladder:rung 1:2:3: error: Open branch")));
}

TEST(CliCheck, TheLadderOfAProgramGetsNoListingFormWarnings) {
    QTemporaryDir dir;
    const CliRun r = checkText(dir, "or.ladder",
                               "LADDER vigor WIDTH 8\n"
                               "RUNG 1 ROWS 2 COLUMNS 1\n"
                               "|-[ X0 ]-+(OUT Y0)\n"
                               "|        |\n"
                               "|-[ X1 ]-+\n"
                               "RUNG 2 ROWS 1 COLUMNS 0\n"
                               "|-(END)\n");
    EXPECT_EQ(r.code, 0);
    EXPECT_EQ(r.out, QString());
    const CliRun order =
        cli({QStringLiteral("check"),
             QStringLiteral(RUNG_SOURCE_DIR "/tests/data/il/vigor_seed_execution_order.il"),
             QStringLiteral("--target"), QStringLiteral("vigor")});
    EXPECT_FALSE(order.out.contains(QStringLiteral("[FZ"))) << order.out.toStdString();
    const CliRun bridge =
        cli({QStringLiteral("check"),
             QStringLiteral(RUNG_SOURCE_DIR "/tests/data/ladder/bridge_corrected.ladder")});
    EXPECT_EQ(codes(bridge.out), QStringList{QStringLiteral("EN001")}) << bridge.out.toStdString();
}

TEST(CliCheck, AFindingAboutTheWholeFileHasAPlaceToo) {
    QTemporaryDir dir;
    const CliRun r = checkText(dir, "e.ladder", "LADDER vigor WIDTH 8\n");
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(
        r.out,
        QStringLiteral("%1: error: END is missing [EN001]\n").arg(dir.filePath("e.ladder:1:1")));
}

TEST(CliCheck, ALadderWithoutItsHeaderIsASyntaxErrorWithOrWithoutTarget) {
    QTemporaryDir dir;
    const QByteArray text = "RUNG 1 ROWS 1 COLUMNS 1\n|-[ X0 ]--(OUT Y0)\n";
    for (const char *target : {static_cast<const char *>(nullptr), "vigor"}) {
        const CliRun r = checkText(dir, "h.ladder", text, target);
        EXPECT_EQ(r.code, 1) << (target ? target : "no target") << r.err.toStdString();
        EXPECT_TRUE(r.out.startsWith(dir.filePath(QStringLiteral("h.ladder:1:1: error: "))))
            << r.out.toStdString();
        EXPECT_TRUE(r.out.contains(QStringLiteral("[SYN001]")));
    }
}

// ---- input size -----------------------------------------------------------------------------

TEST(CliInput, AFileOverTheLimitIsRefused) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.il"));
    {
        QFile f(path);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        const QByteArray rung = "LD X0\nOUT Y0\n";
        QByteArray chunk;
        while (chunk.size() < 1024 * 1024)
            chunk += rung;
        for (int i = 0; i < 9; ++i)
            f.write(chunk);
    }
    const CliRun r =
        cli({QStringLiteral("check"), path, QStringLiteral("--target"), QStringLiteral("vigor")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(path)) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("8 MB"))) << r.err.toStdString();
    EXPECT_EQ(r.out, QString());
}

TEST(CliInput, AnEndlessDeviceIsRefused) {
    if (!QFile::exists(QStringLiteral("/dev/zero")))
        GTEST_SKIP() << "no /dev/zero";
    for (const char *command : {"check", "convert"}) {
        QStringList args{QString::fromLatin1(command), QStringLiteral("/dev/zero"),
                         QStringLiteral("--target"), QStringLiteral("vigor")};
        if (QLatin1String(command) == QLatin1String("convert"))
            args << QStringLiteral("--to") << QStringLiteral("ladder");
        const CliRun r = cli(args);
        EXPECT_EQ(r.code, 2) << command;
        EXPECT_TRUE(r.err.contains(QStringLiteral("8 MB"))) << r.err.toStdString();
    }
    const CliRun simulated =
        cli({QStringLiteral("simulate"), QStringLiteral("/dev/zero"), QStringLiteral("--target"),
             QStringLiteral("vigor"), QStringLiteral("--scans"), QStringLiteral("1"),
             QStringLiteral("--trace"), QStringLiteral("Y0")});
    EXPECT_EQ(simulated.code, 2);
    EXPECT_TRUE(simulated.err.contains(QStringLiteral("8 MB"))) << simulated.err.toStdString();
}

TEST(CliInput, RandomBytesAreASyntaxErrorNotACrash) {
    QTemporaryDir dir;
    QByteArray bytes;
    std::uint32_t x = 12345;
    for (int i = 0; i < 64 * 1024; ++i) {
        x = x * 1664525u + 1013904223u;
        bytes += static_cast<char>(x >> 24);
    }
    for (const char *name : {"r.il", "r.ladder"}) {
        const CliRun r = checkText(dir, name, bytes, "vigor");
        EXPECT_EQ(r.code, 1) << name << r.err.toStdString();
        EXPECT_TRUE(r.out.contains(QStringLiteral("[SYN001]"))) << name;
    }
}

// ---- convert --------------------------------------------------------------------------------

TEST(CliConvert, AListingIsWrittenBackInTheCanonicalForm) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("v.il"), "LD X0\nLD X1\nANB\nOUT Y0\nEND\n");
    const CliRun r = cli({QStringLiteral("convert"), file, QStringLiteral("--target"),
                          QStringLiteral("vigor"), QStringLiteral("--to"), QStringLiteral("il")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
}

TEST(CliConvert, TheReasonsForWritingNothingAreTheDocumentedCodes) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("m.il"), "LD X0\nMPP\nOUT Y0\nEND\n");
    const CliRun r =
        cli({QStringLiteral("convert"), file, QStringLiteral("--target"), QStringLiteral("vigor"),
             QStringLiteral("--to"), QStringLiteral("ladder")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(
        r.err.contains(QStringLiteral("m.il:2:1: error: MPP without a matching MPS [ST002]")))
        << r.err.toStdString();
    EXPECT_FALSE(r.err.contains(QStringLiteral("[CV")));
}

TEST(CliLanguage, TheOptionIsTakenOutOfTheArgumentsWhereverItIs) {
    QStringList args{QStringLiteral("rungstudio-cli"), QStringLiteral("check"),
                     QStringLiteral("--lang"), QStringLiteral("it"), QStringLiteral("a.il")};
    QString language;
    QString error;
    ASSERT_TRUE(rung::app::takeLanguageOption(&args, &language, &error));
    EXPECT_EQ(language, QStringLiteral("it"));
    EXPECT_EQ(args, (QStringList{QStringLiteral("rungstudio-cli"), QStringLiteral("check"),
                                 QStringLiteral("a.il")}));
    args = {QStringLiteral("rungstudio-cli"), QStringLiteral("--lang=hu"), QStringLiteral("check")};
    ASSERT_TRUE(rung::app::takeLanguageOption(&args, &language, &error));
    EXPECT_EQ(language, QStringLiteral("hu"));
    EXPECT_EQ(args, (QStringList{QStringLiteral("rungstudio-cli"), QStringLiteral("check")}));
    args = {QStringLiteral("rungstudio-cli"), QStringLiteral("check")};
    ASSERT_TRUE(rung::app::takeLanguageOption(&args, &language, &error));
    EXPECT_TRUE(language.isEmpty()); // the locale decides
    for (const QStringList &bad : {QStringList{QStringLiteral("x"), QStringLiteral("--lang")},
                                   QStringList{QStringLiteral("x"), QStringLiteral("--lang=fr")}}) {
        args = bad;
        EXPECT_FALSE(rung::app::takeLanguageOption(&args, &language, &error));
        EXPECT_EQ(error, QStringLiteral("--lang must be one of en, hu, it"));
    }
}

// docs/cli.md: "an input with errors writes nothing". The errors are every finding of `check`,
// not only the syntax: an empty file (no END) and a doubly driven output parse and convert, yet
// `check` rejects them, so `convert` must not write them.
TEST(CliConvert, WhatCheckRejectsIsNotWritten) {
    QTemporaryDir dir;
    const QString empty = write(dir, QStringLiteral("empty.il"), "");
    const QString dup = write(dir, QStringLiteral("dup.il"),
                              "LD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND(01)\n");
    for (const QString &file : {empty, dup}) {
        const CliRun check = cli(
            {QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("cpm1")});
        ASSERT_EQ(check.code, 1) << file.toStdString();
        for (const char *to : {"il", "ladder", "project"}) {
            const QString out = dir.filePath(QStringLiteral("out.") + QLatin1String(to));
            const CliRun r = cli({QStringLiteral("convert"), file, QStringLiteral("--target"),
                                  QStringLiteral("cpm1"), QStringLiteral("--to"), QLatin1String(to),
                                  QStringLiteral("-o"), out});
            EXPECT_EQ(r.code, 1) << file.toStdString() << " --to " << to;
            EXPECT_FALSE(QFile::exists(out)) << file.toStdString() << " --to " << to;
            // Every error line of `check` is on stderr, then the reason nothing was written.
            for (const QString &line : check.out.split(u'\n', Qt::SkipEmptyParts)) {
                if (line.contains(QStringLiteral(": error: "))) {
                    EXPECT_TRUE(r.err.contains(line)) << line.toStdString();
                }
            }
            EXPECT_TRUE(r.err.contains(QStringLiteral("nothing written")));
        }
        // Nothing on stdout either.
        const CliRun toStdout =
            cli({QStringLiteral("convert"), file, QStringLiteral("--target"),
                 QStringLiteral("cpm1"), QStringLiteral("--to"), QStringLiteral("il")});
        EXPECT_EQ(toStdout.code, 1);
        EXPECT_TRUE(toStdout.out.isEmpty()) << toStdout.out.toStdString();
    }
}

TEST(CliConvert, ForceWritesAProgramWithCheckErrorsAndStillReportsThem) {
    QTemporaryDir dir;
    const QString dup = write(dir, QStringLiteral("dup.il"),
                              "LD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND(01)\n");
    const QString out = dir.filePath(QStringLiteral("dup.rung"));
    const CliRun r = cli({QStringLiteral("convert"), dup, QStringLiteral("--target"),
                          QStringLiteral("cpm1"), QStringLiteral("--to"), QStringLiteral("project"),
                          QStringLiteral("-o"), out, QStringLiteral("--force")});
    EXPECT_EQ(r.code, 1); // the program written still has errors
    EXPECT_TRUE(r.err.contains(QStringLiteral("dup.il:4:1: error:"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("[DC001]")));
    ASSERT_TRUE(QFile::exists(out));
    // What was written is the program as typed: converting it back gives the same listing.
    const CliRun back = cli({QStringLiteral("convert"), out, QStringLiteral("--to"),
                             QStringLiteral("il"), QStringLiteral("--force")});
    EXPECT_EQ(back.out, QStringLiteral("LD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND(01)\n"));
}

TEST(CliConvert, ForceNeverWritesATextThatDoesNotParse) {
    QTemporaryDir dir;
    const QString bad = write(dir, QStringLiteral("bad.il"), "LD X0\nFOO X1\nOUT Y0\nEND\n");
    const QString out = dir.filePath(QStringLiteral("bad.ladder"));
    const CliRun r = cli({QStringLiteral("convert"), bad, QStringLiteral("--target"),
                          QStringLiteral("vigor"), QStringLiteral("--to"), QStringLiteral("ladder"),
                          QStringLiteral("-o"), out, QStringLiteral("--force")});
    EXPECT_EQ(r.code, 1);
    EXPECT_FALSE(QFile::exists(out)); // written, the ladder would have lost FOO X1
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad.il:2:1: error:"))) << r.err.toStdString();
}

// Issue 14: what the simulator cannot model is named at `check` time, by the code and words
// the simulator uses when a simulation starts, and it is a warning (exit 0).
TEST(CliCheck, WhatTheSimulatorDoesNotModelIsAWarningOfCheck) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("pid.il"),
                               "; target: pl110\nLD I1\nPID 1 2 3\nLD I1\nOUT Q1\nEND\n");
    const CliRun r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 0) << r.out.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("%1:3:1: warning: PID is not simulated: it does nothing in "
                                    "the simulator [SIM100]\n")
                         .arg(file));
}

TEST(CliCheck, AnOperandTheSimulatorRefusesIsACheckErrorAtItsPlace) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("qi.il"),
                               "; target: pl110\nLD I1\nOUTQI Q9\nLD I2\nTON T1 5 50\nEND\n");
    const CliRun r = cli({QStringLiteral("check"), file});
    EXPECT_EQ(r.code, 1);
    EXPECT_EQ(r.out, QStringLiteral("%1:3:7: error: OUTQI takes only Q1..Q8, not Q9 [OP005]\n"
                                    "%1:5:10: error: the time base (ms) of TON must be 10, 100 or "
                                    "1000, not 50 [OP005]\n")
                         .arg(file));
}

// Issue 14: a CPM1 user reads the CPM1's words - AND LD, not ANB - and the duplicate-coil
// message is not the VPC console's "Oper duplication".
TEST(CliCheck, MessagesSpeakTheFamilysLanguage) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("st.il"),
                               "LD 000.00\nLD 000.01\nLD 000.02\nAND LD\nAND LD\nOUT 010.00\n"
                               "LD 000.03\nOUT 010.00\nEND(01)\n");
    const CliRun r =
        cli({QStringLiteral("check"), file, QStringLiteral("--target"), QStringLiteral("cpm1")});
    EXPECT_TRUE(r.out.contains(QStringLiteral("Stacked AND LD: combine each block with AND LD")))
        << r.out.toStdString();
    EXPECT_FALSE(r.out.contains(QStringLiteral("ANB")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("ORB")));
    EXPECT_FALSE(r.out.contains(QStringLiteral("Oper duplication")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("[DC001]")));
}

// Issue 14, PL110 manual 5.4 and 2.1.2: PLProg draws the initialisation code ([Init]) and the
// two timed-interrupt programs (SM16 / SM17) beside the main ladder. A listing is one
// program: check, convert (to a ladder or a project) and simulate all refuse a section line
// with the same words, at its place, and write nothing; the message says where initialisation
// goes (LD SM0.1) and that interrupt programs are not supported.
TEST(CliSections, InitAndInterruptSectionsAreRefusedAlikeByEveryCommand) {
    QTemporaryDir dir;
    const QString file = write(dir, QStringLiteral("sections.il"),
                               "; target: pl110\n[Init]\nLD SM0.0\nSBIT SMW103 0\n[Main]\n"
                               "LD I1\nOUT Q1\n[Interrupt 1]\nLD I2\nOUT Q2\nEND\n");
    const CliRun check = cli({QStringLiteral("check"), file});
    EXPECT_EQ(check.code, 1);
    for (const char *line :
         {"sections.il:2:1: error:", "sections.il:5:1: error:", "sections.il:8:1: error:"})
        EXPECT_TRUE(check.out.contains(QLatin1String(line))) << line << check.out.toStdString();
    EXPECT_TRUE(check.out.contains(
        QStringLiteral("Program sections such as '[Init]' are not supported: a listing is one "
                       "main program, run at every scan; put what runs once under LD SM0.1 (ON "
                       "in the first scan). Interrupt programs are not supported")))
        << check.out.toStdString();
    EXPECT_TRUE(check.out.contains(QStringLiteral("'[Interrupt 1]' are not supported")))
        << check.out.toStdString();
    for (const char *to : {"ladder", "project"}) {
        const QString out = dir.filePath(QStringLiteral("sections.") + QLatin1String(to));
        const CliRun r =
            cli({QStringLiteral("convert"), file, QStringLiteral("--to"), QLatin1String(to),
                 QStringLiteral("-o"), out, QStringLiteral("--force")});
        EXPECT_EQ(r.code, 1) << to;
        EXPECT_FALSE(QFile::exists(out)) << to; // --force never writes what does not parse
        EXPECT_TRUE(r.err.contains(QStringLiteral("sections.il:2:1: error: Program sections")))
            << r.err.toStdString();
    }
    const CliRun sim = cli({QStringLiteral("simulate"), file, QStringLiteral("--scans"),
                            QStringLiteral("2"), QStringLiteral("--trace"), QStringLiteral("Q1")});
    EXPECT_NE(sim.code, 0);
    EXPECT_TRUE(sim.err.contains(QStringLiteral("sections.il:8:1: error: Program sections")))
        << sim.err.toStdString();
}
