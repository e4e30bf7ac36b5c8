// The plain scan's fast loop (Engine::runFast, issue 35) against the full interpreter: the
// same image, the same power flow and the same runtime errors, scan after scan, on random
// programs of every family, on the example projects, on forced bits and on the steps the loop
// hands to the full interpreter. The reference is the engine stepped one instruction at a
// time (stepInstruction), which never runs the fast loop.

#include "random_programs.h"
#include "sim_test_target.h"

#include "tests/benchmarks/mixed_program.h"

#include "model/convert/convert.h"
#include "model/project/project.h"
#include "model/target/address.h"

#include <QDirIterator>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace rung::simulator {

namespace {

void stepWholeScan(Engine &e) {
    int steps = 0;
    while (e.stepInstruction() != ScanStop::Completed)
        ASSERT_LT(++steps, 1000000);
}

// Scans `fast` and `stepped` (both built from `program`) side by side with random inputs,
// forcing a bit now and then; every scan the images, the power flow and the errors agree.
void expectSameScans(const std::shared_ptr<const Program> &program,
                     const std::vector<model::Address> &inputs,
                     const std::vector<model::Address> &forceable, int scans, unsigned seed,
                     unsigned onInFour = 3) {
    Engine fast(program);
    Engine stepped(program);
    for (Engine *e : {&fast, &stepped})
        e->setPowerFlowRecording(true);
    std::mt19937 rng(seed);
    for (int scan = 0; scan < scans; ++scan) {
        for (const model::Address &in : inputs) {
            const bool on = (rng() % 4u) < onInFour;
            fast.setBit(in, on);
            stepped.setBit(in, on);
        }
        if (!forceable.empty() && scan % 7 == 3) {
            const model::Address &a = forceable[rng() % forceable.size()];
            if (scan % 21 == 3) {
                fast.releaseAll();
                stepped.releaseAll();
            } else {
                const bool on = (rng() & 1u) != 0;
                fast.force(a, on);
                stepped.force(a, on);
            }
        }
        const bool record = scan % 5 != 4; // the scans nobody watches too
        fast.setPowerFlowRecording(record);
        stepped.setPowerFlowRecording(record);
        fast.scan();
        stepWholeScan(stepped);
        ASSERT_EQ(test::image(fast), test::image(stepped)) << "scan " << scan;
        if (record) {
            ASSERT_EQ(fast.powerFlow(), stepped.powerFlow()) << "scan " << scan;
        }
        ASSERT_EQ(fast.runtimeErrors().size(), stepped.runtimeErrors().size()) << "scan " << scan;
    }
}

} // namespace

TEST(FastLoop, RandomProgramsOfEveryFamilyScanAsTheFullInterpreter) {
    test::forEachRandomProgram(30, 10,
                               [](const model::Target &t, const model::InstructionList &list,
                                  const CompileResult &compiled, unsigned seed) {
                                   std::vector<model::Address> written;
                                   const auto inputs = test::inputsOf(t, list, &written);
                                   expectSameScans(compiled.program, inputs, written, 40, seed);
                               });
}

// What the random programs do not write: SET / RST of bits, words, timers and counters, the
// word arithmetic (16-bit moves and sums of words and constants, INC, DEC), a jump over a
// rung, an interlock (Slow steps between fast ones), a one-input counter and its reset.
TEST(FastLoop, CoilsBoxesJumpsAndInterlocksScanAsTheFullInterpreter) {
    const char *program =
        "LD X0\nSET M0\nLD X1\nRST M0\nLD X2\nANI M0\nOUT Y0\n"
        "LD X3\nCNT C0 K3\nLD X4\nAND X5\nAND X6\nRST C0\nLD C0\nOUT Y1\n"
        "LD X5\nTMR T0 K2\nLD T0\nOUT Y2\nLD X6\nRST T0\n"
        "LD X7\nJMP K1\nLD X0\nOUT Y3\nMOV D0 D1\nJME K1\n"
        "LD X1\nIL\nLD X2\nORI X3\nOUT Y4\nADD D1 K7 D2\nSUB D2 K3 D3\nILC\n"
        "LD SM9000\nINC D4\nDEC D5\nADD D4 D5 D6\nMOV D6 D7\nLD X2\nMOV K-7 D8\nSUB D4 D5 D9\n"
        "LDP X3\nOR X4\nANDP X5\nOUTN Y5\nLDF X6\nINV\nOUT Y6\nEND";
    test::TableSim sim(program);
    ASSERT_TRUE(sim.result.ok()) << sim.result.diagnostics.front().message.toStdString();
    std::vector<model::Address> inputs;
    for (int k = 0; k < 8; ++k)
        inputs.push_back(sim.at(QStringLiteral("X%1").arg(k).toLatin1().constData()));
    expectSameScans(sim.result.program, inputs, {sim.at("Y0"), sim.at("M0"), sim.at("Y4")}, 300, 3,
                    2);
}

