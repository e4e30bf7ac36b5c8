// The simulator as the oracle of the conversion: a random program and the program that came
// back through the ladder (IL -> ladder -> IL) give identical traces under the same stimuli.

#include "tests/model/random_program.h"

#include "model/convert/convert.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace rung;

namespace {

std::shared_ptr<const simulator::Program> compile(const model::InstructionList &list) {
    simulator::CompileResult r = simulator::compileProgram(list);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].message.toStdString());
    return r.program;
}

} // namespace

class SimulatedEquivalence : public ::testing::TestWithParam<std::tuple<model::Family, bool>> {};

// Plain programs, and (extended) programs with edge and compare contacts, timers and their
// contacts, and a move box per family: what the combinational evaluators cannot judge.
TEST_P(SimulatedEquivalence, ListingAndItsRoundTripGiveIdenticalTraces) {
    const model::Target &t = model::Target::get(std::get<0>(GetParam()));
    std::set<model::Op> ops;
    std::set<model::ContactMode> modes;
    int compares = 0;
    for (std::uint64_t seed = 1; seed <= 150; ++seed) {
        rung::testing::RandomProgramOptions o;
        o.rungs = 5;
        o.extended = std::get<1>(GetParam());
        const QString text = rung::testing::randomProgram(t, seed, o);
        SCOPED_TRACE(QStringLiteral("seed %1\n%2").arg(seed).arg(text).toStdString());
        const model::ParseResult parsed = model::parseInstructionList(t, text);
        ASSERT_TRUE(parsed.ok()) << parsed.errors[0].line << ": "
                                 << parsed.errors[0].message.toStdString();
        const model::ToListingResult back =
            model::ladderToList(model::listToLadder(parsed.list).ladder);
        ASSERT_TRUE(back.ok());
        for (const model::Instruction &ins : parsed.list.instructions) {
            ops.insert(ins.op());
            modes.insert(ins.spec->mode);
            compares += ins.spec->compare != model::CompareOp::None ? 1 : 0;
        }
        auto a = compile(parsed.list);
        auto b = compile(back.list);
        ASSERT_TRUE(a && b);
        simulator::Engine ea(a);
        simulator::Engine eb(b);
        std::set<model::Address> devices;
        std::vector<model::Address> inputs;
        for (const model::Instruction &ins : parsed.list.instructions)
            for (const model::Operand &op : ins.operands)
                if (op.kind == model::Operand::Kind::Device) {
                    devices.insert(op.address);
                    if (t.area(op.address.area).physical && !t.area(op.address.area).writable)
                        inputs.push_back(op.address);
                }
        std::mt19937_64 rng(seed);
        for (int scan = 0; scan < 30; ++scan) {
            for (const model::Address &in : inputs) {
                const bool on = (rng() & 1u) != 0;
                ea.setBit(in, on);
                eb.setBit(in, on);
            }
            ea.scan();
            eb.scan();
            for (const model::Address &d : devices) {
                ASSERT_EQ(ea.bit(d), eb.bit(d))
                    << "scan " << scan << " device " << model::formatAddress(t, d).toStdString();
                ASSERT_EQ(ea.value(d), eb.value(d))
                    << "scan " << scan << " value of " << model::formatAddress(t, d).toStdString();
            }
        }
    }
    if (std::get<1>(GetParam())) { // the extended programs do hold what they promise
        EXPECT_TRUE(ops.count(model::Op::Timer));
        EXPECT_TRUE(ops.count(model::Op::Apply) || ops.count(model::Op::Transfer));
        if (t.family == model::Family::Vigor || t.family == model::Family::Pl110) {
            EXPECT_TRUE(modes.count(model::ContactMode::Rising) &&
                        modes.count(model::ContactMode::Falling));
        }
        if (t.family != model::Family::Cpm1) {
            EXPECT_GT(compares, 0);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Targets, SimulatedEquivalence,
    ::testing::Combine(::testing::Values(model::Family::Vpc, model::Family::Vigor,
                                         model::Family::Cpm1, model::Family::Pl110),
                       ::testing::Bool()),
    [](const auto &info) {
        return model::Target::get(std::get<0>(info.param)).id.toStdString() +
               (std::get<1>(info.param) ? "_extended" : "");
    });
