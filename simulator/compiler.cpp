#include "compiler.h"

#include "family.h"

#include "model/address.h"

#include <QCoreApplication>

#include <algorithm>
#include <map>
#include <variant>

namespace rung::simulator {

using model::AreaKind;
using model::Op;

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(rung::simulator::Compiler)
};

// lupdate loses the scope of Tr::tr after some comparisons in inline member functions and
// files those texts under a context "Tr" that the program never asks for; the explicit
// context keeps them translatable.
QString trCompiler(const char *text) {
    return QCoreApplication::translate("rung::simulator::Compiler", text);
}

constexpr int kMaxBlockDepth = 63; // Engine keeps a 64-entry block stack
constexpr int kMaxPushDepth = 32;
constexpr int kMaxZoneElements = 65536;

class Compiler {
public:
    explicit Compiler(const model::InstructionList &list)
        : m_list(list)
        , m_target(*list.target)
        , m_sem(familySemantics(m_target.family)) {
        auto program = std::make_shared<Program>();
        program->layout = std::make_shared<MemoryLayout>(m_target);
        m_program = program;
        m_layout = program->layout.get();
    }

    CompileResult run();

private:
    void error(const model::Instruction &ins, const QString &message) {
        model::Diagnostic d;
        d.code = QStringLiteral("SIM001");
        d.severity = model::Severity::Error;
        d.location.line = ins.line;
        d.location.column = ins.column;
        d.message = message;
        m_diagnostics.push_back(std::move(d));
        m_failed = true;
    }
    void notSimulated(const model::Instruction &ins) {
        model::Diagnostic d;
        d.code = QStringLiteral("SIM100");
        d.severity = model::Severity::Warning;
        d.location.line = ins.line;
        d.location.column = ins.column;
        d.message = Tr::tr("%1 is not simulated: it does nothing in the simulator")
                        .arg(ins.spec ? ins.spec->mnemonic : QString());
        m_diagnostics.push_back(std::move(d));
    }
    QString describe(const model::Operand &o) const {
        if (o.kind == model::Operand::Kind::Device)
            return model::formatAddress(m_target, o.address);
        if (o.kind == model::Operand::Kind::Constant)
            return model::formatConstant(m_target, o.constant);
        return o.text;
    }

    const model::Operand *operand(const model::Instruction &ins, std::size_t i) {
        if (i < ins.operands.size())
            return &ins.operands[i];
        error(ins, trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 needs operand %2"))
                       .arg(ins.spec->mnemonic)
                       .arg(i + 1));
        return nullptr;
    }
    bool isDevice(const model::Operand &o) const {
        return o.kind == model::Operand::Kind::Device && o.address.valid() &&
               o.address.area < m_layout->areaCount();
    }
    AreaKind kindOf(const model::Operand &o) const { return m_layout->area(o.address.area).kind; }

