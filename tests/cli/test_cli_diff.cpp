#include "model/project/project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStandardPaths>
#include <QTemporaryDir>

#include "tests/cli/cli_run.h"
#include "tests/test_files.h"

#include <gtest/gtest.h>

namespace {

using rung::test::cli;
using rung::test::CliRun;

const QByteArray kPump = "; target: vigor\n"
                         "; start the pump\nLD X0\nOR Y0\nAND X1\nOUT Y0\n"
                         "LD X2\nTMR T0 K10\n"
                         "LD T0\nOUT Y1\n"
                         "END\n";

QString example(const char *path) {
    return QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/") + QLatin1String(path);
}

} // namespace

TEST(CliDiff, ExitsZeroWhenTheSameOneWhenDifferentAsDiff) {
    QTemporaryDir dir;
    const QString a = rung::test::writeFile(dir, QStringLiteral("a.il"), kPump);
    // A fuzzy spelling of the first rung and other whitespace: the same program.
    const QString same = rung::test::writeFile(
        dir, QStringLiteral("same.il"),
        "; target: vigor\n; start the pump\nLD X0\nLD Y0\nORB\n  AND   X1\nOUT Y0\n\n"
        "LD X2\nTMR T0 K10\nLD T0\nOUT Y1\nEND\n");
    QByteArray changed = kPump;
    changed.replace("TMR T0 K10", "TMR T0 K20");
    const QString b = rung::test::writeFile(dir, QStringLiteral("b.il"), changed);
    CliRun r = cli({QStringLiteral("diff"), a, same});
    EXPECT_EQ(r.code, 0) << r.out.toStdString() << r.err.toStdString();
    EXPECT_TRUE(r.out.endsWith(QStringLiteral("The programs are the same (rungs: 4).\n")));
    r = cli({QStringLiteral("diff"), a, b});
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("--- A: %1\n+++ B: %2\n"
                                    "rung 2: changed\n"
                                    "    * output changed: TMR T0 K10 -> TMR T0 K20 (operand 2: "
                                    "K10 -> K20)\n"
                                    "Rungs: 4 in A, 4 in B; 3 the same, 0 moved, 1 changed, 0 "
                                    "moved and changed, 0 inserted, 0 deleted.\n")
                         .arg(a, b));
}

TEST(CliDiff, ErrorsExitTwo) {
    QTemporaryDir dir;
    const QString a = rung::test::writeFile(dir, QStringLiteral("a.il"), kPump);
    const QString bad = rung::test::writeFile(dir, QStringLiteral("bad.il"),
                                              "; target: vigor\nLD X8\nOUT Y0\nEND\n");
    const QString omron = rung::test::writeFile(dir, QStringLiteral("o.il"),
                                                "; target: cpm1\nLD 000.00\nOUT "
                                                "010.00\nEND(01)\n");
    CliRun r = cli({QStringLiteral("diff"), a, dir.filePath(QStringLiteral("none.il"))});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.out.isEmpty());
    // A line that does not parse: the comparison would miss it.
    r = cli({QStringLiteral("diff"), a, bad});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad.il:2:5: error: X8: X is numbered in octal")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("does not read whole, so it is not compared")));
    r = cli({QStringLiteral("diff"), a, omron});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("only programs of one PLC are compared")))
        << r.err.toStdString();
    r = cli({QStringLiteral("diff"), a});
    EXPECT_EQ(r.code, 2);
    r = cli({QStringLiteral("diff"), a, a, QStringLiteral("--format"), QStringLiteral("xml")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--format must be text or json")));
}

// A project and the listing it holds, the listing naming no target: the project's.
TEST(CliDiff, AProjectComparesWithItsOwnListing) {
    QTemporaryDir dir;
    const QString project = example("vigor/traffic-light.rung");
    CliRun listing =
        cli({QStringLiteral("convert"), project, QStringLiteral("--to"), QStringLiteral("il")});
    ASSERT_EQ(listing.code, 0) << listing.err.toStdString();
    ASSERT_FALSE(listing.out.startsWith(QStringLiteral("; target:")));
    const QString il = rung::test::writeFile(dir, QStringLiteral("t.il"), listing.out.toUtf8());
    const CliRun r = cli({QStringLiteral("diff"), project, il});
    // The listing holds no symbols: those are the only difference.
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral(" 0 moved, 0 changed, 0 moved and changed, 0 "
                                              "inserted, 0 deleted.")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("- symbol Y0 removed: name \"Red\"\n")));
}

