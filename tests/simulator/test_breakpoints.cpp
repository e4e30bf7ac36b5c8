// Breakpoints and stepping inside a scan (issue 11): the engine stops before the
// breakpoint's instruction with the logic result, block stack and MPS stack the interpreter
// holds there; conditions ("when Y0 rises", "when D10 > 100"); resuming, stepping and
// finishing give the same scan as an unbroken one; the online edit keeps the image.

#include "sim_test_target.h"

#include "tests/simulator/random_programs.h"

#include "model/target/address.h"
#include "simulator/online_edit.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace rung;
using namespace rung::simulator;

using Sim = test::TableSim;
using When = Breakpoint::When;

namespace {

// Steps: 0 LD X0, 1 OR X1, 2 LD X2, 3 AND X3, 4 ORB, 5 MPS, 6 AND X4, 7 OUT Y0, 8 MPP,
// 9 OUT Y1, 10 LD X5, 11 LD X6, 12 ANB, 13 OUT Y2, 14 END.
constexpr const char *kBlocks = "LD X0\nOR X1\nLD X2\nAND X3\nORB\nMPS\nAND X4\nOUT Y0\nMPP\n"
                                "OUT Y1\nLD X5\nLD X6\nANB\nOUT Y2\nEND";

Breakpoint at(int instruction) {
    Breakpoint b;
    b.instruction = instruction;
    return b;
}

} // namespace

