#pragma once

// What the engine tests that run random programs of every family share: the programs
// themselves, compiled (each under a trace naming its family, seed and text), and their inputs.

#include "tests/model/random_program.h"

#include "model/listing/il.h"
#include "model/project/project.h"
#include "simulator/compiler.h"

#include <QDirIterator>

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

// Every example project (resources/examples), its ladder as a listing, compiled (a failure
// fails the test); check(target, list, compiled) for each. Returns how many there were.
template <class Check> int forEachExampleProgram(Check &&check) {
    QDirIterator it(QStringLiteral(RUNG_SOURCE_DIR "/resources/examples"),
                    {QStringLiteral("*.rung")}, QDir::Files, QDirIterator::Subdirectories);
    int examples = 0;
    while (it.hasNext()) {
        const QString path = it.next();
        SCOPED_TRACE(path.toStdString());
        model::ProjectError error;
        const auto project = model::loadProject(path, &error);
        EXPECT_TRUE(project) << error.message.toStdString();
        if (!project)
            continue;
        const model::ToListingResult listing = model::ladderToList(project->program);
        EXPECT_TRUE(listing.ok());
        const CompileResult compiled = compileProgram(listing.list);
        EXPECT_TRUE(compiled.ok());
        if (!listing.ok() || !compiled.ok())
            continue;
        check(*project->target, listing.list, compiled);
        ++examples;
    }
    return examples;
}

} // namespace rung::simulator::test
