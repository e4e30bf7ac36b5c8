#pragma once

// What the engine tests that run random programs of every family share: the programs
// themselves, compiled (each under a trace naming its family, seed and text), and their inputs.

#include "tests/model/random_program.h"

#include "model/listing/il.h"
#include "simulator/compiler.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace rung::simulator::test {

// The devices of the list a program only reads (physical inputs), to drive; `written` gets the
// bit devices it may write (to force now and then), when asked.
inline std::vector<model::Address> inputsOf(const model::Target &t,
                                            const model::InstructionList &list,
                                            std::vector<model::Address> *written = nullptr) {
    std::vector<model::Address> inputs;
    for (const model::Instruction &ins : list.instructions)
        for (const model::Operand &op : ins.operands) {
            if (op.kind != model::Operand::Kind::Device)
                continue;
            const model::Area &area = t.area(op.address.area);
            if (area.physical && !area.writable)
                inputs.push_back(op.address);
            else if (written && area.kind == model::AreaKind::Bit)
                written->push_back(op.address);
        }
    return inputs;
}

// Seeds 1..seeds of an extended random program of `rungs` rungs for each of the four families,
// parsed and compiled (a failure fails the test); check(target, list, compiled, seed) for each.
template <class Check> void forEachRandomProgram(int seeds, int rungs, Check &&check) {
    for (const model::Family family :
         {model::Family::Vpc, model::Family::Vigor, model::Family::Cpm1, model::Family::Pl110}) {
        const model::Target &t = model::Target::get(family);
        for (std::uint64_t seed = 1; seed <= std::uint64_t(seeds); ++seed) {
            rung::testing::RandomProgramOptions o;
            o.rungs = rungs;
            o.extended = true;
            const QString text = rung::testing::randomProgram(t, seed, o);
            SCOPED_TRACE(
                QStringLiteral("%1 seed %2\n%3").arg(t.id).arg(seed).arg(text).toStdString());
            const model::ParseResult parsed = model::parseInstructionList(t, text);
            ASSERT_TRUE(parsed.ok());
            const CompileResult compiled = compileProgram(parsed.list);
            ASSERT_TRUE(compiled.ok());
            check(t, parsed.list, compiled, static_cast<unsigned>(seed));
        }
    }
}

} // namespace rung::simulator::test
