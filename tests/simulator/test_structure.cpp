// The compiler reads a listing's rungs, jumps and stacks as model/listing/structure.h defines
// them, the same as the converter and the checks.

#include "real_target_sim.h"

#include "model/listing/structure.h"

#include <gtest/gtest.h>

using namespace rung;
using namespace rung::simulator;
using test::RealTargetSim;

namespace {

QString repeated(const char *line, int n) {
    QString s;
    for (int k = 0; k < n; ++k)
        s += QString::fromLatin1(line) + QLatin1Char('\n');
    return s;
}

bool hasCode(const CompileResult &r, const char *code) {
    for (const model::Diagnostic &d : r.diagnostics)
        if (d.code == QLatin1String(code))
            return true;
    return false;
}

} // namespace

// Fixed by the one rung split: the compiler started a new rung (and an empty block stack) at
// the load after OUT Y0 and refused the ANB that joins it to the branch point, a rung the
// converter draws and the PLC runs as X0 AND (X1 OR X2).
TEST(CompiledStructure, ABlockJoinedAfterAnOutputRunsInSeriesWithTheBranchPoint) {
    RealTargetSim s(model::Family::Vigor, "LD X0\nOUT Y0\nLD X1\nOR X2\nANB\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok()) << (s.result.diagnostics.empty()
                                       ? std::string()
                                       : s.result.diagnostics[0].message.toStdString());
    for (int inputs = 0; inputs < 8; ++inputs) {
        const bool x0 = inputs & 1, x1 = inputs & 2, x2 = inputs & 4;
        s.in("X0", x0);
        s.in("X1", x1);
        s.in("X2", x2);
        s.engine->scan();
        EXPECT_EQ(s.bit("Y0"), x0) << inputs;
        EXPECT_EQ(s.bit("Y1"), x0 && (x1 || x2)) << inputs;
    }
}

// A rung's first load still empties the block stack: a block left open by a broken rung does
// not leak into the next.
TEST(CompiledStructure, TheNextRungStartsWithAnEmptyBlockStack) {
    RealTargetSim s(model::Family::Vigor, "LD X0\nOUT Y0\nLD X1\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok());
    EXPECT_EQ(s.result.program->maxBlockDepth, 0);
}

// Jumps that do not pair are the checks' NE findings, with the checks' codes.
TEST(CompiledStructure, AJumpWithoutItsEndIsReportedWithTheChecksCode) {
    RealTargetSim s(model::Family::Vpc, "LD i00\nJMP\nLD i01\nOUT o00\nEND");
    EXPECT_FALSE(s.result.ok());
    EXPECT_TRUE(hasCode(s.result, "NE004"));
    RealTargetSim nested(model::Family::Vpc,
                         "LD i00\nJMP\nLD i01\nJMP\nLD i02\nOUT o00\nJPE\nJPE\nEND");
    EXPECT_FALSE(nested.result.ok());
    EXPECT_TRUE(hasCode(nested.result, "NE003"));
}

TEST(CompiledStructure, ANumberedJumpGoesToItsEnd) {
    RealTargetSim s(model::Family::Cpm1, "LD 000.00\nJMP(04) 01\nLD 000.01\nOUT 010.00\n"
                                         "JME(05) 01\nEND(01)");
    ASSERT_TRUE(s.result.ok());
    s.in("000.01", true);
    s.engine->scan(); // 000.00 OFF: the jump is taken, 010.00 keeps its value
    EXPECT_FALSE(s.bit("010.00"));
    s.in("000.00", true);
    s.engine->scan();
    EXPECT_TRUE(s.bit("010.00"));
}

TEST(CompiledStructure, OpenBlocksAreLimitedToTheSimulatorsBlockStack) {
    const auto rung = [](int blocks) {
        return QStringLiteral("LD X0\n") + repeated("LD X1", blocks - 1) +
               repeated("ANB", blocks - 1) + QStringLiteral("OUT Y0\nEND\n");
    };
    const QByteArray fits = rung(model::kMaxOpenBlocks).toLatin1();
    RealTargetSim ok(model::Family::Vigor, fits.constData());
    EXPECT_TRUE(ok.result.ok());
    EXPECT_EQ(ok.result.program->maxBlockDepth, model::kMaxOpenBlocks - 1);
    const QByteArray tooMany = rung(model::kMaxOpenBlocks + 1).toLatin1();
    RealTargetSim refused(model::Family::Vigor, tooMany.constData());
    EXPECT_FALSE(refused.result.ok());
}

TEST(CompiledStructure, MpsLevelsAreTheTargetsLimit) {
    const model::Target &t = model::Target::get(model::Family::Vigor);
    const auto program = [](int levels) {
        return QStringLiteral("LD X0\n") + repeated("MPS", levels) + QStringLiteral("OUT Y0\n") +
               repeated("MPP", levels) + QStringLiteral("OUT Y1\nEND\n");
    };
    const QByteArray fits = program(t.limits.stackDepth).toLatin1();
    RealTargetSim ok(model::Family::Vigor, fits.constData());
    EXPECT_TRUE(ok.result.ok());
    EXPECT_EQ(ok.result.program->maxPushDepth, t.limits.stackDepth);
    const QByteArray deeper = program(t.limits.stackDepth + 1).toLatin1();
    RealTargetSim refused(model::Family::Vigor, deeper.constData());
    EXPECT_FALSE(refused.result.ok());
}
