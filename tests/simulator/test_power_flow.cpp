// The overlay's power flow (model/image/power_flow.h) against the real scan engine: which nodes
// carry power, which contacts conduct, what the values under the boxes say, in series,
// parallel, ANB and ORB blocks, inverted and edge contacts, an interlock that is off, a
// source without power flow (an online PLC), and, over random programs of every family, that
// every output's drawn condition is the one the scan computed.

#include "model/image/power_flow.h"

#include "model/convert/convert.h"
#include "model/target/address.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include "tests/model/random_program.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace rung;
using model::ProgramFlow;
using model::RungOverlay;

namespace {

// A program drawn from a listing, converted back (the listing the IDE runs) and compiled.
struct Running {
    const model::Target &target;
    model::LadderProgram ladder;
    model::ToListingResult listing;
    std::unique_ptr<simulator::Engine> engine;
    model::Snapshot snapshot;

    Running(model::Family family, const QString &text)
        : target(model::Target::get(family)) {
        const model::ParseResult parsed = model::parseInstructionList(target, text);
        EXPECT_TRUE(parsed.ok()) << (parsed.ok() ? std::string()
                                                 : parsed.errors[0].message.toStdString());
        ladder = model::listToLadder(parsed.list).ladder;
        listing = model::ladderToList(ladder);
        EXPECT_TRUE(listing.ok());
        // Compiled as it stands (random programs drive a coil twice, which the checks refuse).
        const simulator::CompileResult compiled = simulator::compileProgram(listing.list);
        EXPECT_TRUE(compiled.ok())
            << (compiled.diagnostics.empty() ? std::string()
                                             : compiled.diagnostics[0].message.toStdString());
        engine = std::make_unique<simulator::Engine>(compiled.program);
        engine->setPowerFlowRecording(true);
    }
    model::Address at(const char *device) const {
        return std::get<model::Address>(model::parseAddress(target, QString::fromLatin1(device)));
    }
    void set(const char *device, bool on) { engine->setBit(at(device), on); }
    // Rising edges on a counter's input, a scan ON and a scan OFF each.
    void pulse(const char *device, int times) {
        for (int i = 0; i < times; ++i) {
            set(device, true);
            scan();
            set(device, false);
            scan();
        }
    }
    // Scans, then the overlay of a rung as the view would draw it.
    RungOverlay scan(int rung = 0, int scans = 1) {
        engine->runScans(static_cast<quint64>(scans));
        return overlay(rung);
    }
    RungOverlay overlay(int rung, bool withPowerFlow = true) {
        snapshot = engine->snapshot();
        if (!withPowerFlow)
            snapshot.powerFlow.clear(); // an online PLC reports no power flow
        return ProgramFlow(ladder, listing, snapshot).rung(rung);
    }
};

TEST(PowerFlow, SeriesContactsPassPowerUpToTheFirstOpenOne) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    p.set("X0", true);
    RungOverlay o = p.scan();
    ASSERT_EQ(o.rows, 1);
    ASSERT_EQ(o.columns, 2);
    EXPECT_TRUE(o.rail);
    EXPECT_TRUE(o.nodeOn(0, 0));
    EXPECT_TRUE(o.conducts(0, 0));
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_TRUE(o.nodeOn(0, 1)); // power reaches the open X1
    EXPECT_FALSE(o.conducts(0, 1));
    EXPECT_FALSE(o.passes(0, 1));
    ASSERT_NE(o.output(0), nullptr);
    EXPECT_FALSE(o.output(0)->powered);
    EXPECT_FALSE(o.output(0)->on);
    EXPECT_TRUE(o.output(0)->hasBit);

    p.set("X1", true);
    o = p.scan();
    EXPECT_TRUE(o.passes(0, 1));
    EXPECT_TRUE(o.output(0)->powered);
    EXPECT_TRUE(o.output(0)->on);
}

TEST(PowerFlow, AParallelContactJoinsItsRowAtTheNode) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nOR X1\nOUT Y0\nEND\n"));
    p.set("X1", true);
    const RungOverlay o = p.scan();
    ASSERT_EQ(o.rows, 2);
    EXPECT_FALSE(o.conducts(0, 0));
    EXPECT_FALSE(o.passes(0, 0));
    EXPECT_TRUE(o.passes(1, 0));
    EXPECT_TRUE(o.nodeOn(0, 1)); // the link carries X1's power up to the coil's row
    EXPECT_TRUE(o.output(0)->powered);
}