    BitRef bitOf(const model::Instruction &ins, std::size_t i) {
        const model::Operand *o = operand(ins, i);
        if (!o)
            return {};
        BitRef r = isDevice(*o) ? m_layout->bit(o->address) : BitRef{};
        if (!r.valid())
            error(ins, Tr::tr("%1 is not a bit device").arg(describe(*o)));
        return r;
    }
    // A readable word: timers and counters give their current value.
    WordOperand sourceOf(const model::Instruction &ins, std::size_t i) {
        const model::Operand *o = operand(ins, i);
        WordOperand w;
        if (!o)
            return w;
        if (o->kind == model::Operand::Kind::Constant) {
            w.constant = static_cast<std::int32_t>(o->constant.value);
            if (o->constant.value != w.constant)
                error(ins, Tr::tr("constant %1 is out of range").arg(describe(*o)));
            return w;
        }
        w.index = isDevice(*o) ? m_layout->word(o->address) : -1;
        if (w.index < 0)
            error(ins, Tr::tr("%1 is not a word device or a constant").arg(describe(*o)));
        return w;
    }
    // A writable word; setValue: timers/counters mean their set value (VPC transfers).
    std::int32_t destOf(const model::Instruction &ins, std::size_t i, bool setValue,
                        std::uint8_t *width) {
        const model::Operand *o = operand(ins, i);
        if (!o)
            return -1;
        int index = -1;
        if (isDevice(*o)) {
            const bool tc = kindOf(*o) == AreaKind::Timer || kindOf(*o) == AreaKind::Counter;
            index =
                tc && setValue ? m_layout->setValueWord(o->address) : m_layout->word(o->address);
            if (index >= 0 && !m_target.area(o->address.area).writable && !tc)
                index = -2;
            *width = static_cast<std::uint8_t>(m_layout->wordBits(o->address));
        }
        if (index == -2)
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 cannot be written"))
                      .arg(describe(*o)));
        else if (index < 0)
            error(ins, trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler",
                                                    "%1 is not a word device"))
                           .arg(describe(*o)));
        return index;
    }
    // The word after a destination (MUL high word, DIV remainder).
    std::int32_t nextWord(const model::Instruction &ins, std::size_t i) {
        const model::Operand *o = operand(ins, i);
        if (!o || !isDevice(*o))
            return -1;
        model::Address a = o->address;
        ++a.index;
        const int w = m_layout->word(a);
        if (w < 0)
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler",
                                               "%1 needs the next word too, which does not exist"))
                      .arg(describe(*o)));
        return w;
    }
    ResetTarget resetTargetOf(const model::Address &a) {
        ResetTarget t;
        const AreaKind k = m_layout->area(a.area).kind;
        if (k == AreaKind::Timer || k == AreaKind::Counter) {
            t.bit = m_layout->bit(a);
            t.word = m_layout->word(a);
            t.state = m_layout->elementState(a);
        } else if (k == AreaKind::Bit || a.bit >= 0) {
            t.bit = m_layout->bit(a);
        } else {
            t.word = m_layout->word(a);
        }
        return t;
    }

    void outputDone() { m_rungStart = true; }
    void popBlocks(const model::Instruction &ins, int n) {
        if (m_depth < n) {
            error(ins,
                  Tr::tr("%1 needs %2 open blocks before it").arg(ins.spec->mnemonic).arg(n + 1));
            m_depth = 0;
            return;
        }
        m_depth -= n;
    }

    void compileContact(const model::Instruction &ins, Step &s);
    void compileTimer(const model::Instruction &ins, Step &s);
    void compileCounter(const model::Instruction &ins, Step &s);
    void compileApply(const model::Instruction &ins, Step &s);
    void compileSystem();
    void resolveJumps();

    const model::InstructionList &m_list;
    const model::Target &m_target;
    FamilySemantics m_sem;
    std::shared_ptr<Program> m_program;
    const MemoryLayout *m_layout = nullptr;
    std::vector<model::Diagnostic> m_diagnostics;
    bool m_failed = false;
    bool m_rungStart = true;
    int m_depth = 0;
    int m_push = 0;
    int m_stlArea = -1;
    BitRef m_stlBit;
};

void Compiler::compileContact(const model::Instruction &ins, Step &s) {
    const model::InstructionSpec &spec = *ins.spec;
    const int which = spec.op == Op::Load ? 0 : spec.op == Op::And ? 1 : 2;
    const bool negated = spec.negated || spec.mode == model::ContactMode::Negated;
    if (spec.op == Op::Load) {
        if (m_rungStart) {
            s.flags |= kRungStart;
            m_depth = 0;
            m_push = 0;
        } else if (++m_depth > kMaxBlockDepth) {
            error(ins, Tr::tr("more than %1 open blocks").arg(kMaxBlockDepth));
            m_depth = kMaxBlockDepth;
        }
    }
    m_rungStart = false;
    m_program->maxBlockDepth = std::max(m_program->maxBlockDepth, m_depth);
    if (negated)
        s.flags |= kNegated;
    if (spec.compare != model::CompareOp::None) {
        s.code = static_cast<Code>(static_cast<int>(Code::LoadCompare) + which);
        s.op = static_cast<std::uint8_t>(spec.compare);
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        return;
    }
    s.bit = bitOf(ins, 0);
    if (spec.mode == model::ContactMode::Rising || spec.mode == model::ContactMode::Falling) {
        s.code = static_cast<Code>(static_cast<int>(Code::LoadEdge) + which);
        if (spec.mode == model::ContactMode::Falling)
            s.flags |= kFalling;
        s.slot = m_program->edgeSlots++;
        return;
    }
    s.code = static_cast<Code>(static_cast<int>(Code::Load) + which);
}

