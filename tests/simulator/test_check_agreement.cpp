// `check` and `simulate` agree on every operand (issue 14): each operand the simulator's
// compiler refuses is a table rule (model::operandBreaches) that `check` reports as an OP
// error on the instruction's line, and the compiler reads the same rule. Per family, every case
// the audit found, each with a correct neighbour that both accept; then a property over random
// operands for every application instruction of every family.

#include "tests/model/random_program.h"

#include "model/checks/checks.h"
#include "model/listing/il.h"
#include "model/target/address.h"
#include "simulator/compiler.h"

#include <gtest/gtest.h>

#include <random>

using namespace rung;

namespace {

struct Refused {
    const char *program;
    int line;
    const char *says;      // in check's message
    const char *neighbour; // a correct program next to it: both accept
};

std::vector<model::Diagnostic> checkErrorsOn(const model::InstructionList &list, int line) {
    std::vector<model::Diagnostic> found;
    for (model::Diagnostic &d : model::checkList(list, {}))
        if (d.severity == model::Severity::Error && d.location.line == line)
            found.push_back(std::move(d));
    return found;
}

void expectAgreement(model::Family family, const std::vector<Refused> &cases) {
    const model::Target &target = model::Target::get(family);
    for (const Refused &c : cases) {
        SCOPED_TRACE(c.program);
        const model::ParseResult parsed =
            model::parseInstructionList(target, QString::fromLatin1(c.program));
        ASSERT_TRUE(parsed.ok()) << parsed.errors.front().message.toStdString();
        const std::vector<model::Diagnostic> errors = checkErrorsOn(parsed.list, c.line);
        ASSERT_EQ(errors.size(), 1u) << "check gives one error on line " << c.line;
        EXPECT_TRUE(errors.front().code.startsWith(QLatin1String("OP")))
            << errors.front().code.toStdString();
        EXPECT_TRUE(errors.front().message.contains(QLatin1String(c.says)))
            << errors.front().message.toStdString();
        const simulator::CompileResult compiled = simulator::compileProgram(parsed.list);
        EXPECT_FALSE(compiled.ok()) << "the compiler refuses it too";
        ASSERT_EQ(compiled.diagnostics.size(), 1u) << "with the table's words, not its own too";
        EXPECT_EQ(compiled.diagnostics.front().location.line, c.line);
        EXPECT_EQ(compiled.diagnostics.front().message, errors.front().message);

        SCOPED_TRACE(c.neighbour);
        const model::ParseResult good =
            model::parseInstructionList(target, QString::fromLatin1(c.neighbour));
        ASSERT_TRUE(good.ok()) << good.errors.front().message.toStdString();
        for (const model::Diagnostic &d : model::checkList(good.list, {}))
            EXPECT_NE(d.severity, model::Severity::Error) << d.message.toStdString();
        const simulator::CompileResult ok = simulator::compileProgram(good.list);
        EXPECT_TRUE(ok.ok()) << (ok.diagnostics.empty()
                                     ? std::string()
                                     : ok.diagnostics.front().message.toStdString());
    }
}

} // namespace