// LD X0 / LD X1 / OR X2 / ANB: the logic result after LD X1 is X1 alone, but no power
// reaches X1 while X0 is open. The wires must not show the block's local result.
TEST(PowerFlow, AnAnbBlockGetsNoPowerBehindAnOpenContact) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nLD X1\nOR X2\nANB\nOUT Y0\nEND\n"));
    p.set("X1", true);
    RungOverlay o = p.scan();
    ASSERT_EQ(o.rows, 2);
    ASSERT_EQ(o.columns, 2);
    EXPECT_FALSE(o.passes(0, 0));
    EXPECT_TRUE(o.conducts(0, 1)) << "X1 is ON: drawn closed";
    EXPECT_FALSE(o.nodeOn(0, 1));
    EXPECT_FALSE(o.passes(0, 1)) << "but no power passes it";
    EXPECT_FALSE(o.output(0)->powered);

    p.set("X0", true);
    o = p.scan();
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_TRUE(o.passes(0, 1));
    EXPECT_FALSE(o.passes(1, 1)); // X2 is OFF
    EXPECT_TRUE(o.nodeOn(1, 1));  // the node left of X2 is the one after X0
    EXPECT_TRUE(o.output(0)->powered);
}

TEST(PowerFlow, AnOrbBlockIsPoweredThroughEitherRow) {
    Running p(model::Family::Vigor,
              QStringLiteral("LD X0\nAND X1\nLD X2\nAND X3\nORB\nOUT Y0\nEND\n"));
    p.set("X0", true);
    p.set("X2", true);
    p.set("X3", true);
    const RungOverlay o = p.scan();
    ASSERT_EQ(o.rows, 2);
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_FALSE(o.passes(0, 1));
    EXPECT_TRUE(o.passes(1, 0));
    EXPECT_TRUE(o.passes(1, 1));
    EXPECT_TRUE(o.nodeOn(0, 2)); // the rows join before the coil
    EXPECT_TRUE(o.output(0)->powered);
}

TEST(PowerFlow, AClosedContactConductsWhileItsDeviceIsOff) {
    Running p(model::Family::Vigor, QStringLiteral("LDI X0\nOUT Y0\nEND\n"));
    RungOverlay o = p.scan();
    EXPECT_TRUE(o.conducts(0, 0));
    EXPECT_TRUE(o.output(0)->on);
    p.set("X0", true);
    o = p.scan();
    EXPECT_FALSE(o.conducts(0, 0));
    EXPECT_FALSE(o.output(0)->on);
}

TEST(PowerFlow, InvPassesWhatReachesItInverted) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nINV\nOUT Y0\nEND\n"));
    RungOverlay o = p.scan();
    ASSERT_EQ(o.columns, 2);
    EXPECT_FALSE(o.passes(0, 0));
    EXPECT_TRUE(o.passes(0, 1));
    EXPECT_TRUE(o.output(0)->powered);
    p.set("X0", true);
    o = p.scan();
    EXPECT_FALSE(o.passes(0, 1));
    EXPECT_FALSE(o.output(0)->powered);
}

// An edge lasts one scan: only the power flow knows it. Without one (an online PLC) the
// contact is drawn open.
TEST(PowerFlow, AnEdgeContactConductsInTheScanOfTheEdge) {
    Running p(model::Family::Vigor, QStringLiteral("LDP X0\nOUT Y0\nEND\n"));
    EXPECT_FALSE(p.scan().conducts(0, 0));
    p.set("X0", true);
    RungOverlay o = p.scan();
    EXPECT_TRUE(o.conducts(0, 0));
    EXPECT_TRUE(o.output(0)->powered);
    EXPECT_FALSE(p.overlay(0, false).conducts(0, 0));
    o = p.scan();
    EXPECT_FALSE(o.conducts(0, 0));
    EXPECT_FALSE(o.output(0)->powered);
}