// The timer/counter element and its set value: the first operand that names a timer/counter
// area, and the operand after it (VPC keeps set values in memory: no operand).
void Compiler::compileTimer(const model::Instruction &ins, Step &s) {
    s.code = Code::Timer;
    const model::Operand *t = operand(ins, 0);
    if (!t)
        return;
    if (!isDevice(*t) || kindOf(*t) != AreaKind::Timer) {
        error(ins, Tr::tr("%1 is not a timer").arg(describe(*t)));
        return;
    }
    s.bit = m_layout->bit(t->address);
    s.dest = m_layout->word(t->address);
    s.slot = m_layout->elementState(t->address);
    s.y.index = m_layout->setValueWord(t->address); // shows the set value in use
    if (ins.operands.size() > 1) {
        s.x = sourceOf(ins, 1);
        if (m_sem.bcdSetValues && s.x.index >= 0)
            s.flags |= kBcd;
    } else {
        s.x.index = s.y.index;
    }
    if (t->address.index < m_sem.downTimersBelow)
        s.flags |= kDown;
    double base = m_sem.timerBaseMs > 0 ? m_sem.timerBaseMs : m_target.defaultTimerBaseMs;
    if (m_sem.fastTimerFunctionCode >= 0 && ins.spec->functionCode == m_sem.fastTimerFunctionCode)
        base = m_sem.fastTimerBaseMs;
    if (m_target.family == model::Family::Pl110) {
        // TON / TOFF / TONR T PT [base]: the time base is the third operand (10, 100 or
        // 1000 ms, seed 003 4.2.4); the current value lives in the T word so that
        // MOV(Tx = #0) resets a TONR as the manual says.
        s.code = Code::PlTimer;
        s.op = static_cast<std::uint8_t>(
            ins.spec->timerMode == model::TimerMode::OffDelay       ? PlTimerMode::OffDelay
            : ins.spec->timerMode == model::TimerMode::Accumulating ? PlTimerMode::Accumulating
                                                                    : PlTimerMode::OnDelay);
        if (const model::Operand *b = ins.operands.size() > 2 ? &ins.operands[2] : nullptr) {
            const qint64 v = b->kind == model::Operand::Kind::Constant ? b->constant.value : -1;
            if (v != 10 && v != 100 && v != 1000) {
                error(ins, Tr::tr("the time base of %1 must be 10, 100 or 1000 ms, not %2")
                               .arg(ins.spec->mnemonic, describe(*b)));
                return;
            }
            base = static_cast<double>(v);
        }
    }
    s.count = std::max(1, static_cast<int>(base));
    outputDone();
}

