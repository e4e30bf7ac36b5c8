#include "model/project/project.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include "tests/cli/cli_run.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

namespace {

using rung::test::cli;
using rung::test::CliRun;

const QByteArray kLatch = "; target: vigor\nLD X0\nOR Y0\nANI X1\nOUT Y0\nEND\n";

QString examples() {
    return QStringLiteral(RUNG_SOURCE_DIR "/resources/examples");
}

QByteArray readAll(const QString &path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << path.toStdString();
    return f.readAll();
}

} // namespace

// docs/scenario-tests.md: the example projects' scenarios hold.
TEST(CliTest, EveryExampleScenarioPasses) {
    const CliRun r = cli({QStringLiteral("test"), examples()});
    EXPECT_EQ(r.code, 0) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.out.endsWith(QStringLiteral(": 0 failed; 0 scenario(s) did not pass\n")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("6 scenario(s), "))) << r.out.toStdString();
}

// One line per failing expectation: the file, the statement's line, the time, what was
// expected and the values seen; exit 1; JUnit XML for a CI.
TEST(CliTest, AFailingExpectationIsALineWithItsPlaceAndJUnitSaysSo) {
    QTemporaryDir dir;
    rung::test::writeFile(dir, QStringLiteral("latch.il"), kLatch);
    const QString scenario =
        rung::test::writeFile(dir, QStringLiteral("latch.rungtest"),
                              "program latch.il\n"
                              "at 0s set X0=1\n"
                              "at 100ms set X0=0\n"
                              "at 1s expect Y0=1\n"
                              "at 2s set X1=1\n"
                              "at 2s expect Y0=1          # wrong: the stop wins\n");
    const QString junit = dir.filePath(QStringLiteral("out/report.xml"));
    QDir(dir.path()).mkpath(QStringLiteral("out"));
    const CliRun r = cli({QStringLiteral("test"), scenario, QStringLiteral("--junit"), junit});
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("%1:6: at 2s: expected Y0=1, seen Y0=0\n"
                                    "1 scenario(s), 2 expectation(s): 1 failed; 1 scenario(s) "
                                    "did not pass\n")
                         .arg(scenario));
    QXmlStreamReader xml(readAll(junit));
    int cases = 0;
    QString failure;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("testcase"))
            ++cases;
        if (xml.name() == QLatin1String("failure"))
            failure = xml.readElementText();
    }
    EXPECT_FALSE(xml.hasError());
    EXPECT_EQ(cases, 2);
    EXPECT_EQ(failure, QStringLiteral("%1:6: at 2s: expected Y0=1, seen Y0=0").arg(scenario));
}

// A scenario replayed against a changed program: the stairway light's timer made shorter.
TEST(CliTest, AChangedProgramFailsItsScenario) {
    QTemporaryDir dir;
    rung::model::ProjectError error;
    auto project =
        rung::model::loadProject(examples() + QStringLiteral("/pl110/stairway-light.rung"), &error);
    ASSERT_TRUE(project) << error.message.toStdString();
    QByteArray json = rung::model::projectToJson(*project);
    ASSERT_TRUE(json.contains("TON T1 300 100"));
    json.replace("TON T1 300 100", "TON T1 200 100");
    rung::test::writeFile(dir, QStringLiteral("stairway-light.rung"), json);
    QFile::copy(examples() + QStringLiteral("/pl110/stairway-light.rungtest"),
                dir.filePath(QStringLiteral("stairway-light.rungtest")));
    const CliRun r = cli({QStringLiteral("test"), dir.path()});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral("stairway-light.rungtest:9: at 29.9s: expected Q1=1, "
                                              "seen Q1=0\n")))
        << r.out.toStdString();
}

TEST(CliTest, AScenarioThatDoesNotRunSaysWhyAndFails) {
    QTemporaryDir dir;
    rung::test::writeFile(dir, QStringLiteral("bad.il"), "; target: vigor\nLD X8\nOUT Y0\nEND\n");
    const QString noProgram = rung::test::writeFile(dir, QStringLiteral("a.rungtest"),
                                                    "program bad.il\nat 0s expect Y0=0\n");
    CliRun r = cli({QStringLiteral("test"), noProgram});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.contains(QStringLiteral("a.rungtest:1: error: ")));
    EXPECT_TRUE(r.out.contains(QStringLiteral("bad.il:2:5: error: X8: X is numbered in octal")))
        << r.out.toStdString();
    const QString typo = rung::test::writeFile(dir, QStringLiteral("b.rungtest"),
                                               "program ok.il\nat 0s expct Y0=0\n");
    r = cli({QStringLiteral("test"), typo});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("%1:2: error: \"at 0s expct Y0=0\" is no "
                                                "statement")
                                     .arg(typo)))
        << r.out.toStdString();
}

TEST(CliTest, UsageAndMissingFilesExitTwo) {
    QTemporaryDir dir;
    EXPECT_EQ(cli({QStringLiteral("test")}).code, 2);
    EXPECT_EQ(cli({QStringLiteral("test"), dir.filePath(QStringLiteral("none.rungtest"))}).code, 2);
    const CliRun empty = cli({QStringLiteral("test"), dir.path()});
    EXPECT_EQ(empty.code, 2);
    EXPECT_TRUE(empty.err.contains(QStringLiteral("no .rungtest file in the folder")));
    EXPECT_EQ(cli({QStringLiteral("test"), examples(), QStringLiteral("--junit")}).code, 2);
    EXPECT_EQ(cli({QStringLiteral("test"), examples(), QStringLiteral("--fast")}).code, 2);
}