TEST(CliDiff, JsonForPrograms) {
    QTemporaryDir dir;
    const QString a = rung::test::writeFile(dir, QStringLiteral("a.il"), kPump);
    QByteArray moved = "; target: vigor\nLD X2\nTMR T0 K10\n; start the pump\nLD X0\nOR Y0\n"
                       "ANI X1\nOUT Y0\nLD T0\nOUT Y1\nEND\n";
    const QString b = rung::test::writeFile(dir, QStringLiteral("b.il"), moved);
    const CliRun r =
        cli({QStringLiteral("diff"), a, b, QStringLiteral("--format"), QStringLiteral("json")});
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    QJsonParseError e;
    const QJsonObject json = QJsonDocument::fromJson(r.out.toUtf8(), &e).object();
    ASSERT_EQ(e.error, QJsonParseError::NoError) << r.out.toStdString();
    EXPECT_FALSE(json.value(QStringLiteral("equal")).toBool());
    const QJsonObject summary = json.value(QStringLiteral("summary")).toObject();
    EXPECT_EQ(summary.value(QStringLiteral("moved-changed")).toInt(), 1) << r.out.toStdString();
    EXPECT_EQ(summary.value(QStringLiteral("same")).toInt(), 3);
    EXPECT_EQ(json.value(QStringLiteral("rungs")).toArray().size(), 4);
}

// git passes /dev/null for a file added or deleted.
TEST(CliDiff, DevNullIsAnEmptyProgram) {
    const QString project = example("vigor/flasher.rung");
    const CliRun r = cli({QStringLiteral("diff"), QStringLiteral("/dev/null"), project});
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("+ rung 1 of B: inserted")));
    EXPECT_TRUE(r.out.contains(QStringLiteral(" 0 deleted.")));
}

TEST(CliShow, PrintsAProjectAsAListingAndAnythingElseAsItIs) {
    CliRun r = cli({QStringLiteral("show"), example("cpm1/parts-counter.rung")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("; target: cpm1\n"))) << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("; symbols:\n;   000.00 = Part sensor  -- a part "
                                              "passes\n")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.contains(QStringLiteral("; watch list \"Counts\":\n")));
    QTemporaryDir dir;
    const QString conflicted = rung::test::writeFile(
        dir, QStringLiteral("c.rung"), "<<<<<<< HEAD\n{}\n=======\n{}\n>>>>>>> other\n");
    r = cli({QStringLiteral("show"), conflicted});
    EXPECT_EQ(r.code, 0);
    EXPECT_TRUE(r.out.startsWith(QStringLiteral("; not read as a project: c.rung: Line 1")))
        << r.out.toStdString();
    EXPECT_TRUE(r.out.endsWith(QStringLiteral(">>>>>>> other\n")));
    r = cli({QStringLiteral("show"), dir.filePath(QStringLiteral("none.rung"))});
    EXPECT_EQ(r.code, 2);
}

namespace {

// git in a temporary repository, with no configuration of this machine's user.
struct GitRepo {
    QTemporaryDir dir;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();

    GitRepo() {
        env.insert(QStringLiteral("HOME"), dir.path());
        env.insert(QStringLiteral("GIT_CONFIG_NOSYSTEM"), QStringLiteral("1"));
        env.insert(QStringLiteral("GIT_AUTHOR_NAME"), QStringLiteral("Test"));
        env.insert(QStringLiteral("GIT_AUTHOR_EMAIL"), QStringLiteral("test@example.org"));
        env.insert(QStringLiteral("GIT_COMMITTER_NAME"), QStringLiteral("Test"));
        env.insert(QStringLiteral("GIT_COMMITTER_EMAIL"), QStringLiteral("test@example.org"));
        env.insert(QStringLiteral("LC_ALL"), QStringLiteral("C"));
        env.insert(QStringLiteral("GIT_PAGER"), QStringLiteral("cat"));
    }
    // stdout; the test fails on a non-zero exit unless `allowed` says otherwise.
    QString git(const QStringList &args, int allowed = 0) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.setWorkingDirectory(dir.path());
        p.start(QStringLiteral("git"), args);
        EXPECT_TRUE(p.waitForFinished(60000)) << args.join(' ').toStdString();
        const int code = p.exitCode();
        EXPECT_TRUE(code == 0 || code == allowed)
            << args.join(' ').toStdString() << ": " << p.readAllStandardError().toStdString();
        return QString::fromUtf8(p.readAllStandardOutput());
    }
    void copy(const QString &from, const QString &name) {
        QFile::remove(dir.filePath(name));
        ASSERT_TRUE(QFile::copy(from, dir.filePath(name)));
        QFile(dir.filePath(name)).setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner);
    }
};

