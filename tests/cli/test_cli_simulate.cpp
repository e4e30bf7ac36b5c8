// `rungstudio-cli simulate`: what happens around the trace (the trace itself is pinned by the
// golden tests in tests/simulator).

#include "app/cli/cli.h"

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
    // CPM1: a coil may appear only once (seed 002), so the PLC would refuse this program.
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
    EXPECT_EQ(r.out, QStringLiteral("scan,time_ms,010.00\n0,0,0\n1,10,1\n"));
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