// The converter's IL / ILC of a VPC rung and the user's own interlock: rungs inside an
// interlock that is OFF get no power at their rail, whatever their contacts say.
TEST(PowerFlow, AnInterlockThatIsOffTakesThePowerFromItsRungs) {
    Running p(model::Family::Vpc, QStringLiteral("LD i00\nIL\nLD i01\nOUT o00\nILC\nEND\n"));
    ASSERT_GE(p.ladder.rungs.size(), 3u);
    p.set("i01", true);
    RungOverlay o = p.scan(1);
    EXPECT_FALSE(o.rail);
    EXPECT_TRUE(o.conducts(0, 0)) << "i01 is ON: drawn closed";
    EXPECT_FALSE(o.passes(0, 0));
    EXPECT_FALSE(o.output(0)->powered);
    p.set("i00", true);
    o = p.scan(1);
    EXPECT_TRUE(o.rail);
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_TRUE(o.output(0)->powered);
}

// A step ladder: the rungs of a step get power while the step is active; the STL box itself
// takes no condition (no power drawn into it) and shows its step relay.
TEST(PowerFlow, AStepsRungsArePoweredWhileTheStepIsActive) {
    Running p(model::Family::Vigor, QStringLiteral("STL S0\nLD X0\nOUT Y0\nRET\nEND\n"));
    ASSERT_GE(p.ladder.rungs.size(), 4u);
    p.set("X0", true);
    RungOverlay step = p.scan(0);
    ASSERT_NE(step.output(0), nullptr);
    EXPECT_FALSE(step.output(0)->powered);
    EXPECT_TRUE(step.output(0)->hasBit);
    EXPECT_FALSE(step.output(0)->on);
    EXPECT_FALSE(step.nodeOn(0, step.columns)) << "no power into an STL";
    RungOverlay inside = p.overlay(1);
    EXPECT_FALSE(inside.rail);
    EXPECT_TRUE(inside.conducts(0, 0));
    EXPECT_FALSE(inside.output(0)->powered);
    EXPECT_FALSE(p.overlay(1, false).rail) << "without power flow the step relay tells";

    p.engine->setBit(p.at("S0"), true);
    step = p.scan(0);
    EXPECT_TRUE(step.output(0)->on);
    EXPECT_FALSE(step.output(0)->powered);
    inside = p.overlay(1);
    EXPECT_TRUE(inside.rail);
    EXPECT_TRUE(inside.output(0)->powered);
    EXPECT_TRUE(p.overlay(1, false).rail);
    EXPECT_TRUE(p.overlay(2).rail) << "after RET";
}

TEST(PowerFlow, WithoutPowerFlowTheDevicesDecide) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nLD X1\nOR X2\nANB\nOUT Y0\nEND\n"));
    p.set("X0", true);
    p.set("X2", true);
    p.scan();
    const RungOverlay o = p.overlay(0, false);
    EXPECT_TRUE(o.rail);
    EXPECT_TRUE(o.passes(0, 0));
    EXPECT_FALSE(o.passes(0, 1));
    EXPECT_TRUE(o.passes(1, 1));
    EXPECT_TRUE(o.output(0)->powered);
    EXPECT_EQ(o, p.overlay(0, true)) << "the same drawing as with the scan's power flow";
}

TEST(PowerFlow, ForcedDevicesAreMarkedOnTheirElements) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nAND X1\nOUT Y0\nEND\n"));
    p.engine->force(p.at("X1"), true);
    p.engine->force(p.at("Y0"), true);
    const RungOverlay o = p.scan();
    EXPECT_FALSE(o.isForced(0, 0));
    EXPECT_TRUE(o.isForced(0, 1));
    EXPECT_TRUE(o.conducts(0, 1));
    EXPECT_TRUE(o.output(0)->forced);
    EXPECT_TRUE(o.output(0)->on) << "forced ON against its open condition";
    EXPECT_FALSE(o.output(0)->powered);
}

TEST(PowerFlow, ACompareContactShowsItsWordAndConductsByTheComparison) {
    Running p(model::Family::Vigor, QStringLiteral("LD>= D0 K10\nOUT Y0\nEND\n"));
    p.engine->writeWord(p.at("D0"), 12);
    RungOverlay o = p.scan();
    EXPECT_EQ(o.valueAt(0, 0), QStringLiteral("12"));
    EXPECT_TRUE(o.conducts(0, 0));
    EXPECT_TRUE(o.output(0)->powered);
    p.engine->writeWord(p.at("D0"), 9);
    o = p.scan();
    EXPECT_EQ(o.valueAt(0, 0), QStringLiteral("9"));
    EXPECT_FALSE(o.conducts(0, 0));
    EXPECT_FALSE(p.overlay(0, false).conducts(0, 0));
}

