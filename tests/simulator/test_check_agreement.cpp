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

#include <algorithm>
#include <map>
#include <random>
#include <set>

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

// A word operand is a word: the "Operand Devices" tables of the Vigor M/VB/VH communication
// manual mark X, Y, M, S apart from KnX, KnY, KnM, KnS, so a Vigor word slot takes K4M0, not
// M0; CPM1 TR (W353) is a bit for LD and OUT only; the PL110 reads 16 bits of a bit area as a
// word from I1, I17, ... (Area::bitsAsWords).
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

// A bit operand is a bit: CMP's result D, D+1, D+2 are bit devices (Vigor M/VB/VH
// communication manual), a CPM1 control bit or contact names a bit of a channel (011.00), not
// the channel.
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
    // A PL110 word of bits read as a contact (PL110 manual 2.1.1: V1.0..V1.15 are its bits).
    expectAgreement(model::Family::Pl110,
                    {
                        {"LD V1\nOUT Q1\nEND", 1,
                         "the operand 1 of LD is a bit: V1 is a whole word (V1.0 is its first bit)",
                         "LD V1.0\nOUT Q1\nEND"},
                        {"LD I1\nANDN SM37\nOUT Q1\nEND", 2, "SM37 is a whole word",
                         "LD I1\nANDN SM37.7\nOUT Q1\nEND"},
                    });
}

// Vigor CCD S D n reads n bytes from the words at S: a device (Vigor M/VB/VH communication
// manual, B-3-9: CCD D52 D104 K11); DMOV S D reads S and S+1 unless S is a 32-bit counter or a
// timer (C200..C255 hold 32 bits), and writes D, D+1 unless D is a 32-bit counter.
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

// Random operands near the ends of the areas and around the constants' limits, and a program
// around the instruction: whenever the compiler refuses it, `check` has an error on its line,
// and whenever the compiler takes it, `check` has no operand error there.
namespace {

class OperandProperty {
public:
    explicit OperandProperty(model::Family family)
        : m_target(model::Target::get(family))
        , m_random(0x14a + static_cast<int>(family)) {}

    const model::Target &target() const { return m_target; }

    QString operands(const model::InstructionSpec &spec) {
        static const char *const words[] = {"+", "<<", "%", "x"};
        QStringList out;
        for (std::size_t k = 0; k < spec.operands.size(); ++k) {
            const int way = pick(5);
            out << (way < 2   ? device()
                    : way < 4 ? constant()
                              : QString::fromLatin1(words[pick(4)]));
        }
        return out.join(u' ');
    }

    // A rung of random logic before, so that the instruction is not the program's first.
    QString before() {
        rung::testing::RandomProgramOptions options;
        options.rungs = 1;
        options.end = false;
        return rung::testing::randomProgram(m_target, m_random(), options).trimmed();
    }

    QString alwaysOn() const {
        return model::formatAddress(m_target,
                                    model::systemAddress(m_target, model::SystemRole::AlwaysOn));
    }

    // `text` has the instruction under test on `line`.
    void verdict(const QString &text, int line) {
        const model::ParseResult parsed = model::parseInstructionList(m_target, text);
        if (!parsed.ok())
            return; // the parser's own error
        const simulator::CompileResult result = simulator::compileProgram(parsed.list);
        if (result.ok()) {
            ++compiled;
            // The other way round: an operand check refuses, the compiler refuses too. (Not
            // OP003, a timer and a counter of one number: two instructions' quarrel over one
            // bank, which the simulator keeps as the PLC does.) Where the compiler leaves a
            // rule to `check` (compilerAlone false: what a coil may drive, OP002, and a set
            // value's range, OP004), a simulation still does not start: every way into one
            // (the IDE, `simulate`) goes through prepareProgram, which runs the checks first.
            for (const model::Diagnostic &d : checkErrorsOn(parsed.list, line)) {
                if (!d.code.startsWith(QLatin1String("OP")) || d.code == QLatin1String("OP003"))
                    continue;
                if (compilerAlone) {
                    ADD_FAILURE() << text.toStdString() << m_target.id.toStdString()
                                  << ": check says '" << d.message.toStdString() << "' on line "
                                  << line << ", the compiler takes it";
                    continue;
                }
                const simulator::CompileResult started = simulator::prepareProgram(parsed.list);
                EXPECT_FALSE(started.ok()) << text.toStdString();
                EXPECT_TRUE(std::any_of(started.diagnostics.begin(), started.diagnostics.end(),
                                        [&](const model::Diagnostic &x) {
                                            return x.message == d.message &&
                                                   x.location.line == line;
                                        }))
                    << text.toStdString() << d.message.toStdString();
            }
            return;
        }
        ++refused;
        SCOPED_TRACE(text.toStdString());
        for (const model::Diagnostic &d : result.diagnostics) {
            if (d.severity != model::Severity::Error)
                continue;
            EXPECT_FALSE(checkErrorsOn(parsed.list, d.location.line).empty())
                << m_target.id.toStdString() << ": the compiler says '" << d.message.toStdString()
                << "' on line " << d.location.line << ", check nothing there";
        }
    }