void Compiler::compileCounter(const model::Instruction &ins, Step &s) {
    const bool upDown = ins.spec->op == Op::UpDownCounter;
    s.code = upDown ? Code::UpDownCounter : Code::Counter;
    if (upDown && m_target.family == model::Family::Pl110) {
        s.code = Code::PlCounter;
        if (ins.spec->counterMode == model::CounterMode::Down)
            s.flags |= kDown;
    }
    const model::Operand *c = operand(ins, 0);
    if (!c)
        return;
    if (!isDevice(*c) || kindOf(*c) != AreaKind::Counter) {
        error(ins, Tr::tr("%1 is not a counter").arg(describe(*c)));
        return;
    }
    s.bit = m_layout->bit(c->address);
    s.dest = m_layout->word(c->address);
    s.slot = m_layout->elementState(c->address);
    s.width = static_cast<std::uint8_t>(m_layout->wordBits(c->address));
    s.y.index = m_layout->setValueWord(c->address);
    if (ins.operands.size() > 1) {
        s.x = sourceOf(ins, 1);
        if (m_sem.bcdSetValues && s.x.index >= 0)
            s.flags |= kBcd;
    } else {
        s.x.index = s.y.index;
    }
    if (!upDown && c->address.index < m_sem.downCountersBelow)
        s.flags |= kDown;
    const int inputs = upDown ? 3 : std::max(1, ins.spec->inputs);
    if (inputs == 1)
        s.flags |= kOneInput;
    popBlocks(ins, inputs - 1);
    outputDone();
}