// A timer as elapsed / preset in its units (Vigor TMR counts 100 ms), a CPM1 TIM (counts
// down: the time elapsed is preset - PV) and a counter as count / preset.
TEST(PowerFlow, TimersAndCountersShowElapsedOrCountOverPreset) {
    Running vigor(model::Family::Vigor, QStringLiteral("LD X0\nTMR T0 K50\nEND\n"));
    vigor.set("X0", true);
    RungOverlay o = vigor.scan(0, 31); // 300 ms after the first scan that saw X0
    EXPECT_EQ(vigor.engine->value(vigor.at("T0")), 3);
    EXPECT_EQ(o.output(0)->value, QStringLiteral("3/50 ×0.1 s"));
    EXPECT_TRUE(o.output(0)->powered);
    EXPECT_FALSE(o.output(0)->on);

    Running cpm1(model::Family::Cpm1, QStringLiteral("LD 000.00\nTIM 000 #0050\nEND\n"));
    cpm1.set("000.00", true);
    o = cpm1.scan(0, 21);
    EXPECT_EQ(cpm1.engine->value(cpm1.at("TIM000")), 0x48)
        << "the PV counts down from 50, in BCD digits (W353)";
    EXPECT_EQ(o.output(0)->value, QStringLiteral("2/50 ×0.1 s"));

    Running counter(model::Family::Vigor, QStringLiteral("LD X0\nCNT C0 K10\nEND\n"));
    counter.pulse("X0", 3);
    EXPECT_EQ(counter.overlay(0).output(0)->value, QStringLiteral("3/10"));
}

// A CPM1 CNT counts down from its set value, both in BCD digits (W353): #0012 with three
// counts is 9 of 12, not the raw words 9 and 18.
TEST(PowerFlow, ACpm1CounterShowsItsBcdDigitsAsNumbers) {
    Running p(model::Family::Cpm1, QStringLiteral("LD 000.00\nLD 000.01\nCNT 001 #0012\nEND\n"));
    p.pulse("000.00", 3);
    EXPECT_EQ(p.engine->value(p.at("CNT 001")), 0x09);
    EXPECT_EQ(p.overlay(0).output(0)->value, QStringLiteral("9/12"));
}

// Online, the PLC answers only for what a protocol area holds: a Vigor timer's current value,
// not its K preset, which lives in the program. The overlay then takes the box's own preset:
// the constant, or the word it names once that word was read; never a 0 nobody read.
TEST(PowerFlow, OnlineATimerWhosePresetNoAreaHoldsShowsTheBoxsOwnPreset) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nTMR T0 K350\nTMR T1 D10\nEND\n"));
    p.engine->writeWord(p.at("D10"), 50);
    p.set("X0", true);
    p.scan(0, 31);
    p.snapshot = p.engine->snapshot();
    const model::MemoryLayout &layout = *p.snapshot.layout;
    // What an online session over the Vigor link reads: bits and current values only.
    auto read = std::make_shared<std::vector<bool>>(p.snapshot.words.size(), false);
    for (const char *device : {"X0", "T0", "T1"}) {
        (*read)[std::size_t(layout.word(p.at(device)))] = true;
        (*read)[std::size_t(layout.bit(p.at(device)).word)] = true;
    }
    // The words nobody asked for hold 0 online.
    for (const char *device : {"T0", "T1"})
        p.snapshot.words[std::size_t(layout.setValueWord(p.at(device)))] = 0;
    p.snapshot.words[std::size_t(layout.word(p.at("D10")))] = 0;
    p.snapshot.wordsRead = read;
    EXPECT_FALSE(p.snapshot.setValueKnown(p.at("T0")));
    EXPECT_FALSE(p.snapshot.valueKnown(p.at("D10")));
    const model::Instruction &t0 = p.listing.list.instructions[1];
    const model::Instruction &t1 = p.listing.list.instructions[2];
    ASSERT_EQ(t0.op(), model::Op::Timer);
    EXPECT_EQ(ProgramFlow::timerText(p.target, t0, p.snapshot), QStringLiteral("3/350 ×0.1 s"));
    EXPECT_EQ(ProgramFlow::timerText(p.target, t1, p.snapshot), QStringLiteral("3/? ×0.1 s"))
        << "D10 was not read: its preset is not known";
    // D10 read as well: its value is the preset.
    (*read)[std::size_t(layout.word(p.at("D10")))] = true;
    p.snapshot.words[std::size_t(layout.word(p.at("D10")))] = 50;
    EXPECT_EQ(ProgramFlow::timerText(p.target, t1, p.snapshot), QStringLiteral("3/50 ×0.1 s"));
    // A constant preset is the program's (issue 31): a set value in the memory that the box
    // has not loaded yet (after Stop: 0) is not shown for it; a word preset is the memory's.
    model::Snapshot simulated = p.engine->snapshot();
    EXPECT_TRUE(simulated.setValueKnown(p.at("T0")));
    p.engine->writeSetValue(p.at("T0"), 0);
    p.engine->writeSetValue(p.at("T1"), 40);
    simulated = p.engine->snapshot();
    EXPECT_EQ(ProgramFlow::presetOf(p.target, &t0, p.at("T0"), simulated), 350);
    EXPECT_EQ(ProgramFlow::presetOf(p.target, &t1, p.at("T1"), simulated), 40);
}

