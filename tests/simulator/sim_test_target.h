#pragma once

// A small synthetic target for engine tests that do not depend on the real device tables:
// Vigor-like areas (decimal numbering) and instruction specs, plus a minimal assembler that
// turns "MNEMONIC OPERAND..." lines into an InstructionList against it.

#include "model/listing/il.h"
#include "simulator/compiler.h"
#include "simulator/engine.h"

#include <QStringList>

#include <memory>
#include <stdexcept>

namespace rung::simulator::test {

inline model::Area area(const char *key, model::AreaKind kind, int first, int last,
                        bool writable = true, bool physical = false, bool retentive = false) {
    model::Area a;
    a.key = QString::fromLatin1(key);
    a.prefix = a.key;
    a.kind = kind;
    a.first = first;
    a.last = last;
    a.writable = writable;
    a.physical = physical;
    a.retentive = retentive;
    return a;
}

inline model::InstructionSpec spec(const char *mnemonic, model::Op op,
                                   model::ContactMode mode = model::ContactMode::Normal,
                                   int inputs = 1) {
    model::InstructionSpec s;
    s.mnemonic = QString::fromLatin1(mnemonic);
    s.op = op;
    s.mode = mode;
    s.inputs = inputs;
    return s;
}

inline std::unique_ptr<model::Target> makeTestTarget(model::Family family = model::Family::Vigor) {
    using model::AreaKind;
    using model::ContactMode;
    using model::Op;
    auto t = std::make_unique<model::Target>();
    // The family's execution facts and constant rules, on the synthetic areas.
    const model::Target &real = model::Target::get(family);
    t->family = family;
    t->id = QStringLiteral("test");
    t->defaultTimerBaseMs = real.defaultTimerBaseMs;
    t->constants = real.constants;
    t->semantics = real.semantics;
    t->limits.timerMax = real.limits.timerMax;
    t->limits.counterMin = real.limits.counterMin;
    t->limits.counterMax = real.limits.counterMax;
    t->limits.scanTimeMax = real.limits.scanTimeMax;
    t->limits.stackDepth = 8;
    t->areas = {area("X", AreaKind::Bit, 0, 31, false, true),
                area("Y", AreaKind::Bit, 0, 31, true, true),
                area("M", AreaKind::Bit, 0, 499),
                area("L", AreaKind::Bit, 500, 599, true, false, true), // retentive M range
                area("SM", AreaKind::Bit, 9000, 9015, false),
                area("S", AreaKind::Bit, 0, 99),
                area("T", AreaKind::Timer, 0, 31),
                area("C", AreaKind::Counter, 0, 31, true, false, true),
                area("D", AreaKind::Word, 0, 99),
                area("R", AreaKind::Word, 100, 199, true, false, true)};
    t->systemDevices = {{QStringLiteral("SM9000"), model::SystemRole::AlwaysOn, nullptr},
                        {QStringLiteral("SM9002"), model::SystemRole::FirstScan, nullptr},
                        {QStringLiteral("SM9010"), model::SystemRole::ScanToggle, nullptr},
                        {QStringLiteral("SM9013"), model::SystemRole::Clock1s, nullptr}};
    auto &in = t->instructions;
    in.push_back(spec("LD", Op::Load));
    in.push_back(spec("LDI", Op::Load, ContactMode::Negated));
    in.push_back(spec("LDP", Op::Load, ContactMode::Rising));
    in.push_back(spec("LDF", Op::Load, ContactMode::Falling));
    in.push_back(spec("AND", Op::And));
    in.push_back(spec("ANI", Op::And, ContactMode::Negated));
    in.push_back(spec("ANDP", Op::And, ContactMode::Rising));
    in.push_back(spec("OR", Op::Or));
    in.push_back(spec("ORI", Op::Or, ContactMode::Negated));
    in.push_back(spec("ANB", Op::AndBlock));
    in.push_back(spec("ORB", Op::OrBlock));
    in.push_back(spec("MPS", Op::Push));
    in.push_back(spec("MRD", Op::ReadStack));
    in.push_back(spec("MPP", Op::Pop));
    in.push_back(spec("INV", Op::Invert));
    in.push_back(spec("OUT", Op::Out));
    auto outNot = spec("OUTN", Op::Out);
    outNot.negated = true;
    in.push_back(outNot);
    in.push_back(spec("SET", Op::Set));
    in.push_back(spec("RST", Op::Reset));
    in.push_back(spec("PLS", Op::PulseRise));
    in.push_back(spec("PLF", Op::PulseFall));
    in.push_back(spec("KEEP", Op::Keep, ContactMode::Normal, 2));
    in.push_back(spec("TMR", Op::Timer));
    in.push_back(spec("CNT", Op::Counter));
    in.push_back(spec("CNT2", Op::Counter, ContactMode::Normal, 2));
    in.push_back(spec("CNTR", Op::UpDownCounter, ContactMode::Normal, 3));
    for (auto [name, f] : {std::pair{"MOV", model::ApplyFunction::Mov},
                           {"CMP", model::ApplyFunction::Compare},
                           {"ZRST", model::ApplyFunction::ZoneReset},
                           {"ADD", model::ApplyFunction::Add},
                           {"SUB", model::ApplyFunction::Sub},
                           {"MUL", model::ApplyFunction::Mul},
                           {"DIV", model::ApplyFunction::Div},
                           {"INC", model::ApplyFunction::Inc},
                           {"DEC", model::ApplyFunction::Dec},
                           {"FM", model::ApplyFunction::Math},
                           {"SBIT", model::ApplyFunction::SetBit},
                           {"RBIT", model::ApplyFunction::ResetBit},
                           {"BLKMOV", model::ApplyFunction::BlockMove},
                           {"PID", model::ApplyFunction::NotSimulated}}) {
        auto s = spec(name, Op::Apply);
        s.function = f;
        in.push_back(s);
    }
    for (auto [name, c] : {std::pair{"LD=", model::CompareOp::Eq},
                           {"LD>", model::CompareOp::Gt},
                           {"LD<", model::CompareOp::Lt}}) {
        auto s = spec(name, Op::Load);
        s.compare = c;
        in.push_back(s);
    }
    auto transfer = spec("XFER", Op::Transfer);
    transfer.transfer = model::TransferOp::Add;
    in.push_back(transfer);
    in.push_back(spec("IL", Op::Interlock));
    in.push_back(spec("ILC", Op::InterlockClear));
    in.push_back(spec("JMP", Op::Jump));
    in.push_back(spec("JME", Op::JumpEnd));
    in.push_back(spec("STL", Op::StepLadder));
    in.push_back(spec("RET", Op::Return));
    in.push_back(spec("END", Op::End));
    return t;
}

// "X3" -> the area whose prefix matches and whose range holds 3; "K10" -> constant 10.
inline model::Operand operandOf(const model::Target &t, const QString &text) {
    model::Operand o;
    if (!text.isEmpty() && !text[0].isLetterOrNumber()) { // FM operator
        o.kind = model::Operand::Kind::Text;
        o.text = text;
        return o;
    }
    if (text.startsWith(QLatin1Char('K'))) {
        o.kind = model::Operand::Kind::Constant;
        o.constant.value = text.mid(1).toLongLong();
        o.constant.style = model::Constant::Style::Decimal;
        return o;
    }
    qsizetype digits = 0;
    while (digits < text.size() && !text[digits].isDigit())
        ++digits;
    const QString prefix = text.left(digits);
    const int number = text.mid(digits).toInt();
    for (std::size_t k = 0; k < t.areas.size(); ++k) {
        const model::Area &a = t.areas[k];
        if (a.prefix == prefix && number >= a.first && number <= a.last) {
            o.address = {static_cast<int>(k), number, -1};
            return o;
        }
    }
    throw std::invalid_argument(text.toStdString());
}

inline model::InstructionList assemble(const model::Target &t, const QString &text) {
    model::InstructionList list;
    list.target = &t;
    int line = 0;
    for (const QString &raw : text.split(QLatin1Char('\n'))) {
        ++line;
        const QStringList parts = raw.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        if (parts.isEmpty())
            continue;
        model::Instruction ins;
        ins.spec = t.findInstruction(parts[0]);
        if (!ins.spec)
            throw std::invalid_argument(parts[0].toStdString());
        ins.line = line;
        ins.column = 1;
        for (qsizetype k = 1; k < parts.size(); ++k)
            ins.operands.push_back(operandOf(t, parts[k]));
        ins.step = static_cast<int>(list.instructions.size());
        list.instructions.push_back(ins);
    }
    return list;
}

// A program of the synthetic target, compiled and ready to scan: the fixture of the engine
// tests and of the table-semantics tests (which change the target before compile()).
struct TableSim {
    explicit TableSim(std::unique_ptr<model::Target> t)
        : target(std::move(t)) {}
    explicit TableSim(const char *program, model::Family family = model::Family::Vigor)
        : TableSim(makeTestTarget(family)) {
        compile(program);
    }
    bool compile(const char *program) {
        list = assemble(*target, QString::fromLatin1(program));
        result = compileProgram(list);
        engine = result.ok() ? std::make_unique<Engine>(result.program) : nullptr;
        return result.ok();
    }
    model::Address at(const char *name) const {
        return operandOf(*target, QString::fromLatin1(name)).address;
    }
    void in(const char *name, bool on) { engine->setBit(at(name), on); }
    bool bit(const char *name) const { return engine->bit(at(name)); }
    int value(const char *name) const { return engine->value(at(name)); }
    void scan(quint64 n = 1) { engine->runScans(n); }

    std::unique_ptr<model::Target> target;
    model::InstructionList list;
    CompileResult result;
    std::unique_ptr<Engine> engine;
};

// The engine's memory image as a vector, for comparing two engines with EXPECT_EQ.
inline std::vector<std::int32_t> image(const Engine &engine) {
    const auto words = engine.words();
    return {words.begin(), words.end()};
}

} // namespace rung::simulator::test