void Compiler::compileApply(const model::Instruction &ins, Step &s) {
    using model::ApplyFunction;
    switch (ins.spec->function) {
    case ApplyFunction::Mov:
        s.code = Code::Move;
        s.x = sourceOf(ins, 0);
        s.dest = destOf(ins, 1, false, &s.width);
        break;
    case ApplyFunction::Compare: {
        s.code = Code::Compare;
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        const model::Operand *d = operand(ins, 2);
        if (!d)
            break;
        s.slot = static_cast<int>(m_program->bitLists.size());
        s.count = 3;
        for (int k = 0; k < 3; ++k) {
            model::Address a = d->address;
            a.index += k;
            const BitRef r = isDevice(*d) ? m_layout->bit(a) : BitRef{};
            if (!r.valid()) {
                error(ins, Tr::tr("%1 needs three bit devices from %2")
                               .arg(ins.spec->mnemonic, describe(*d)));
                break;
            }
            m_program->bitLists.push_back(r);
        }
        break;
    }
    case ApplyFunction::ZoneReset: {
        s.code = Code::Reset;
        const model::Operand *a = operand(ins, 0);
        const model::Operand *b = operand(ins, 1);
        if (!a || !b)
            break;
        if (!isDevice(*a) || !isDevice(*b) || a->address.area != b->address.area ||
            b->address.index < a->address.index ||
            b->address.index - a->address.index >= kMaxZoneElements) {
            error(ins, Tr::tr("%1 needs two devices of one kind, the first not after the "
                              "second")
                           .arg(ins.spec->mnemonic));
            break;
        }
        s.slot = static_cast<int>(m_program->resets.size());
        for (model::Address x = a->address; x.index <= b->address.index; ++x.index)
            m_program->resets.push_back(resetTargetOf(x));
        s.count = static_cast<int>(m_program->resets.size()) - s.slot;
        break;
    }
    case ApplyFunction::Add:
    case ApplyFunction::Sub:
    case ApplyFunction::Mul:
    case ApplyFunction::Div:
        s.code = ins.spec->function == ApplyFunction::Add   ? Code::Add
                 : ins.spec->function == ApplyFunction::Sub ? Code::Sub
                 : ins.spec->function == ApplyFunction::Mul ? Code::Mul
                                                            : Code::Div;
        s.x = sourceOf(ins, 0);
        s.y = sourceOf(ins, 1);
        s.dest = destOf(ins, 2, false, &s.width);
        if (s.code == Code::Mul || s.code == Code::Div)
            s.slot = s.width >= 32 && s.code == Code::Mul ? -1 : nextWord(ins, 2);
        break;
    case ApplyFunction::Inc:
    case ApplyFunction::Dec:
        s.code = ins.spec->function == ApplyFunction::Inc ? Code::Inc : Code::Dec;
        s.dest = destOf(ins, 0, false, &s.width);
        break;
    case ApplyFunction::Math: {
        // FM S1 OP S2 D (the operator is kept as text by the parser)
        s.code = Code::Math;
        s.x = sourceOf(ins, 0);
        const model::Operand *op = operand(ins, 1);
        s.y = sourceOf(ins, 2);
        s.dest = destOf(ins, 3, false, &s.width);
        static const std::pair<const char *, MathOp> ops[] = {
            {"+", MathOp::Add}, {"-", MathOp::Sub},  {"*", MathOp::Mul},
            {"/", MathOp::Div}, {"|", MathOp::Or},   {"&", MathOp::And},
            {"^", MathOp::Xor}, {"<<", MathOp::Shl}, {">>", MathOp::Shr}};
        bool found = false;
        for (const auto &[text, value] : ops)
            if (op && op->text.trimmed() == QLatin1String(text)) {
                s.op = static_cast<std::uint8_t>(value);
                found = true;
            }
        if (op && !found)
            error(ins, Tr::tr("unknown operator %1 (use + - * / | & ^ << >>)").arg(op->text));
        break;
    }
    case ApplyFunction::SetBit:
    case ApplyFunction::ResetBit: {
        // SBIT / RBIT: a bit address, or a word and the bit number 0..15
        BitRef r;
        const model::Operand *o = operand(ins, 0);
        if (o && isDevice(*o) && ins.operands.size() > 1 &&
            ins.operands[1].kind == model::Operand::Kind::Constant) {
            model::Address a = o->address;
            a.bit = static_cast<int>(ins.operands[1].constant.value);
            r = a.bit >= 0 && a.bit < 16 ? m_layout->bit(a) : BitRef{};
        } else if (o && isDevice(*o)) {
            r = m_layout->bit(o->address);
        }
        if (o && !r.valid()) {
            error(ins, Tr::tr("%1 needs a bit: a bit device, or a word and a bit number 0..15")
                           .arg(ins.spec->mnemonic));
            break;
        }
        if (ins.spec->function == ApplyFunction::SetBit) {
            s.code = Code::Set;
            s.bit = r;
        } else {
            s.code = Code::Reset;
            s.slot = static_cast<int>(m_program->resets.size());
            s.count = 1;
            ResetTarget t;
            t.bit = r;
            m_program->resets.push_back(t);
        }
        break;
    }
    case ApplyFunction::BlockMove: {
        // BLKMOV S D n: n words from S (or the constant S n times) to D
        s.code = Code::BlockMove;
        s.x = sourceOf(ins, 0);
        s.dest = destOf(ins, 1, false, &s.width);
        const model::Operand *n = operand(ins, 2);
        if (!n || m_failed)
            break;
        if (n->kind != model::Operand::Kind::Constant || n->constant.value < 1 ||
            n->constant.value > kMaxZoneElements) {
            error(ins, Tr::tr("%1 needs a count from 1 to %2")
                           .arg(ins.spec->mnemonic)
                           .arg(kMaxZoneElements));
            break;
        }
        s.count = static_cast<int>(n->constant.value);
        // Both blocks must lie inside their areas.
        auto fits = [&](const model::Operand &o) {
            model::Address last = o.address;
            last.index += s.count - 1;
            return m_layout->word(last) == m_layout->word(o.address) + s.count - 1 &&
                   m_layout->word(last) >= 0;
        };
        if (!fits(ins.operands[1]) || (s.x.index >= 0 && !fits(ins.operands[0])))
            error(ins, Tr::tr("the block of %1 words runs past the end of its area").arg(s.count));
        break;
    }
    case ApplyFunction::IndirectMove: {
        // MOVIND S D INDEX: the area from D on is a vector; element INDEX (0-based) := S.
        s.code = Code::IndirectMove;
        s.x = sourceOf(ins, 0);
        s.dest = destOf(ins, 1, false, &s.width);
        s.y = sourceOf(ins, 2);
        if (m_failed)
            break;
        // How many words the vector has: from D to the end of D's area (a bit area read
        // as words has one word per 16 bits).
        const model::Address base = ins.operands[1].address;
        const model::Area &area = m_target.area(base.area);
        const int span = area.last - base.index;
        s.count = 1 + (area.kind == AreaKind::Bit ? span / 16 : span);
        break;
    }
    default:
        notSimulated(ins);
        s.code = Code::Nop;
        break;
    }
    outputDone();
}