TEST(PowerFlow, ABoxShowsTheValuesOfItsWords) {
    Running p(model::Family::Vigor, QStringLiteral("LD X0\nMOV K7 D3\nEND\n"));
    RungOverlay o = p.scan();
    EXPECT_EQ(o.output(0)->value, QStringLiteral("D3 = 0"));
    EXPECT_FALSE(o.output(0)->hasBit);
    p.set("X0", true);
    o = p.scan();
    EXPECT_EQ(o.output(0)->value, QStringLiteral("D3 = 7"));
    EXPECT_TRUE(o.output(0)->powered);
}

// Over random programs of every family (timers, edges, compares, moves, MPS and IL
// branches, rungs that read their own outputs): the condition drawn at each single-input
// output is the logic result the scan had there, scan after scan.
TEST(PowerFlow, EveryOutputsDrawnConditionIsTheScansResult) {
    int checked = 0;
    for (const model::Family family : model::Target::families()) {
        const model::Target &t = model::Target::get(family);
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            rung::testing::RandomProgramOptions options;
            options.rungs = 6;
            options.extended = seed % 2 == 0;
            const QString text = rung::testing::randomProgram(t, seed, options);
            SCOPED_TRACE(
                QStringLiteral("%1 seed %2\n%3").arg(t.id).arg(seed).arg(text).toStdString());
            Running p(family, text);
            if (::testing::Test::HasFailure())
                return;
            std::vector<model::Address> inputs;
            for (const model::Instruction &ins : p.listing.list.instructions)
                for (const model::Operand &op : ins.operands)
                    if (op.kind == model::Operand::Kind::Device &&
                        t.area(op.address.area).physical && !t.area(op.address.area).writable)
                        inputs.push_back(op.address);
            std::mt19937_64 rng(seed);
            for (int scan = 0; scan < 12; ++scan) {
                for (const model::Address &in : inputs)
                    p.engine->setBit(in, (rng() & 1u) != 0);
                p.engine->scan();
                p.snapshot = p.engine->snapshot();
                const ProgramFlow flow(p.ladder, p.listing, p.snapshot);
                ASSERT_TRUE(flow.hasPowerFlow());
                const auto &instructions = p.listing.list.instructions;
                for (std::size_t i = 0; i < instructions.size(); ++i) {
                    const model::CellOrigin &at = p.listing.origin[i];
                    if (at.rung < 0 || at.row < 0 || model::isLogic(instructions[i].op()) ||
                        model::isUnconditional(instructions[i].op()) ||
                        instructions[i].spec->inputs != 1)
                        continue;
                    const model::Rung &rung = p.ladder.rungs[static_cast<std::size_t>(at.rung)];
                    if (at.column != rung.columns)
                        continue;
                    const RungOverlay o = flow.rung(at.rung);
                    ASSERT_NE(o.output(at.row), nullptr);
                    EXPECT_EQ(o.output(at.row)->powered, static_cast<bool>(p.snapshot.powerFlow[i]))
                        << "scan " << scan << ", rung " << at.rung + 1 << ", row " << at.row + 1
                        << ": " << model::printInstruction(t, instructions[i]).toStdString();
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 5000);
}

} // namespace