// A step ladder (STL / RET, SET of the next step), as the benchmarks' traffic light runs it for
// a simulated day: two full cycles of its lights.
TEST(FastLoop, AStepLadderScansAsTheFullInterpreter) {
    test::TableSim sim("LD SM9002\nSET S0\n"
                       "STL S0\nOUT Y0\nTMR T0 K350\nLD T0\nSET S1\n"
                       "STL S1\nOUT Y1\nTMR T1 K50\nLD T1\nSET S2\n"
                       "STL S2\nOUT M2\nTMR T2 K250\nLD T2\nSET S3\n"
                       "STL S3\nTMR T3 K50\nLDI T5\nTMR T4 K5\nLD T4\nTMR T5 K5\nLDI T4\n"
                       "OUT M3\nLD T3\nSET S0\nRET\nLD M2\nOR M3\nOUT Y2\nEND");
    ASSERT_TRUE(sim.result.ok()) << sim.result.diagnostics.front().message.toStdString();
    for (const FastStep &f : sim.result.program->fast)
        EXPECT_NE(f.op, FastOp::Slow);
    expectSameScans(sim.result.program, {}, {sim.at("Y0"), sim.at("S1")}, 2000, 9);
}

// A rung's start with a holding contact (LD a, AND b, OR c: FastOp::SeriesStartOr), plain and
// negated, outside and inside an interlock and a step ladder's step that are OFF now and then:
// there the holding contact must not close the rung either.
TEST(FastLoop, ARungStartWithAHoldingContactScansAsTheFullInterpreter) {
    test::TableSim sim("LD X0\nAND X1\nOR Y0\nOUT Y0\nLDI X2\nANI X3\nORI X4\nOUT Y1\n"
                       "LD X5\nIL\nLD X0\nAND X1\nOR X2\nOUT Y2\nLDI X3\nAND X4\nORI X6\n"
                       "OUT Y3\nILC\nLD X6\nSET S0\nLD X7\nRST S0\nSTL S0\nLD X1\nANI X2\nOR X3\n"
                       "OUT Y4\nRET\nEND");
    ASSERT_TRUE(sim.result.ok()) << sim.result.diagnostics.front().message.toStdString();
    const auto &fast = sim.result.program->fast;
    // Three with a negated contact, two without (FastOp::SeriesStartOrP).
    EXPECT_EQ(std::count_if(fast.begin(), fast.end(),
                            [](const FastStep &f) { return f.op == FastOp::SeriesStartOr; }),
              3);
    EXPECT_EQ(std::count_if(fast.begin(), fast.end(),
                            [](const FastStep &f) { return f.op == FastOp::SeriesStartOrP; }),
              2);
    std::vector<model::Address> inputs;
    for (int k = 0; k < 8; ++k)
        inputs.push_back(sim.at(QStringLiteral("X%1").arg(k).toLatin1().constData()));
    expectSameScans(sim.result.program, inputs, {sim.at("Y0"), sim.at("Y3")}, 400, 11, 2);
}

// The benchmark's 2048 steps run in the fast loop alone: no step goes to the full
// interpreter (so the benchmark measures the loop), and the results agree.
TEST(FastLoop, TheBenchmarkProgramRunsInTheFastLoopAlone) {
    const QString text = bench::mixedProgram();
    auto target = test::makeTestTarget();
    const model::InstructionList list = test::assemble(*target, text);
    const CompileResult compiled = compileProgram(list);
    ASSERT_TRUE(compiled.ok());
    ASSERT_EQ(compiled.program->fast.size(), compiled.program->steps.size() + 1);
    for (std::size_t i = 0; i < compiled.program->steps.size(); ++i)
        EXPECT_NE(compiled.program->fast[i].op, FastOp::Slow) << "step " << i;
    std::vector<model::Address> inputs;
    for (int k = 0; k < 32; ++k)
        inputs.push_back(test::operandOf(*target, QStringLiteral("X%1").arg(k)).address);
    expectSameScans(compiled.program, inputs, {}, 60, 5);
}