void Compiler::compileSystem() {
    for (const model::SystemDevice &d : m_target.systemDevices) {
        const auto parsed = model::parseAddress(m_target, d.device);
        if (!std::holds_alternative<model::Address>(parsed))
            continue;
        const model::Address a = std::get<model::Address>(parsed);
        SystemBinding b;
        b.role = d.role;
        switch (d.role) {
        case model::SystemRole::ScanTimeCurrent:
        case model::SystemRole::ScanTimeMin:
        case model::SystemRole::ScanTimeMax:
            b.word = m_layout->word(a);
            if (b.word >= 0)
                m_program->system.push_back(b);
            break;
        case model::SystemRole::Other:
        case model::SystemRole::Error:
        case model::SystemRole::Connected:
            break;
        default:
            b.bit = m_layout->bit(a);
            if (b.bit.valid())
                m_program->system.push_back(b);
            break;
        }
    }
    auto addr = [&](const char *text) -> model::Address {
        if (!text)
            return {};
        const auto parsed = model::parseAddress(m_target, QString::fromLatin1(text));
        return std::holds_alternative<model::Address>(parsed) ? std::get<model::Address>(parsed)
                                                              : model::Address{};
    };
    auto bits = [&](const char *first, std::vector<BitRef> &into) {
        model::Address a = addr(first);
        for (int k = 0; a.valid() && k < m_sem.parallelBits; ++k, ++a.index) {
            const BitRef r = m_layout->bit(a);
            if (!r.valid())
                return;
            into.push_back(r);
        }
    };
    if (const model::Address o = addr(m_sem.parallelOut); o.valid()) {
        m_program->parallelOutWord = m_layout->word(o);
        bits(m_sem.parallelOutFirstBit, m_program->parallelOutBits);
    }
    if (const model::Address i = addr(m_sem.parallelIn); i.valid()) {
        m_program->parallelInWord = m_layout->word(i);
        bits(m_sem.parallelInFirstBit, m_program->parallelInBits);
    }
    for (int k = 0; k < m_layout->areaCount(); ++k) {
        const AreaLayout &l = m_layout->area(k);
        const model::Area &area = m_target.area(k);
        if (l.bitBase >= 0)
            m_program->bitWordRanges.push_back({l.bitBase, l.bitBase + (l.count + 15) / 16});
        if (area.physical && !area.writable) {
            if (l.kind == AreaKind::Bit)
                m_program->inputWordRanges.push_back({l.bitBase, l.bitBase + (l.count + 15) / 16});
            else if (l.wordBase >= 0)
                m_program->inputWordRanges.push_back({l.wordBase, l.wordBase + l.count});
        }
    }
}

