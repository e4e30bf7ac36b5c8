// `rungstudio-cli simulate`: what happens around the trace (the trace itself is pinned by the
// golden tests in tests/simulator).

#include "app/cli/cli.h"
#include "tests/cli/cli_run.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

struct SimRun {
    int code = 0;
    QString out;
    QString err;
};

SimRun simulate(const QString &listing, QStringList options) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("prog.il"));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(listing.toUtf8());
    f.close();
    SimRun r;
    QTextStream out(&r.out);
    QTextStream err(&r.err);
    options.prepend(path);
    options.prepend(QStringLiteral("simulate"));
    options.prepend(QStringLiteral("rungstudio-cli"));
    r.code = rung::app::runCli(options, out, err);
    out.flush();
    err.flush();
    return r;
}

} // namespace

TEST(CliSimulate, AProgramThatFailsTheChecksDoesNotStartAndSaysWhy) {
    // CPM1: a coil may appear only once (Omron CPM1 guide), so the PLC would refuse this program.
    const SimRun r =
        simulate(QStringLiteral("LD 000.00\nOUT 010.00\nLD 000.01\nOUT 010.00\nEND\n"),
                 {QStringLiteral("--target"), QStringLiteral("cpm1"), QStringLiteral("--scans"),
                  QStringLiteral("3"), QStringLiteral("--trace"), QStringLiteral("010.00")});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.isEmpty()) << r.out.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral(":4:"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("does not start"))) << r.err.toStdString();
}

TEST(CliSimulate, TheSameProgramWithOneCoilRuns) {
    const SimRun r =
        simulate(QStringLiteral("LD 000.00\nOR 000.01\nOUT 010.00\nEND\n"),
                 {QStringLiteral("--target"), QStringLiteral("cpm1"), QStringLiteral("--scans"),
                  QStringLiteral("2"), QStringLiteral("--set"), QStringLiteral("000.01=1@1"),
                  QStringLiteral("--trace"), QStringLiteral("010.00")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_EQ(r.out, QStringLiteral("scan,time_ms,010.00\n1,10,0\n2,20,1\n"));
}

TEST(CliSimulate, RuntimeErrorsNameTheLineAndStep) {
    const SimRun r =
        simulate(QStringLiteral("; target: pl110\nLD SM0.0\nMOVIND 5 V340 V0\nEND\n"),
                 {QStringLiteral("--scans"), QStringLiteral("2"), QStringLiteral("--set"),
                  QStringLiteral("V0=12@1"), QStringLiteral("--trace"), QStringLiteral("V340")});
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("prog.il:3: "))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("step 1"))) << r.err.toStdString();
}

namespace {

QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        f.write(bytes);
    return path;
}

rung::test::CliRun run(const QStringList &args) {
    return rung::test::cli(args);
}

const QStringList kLatchTrace = {QStringLiteral("--scans"), QStringLiteral("6"),
                                 QStringLiteral("--set"),   QStringLiteral("X1=1@1"),
                                 QStringLiteral("--set"),   QStringLiteral("X1=0@2"),
                                 QStringLiteral("--set"),   QStringLiteral("X2=1@4"),
                                 QStringLiteral("--trace"), QStringLiteral("X1,X2,Y1")};
const QString kLatchCsv = QStringLiteral("scan,time_ms,X1,X2,Y1\n1,10,0,0,0\n2,20,1,0,1\n"
                                         "3,30,0,0,1\n4,40,0,0,1\n5,50,0,1,0\n6,60,0,1,0\n");

} // namespace

