// The trace options and CSV form shared by `rungstudio-cli simulate` and the golden tests.

#include "sim_test_target.h"

#include "simulator/compiler.h"
#include "simulator/trace.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;

namespace {

QStringList split(const char *text) {
    return QString::fromLatin1(text).split(QLatin1Char(' '), Qt::SkipEmptyParts);
}

} // namespace

TEST(Trace, OptionsNeedScansAndTrace) {
    auto t = test::makeTestTarget();
    TraceRequest r;
    QString error;
    EXPECT_FALSE(parseTraceOptions(*t, split("--trace Y0"), &r, &error));
    EXPECT_FALSE(error.isEmpty());
    TraceRequest r2;
    EXPECT_FALSE(parseTraceOptions(*t, split("--scans 3"), &r2, &error));
}

TEST(Trace, BadOptionsSayWhatIsWrong) {
    auto t = test::makeTestTarget();
    QString error;
    for (const char *args : {"--scans 3 --trace Y0 --set X0=1", "--scans -1 --trace Y0",
                             "--scans 3 --trace Q7", "--scans 3 --trace Y0 --period 0",
                             "--scans 3 --trace Y0 --bogus 1", "--scans 3 --trace"}) {
        TraceRequest r;
        error.clear();
        EXPECT_FALSE(parseTraceOptions(*t, split(args), &r, &error)) << args;
        EXPECT_FALSE(error.isEmpty()) << args;
    }
}

TEST(Trace, PrintsARowPerScanFromOneWithStimuliAppliedOnceTheirScansHaveRun) {
    auto t = test::makeTestTarget();
    const auto list = test::assemble(*t, QStringLiteral("LD X0\nOUT Y0\nLD X0\nTMR T0 K1\nEND"));
    const CompileResult c = compileProgram(list);
    ASSERT_TRUE(c.ok());
    TraceRequest r;
    QString error;
    ASSERT_TRUE(parseTraceOptions(
        *t, split("--scans 4 --period 50 --set X0=1@1 --set X0=0@3 --trace Y0,T0,cv:T0,D0"), &r,
        &error))
        << error.toStdString();
    QString csv;
    QTextStream out(&csv);
    runTrace(c.program, r, out);
    out.flush();
    EXPECT_EQ(csv, QStringLiteral("scan,time_ms,Y0,T0,cv:T0,D0\n"
                                  "1,50,0,0,0,0\n"
                                  "2,100,1,0,0,0\n"
                                  "3,150,1,0,0,0\n"
                                  "4,200,0,0,0,0\n"));
}