// The Vigor timers of every time base and the counters with a K set value run as the lean
// FastOp::TimerK / CounterK, a rung's single contact goes straight into its timer, counter, move
// or coil, and an output branch drives a negated coil: the same scans as the full interpreter.
TEST(FastLoop, ConstantTimersCountersAndOneContactRungsScanAsTheFullInterpreter) {
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    const char *text = "LD X0\nTMR T0 K3\nLD X1\nTMR T200 K25\nLD X2\nAND X3\nTMR T250 K7\n"
                       "LDI X4\nCNT C0 K4\nLD X5\nRST C0\nLD X6\nCNT C1 K0\n"
                       "LD X7\nMOV D0 D1\nLD X0\nMOV K123 D2\nLD X1\nOUT Y0\n"
                       "LD T0\nOR T200\nOUT Y3\nLD C0\nOUT Y4\nLD M9000\nINC D0\nEND\n";
    const model::ParseResult parsed = model::parseInstructionList(vigor, QString::fromLatin1(text));
    ASSERT_TRUE(parsed.ok()) << parsed.errors.front().message.toStdString();
    const CompileResult compiled = compileProgram(parsed.list);
    ASSERT_TRUE(compiled.ok()) << compiled.diagnostics.front().message.toStdString();
    std::vector<FastOp> ops;
    for (const FastStep &f : compiled.program->fast)
        ops.push_back(f.op);
    for (const FastOp op :
         {FastOp::TimerK, FastOp::CounterK, FastOp::LoadStartTimerK, FastOp::LoadStartCounterK,
          FastOp::LoadStartMoveWord16, FastOp::LoadStartMoveConst16, FastOp::LoadStartOut})
        EXPECT_NE(std::find(ops.begin(), ops.end(), op), ops.end()) << int(op);
    std::vector<model::Address> written;
    const auto inputs = test::inputsOf(vigor, parsed.list, &written);
    expectSameScans(compiled.program, inputs, written, 600, 17, 3);

    // An output branch into a negated coil (OUTN, a family that has it).
    test::TableSim sim("LD X0\nMPS\nAND X1\nOUTN Y1\nMPP\nOUT Y2\nLD X2\nMPS\nANI X3\nOUT Y3\n"
                       "MPP\nOUTN Y4\nEND");
    ASSERT_TRUE(sim.result.ok());
    EXPECT_EQ(sim.result.program->fast[1].op, FastOp::BranchOutNotP); // AND X1: not negated
    EXPECT_EQ(sim.result.program->fast[7].op, FastOp::BranchOut);
    std::vector<model::Address> in;
    for (const char *x : {"X0", "X1", "X2", "X3"})
        in.push_back(sim.at(x));
    expectSameScans(sim.result.program, in, {sim.at("Y1"), sim.at("Y3")}, 200, 19, 2);
}

// The loop without guards (Program::guarded false) reads no gate and tests no stack bound: only
// where no step moves the scan elsewhere and no rung holds as many LDs or MPSs as the stacks.
// Where a jump or a subroutine could bring a step its stacks from elsewhere, or a rung's own
// MPSs reach the push stack's bound, the guarded loop runs, and the results are the full
// interpreter's.
TEST(FastLoop, TheStacksBoundsAreTestedOnlyWhereTheStepsOrderDoesNotBoundThem) {
    auto target = test::makeTestTarget();
    const CompileResult bench = compileProgram(test::assemble(*target, bench::mixedProgram()));
    ASSERT_TRUE(bench.ok());
    EXPECT_FALSE(bench.program->guarded);

    test::TableSim jump(
        "LD X0\nJMP K1\nLD X1\nOUT Y0\nJME K1\nLD X2\nLD X3\nOR X4\nANB\nOUT Y1\nEND");
    ASSERT_TRUE(jump.result.ok());
    EXPECT_TRUE(jump.result.program->guarded);
    test::TableSim step("LD SM9002\nSET S0\nSTL S0\nOUT Y0\nRET\nEND");
    ASSERT_TRUE(step.result.ok());
    EXPECT_TRUE(step.result.program->guarded);

    // 40 output branches on one rung: never deeper than one MPS, but 40 of them in the rung's
    // order, more than the push stack's 32: guarded (the bound is the count, not the depth).
    QString branches = QStringLiteral("LD X0\n");
    for (int k = 0; k < 40; ++k)
        branches += QStringLiteral("MPS\nAND X%1\nOUT M%2\nMPP\n").arg(k % 4 + 1).arg(k);
    branches += QStringLiteral("OUT Y0\nEND");
    test::TableSim many(branches.toLatin1().constData());
    ASSERT_TRUE(many.result.ok()) << many.result.diagnostics.front().message.toStdString();
    EXPECT_TRUE(many.result.program->guarded);
    // 31 on the rung: bounded.
    QString fewer = QStringLiteral("LD X0\n");
    for (int k = 0; k < 31; ++k)
        fewer += QStringLiteral("MPS\nAND X%1\nOUT M%2\nMPP\n").arg(k % 4 + 1).arg(k);
    fewer += QStringLiteral("OUT Y0\nEND");
    test::TableSim few(fewer.toLatin1().constData());
    ASSERT_TRUE(few.result.ok());
    EXPECT_FALSE(few.result.program->guarded);

    std::vector<model::Address> in;
    for (const char *x : {"X0", "X1", "X2", "X3", "X4"})
        in.push_back(jump.at(x));
    expectSameScans(jump.result.program, in, {jump.at("Y1")}, 200, 29, 2);
    expectSameScans(many.result.program, in, {many.at("M3")}, 200, 31, 2);
    expectSameScans(few.result.program, in, {few.at("M3")}, 200, 37, 2);
}