TEST(CheckSimulatorAgreement, Vigor) {
    expectAgreement(
        model::Family::Vigor,
        {
            // BMOV: both blocks inside the registers (D8190..D8199 passes D8191).
            {"LD M9000\nBMOV D8190 D0 K10\nEND", 2, "D8192 does not exist",
             "LD M9000\nBMOV D8182 D0 K10\nEND"},
            {"LD M9000\nBMOV D0 D8190 K10\nEND", 2, "BMOV uses D8190..D8199",
             "LD M9000\nBMOV D0 D190 K20\nEND"}, // D190..D209 runs on into the latched D200
            {"LD M9000\nBMOV D0 D10 K0\nEND", 2, "must be at least 1, not 0",
             "LD M9000\nBMOV D0 D10 K1\nEND"},
            // A block of counter values stays in one counter area.
            {"LD M9000\nBMOV C90 D0 K20\nEND", 2, "a block stays in one",
             "LD M9000\nBMOV C80 D0 K20\nEND"},
            // MUL / DIV write D and D+1.
            {"LD M9000\nMUL D0 D1 D8191\nEND", 2, "D8192 does not exist",
             "LD M9000\nMUL D0 D1 D199\nEND"},
            {"LD M9000\nDIV D0 D1 D8191\nEND", 2, "D8192 does not exist",
             "LD M9000\nDIV D0 D1 D8190\nEND"},
            // CMP writes three bits from D.
            {"LD M9000\nCMP D0 D1 M5119\nEND", 2, "M5120 does not exist",
             "LD M9000\nCMP D0 D1 M498\nEND"},
            {"LD M9000\nCMP D0 D1 Y777\nEND", 2, "Y1000 does not exist",
             "LD M9000\nCMP D0 D1 Y775\nEND"},
            // ZRST: one kind, the first not after the last, every device between.
            {"LD M9000\nZRST D10 D5\nEND", 2, "not before it", "LD M9000\nZRST D5 D10\nEND"},
            {"LD M9000\nZRST M0 D5\nEND", 2, "of the kind of the first",
             "LD M9000\nZRST M0 M600\nEND"},
            {"LD M9000\nZRST M5000 M9100\nEND", 2, "M5120 does not exist",
             "LD M9000\nZRST T0 T255\nEND"},
        });
}

TEST(CheckSimulatorAgreement, Pl110) {
    expectAgreement(model::Family::Pl110,
                    {
                        // 4.2.6: + - * / | & ^ << >> only.
                        {"LD SM0.0\nFM V0 % 2 V1\nEND", 2, "not %", "LD SM0.0\nFM V0 ^ 2 V1\nEND"},
                        {"LD SM0.0\nFM V0 2 2 V1\nEND", 2, "not 2", "LD SM0.0\nFM V0 >> 2 V1\nEND"},
                        // 4.2.8: at least one word, each block inside its area.
                        {"LD SM0.0\nBLKMOV V0 V10 0\nEND", 2, "at least 1, not 0",
                         "LD SM0.0\nBLKMOV V0 V10 1\nEND"},
                        {"LD SM0.0\nBLKMOV V340 V0 20\nEND", 2, "V350 does not exist",
                         "LD SM0.0\nBLKMOV V330 V0 20\nEND"},
                        {"LD SM0.0\nBLKMOV 7 V340 20\nEND", 2, "V350 does not exist",
                         "LD SM0.0\nBLKMOV 7 V330 20\nEND"},
                    });
}

TEST(CheckSimulatorAgreement, Cpm1) {
    expectAgreement(model::Family::Cpm1,
                    {
                        // W353 MUL(32): R and R+1.
                        {"LD 253.13\nMUL(32) #0002 #0003 DM 1023\nEND", 2, "does not exist",
                         "LD 253.13\nMUL(32) #0002 #0003 DM 1022\nEND"},
                    });
}