// Jumps go to their JPE/JME: VPC pairs JMP..JPE by nesting, CPM1 by label number.
void Compiler::resolveJumps() {
    std::map<QString, int> labels;
    const auto &ins = m_list.instructions;
    auto labelOf = [&](const model::Instruction &i) -> QString {
        if (i.operands.empty())
            return {};
        const model::Operand &o = i.operands.front();
        return o.kind == model::Operand::Kind::Constant ? QString::number(o.constant.value)
                                                        : o.text;
    };
    for (std::size_t k = 0; k < ins.size(); ++k)
        if (ins[k].op() == Op::JumpEnd && !ins[k].operands.empty()) {
            const QString l = labelOf(ins[k]);
            if (labels.contains(l))
                error(ins[k], Tr::tr("label %1 ends more than one jump").arg(l));
            labels[l] = static_cast<int>(k);
        }
    std::vector<int> open;
    for (std::size_t k = 0; k < ins.size(); ++k) {
        Step &s = m_program->steps[k];
        if (ins[k].op() == Op::Jump) {
            if (ins[k].operands.empty()) {
                open.push_back(static_cast<int>(k));
            } else {
                const auto it = labels.find(labelOf(ins[k]));
                if (it == labels.end() || it->second < static_cast<int>(k))
                    error(ins[k], Tr::tr("jump %1 has no end after it").arg(labelOf(ins[k])));
                else
                    s.slot = it->second;
            }
        } else if (ins[k].op() == Op::JumpEnd && ins[k].operands.empty()) {
            if (open.empty()) {
                error(ins[k], Tr::tr("%1 without a jump before it").arg(ins[k].spec->mnemonic));
                continue;
            }
            m_program->steps[static_cast<std::size_t>(open.back())].slot = static_cast<int>(k);
            open.pop_back();
        }
    }
    for (int k : open)
        error(ins[static_cast<std::size_t>(k)],
              Tr::tr("%1 has no end").arg(ins[static_cast<std::size_t>(k)].spec->mnemonic));
}