    int refused = 0;
    int compiled = 0;
    bool compilerAlone = true;

private:
    int pick(int n) { return static_cast<int>(m_random() % static_cast<std::uint64_t>(n)); }

    // An area's first or last elements, or one past.
    QString device() {
        const model::Area &a = m_target.area(pick(static_cast<int>(m_target.areas.size())));
        const int offsets[] = {0, 1, -1, -2, -3, -9, -19};
        const int o = offsets[pick(7)];
        const int n = o >= 0 ? a.first + o : a.last + 1 + o;
        return model::formatAddress(
            m_target, model::Address{static_cast<int>(&a - m_target.areas.data()), n, -1});
    }

    QString constant() {
        const int values[] = {0, 1, 2, 3, 15, 16, 20, -1, 100, 1000};
        const model::Constant c{values[pick(10)], m_target.constants.prefixed
                                                      ? model::Constant::Style::Decimal
                                                      : model::Constant::Style::Plain};
        return m_target.constants.bcd ? QStringLiteral("#%1").arg(c.value, 4, 10, QLatin1Char('0'))
                                      : model::formatConstant(m_target, c);
    }

    const model::Target &m_target;
    std::mt19937_64 m_random;
};

} // namespace

// Every application instruction of every family. (That way round it found CMP's results and
// ZRST's ends on the Vigor's inputs; the ~190 it once found the first way were plain bit
// devices in word slots, whole words or channels in bit slots, a CCD constant and DMOV pairs:
// the table rules of the three tests above. Twelve seeds found none when it was enabled.)
TEST(CheckSimulatorAgreement, WhateverTheCompilerRefusesCheckReportsOnItsLine) {
    int refused = 0;
    int compiled = 0;
    for (const model::Family family : model::Target::families()) {
        OperandProperty property(family);
        for (const model::InstructionSpec &spec : property.target().instructions) {
            if (spec.op != model::Op::Apply || spec.operands.empty())
                continue;
            for (int round = 0; round < 60; ++round) {
                const QString before = property.before();
                const QString text =
                    before + QStringLiteral("\nLD %1\n%2 %3\nEND\n")
                                 .arg(property.alwaysOn(), spec.mnemonic, property.operands(spec));
                property.verdict(text, static_cast<int>(text.count(u'\n')) - 1);
            }
        }
        refused += property.refused;
        compiled += property.compiled;
    }
    // The property saw both sides.
    EXPECT_GT(refused, 50);
    EXPECT_GT(compiled, 50);
}

// The same for the contacts, coils and the timer and counter boxes of every family (the
// instructions a user writes most): a contact closes its rung with a coil of the family,
// a box gets as many inputs as it takes. (It found PL110 LD V1, a whole word as a contact:
// check let it pass, the simulator refused it.)
TEST(CheckSimulatorAgreement, ContactsCoilsTimersAndCountersAgreeToo) {
    const std::map<QString, const char *> coil = {{QStringLiteral("vpc"), "o00"},
                                                  {QStringLiteral("vigor"), "Y0"},
                                                  {QStringLiteral("cpm1"), "010.00"},
                                                  {QStringLiteral("pl110"), "Q1"}};
    int refused = 0;
    int compiled = 0;
    std::set<model::Op> seen;
    for (const model::Family family : model::Target::families()) {
        OperandProperty property(family);
        property.compilerAlone = false;
        const QString out = QStringLiteral("OUT ") + QLatin1String(coil.at(property.target().id));
        for (const model::InstructionSpec &spec : property.target().instructions) {
            if (spec.operands.empty() || spec.op == model::Op::Apply ||
                !(model::isContact(spec.op) || spec.op == model::Op::Out ||
                  spec.op == model::Op::Set || spec.op == model::Op::Reset ||
                  spec.op == model::Op::PulseRise || spec.op == model::Op::PulseFall ||
                  spec.op == model::Op::Keep || spec.op == model::Op::Timer ||
                  spec.op == model::Op::Counter || spec.op == model::Op::UpDownCounter ||
                  spec.op == model::Op::Transfer))
                continue;
            seen.insert(spec.op);
            for (int round = 0; round < 40; ++round) {
                QStringList lines{property.before()};
                const QString on = QStringLiteral("LD ") + property.alwaysOn();
                if (spec.op != model::Op::Load)
                    for (int k = 0; k < (model::isContact(spec.op) ? 1 : spec.inputs); ++k)
                        lines << on;
                lines << spec.mnemonic + u' ' + property.operands(spec);
                const int line = static_cast<int>(lines.join(u'\n').count(u'\n')) + 1;
                if (model::isContact(spec.op))
                    lines << out;
                lines << QStringLiteral("END\n");
                property.verdict(lines.join(u'\n'), line);
            }
        }
        refused += property.refused;
        compiled += property.compiled;
    }
    EXPECT_GT(refused, 50);
    EXPECT_GT(compiled, 50);
    for (const model::Op op : {model::Op::Load, model::Op::And, model::Op::Or, model::Op::Out,
                               model::Op::Set, model::Op::Reset, model::Op::Timer,
                               model::Op::Counter, model::Op::UpDownCounter, model::Op::Keep})
        EXPECT_TRUE(seen.count(op)) << static_cast<int>(op);
}