// A word operand is a word: seed 001's "Operand Devices" tables mark X, Y, M, S apart from
// KnX, KnY, KnM, KnS, so a Vigor word slot takes K4M0, not M0; CPM1 TR (W353) is a bit for
// LD and OUT only; the PL110 reads 16 bits of a bit area as a word from I1, I17, ...
// (Area::bitsAsWords).
TEST(CheckSimulatorAgreement, ABitDeviceIsNoWordOperand) {
    expectAgreement(
        model::Family::Vigor,
        {
            {"LD M9000\nMOV M0 D0\nEND", 2,
             "the operand 1 of MOV is a word: M0 is a "
             "single bit",
             "LD M9000\nMOV K4M0 D0\nEND"},
            {"LD M9000\nINC Y0\nEND", 2, "Y0 is a single bit", "LD M9000\nINC K4Y0\nEND"},
            {"LD M9000\nADD D0 K1 S500\nEND", 2, "S500 is a single bit",
             "LD M9000\nADD D0 K1 K4S500\nEND"},
            {"LD M9000\nMUL K2 K20 M16\nEND", 2, "M16 is a single bit",
             "LD M9000\nMUL K2 K20 D16\nEND"},
        });
    expectAgreement(model::Family::Cpm1,
                    {
                        {"LD 253.13\nMOV(21) #0001 TR 1\nEND", 2, "TR 1 is a single bit",
                         "LD 253.13\nMOV(21) #0001 HR01\nEND"},
                        {"LD 253.13\nINC(38) TR 0\nEND", 2, "TR 0 is a single bit",
                         "LD 253.13\nINC(38) DM 0000\nEND"},
                    });
    expectAgreement(
        model::Family::Pl110,
        {
            {"LD SM0.0\nMOV I2 V0\nEND", 2, "I2 starts no word of 16 bits (I1 and I17 do)",
             "LD SM0.0\nMOV I17 V0\nEND"},
            {"LD SM0.0\nMOV V0 M20\nEND", 2, "(M17 and M33 do)", "LD SM0.0\nMOV V0 M17\nEND"},
        });
}

// A bit operand is a bit: CMP's result D, D+1, D+2 are bit devices (seed 001), a CPM1 control
// bit or contact names a bit of a channel (011.00), not the channel.
TEST(CheckSimulatorAgreement, AWholeWordIsNoBitOperand) {
    expectAgreement(
        model::Family::Vigor,
        {
            {"LD M9000\nCMP D0 D1 D9000\nEND", 2,
             "the operand 3 of CMP is a bit: D9000 is a whole word", "LD M9000\nCMP D0 D1 M0\nEND"},
        });
    expectAgreement(
        model::Family::Cpm1,
        {
            {"LD 011\nOUT 010.00\nEND", 1,
             "011 is a whole channel (011.00 is its "
             "first bit)",
             "LD 011.00\nOUT 010.00\nEND"},
            {"LD 000.00\nOUT 010\nEND", 2, "010 is a whole channel", "LD 000.00\nOUT 010.01\nEND"},
        });
}

// Vigor CCD S D n reads n bytes from the words at S: a device (seed 001 B-3-9 CCD D52 D104
// K11); DMOV S D reads S and S+1 unless S is a 32-bit counter or a timer (C200..C255 hold 32
// bits), and writes D, D+1 unless D is a 32-bit counter.
TEST(CheckSimulatorAgreement, BlocksAndPairsOfTheVigor) {
    expectAgreement(
        model::Family::Vigor,
        {
            {"LD M9000\nCCD K100 D104 K11\nEND", 2,
             "the operand 1 of CCD must be a device, not K100", "LD M9000\nCCD D52 D104 K11\nEND"},
            {"LD M9000\nDMOV D8191 D0\nEND", 2, "D8192 does not exist",
             "LD M9000\nDMOV C255 D0\nEND"},
            {"LD M9000\nDMOV K1 D8191\nEND", 2, "D8192 does not exist",
             "LD M9000\nDMOV K1 C255\nEND"},
            {"LD M9000\nDMOV D0 T255\nEND", 2, "T256 does not exist",
             "LD M9000\nDMOV T255 D0\nEND"},
        });
}