TEST(Breakpoints, StopBeforeTheInstructionWithTheBlockStack) {
    Sim s(kBlocks);
    ASSERT_TRUE(s.result.ok());
    s.in("X0", true);
    s.in("X2", true); // X2 AND X3 = OFF: the block below holds X0 OR X1 = ON
    ASSERT_TRUE(s.engine->setBreakpoints({at(4)}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    ASSERT_TRUE(s.engine->insideScan());
    const auto p = s.engine->pausePosition();
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->instruction, 4); // ORB has not run
    EXPECT_FALSE(p->result);      // X2 AND X3
    EXPECT_EQ(p->blockStack, std::vector<bool>{true});
    EXPECT_TRUE(p->memoryStack.empty());
    EXPECT_EQ(p->breakpoint, 4);
    EXPECT_EQ(s.engine->statistics().scans, 0u); // the scan is not over
    EXPECT_EQ(s.engine->snapshot().pause, p);
    // Continuing ends the scan; the next one stops there again.
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    EXPECT_FALSE(s.engine->insideScan());
    EXPECT_EQ(s.engine->statistics().scans, 1u);
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_FALSE(s.engine->snapshot().pause.has_value());
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
}

TEST(Breakpoints, StopWithTheMpsStackAndNoOutputWrittenYet) {
    Sim s(kBlocks);
    s.in("X1", true);
    s.in("X4", true);
    ASSERT_TRUE(s.engine->setBreakpoints({at(7), at(13)}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    auto p = s.engine->pausePosition();
    ASSERT_TRUE(p);
    EXPECT_EQ(p->instruction, 7);
    EXPECT_TRUE(p->result);                             // (X0 OR X1) AND X4
    EXPECT_EQ(p->memoryStack, std::vector<bool>{true}); // MPS kept X0 OR X1
    EXPECT_TRUE(p->blockStack.empty());
    EXPECT_FALSE(s.bit("Y0")); // OUT Y0 is the next instruction
    // The second breakpoint, in the same scan: the stack of AND LD holds X5's block.
    s.in("X5", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    p = s.engine->pausePosition();
    ASSERT_TRUE(p);
    EXPECT_EQ(p->instruction, 13);
    EXPECT_TRUE(s.bit("Y0"));
    EXPECT_TRUE(s.bit("Y1"));
    EXPECT_TRUE(p->memoryStack.empty());
    // An input written while stopped is stimulus for the next scan, not this one's image:
    // X5 was read at the start of this scan (OFF), so Y2 stays OFF.
    EXPECT_FALSE(p->result);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    EXPECT_FALSE(s.bit("Y2"));
}

TEST(Breakpoints, SteppingShowsEachInstructionAndEndsTheScanLikeAPlainOne) {
    Sim stepped(kBlocks);
    Sim plain(kBlocks);
    for (Sim *s : {&stepped, &plain}) {
        s->in("X0", true);
        s->in("X4", true);
        s->in("X5", true);
        s->in("X6", true);
    }
    // At the boundary a step starts the scan and stops before the first instruction.
    EXPECT_EQ(stepped.engine->stepInstruction(), ScanStop::Stepped);
    std::vector<int> positions;
    std::vector<bool> results;
    for (int guard = 0; guard < 40; ++guard) {
        const auto p = stepped.engine->pausePosition();
        ASSERT_TRUE(p);
        positions.push_back(p->instruction);
        results.push_back(p->result);
        if (stepped.engine->stepInstruction() == ScanStop::Completed)
            break;
    }
    EXPECT_EQ(positions, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14}));
    // Before 1: X0; before 5 (MPS): X0 OR X1 OR (X2 AND X3); before 13: X5 AND X6.
    EXPECT_TRUE(results[1]);
    EXPECT_TRUE(results[5]);
    EXPECT_TRUE(results[13]);
    EXPECT_FALSE(stepped.engine->insideScan());
    plain.scan();
    EXPECT_EQ(test::image(*stepped.engine), test::image(*plain.engine));
    EXPECT_EQ(stepped.engine->statistics().scans, 1u);
    EXPECT_EQ(stepped.engine->statistics().timeMs, plain.engine->statistics().timeMs);
}

TEST(Breakpoints, ScanFinishesTheStoppedScanWithoutStoppingAgain) {
    Sim s(kBlocks);
    ASSERT_TRUE(s.engine->setBreakpoints({at(2), at(9)}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    s.engine->scan(); // the rest of the scan; 9 does not stop it
    EXPECT_FALSE(s.engine->insideScan());
    EXPECT_EQ(s.engine->statistics().scans, 1u);
}

TEST(Breakpoints, RisingConditionStopsOnlyInTheScanWhereTheBitRose) {
    Sim s("LD X0\nOUT Y0\nLD Y0\nOUT Y1\nEND");
    Breakpoint b = at(2);
    b.when = When::Rises;
    b.device = s.at("Y0");
    ASSERT_TRUE(s.engine->setBreakpoints({b}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    s.in("X0", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 2);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed); // the rest of that scan
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed); // Y0 still ON: no rise
    s.in("X0", false);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    s.in("X0", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
}

TEST(Breakpoints, FallingOnAndOffConditions) {
    Sim s("LD X0\nOUT Y0\nLD Y0\nOUT Y1\nEND");
    Breakpoint falls = at(2);
    falls.when = When::Falls;
    falls.device = s.at("Y0");
    Breakpoint isOn = at(3);
    isOn.when = When::IsOn;
    isOn.device = s.at("X1");
    ASSERT_TRUE(s.engine->setBreakpoints({falls, isOn}));
    s.in("X0", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    s.in("X0", false);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 2);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    s.in("X1", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 3);
    Breakpoint isOff = isOn;
    isOff.when = When::IsOff;
    ASSERT_TRUE(s.engine->setBreakpoints({isOff}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed); // X1 ON
    s.in("X1", false);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
}

TEST(Breakpoints, CompareConditionStopsTheFirstTimeTheWordPassesTheValue) {
    Sim s("LD SM9000\nINC D10\nLD X0\nOUT Y0\nEND");
    Breakpoint b = at(2);
    b.when = When::Compare;
    b.device = s.at("D10");
    b.op = model::CompareOp::Gt;
    b.value = 100;
    ASSERT_TRUE(s.engine->setBreakpoints({b}));
    int scans = 0;
    while (s.engine->scanToBreakpoint() == ScanStop::Completed && scans < 1000)
        ++scans;
    EXPECT_EQ(scans, 100); // the 101st scan stops after its INC
    EXPECT_EQ(s.value("D10"), 101);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 2);
}

TEST(Breakpoints, BadInstructionOrDeviceIsRefusedAndChangesNothing) {
    Sim s(kBlocks);
    ASSERT_TRUE(s.engine->setBreakpoints({at(3)}));
    QString error;
    EXPECT_FALSE(s.engine->setBreakpoints({at(15)}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("15"))) << error.toStdString();
    Breakpoint word = at(2);
    word.when = When::Compare;
    word.device = s.at("X1"); // a bit, and no word starts there (X0 would: X0..X15)
    EXPECT_FALSE(s.engine->setBreakpoints({word}, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("X1"))) << error.toStdString();
    ASSERT_EQ(s.engine->breakpoints().size(), 1u);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 3);
}

TEST(Breakpoints, ABreakpointAJumpPassesOverDoesNotStop) {
    Sim s("LD X0\nJMP K1\nLD X1\nOUT Y0\nJME K1\nLD X2\nOUT Y1\nEND");
    ASSERT_TRUE(s.result.ok()) << s.result.diagnostics[0].message.toStdString();
    ASSERT_TRUE(s.engine->setBreakpoints({at(3), at(6)}));
    // X0 OFF: the jump is taken (Vigor CJ semantics of the synthetic target: skip while OFF).
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 6);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    s.in("X0", true);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 3);
}

TEST(Breakpoints, PowerCycleCutsAStoppedScanAndResetKeepsTheBreakpoints) {
    Sim s(kBlocks);
    ASSERT_TRUE(s.engine->setBreakpoints({at(7)}));
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    s.engine->powerCycle();
    EXPECT_FALSE(s.engine->insideScan());
    EXPECT_EQ(s.engine->statistics().scans, 0u);
    s.engine->reset();
    EXPECT_EQ(s.engine->breakpoints().size(), 1u);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    EXPECT_EQ(s.engine->pausePosition()->instruction, 7);
}

TEST(Breakpoints, AdvanceToReplaysAStopAtTheSameInstruction) {
    Sim s(kBlocks);
    s.in("X1", true);
    ASSERT_TRUE(s.engine->advanceTo(6));
    const auto p = s.engine->pausePosition();
    ASSERT_TRUE(p);
    EXPECT_EQ(p->instruction, 6);
    EXPECT_EQ(p->memoryStack, std::vector<bool>{true});
    EXPECT_FALSE(s.engine->advanceTo(100)); // runs to END
    EXPECT_FALSE(s.engine->insideScan());
    EXPECT_EQ(s.engine->statistics().scans, 1u);
}

// Random programs of every family: a scan broken at breakpoints every few instructions, and
// one stepped instruction by instruction, leave exactly the image of the unbroken scan.
TEST(Breakpoints, BrokenAndSteppedScansEqualThePlainScanOnRandomPrograms) {
    test::forEachRandomProgram(
        25, 6,
        [](const model::Target &t, const model::InstructionList &list,
           const CompileResult &compiled, unsigned seed) {
            Engine plain(compiled.program);
            Engine broken(compiled.program);
            Engine stepped(compiled.program);
            std::vector<Breakpoint> every;
            for (int i = static_cast<int>(seed % 3);
                 i < static_cast<int>(compiled.program->steps.size()); i += 3)
                every.push_back(at(i));
            ASSERT_TRUE(broken.setBreakpoints(every));
            const std::vector<model::Address> inputs = test::inputsOf(t, list);
            std::mt19937_64 rng(seed);
            for (int scan = 0; scan < 20; ++scan) {
                for (const model::Address &in : inputs) {
                    const bool on = (rng() & 1u) != 0;
                    for (Engine *e : {&plain, &broken, &stepped})
                        e->setBit(in, on);
                }
                plain.scan();
                int stops = 0;
                while (broken.scanToBreakpoint() != ScanStop::Completed)
                    ASSERT_LT(++stops, 10000);
                while (stepped.stepInstruction() != ScanStop::Completed)
                    ASSERT_LT(++stops, 20000);
                ASSERT_EQ(test::image(broken), test::image(plain)) << "scan " << scan;
                ASSERT_EQ(test::image(stepped), test::image(plain)) << "scan " << scan;
            }
        });
}

TEST(OnlineEdit, ACounterKeepsItsValueAndTheNewProgramRuns) {
    Sim s("LD X0\nCNT C0 K100\nEND");
    for (int k = 0; k < 7; ++k) {
        s.in("X0", true);
        s.scan();
        s.in("X0", false);
        s.scan();
    }
    ASSERT_EQ(s.value("C0"), 7);
    const auto edited =
        compileProgram(test::assemble(*s.target, QStringLiteral("LD X0\nCNT C0 K100\n"
                                                                "LD C0\nOUT Y0\nLD X1\n"
                                                                "OUT Y1\nEND")));
    ASSERT_TRUE(edited.ok());
    EXPECT_EQ(s.engine->replaceProgram(edited.program), EditApplied::Now);
    s.in("X1", true);
    s.scan();
    EXPECT_EQ(s.value("C0"), 7);
    EXPECT_TRUE(s.bit("Y1")); // the new rung runs
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("C0"), 8);
}

TEST(OnlineEdit, AnEdgeHeldOnDoesNotFireOnTheEditAndAMovedOneKeepsItsMemory) {
    Sim s("LDP X0\nINC D0\nEND");
    s.in("X0", true);
    s.in("X1", true);
    s.scan(3);
    ASSERT_EQ(s.value("D0"), 1);
    // A rung before it and a new rising contact of X1 (held ON): neither fires.
    const auto edited = compileProgram(
        test::assemble(*s.target, QStringLiteral("LDP X1\nINC D1\nLDP X0\nINC D0\nEND")));
    ASSERT_TRUE(edited.ok());
    EXPECT_EQ(s.engine->replaceProgram(edited.program), EditApplied::Now);
    s.scan();
    EXPECT_EQ(s.value("D0"), 1);
    EXPECT_EQ(s.value("D1"), 0);
    s.in("X0", false);
    s.scan();
    s.in("X0", true);
    s.scan();
    EXPECT_EQ(s.value("D0"), 2);
}

TEST(OnlineEdit, InsideAStoppedScanTheEditWaitsForItsEnd) {
    Sim s("LD X0\nOUT Y0\nEND");
    ASSERT_TRUE(s.engine->setBreakpoints({at(1)}));
    s.in("X0", true);
    ASSERT_EQ(s.engine->scanToBreakpoint(), ScanStop::Breakpoint);
    const auto edited =
        compileProgram(test::assemble(*s.target, QStringLiteral("LD X0\nOUT Y1\nEND")));
    EXPECT_EQ(s.engine->replaceProgram(edited.program), EditApplied::AtScanEnd);
    EXPECT_EQ(s.engine->scanToBreakpoint(), ScanStop::Completed);
    EXPECT_TRUE(s.bit("Y0")); // the old program finished its scan
    EXPECT_FALSE(s.bit("Y1"));
    EXPECT_EQ(&s.engine->program(), edited.program.get());
    s.scan();
    EXPECT_TRUE(s.bit("Y1"));
}

TEST(OnlineEdit, AnotherLayoutIsRefused) {
    Sim s("LD X0\nOUT Y0\nEND");
    const model::Target &vigor = model::Target::get(model::Family::Vigor);
    const model::ParseResult other = model::parseInstructionList(vigor, "LD X0\nOUT Y0\nEND");
    ASSERT_TRUE(other.ok());
    const auto compiled = compileProgram(other.list);
    EXPECT_EQ(s.engine->replaceProgram(compiled.program), EditApplied::LayoutDiffers);
    EXPECT_NE(&s.engine->program(), compiled.program.get());
}

TEST(OnlineEdit, TheImpactNamesTimersAndCountersTheEditRenumbers) {
    Sim s("LD X0\nTMR T0 K10\nLD X1\nCNT C3 K5\nEND");
    const auto same = compileProgram(
        test::assemble(*s.target, QStringLiteral("LD X2\nTMR T0 K20\nLD X1\nCNT C3 K5\nEND")));
    const auto renumbered = compileProgram(
        test::assemble(*s.target, QStringLiteral("LD X0\nTMR T5 K10\nLD X1\nCNT C3 K5\nEND")));
    ASSERT_TRUE(same.ok() && renumbered.ok());
    const EditImpact none = assessEdit(*s.result.program, *same.program);
    EXPECT_TRUE(none.keepsImage());
    EXPECT_FALSE(none.changesElements());
    const EditImpact impact = assessEdit(*s.result.program, *renumbered.program);
    EXPECT_TRUE(impact.keepsImage());
    ASSERT_EQ(impact.elementsGone.size(), 1u);
    ASSERT_EQ(impact.elementsNew.size(), 1u);
    EXPECT_EQ(impact.elementsGone[0], s.at("T0"));
    EXPECT_EQ(impact.elementsNew[0], s.at("T5"));
    const model::ParseResult vigor =
        model::parseInstructionList(model::Target::get(model::Family::Vigor), "LD X0\nOUT Y0\nEND");
    EXPECT_TRUE(assessEdit(*s.result.program, *compileProgram(vigor.list).program).layoutDiffers);
}
