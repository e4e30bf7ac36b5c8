// Whatever instruction sequence compiles must scan without crashing or reading out of
// bounds (run under ASan+UBSan); whatever does not compile must say where.

#include "sim_test_target.h"

#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <gtest/gtest.h>

#include <random>

using namespace rung;
using namespace rung::simulator;

namespace {

QString randomOperand(std::mt19937 &rng, const model::InstructionSpec &spec) {
    static const char *bits[] = {"X0", "X1", "Y0", "M3", "S1", "T0", "C1", "SM9000"};
    static const char *words[] = {"D0", "D1", "D99", "K0", "K3", "K-2", "T1", "C0"};
    auto pick = [&](const auto &table) {
        return QString::fromLatin1(table[rng() % std::size(table)]);
    };
    switch (spec.op) {
    case model::Op::Timer:
        return QStringLiteral("T%1 K%2").arg(rng() % 4).arg(rng() % 4);
    case model::Op::Counter:
    case model::Op::UpDownCounter:
        return QStringLiteral("C%1 K%2").arg(rng() % 4).arg(rng() % 4);
    case model::Op::Jump:
    case model::Op::JumpEnd:
        return QStringLiteral("K%1").arg(rng() % 2);
    case model::Op::Apply:
    case model::Op::Transfer:
        if (spec.function == model::ApplyFunction::Math)
            return pick(words) + QStringLiteral(" / ") + pick(words) + QStringLiteral(" D5");
        return pick(words) + QLatin1Char(' ') + pick(words) + QStringLiteral(" D7");
    default:
        if (spec.compare != model::CompareOp::None)
            return pick(words) + QLatin1Char(' ') + pick(words);
        return pick(bits);
    }
}

} // namespace

TEST(Robustness, RandomInstructionSequencesCompileCleanlyOrReportALine) {
    auto target = test::makeTestTarget();
    std::mt19937 rng(20261122);
    int started = 0;
    for (int program = 0; program < 400; ++program) {
        QString text;
        const int length = 1 + static_cast<int>(rng() % 40);
        for (int k = 0; k < length; ++k) {
            const auto &spec = target->instructions[rng() % target->instructions.size()];
            text += spec.mnemonic;
            if (spec.op != model::Op::AndBlock && spec.op != model::Op::OrBlock &&
                spec.op != model::Op::Push && spec.op != model::Op::ReadStack &&
                spec.op != model::Op::Pop && spec.op != model::Op::Invert &&
                spec.op != model::Op::Interlock && spec.op != model::Op::InterlockClear &&
                spec.op != model::Op::Return && spec.op != model::Op::End)
                text += QLatin1Char(' ') + randomOperand(rng, spec);
            text += QLatin1Char('\n');
        }
        model::InstructionList list;
        try {
            list = test::assemble(*target, text);
        } catch (const std::invalid_argument &) {
            continue; // an operand the synthetic target does not have
        }
        const CompileResult result = compileProgram(list);
        if (!result.ok()) {
            for (const model::Diagnostic &d : result.diagnostics) {
                if (d.severity == model::Severity::Error) {
                    EXPECT_GT(d.location.line, 0) << text.toStdString();
                }
            }
            continue;
        }
        ++started;
        Engine engine(result.program);
        engine.setPowerFlowRecording(true);
        for (int scan = 0; scan < 30; ++scan) {
            engine.setBit(test::operandOf(*target, QStringLiteral("X0")).address, scan % 3 == 0);
            engine.scan();
        }
        EXPECT_EQ(engine.statistics().scans, 30u);
    }
    EXPECT_GT(started, 20); // the generator reaches programs that run
}