// Random operands for every application instruction of every family, near the ends of the
// areas and around the constants' limits: whenever the compiler refuses an instruction,
// `check` has an error on its line, and whenever the compiler takes it, `check` has no operand
// error there (that way round it found CMP's results and ZRST's ends on the Vigor's inputs). (The ~190 it once found were plain bit devices in word
// slots, whole words or channels in bit slots, a CCD constant and DMOV pairs: the table rules
// of the three tests above. Twelve seeds found none when it was enabled.)
TEST(CheckSimulatorAgreement, WhateverTheCompilerRefusesCheckReportsOnItsLine) {
    int refused = 0;
    int compiled = 0;
    for (const model::Family family : model::Target::families()) {
        const model::Target &target = model::Target::get(family);
        std::mt19937_64 random(0x14a + static_cast<int>(family));
        const auto pick = [&](int n) {
            return static_cast<int>(random() % static_cast<std::uint64_t>(n));
        };
        // Devices: an area's first or last elements, or one past; constants around the rules.
        const auto device = [&]() {
            const model::Area &a = target.area(pick(static_cast<int>(target.areas.size())));
            const int offsets[] = {0, 1, -1, -2, -3, -9, -19};
            const int o = offsets[pick(7)];
            const int n = o >= 0 ? a.first + o : a.last + 1 + o;
            return model::formatAddress(
                target, model::Address{static_cast<int>(&a - target.areas.data()), n, -1});
        };
        const auto constant = [&]() {
            const int values[] = {0, 1, 2, 3, 15, 16, 20, -1, 100, 1000};
            const model::Constant c{values[pick(10)], target.constants.prefixed
                                                          ? model::Constant::Style::Decimal
                                                          : model::Constant::Style::Plain};
            return target.constants.bcd
                       ? QStringLiteral("#%1").arg(c.value, 4, 10, QLatin1Char('0'))
                       : model::formatConstant(target, c);
        };
        const char *words[] = {"+", "<<", "%", "x"};
        for (const model::InstructionSpec &spec : target.instructions) {
            if (spec.op != model::Op::Apply || spec.operands.empty())
                continue;
            for (int round = 0; round < 60; ++round) {
                QStringList operands;
                for (std::size_t k = 0; k < spec.operands.size(); ++k) {
                    const int way = pick(5);
                    operands << (way < 2   ? device()
                                 : way < 4 ? constant()
                                           : QString::fromLatin1(words[pick(4)]));
                }
                rung::testing::RandomProgramOptions options;
                options.rungs = 1;
                options.end = false;
                const QString before =
                    rung::testing::randomProgram(target, random(), options).trimmed();
                const QString on = model::formatAddress(
                    target, model::systemAddress(target, model::SystemRole::AlwaysOn));
                const QString text = before + QStringLiteral("\nLD %1\n%2 %3\nEND\n")
                                                  .arg(on, spec.mnemonic, operands.join(u' '));
                const model::ParseResult parsed = model::parseInstructionList(target, text);
                if (!parsed.ok())
                    continue; // the parser's own error
                const simulator::CompileResult result = simulator::compileProgram(parsed.list);
                if (result.ok()) {
                    ++compiled;
                    // The other way round: an operand check refuses, the compiler refuses too.
                    // (Not OP003, a timer and a counter of one number: two instructions'
                    // quarrel over one bank, which the simulator keeps as the PLC does.)
                    const int line = static_cast<int>(text.count(u'\n')) - 1;
                    for (const model::Diagnostic &d : checkErrorsOn(parsed.list, line))
                        if (d.code.startsWith(QLatin1String("OP")) &&
                            d.code != QLatin1String("OP003"))
                            ADD_FAILURE() << text.toStdString() << target.id.toStdString()
                                          << ": check says '" << d.message.toStdString()
                                          << "' on line " << line << ", the compiler takes it";
                    continue;
                }
                ++refused;
                SCOPED_TRACE(text.toStdString());
                for (const model::Diagnostic &d : result.diagnostics) {
                    if (d.severity != model::Severity::Error)
                        continue;
                    EXPECT_FALSE(checkErrorsOn(parsed.list, d.location.line).empty())
                        << target.id.toStdString() << ": the compiler says '"
                        << d.message.toStdString() << "' on line " << d.location.line
                        << ", check nothing there";
                }
            }
        }
    }
    // The property saw both sides.
    EXPECT_GT(refused, 50);
    EXPECT_GT(compiled, 50);
}