// Each run of contacts in its P form (no contact negated: the loop applies no negation) beside
// the same run with a negated contact: the forms the compiler chose, and the same scans as the
// full interpreter.
TEST(FastLoop, RunsOfContactsNoneNegatedScanAsTheFullInterpreter) {
    test::TableSim sim(
        "LD X0\nAND X1\nOUT Y0\nLD X2\nANI X3\nOUT Y1\n"
        "LD X0\nAND X1\nAND X2\nAND X3\nOUT Y2\nLD X0\nAND X1\nANI X2\nAND X3\nOUT Y3\n"
        "LD X0\nLD X1\nOR X2\nANB\nOUT Y4\nLD X0\nLDI X1\nOR X2\nANB\nOUT Y5\n"
        "LD X0\nLD X1\nAND X2\nORB\nOUT Y6\nLD X0\nLD X1\nANI X2\nORB\nOUT Y7\n"
        "LD X3\nMPS\nAND X1\nOUT M0\nMPP\nOUT M1\nLD X3\nMPS\nAND X2\nOUTN M2\nMPP\n"
        "OUT M3\nLD X0\nAND X1\nOR M4\nOUT M4\nLD X0\nAND X2\nORI M5\nOUT M5\nEND");
    ASSERT_TRUE(sim.result.ok()) << sim.result.diagnostics.front().message.toStdString();
    std::vector<FastOp> ops;
    for (const FastStep &f : sim.result.program->fast)
        ops.push_back(f.op);
    for (const FastOp op :
         {FastOp::SeriesStart2P, FastOp::SeriesStart2, FastOp::SeriesAnd2P, FastOp::SeriesAnd2,
          FastOp::ParallelAndP, FastOp::ParallelAnd, FastOp::SeriesOrP, FastOp::SeriesOr,
          FastOp::BranchOutP, FastOp::BranchOutNotP, FastOp::SeriesStartOrP, FastOp::SeriesStartOr})
        EXPECT_NE(std::find(ops.begin(), ops.end(), op), ops.end()) << int(op);
    std::vector<model::Address> in;
    for (const char *x : {"X0", "X1", "X2", "X3"})
        in.push_back(sim.at(x));
    expectSameScans(sim.result.program, in, {sim.at("Y4"), sim.at("M0")}, 400, 41, 2);
}

// An online edit lowers a running timer's K below the time it has counted: the lean timer stops
// at the new limit and is done at once, as the full one, scan after scan, and clears when its
// input goes OFF.
TEST(FastLoop, ATimerWhoseSetValueWasLoweredOnlineScansAsTheFullInterpreter) {
    test::TableSim sim("LD X0\nTMR T0 K50\nLD T0\nOUT Y0\nEND");
    ASSERT_TRUE(sim.result.ok());
    const std::shared_ptr<const Program> before = sim.result.program;
    ASSERT_TRUE(sim.compile("LD X0\nTMR T0 K10\nLD T0\nOUT Y0\nEND"));
    const std::shared_ptr<const Program> lowered = sim.result.program;
    EXPECT_EQ(lowered->fast[0].op, FastOp::LoadStartTimerK);
    Engine fast(before);
    Engine stepped(before);
    for (Engine *e : {&fast, &stepped}) {
        e->setPeriodMs(100);
        e->setBit(sim.at("X0"), true);
    }
    for (int scan = 0; scan < 30; ++scan) {
        fast.scan();
        stepWholeScan(stepped);
    }
    ASSERT_EQ(fast.value(sim.at("T0")), 29);
    for (Engine *e : {&fast, &stepped})
        ASSERT_EQ(e->replaceProgram(lowered), EditApplied::Now);
    for (int scan = 0; scan < 20; ++scan) {
        if (scan == 10)
            for (Engine *e : {&fast, &stepped})
                e->setBit(sim.at("X0"), false);
        fast.scan();
        stepWholeScan(stepped);
        ASSERT_EQ(test::image(fast), test::image(stepped)) << "scan " << scan;
    }
}

TEST(FastLoop, EveryExampleProjectScansAsTheFullInterpreter) {
    const int examples = test::forEachExampleProgram(
        [](const model::Target &t, const model::InstructionList &list, const CompileResult &c) {
            std::vector<model::Address> written;
            const auto inputs = test::inputsOf(t, list, &written);
            expectSameScans(c.program, inputs, written, 400, 11);
        });
    EXPECT_GE(examples, 10);
}

} // namespace rung::simulator