// The manual's stop-first latch as the IDE saves it (File > Examples): the project runs as
// its drawing says; before, its JSON was read as instructions (61 errors).
TEST(CliSimulate, AProjectRunsItsRungs) {
    const rung::test::CliRun r =
        run(QStringList{
                QStringLiteral("simulate"),
                QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/stop-first-latch.rung")} +
            kLatchTrace);
    EXPECT_EQ(r.code, 0) << r.err.toStdString();
    EXPECT_TRUE(r.err.isEmpty()) << r.err.toStdString();
    EXPECT_EQ(r.out, kLatchCsv);
}

// The same program as a listing, as a ladder text and as a project (each written by
// `convert`) gives the same trace.
TEST(CliSimulate, ListingLadderTextAndProjectGiveTheSameTrace) {
    QTemporaryDir dir;
    const QString il = writeFile(dir, QStringLiteral("latch.il"),
                                 "; target: vigor\nLD X1\nOR Y1\nANI X2\nOUT Y1\nEND\n");
    const QString ladder = dir.filePath(QStringLiteral("latch.ladder"));
    const QString project = dir.filePath(QStringLiteral("latch.rung"));
    ASSERT_EQ(run({QStringLiteral("convert"), il, QStringLiteral("--to"), QStringLiteral("ladder"),
                   QStringLiteral("-o"), ladder})
                  .code,
              0);
    ASSERT_EQ(run({QStringLiteral("convert"), il, QStringLiteral("--to"), QStringLiteral("project"),
                   QStringLiteral("-o"), project})
                  .code,
              0);
    for (const QString &file : {il, ladder, project}) {
        const rung::test::CliRun r =
            run(QStringList{QStringLiteral("simulate"), file} + kLatchTrace);
        EXPECT_EQ(r.code, 0) << file.toStdString() << ": " << r.err.toStdString();
        EXPECT_EQ(r.out, kLatchCsv) << file.toStdString();
    }
}

TEST(CliSimulate, ALadderTextThatDoesNotReadSaysWhereAndDoesNotStart) {
    QTemporaryDir dir;
    const QString ladder =
        writeFile(dir, QStringLiteral("bad.ladder"), "LADDER vigor WIDTH 8\nthis is no rung\n");
    const rung::test::CliRun r = run(QStringList{QStringLiteral("simulate"), ladder} + kLatchTrace);
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QStringLiteral("bad.ladder:2:"))) << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("does not start"))) << r.err.toStdString();
}

TEST(CliSimulate, AProjectWithAListTypedWithErrorsDoesNotRunItsOlderRungs) {
    QTemporaryDir dir;
    QFile example(
        QStringLiteral(RUNG_SOURCE_DIR "/resources/examples/vigor/stop-first-latch.rung"));
    ASSERT_TRUE(example.open(QIODevice::ReadOnly));
    QByteArray json = example.readAll();
    json.replace("\"model\"", "\"pendingListing\": \"LD X1\\nOUT Q9\\nEND\\n\", \"model\"");
    const QString project = writeFile(dir, QStringLiteral("typed.rung"), json);
    const rung::test::CliRun r =
        run(QStringList{QStringLiteral("simulate"), project} + kLatchTrace);
    EXPECT_EQ(r.code, 1) << r.err.toStdString();
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QStringLiteral("pendingListing"))) << r.err.toStdString();
}

TEST(CliSimulate, ASetAfterTheLastScanIsAnErrorNotIgnored) {
    const SimRun r =
        simulate(QStringLiteral("; target: vigor\nLD X0\nOUT Y0\nEND\n"),
                 {QStringLiteral("--scans"), QStringLiteral("5"), QStringLiteral("--set"),
                  QStringLiteral("X0=1@5"), QStringLiteral("--trace"), QStringLiteral("Y0")});
    EXPECT_EQ(r.code, 2);
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_TRUE(r.err.contains(QStringLiteral("--set X0=1@5 comes after the last scan")))
        << r.err.toStdString();
    EXPECT_TRUE(r.err.contains(QStringLiteral("once 5 scans have run, and 5 run")))
        << r.err.toStdString();
}

TEST(CliSimulate, ScansMustBeBounded) {
    for (const char *scans : {"0", "-3", "many", "10000001", "99999999999999"}) {
        const SimRun r = simulate(QStringLiteral("; target: vigor\nLD X0\nOUT Y0\nEND\n"),
                                  {QStringLiteral("--scans"), QString::fromLatin1(scans),
                                   QStringLiteral("--trace"), QStringLiteral("Y0")});
        EXPECT_EQ(r.code, 2) << scans;
        EXPECT_TRUE(r.out.isEmpty()) << scans;
        EXPECT_TRUE(r.err.contains(QStringLiteral("--scans"))) << r.err.toStdString();
        EXPECT_TRUE(r.err.contains(QStringLiteral("10000000"))) << r.err.toStdString();
    }
    const SimRun most = simulate(QStringLiteral("; target: vigor\nLD X0\nOUT Y0\nEND\n"),
                                 {QStringLiteral("--scans"), QStringLiteral("3"),
                                  QStringLiteral("--trace"), QStringLiteral("Y0")});
    EXPECT_EQ(most.code, 0);
}