bool haveGit() {
    return !QStandardPaths::findExecutable(QStringLiteral("git")).isEmpty();
}

// traffic-light.rung with one contact of its first rung made normally closed.
QByteArray changedTrafficLight() {
    rung::model::ProjectError error;
    auto p = rung::model::loadProject(example("vigor/traffic-light.rung"), &error);
    EXPECT_TRUE(p.has_value());
    for (rung::model::Cell &c : p->program.rungs.front().cells)
        if (c.kind == rung::model::CellKind::Contact) {
            c.contact.mode = rung::model::ContactMode::Negated;
            break;
        }
    return rung::model::projectToJson(*p);
}

} // namespace

// docs/version-control.md: git's textconv set to `rungstudio-cli show` prints listings.
TEST(GitTextconv, DiffShowsTheListing) {
    if (!haveGit())
        GTEST_SKIP() << "git is not installed";
    GitRepo repo;
    repo.git({QStringLiteral("init"), QStringLiteral("-q")});
    repo.git({QStringLiteral("config"), QStringLiteral("diff.rung.textconv"),
              QStringLiteral("'%1' show").arg(QStringLiteral(RUNG_CLI_PATH))});
    rung::test::writeFile(repo.dir, QStringLiteral(".gitattributes"), "*.rung diff=rung\n");
    repo.copy(example("vigor/traffic-light.rung"), QStringLiteral("light.rung"));
    repo.git({QStringLiteral("add"), QStringLiteral(".")});
    repo.git({QStringLiteral("commit"), QStringLiteral("-q"), QStringLiteral("-m"),
              QStringLiteral("first")});
    rung::test::writeFile(repo.dir, QStringLiteral("light.rung"), changedTrafficLight());
    const QString diff = repo.git({QStringLiteral("diff")});
    // The first rung's contact, M9002 (first scan), made normally closed: one line of the listing.
    EXPECT_TRUE(diff.contains(QStringLiteral("\n-LD M9002\n+LDI M9002\n"))) << diff.toStdString();
    EXPECT_FALSE(diff.contains(QStringLiteral("\"cells\""))) << diff.toStdString();
    const QString raw = repo.git({QStringLiteral("diff"), QStringLiteral("--no-textconv")});
    EXPECT_TRUE(raw.contains(QStringLiteral("\"/M9002\""))) << raw.toStdString();
}

TEST(GitDifftool, ReportsRungByRung) {
    if (!haveGit())
        GTEST_SKIP() << "git is not installed";
    GitRepo repo;
    repo.git({QStringLiteral("init"), QStringLiteral("-q")});
    repo.git(
        {QStringLiteral("config"), QStringLiteral("difftool.rung.cmd"),
         QStringLiteral("'%1' diff \"$LOCAL\" \"$REMOTE\"").arg(QStringLiteral(RUNG_CLI_PATH))});
    repo.copy(example("vigor/traffic-light.rung"), QStringLiteral("light.rung"));
    repo.git({QStringLiteral("add"), QStringLiteral(".")});
    repo.git({QStringLiteral("commit"), QStringLiteral("-q"), QStringLiteral("-m"),
              QStringLiteral("first")});
    rung::test::writeFile(repo.dir, QStringLiteral("light.rung"), changedTrafficLight());
    const QString report = repo.git(
        {QStringLiteral("difftool"), QStringLiteral("--tool=rung"), QStringLiteral("--no-prompt")});
    EXPECT_TRUE(
        report.contains(QStringLiteral("rung 1: changed\n    * contact changed: LD M9002 -> "
                                       "LDI M9002\n")))
        << report.toStdString();
    // A new project: compared with /dev/null, every rung inserted.
    repo.copy(example("vigor/flasher.rung"), QStringLiteral("flasher.rung"));
    repo.git({QStringLiteral("add"), QStringLiteral("flasher.rung")});
    const QString added = repo.git({QStringLiteral("difftool"), QStringLiteral("--tool=rung"),
                                    QStringLiteral("--no-prompt"), QStringLiteral("--cached"),
                                    QStringLiteral("--"), QStringLiteral("flasher.rung")});
    EXPECT_TRUE(added.contains(QStringLiteral("+ rung 1 of B: inserted"))) << added.toStdString();
}