CompileResult Compiler::run() {
    const FamilySemantics &sem = m_sem;
    m_program->deferredBitWrites = sem.deferredBitWrites;
    m_program->steps.resize(m_list.instructions.size());
    m_program->lines.resize(m_list.instructions.size());
    compileSystem();
    const int pushLimit = std::min(kMaxPushDepth, std::max(1, m_target.limits.stackDepth));
    for (std::size_t k = 0; k < m_list.instructions.size(); ++k) {
        const model::Instruction &ins = m_list.instructions[k];
        Step &s = m_program->steps[k];
        m_program->lines[k] = ins.line;
        if (!ins.spec) {
            error(ins, Tr::tr("unknown instruction"));
            continue;
        }
        const model::InstructionSpec &spec = *ins.spec;
        switch (spec.op) {
        case Op::Load:
        case Op::And:
        case Op::Or:
            compileContact(ins, s);
            break;
        case Op::AndBlock:
        case Op::OrBlock:
            s.code = spec.op == Op::AndBlock ? Code::AndBlock : Code::OrBlock;
            popBlocks(ins, 1);
            m_rungStart = false;
            break;
        case Op::Push:
            s.code = Code::Push;
            m_rungStart = false; // "MPS LD X1 ANB": the load opens a block on the branch
            if (++m_push > pushLimit) {
                error(ins, Tr::tr("more than %1 nested %2").arg(pushLimit).arg(spec.mnemonic));
                m_push = pushLimit;
            }
            m_program->maxPushDepth = std::max(m_program->maxPushDepth, m_push);
            break;
        case Op::ReadStack:
        case Op::Pop:
            s.code = spec.op == Op::ReadStack ? Code::ReadStack : Code::Pop;
            m_rungStart = false; // "MPP LD X1 ANB" continues the branch
            if (m_push == 0)
                error(ins, Tr::tr("%1 without MPS before it").arg(spec.mnemonic));
            else if (spec.op == Op::Pop)
                --m_push;
            break;
        case Op::Invert:
            s.code = Code::Invert;
            break;
        case Op::Out:
            s.code = Code::Out;
            s.bit = bitOf(ins, 0);
            if (spec.negated)
                s.flags |= kNegated;
            outputDone();
            break;
        case Op::Set:
            s.code = Code::Set;
            s.bit = bitOf(ins, 0);
            if (m_stlArea >= 0 && !ins.operands.empty() &&
                ins.operands[0].address.area == m_stlArea) {
                s.code = Code::SetStep;
                s.slot = static_cast<int>(m_program->bitLists.size());
                m_program->bitLists.push_back(m_stlBit);
            }
            outputDone();
            break;
        case Op::Reset: {
            s.code = Code::Reset;
            const model::Operand *o = operand(ins, 0);
            if (o && isDevice(*o)) {
                const ResetTarget t = resetTargetOf(o->address);
                if (!t.bit.valid() && t.word < 0)
                    error(ins, Tr::tr("%1 cannot be reset").arg(describe(*o)));
                s.slot = static_cast<int>(m_program->resets.size());
                s.count = 1;
                m_program->resets.push_back(t);
            } else if (o) {
                error(ins, Tr::tr("%1 is not a device").arg(describe(*o)));
            }
            outputDone();
            break;
        }
        case Op::PulseRise:
        case Op::PulseFall:
            s.code = Code::Pulse;
            s.bit = bitOf(ins, 0);
            if (spec.op == Op::PulseFall)
                s.flags |= kFalling;
            s.slot = m_program->edgeSlots++;
            outputDone();
            break;
        case Op::Keep:
            s.code = Code::Keep;
            s.bit = bitOf(ins, 0);
            popBlocks(ins, 1);
            outputDone();
            break;
        case Op::Timer:
            compileTimer(ins, s);
            break;
        case Op::Counter:
        case Op::UpDownCounter:
            compileCounter(ins, s);
            break;
        case Op::Transfer:
            s.code = Code::Transfer;
            s.op = static_cast<std::uint8_t>(
                spec.transfer == model::TransferOp::Add        ? TransferKind::Add
                : spec.transfer == model::TransferOp::Subtract ? TransferKind::Subtract
                                                               : TransferKind::Assign);
            if (spec.negated)
                s.flags |= kNegated;
            s.dest = destOf(ins, 0, true, &s.width);
            s.x = sourceOf(ins, 1);
            if (s.dest == m_program->parallelOutWord && s.dest >= 0)
                m_program->writesParallelOut = true;
            outputDone();
            break;
        case Op::Apply:
            compileApply(ins, s);
            if (s.dest == m_program->parallelOutWord && s.dest >= 0)
                m_program->writesParallelOut = true;
            break;
        case Op::Interlock:
            s.code = Code::Interlock;
            outputDone();
            break;
        case Op::InterlockClear:
            s.code = Code::InterlockClear;
            outputDone();
            break;
        case Op::Jump:
            s.code = Code::Jump;
            outputDone();
            break;
        case Op::JumpEnd:
            s.code = Code::JumpEnd;
            outputDone();
            break;
        case Op::StepLadder: {
            s.code = Code::StepLadder;
            s.bit = bitOf(ins, 0);
            m_stlBit = s.bit;
            m_stlArea = ins.operands.empty() ? -1 : ins.operands[0].address.area;
            outputDone();
            break;
        }
        case Op::Return:
            s.code = Code::Return;
            m_stlArea = -1;
            outputDone();
            break;
        case Op::End:
            s.code = Code::End;
            outputDone();
            break;
        case Op::Nop:
            s.code = Code::Nop;
            break;
        }
    }
    resolveJumps();
    CompileResult result;
    result.diagnostics = std::move(m_diagnostics);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const model::Diagnostic &a, const model::Diagnostic &b) {
                         return a.location.line < b.location.line;
                     });
    if (!m_failed)
        result.program = m_program;
    return result;
}

} // namespace

CompileResult compileProgram(const model::InstructionList &list) {
    if (!list.target) {
        CompileResult r;
        model::Diagnostic d;
        d.code = QStringLiteral("SIM001");
        d.message = Tr::tr("the program has no target");
        r.diagnostics.push_back(d);
        return r;
    }
    return Compiler(list).run();
}

CompileResult prepareProgram(const model::InstructionList &list,
                             const model::CheckOptions &options) {
    std::vector<model::Diagnostic> errors;
    for (model::Diagnostic &d : model::checkList(list, options))
        if (d.severity == model::Severity::Error)
            errors.push_back(std::move(d));
    if (errors.empty())
        return compileProgram(list);
    CompileResult result;
    result.diagnostics = std::move(errors);
    return result;
}

} // namespace rung::simulator
