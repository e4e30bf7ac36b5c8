// `rungstudio-cli serve`: what it refuses before it serves, and why (run in-process; the
// serving itself is run as a user runs it in test_virtual_plc_peers.cpp).

#include "app/cli/cli_load_program.h"
#include "tests/cli/cli_run.h"

#include <QDirIterator>

#include <QFile>
#include <QFileInfo>
#include <QTcpServer>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace rung::test {
namespace {

QString program(QTemporaryDir &dir, const char *name, const char *text) {
    const QString path = dir.filePath(QLatin1String(name));
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(text);
    return path;
}

CliRun serve(QStringList args) {
    args.prepend(QStringLiteral("serve"));
    return cli(args);
}

TEST(CliServe, UsageErrorsSayWhatIsWrong) {
    QTemporaryDir dir;
    const QString file = program(dir, "p.il", "; target: pl110\nLD I1\nOUT Q1\nEND\n");
    CliRun r = serve({file, QStringLiteral("--pty")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--protocol is required"))) << r.err.toStdString();
    r = serve(
        {file, QStringLiteral("--protocol"), QStringLiteral("profibus"), QStringLiteral("--pty")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("unknown protocol profibus")));
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--pty")));
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus-tcp"),
               QStringLiteral("--pty")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--tcp")));
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
               QStringLiteral("--tcp"), QStringLiteral("somewhere")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("somewhere")));
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
               QStringLiteral("--pty"), QStringLiteral("--station"), QStringLiteral("0")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("1..247"))) << r.err.toStdString();
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
               QStringLiteral("--pty"), QStringLiteral("--fault"), QStringLiteral("often")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad-checksum"))) << r.err.toStdString();
    r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
               QStringLiteral("--pty"), QStringLiteral("--frame"), QStringLiteral("9X3")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("9X3")));
}

TEST(CliServe, ALinkIsMadeOnlyForAPtyAndNeverOverSomethingOfTheUsers) {
    QTemporaryDir dir;
    const QString file = program(dir, "p.il", "; target: pl110\nLD I1\nOUT Q1\nEND\n");
    const QString at = dir.filePath(QStringLiteral("plc"));
    CliRun r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
                      QStringLiteral("--tcp"), QStringLiteral("127.0.0.1:0"),
                      QStringLiteral("--link"), at});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("--link names the pseudo-terminal of --pty")))
        << r.err.toStdString();
    // A file of the user's, and a link that leads elsewhere: left as they are, exit 2.
    {
        QFile mine(at);
        ASSERT_TRUE(mine.open(QIODevice::WriteOnly));
        mine.write("notes");
    }
    const QString other = dir.filePath(QStringLiteral("other"));
    ASSERT_TRUE(QFile::link(file, other));
    for (const QString &taken : {at, other}) {
        r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus"),
                   QStringLiteral("--pty"), QStringLiteral("--link"), taken});
        EXPECT_EQ(r.code, 2) << taken.toStdString();
        EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
        EXPECT_TRUE(r.err.contains(QStringLiteral("not a link to a pseudo-terminal")))
            << r.err.toStdString();
    }
    QFile mine(at);
    ASSERT_TRUE(mine.open(QIODevice::ReadOnly));
    EXPECT_EQ(mine.readAll(), "notes");
    EXPECT_EQ(QFileInfo(other).symLinkTarget(), file);
}

TEST(CliServe, APlcThatDoesNotSpeakTheProtocolIsNamedWithWhatItSpeaks) {
    QTemporaryDir dir;
    const QString file = program(dir, "c.il", "; target: cpm1\nLD 000.00\nOUT 010.00\nEND(01)\n");
    const CliRun r = serve(
        {file, QStringLiteral("--protocol"), QStringLiteral("modbus"), QStringLiteral("--pty")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(QStringLiteral("CPM1 does not speak modbus; it speaks hostlink")))
        << r.err.toStdString();
    const QString vpc = program(dir, "v.il", "; target: vpc\nLD i00\nOUT o00\nEND\n");
    const CliRun v = serve(
        {vpc, QStringLiteral("--protocol"), QStringLiteral("modbus"), QStringLiteral("--pty")});
    EXPECT_EQ(v.code, 2);
    EXPECT_TRUE(v.err.contains(QStringLiteral("no published protocol"))) << v.err.toStdString();
}

TEST(CliServe, AProgramWithErrorsDoesNotStart) {
    QTemporaryDir dir;
    const QString file =
        program(dir, "e.il", "; target: cpm1\nLD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND\n");
    const CliRun r = serve(
        {file, QStringLiteral("--protocol"), QStringLiteral("hostlink"), QStringLiteral("--pty")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.err.contains(QStringLiteral("e.il:5:1: error:"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("does not start")));
    EXPECT_TRUE(r.out.isEmpty()); // nothing served, no path printed
    const CliRun missing =
        serve({dir.filePath(QStringLiteral("none.il")), QStringLiteral("--protocol"),
               QStringLiteral("hostlink"), QStringLiteral("--pty")});
    EXPECT_EQ(missing.code, 2);
}

TEST(CliServe, ABusyTcpPortIsSaidAndNothingIsServed) {
    QTemporaryDir dir;
    const QString file = program(dir, "p.il", "; target: pl110\nLD I1\nOUT Q1\nEND\n");
    QTcpServer busy;
    ASSERT_TRUE(busy.listen(QHostAddress::LocalHost, 0));
    const QString where = QStringLiteral("127.0.0.1:%1").arg(busy.serverPort());
    const CliRun r = serve({file, QStringLiteral("--protocol"), QStringLiteral("modbus-tcp"),
                            QStringLiteral("--tcp"), where});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.err.contains(where)) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
}

// serve takes what simulate takes and more: a listing, a ladder text or a project, through
// the one loader (app/cli/cli_load_program.h).
TEST(CliServe, EveryExampleProjectLoadsAsAProgramToServe) {
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples"),
                    {QStringLiteral("*.rung")}, QDir::Files, QDirIterator::Subdirectories);
    int projects = 0;
    while (it.hasNext()) {
        const QString file = it.next();
        QString errText;
        QTextStream err(&errText);
        app::LoadedProgram loaded;
        EXPECT_EQ(app::loadProgram({file, {}, {}}, &loaded, err), 0)
            << file.toStdString() << errText.toStdString();
        EXPECT_TRUE(loaded.program) << file.toStdString();
        ++projects;
    }
    EXPECT_GE(projects, 10);
}

TEST(CliServe, ALadderTextLoadsAsTheSameProgramAsItsListing) {
    QTemporaryDir dir;
    const QString il = program(dir, "p.il", "; target: pl110\nLD I1\nOUT Q1\nEND\n");
    const QString ladder = dir.filePath(QStringLiteral("p.ladder"));
    const CliRun converted = cli({QStringLiteral("convert"), il, QStringLiteral("--to"),
                                  QStringLiteral("ladder"), QStringLiteral("-o"), ladder});
    ASSERT_EQ(converted.code, 0) << converted.err.toStdString();
    QString errText;
    QTextStream err(&errText);
    app::LoadedProgram fromIl, fromLadder;
    ASSERT_EQ(app::loadProgram({il, {}, {}}, &fromIl, err), 0) << errText.toStdString();
    ASSERT_EQ(app::loadProgram({ladder, {}, {}}, &fromLadder, err), 0) << errText.toStdString();
    EXPECT_EQ(fromLadder.target, fromIl.target);
    EXPECT_EQ(fromLadder.program->steps.size(), fromIl.program->steps.size());
}

} // namespace
} // namespace rung::test
