#pragma once

// A program of one family's real target table, compiled and ready to scan: the fixture of
// the tests that pin what the manuals name (system devices, retention, PL110 elements, the
// choices where a manual is ambiguous). The engine tests use sim_test_target.h instead.

#include "model/listing/il.h"
#include "model/target/address.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace rung::simulator::test {

struct RealTargetSim {
    RealTargetSim(model::Family family, const char *text)
        : target(model::Target::get(family))
        , parsed(model::parseInstructionList(target, QString::fromLatin1(text))) {
        if (parsed.ok())
            result = compileProgram(parsed.list);
        if (result.ok())
            engine = std::make_unique<Engine>(result.program);
    }
    model::Address at(const char *name) const {
        const auto address = model::parseAddress(target, QString::fromLatin1(name));
        EXPECT_TRUE(std::holds_alternative<model::Address>(address)) << name;
        return std::holds_alternative<model::Address>(address) ? std::get<model::Address>(address)
                                                               : model::Address{};
    }
    void in(const char *name, bool on) { engine->setBit(at(name), on); }
    bool bit(const char *name) const { return engine->bit(at(name)); }
    std::int32_t value(const char *name) const { return engine->value(at(name)); }
    // The value of a bit device after each of n scans, as a 0/1 string.
    std::string bits(const char *name, int n) {
        std::string s;
        for (int i = 0; i < n; ++i) {
            engine->scan();
            s += bit(name) ? '1' : '0';
        }
        return s;
    }
    // n pulses on an input: one scan ON, one scan OFF, n times.
    void pulses(const char *input, int n) {
        for (int k = 0; k < n; ++k) {
            in(input, true);
            engine->scan();
            in(input, false);
            engine->scan();
        }
    }
    // Scans once per character of inputs ('1' = input ON) and collects the bit after each.
    std::string run(const char *input, const char *inputs, const char *output) {
        std::string out;
        for (const char *c = inputs; *c; ++c) {
            engine->setBit(at(input), *c == '1');
            engine->scan();
            out += engine->bit(at(output)) ? '1' : '0';
        }
        return out;
    }

    const model::Target &target;
    model::ParseResult parsed;
    CompileResult result;
    std::unique_ptr<Engine> engine;
};

// A program of one family's table by the family's name: Pl110 s("LD I1\nOUT Q1\nEND").
template <model::Family F> struct FamilySim : RealTargetSim {
    explicit FamilySim(const char *text)
        : RealTargetSim(F, text) {}
};
using Vigor = FamilySim<model::Family::Vigor>;
using Cpm1 = FamilySim<model::Family::Cpm1>;
using Pl110 = FamilySim<model::Family::Pl110>;

} // namespace rung::simulator::test
