#include "compiler_detail.h"
#include "simulator/tr.h"

#include <algorithm>

namespace rung::simulator::detail {

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
            error(ins, CompilerTr::tr("more than %1 open blocks").arg(model::kMaxOpenBlocks));
            m_depth = kMaxBlockDepth;
        }
    }
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
        edgeStep(s, static_cast<Code>(static_cast<int>(Code::LoadEdge) + which),
                 spec.mode == model::ContactMode::Falling);
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
        error(ins, CompilerTr::tr("%1 is not a timer").arg(describe(*t)));
        return;
    }
    s.bit = m_layout->bit(t->address);
    s.dest = m_layout->word(t->address);
    s.slot = m_layout->elementState(t->address);
    s.y.index = m_layout->setValueWord(t->address); // shows the set value in use
    if (ins.operands.size() > 1) {
        s.x = sourceOf(ins, 1);
        if (m_target.constants.bcdSetValues) // a channel or a # constant: BCD digits either way
            s.flags |= kBcd;
    } else {
        s.x.index = s.y.index;
    }
    loadPresetFromMemory(t->address, s);
    if (model::timerCountsDown(m_target, t->address))
        s.flags |= kDown;
    // The time base: the instruction's own (CPM1 TIMH), a PL110 timer's third operand, the
    // timer area's (Vigor T200.. 10 ms), else the target's.
    const double base = model::timerBaseMs(m_target, ins);
    if (m_target.area(t->address.area).timerMode == model::TimerMode::Accumulating)
        s.op = kTimerAccumulates; // Vigor T246..T255: the time stays while the coil is OFF
    if (m_sem.timerCountsInWord) {
        // PL110 TON / TOFF / TONR T PT [base]: the time base is the third operand (10, 100 or
        // 1000 ms, PL110 manual 4.2.4); the current value lives in the T word so that
        // MOV(Tx = #0) resets a TONR as the manual says.
        s.code = Code::PlTimer;
        s.op = static_cast<std::uint8_t>(
            ins.spec->timerMode == model::TimerMode::OffDelay       ? PlTimerMode::OffDelay
            : ins.spec->timerMode == model::TimerMode::Accumulating ? PlTimerMode::Accumulating
                                                                    : PlTimerMode::OnDelay);
    }
    s.count = std::max(1, static_cast<int>(base));
}

void Compiler::compileCounter(const model::Instruction &ins, Step &s) {
    const bool upDown = ins.spec->op == Op::UpDownCounter;
    s.code = upDown ? Code::UpDownCounter : Code::Counter;
    if (upDown && m_sem.upDownCountersSaturate) {
        s.code = Code::PlCounter;
        if (ins.spec->counterMode == model::CounterMode::Down)
            s.flags |= kDown;
    }
    const model::Operand *c = operand(ins, 0);
    if (!c)
        return;
    if (!isDevice(*c) || kindOf(*c) != AreaKind::Counter) {
        error(ins, CompilerTr::tr("%1 is not a counter").arg(describe(*c)));
        return;
    }
    s.bit = m_layout->bit(c->address);
    s.dest = m_layout->word(c->address);
    s.slot = m_layout->elementState(c->address);
    s.width = static_cast<std::uint8_t>(m_layout->wordBits(c->address));
    s.y.index = m_layout->setValueWord(c->address);
    if (ins.operands.size() > 1) {
        s.x = sourceOf(ins, 1);
        if (m_target.constants.bcdSetValues) // a channel or a # constant: BCD digits either way
            s.flags |= kBcd;
    } else {
        s.x.index = s.y.index;
    }
    loadPresetFromMemory(c->address, s);
    if (s.code == Code::PlCounter)
        m_program->endOfScanCounters.push_back(
            static_cast<std::int32_t>(&s - m_program->steps.data()));
    if (!upDown && c->address.index < m_sem.downCountersBelow)
        s.flags |= kDown;
    const int inputs = upDown ? 3 : std::max(1, ins.spec->inputs);
    if (inputs == 1)
        s.flags |= kOneInput;
    popBlocks(ins, inputs - 1);
}

// D = S1 op S2 (two sources), or D = op S (one source; D = S when it is the only operand).
void Compiler::compileWordLogic(const model::Instruction &ins, Step &s, std::size_t sources) {
    using model::ApplyFunction;
    s.code = Code::WordLogic;
    const ApplyFunction f = ins.spec->function;
    s.op = static_cast<std::uint8_t>(f == ApplyFunction::AndWord   ? WordOp::And
                                     : f == ApplyFunction::OrWord  ? WordOp::Or
                                     : f == ApplyFunction::XorWord ? WordOp::Xor
                                     : f == ApplyFunction::ToBcd   ? WordOp::ToBcd
                                     : f == ApplyFunction::FromBcd ? WordOp::FromBcd
                                                                   : WordOp::Not);
    s.x = sourceOf(ins, 0);
    if (sources == 2)
        s.y = sourceOf(ins, 1);
    const std::size_t d = ins.operands.size() == 1 && sources == 1 ? 0 : sources;
    s.dest = destOf(ins, d, false, &s.width);
}

void Compiler::compileApply(const model::Instruction &ins, Step &s) {
    using model::ApplyFunction;
    switch (ins.spec->function) {
    case ApplyFunction::Mov:
        if (ins.spec->doubleWord) {
            compileDoubleMove(ins, s); // compile_words.cpp
            break;
        }
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
        // Its three results are written: not on the inputs (Vigor M/VB/VH communication
        // manual: Y, M, S).
        if (isDevice(*d) && !m_target.area(d->address.area).writable) {
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 cannot be written"))
                      .arg(describe(*d)));
            break;
        }
        s.slot = static_cast<int>(m_program->bitLists.size());
        s.count = 3;
        // D, D+1, D+2 as the table's rule (OperandSpec::words, model::runBreaks) counts them:
        // M499 is followed by M500 of the latched area.
        for (int k = 0; k < 3; ++k) {
            const BitRef r = isDevice(*d)
                                 ? m_layout->bit(model::offsetAddress(m_target, d->address, k))
                                 : BitRef{};
            if (!r.valid()) {
                error(ins, CompilerTr::tr("%1 is not a bit device").arg(describe(*d)));
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
        // One kind, the first not after the last, every device between: the table's rule
        // (OperandSpec::rangeFrom), which reportBreaches has said when it is broken.
        if (m_muted || !isDevice(*a) || !isDevice(*b) ||
            b->address.index - a->address.index >= kMaxZoneElements) {
            error(ins, CompilerTr::tr("%1 is not a device").arg(describe(*b)));
            break;
        }
        // ZRST clears what the program writes: not the inputs (Vigor M/VB/VH communication
        // manual: Y, M, S, T, C, D).
        const model::Operand *readOnly = nullptr;
        for (const model::Operand *end : {a, b})
            if (!readOnly && !m_target.area(end->address.area).writable)
                readOnly = end;
        if (readOnly) {
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 cannot be written"))
                      .arg(describe(*readOnly)));
            break;
        }
        s.slot = static_cast<int>(m_program->resets.size());
        for (int k = 0; k <= b->address.index - a->address.index; ++k) {
            const model::Address x = model::offsetAddress(m_target, a->address, k);
            if (!x.valid())
                break;
            m_program->resets.push_back(resetTargetOf(x));
        }
        s.count = static_cast<int>(m_program->resets.size()) - s.slot;
        break;
    }
    case ApplyFunction::Add:
    case ApplyFunction::Sub:
    case ApplyFunction::Mul:
    case ApplyFunction::Div:
        if (ins.spec->doubleWord) {
            compileDoubleDivide(ins, s); // compile_comm.cpp
            break;
        }
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
        // The operators the table allows (OperandSpec::allowedTexts, which reportBreaches
        // reads) all have a MathOp above; one more in the table and not here is an error.
        if (op && !found)
            error(ins, CompilerTr::tr("the simulator has no operator %1").arg(op->text));
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
            const qint64 n = ins.operands[1].constant.value;
            if (n < 0 || n > 15) {
                r = {};
            } else if (m_layout->area(a.area).kind == model::AreaKind::Bit) {
                // 16 bits of a bit area read as one word from I1, I17, ... (Area::bitsAsWords):
                // its bit n is the device n above the first, so PL110 SBIT Q1 3 sets Q4.
                if (m_layout->word(a) >= 0) {
                    a.index += static_cast<int>(n);
                    r = m_layout->bit(a);
                }
            } else {
                a.bit = static_cast<int>(n);
                r = m_layout->bit(a);
            }
        } else if (o && isDevice(*o)) {
            r = m_layout->bit(o->address);
        }
        if (o && !r.valid()) {
            error(ins,
                  CompilerTr::tr("%1 needs a bit: a bit device, or a word and a bit number 0..15")
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
        // The count and both blocks follow the table's rules (OperandSpec::lowest, countFrom:
        // n >= 1, every word of a block there), which reportBreaches has said when broken.
        if (!n || m_failed || m_muted)
            break;
        if (n->kind != model::Operand::Kind::Constant || n->constant.value < 1 ||
            n->constant.value > kMaxZoneElements) {
            error(ins, CompilerTr::tr("%1 is not a number of words").arg(describe(*n)));
            break;
        }
        s.count = static_cast<int>(n->constant.value);
        // Words of one block lie one after another in the image (model::runBreaks); a bit
        // area read as words counts 16 bits a word.
        auto fits = [&](const model::Operand &o) {
            const int perWord = kindOf(o) == AreaKind::Bit ? 16 : 1;
            const int last = m_layout->word(model::offsetAddress(
                m_target, o.address, static_cast<qint64>(s.count - 1) * perWord));
            return last >= 0 && last == m_layout->word(o.address) + s.count - 1;
        };
        // An indexed block is checked where it lands, each time it runs.
        if ((s.dest >= 0 && !fits(ins.operands[1])) || (s.x.index >= 0 && !fits(ins.operands[0])))
            error(
                ins,
                CompilerTr::tr("the block of %1 words runs past the end of its area").arg(s.count));
        break;
    }
    case ApplyFunction::MoveText: {
        // MOVTXT D n "TEXT" (PL110 manual 4.2.10): the characters' codes, one or two a word
        // high byte first (model::textWords), from D on; the check holds them to D's area.
        s.code = Code::MoveConstants;
        s.dest = destOf(ins, 0, false, &s.width);
        const model::Operand *n = operand(ins, 1);
        const model::Operand *text = operand(ins, 2);
        if (!n || !text || m_failed || m_muted)
            break;
        if (s.dest < 0) {
            error(ins, CompilerTr::tr("%1 is not a word the text can be stored from")
                           .arg(describe(ins.operands[0])));
            break;
        }
        const std::vector<std::int32_t> words =
            model::textWords(text->text, static_cast<int>(n->constant.value));
        s.slot = static_cast<int>(m_program->constants.size());
        s.count = static_cast<int>(words.size());
        m_program->constants.insert(m_program->constants.end(), words.begin(), words.end());
        if (s.count > 0) {
            const int last = m_layout->word(
                model::offsetAddress(m_target, ins.operands[0].address, s.count - 1));
            if (last < 0 || last != s.dest + s.count - 1)
                error(ins, CompilerTr::tr("the text does not fit in the area of %1 from there on")
                               .arg(describe(ins.operands[0])));
        }
        break;
    }
    case ApplyFunction::PanelFieldSet:
    case ApplyFunction::PanelFieldFormat:
    case ApplyFunction::PanelFieldPosition:
        panelField(ins, s);
        break;
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
    case ApplyFunction::AndWord:
    case ApplyFunction::OrWord:
    case ApplyFunction::XorWord:
        compileWordLogic(ins, s, 2);
        break;
    case ApplyFunction::Complement:
    case ApplyFunction::ToBcd:
    case ApplyFunction::FromBcd:
        // CPM1 COM(29) D complements D in place; Vigor CML S D, BCD/BIN S D write D.
        compileWordLogic(ins, s, 1);
        break;
    case ApplyFunction::CheckCode:
        compileCheckCode(ins, s); // compile_words.cpp
        break;
    case ApplyFunction::Swap:
    case ApplyFunction::ToAscii:
    case ApplyFunction::FromAscii:
    case ApplyFunction::ShiftDigits:
    case ApplyFunction::ReadVolume:
        compileText(ins, s); // compile_comm.cpp
        break;
    case ApplyFunction::EasyLink:
    case ApplyFunction::ModbusMaster:
    case ApplyFunction::SerialData:
    case ApplyFunction::ModuleRead:
    case ApplyFunction::ModuleWrite:
    case ApplyFunction::FreePortSend:
    case ApplyFunction::MasterQuery:
        compileComm(ins, s); // compile_comm.cpp
        break;
    case ApplyFunction::Toggle: {
        // OUTB (PL110 manual 4.2.3): each activation of the coil flips the bit; Vigor ALTP
        // flips it at each rising edge. Either writes it: not an input.
        const model::Operand *d = operand(ins, 0);
        if (d && isDevice(*d) && !m_target.area(d->address.area).writable) {
            error(ins,
                  trCompiler(QT_TRANSLATE_NOOP("rung::simulator::Compiler", "%1 cannot be written"))
                      .arg(describe(*d)));
            break;
        }
        s.bit = bitOf(ins, 0);
        edgeStep(s, Code::Toggle, false);
        break;
    }
    case ApplyFunction::CompareToFlags:
    case ApplyFunction::ShiftRegister:
    case ApplyFunction::WordShift:
    case ApplyFunction::MoveNot:
    case ApplyFunction::MoveBit:
    case ApplyFunction::MoveDigit:
    case ApplyFunction::BcdIncrement:
    case ApplyFunction::BcdDecrement:
    case ApplyFunction::BcdAdd:
    case ApplyFunction::BcdSubtract:
    case ApplyFunction::BcdMultiply:
    case ApplyFunction::BcdDivide:
    case ApplyFunction::BinaryAdd:
    case ApplyFunction::BinarySubtract:
    case ApplyFunction::SetCarry:
    case ApplyFunction::ClearCarry:
    case ApplyFunction::SubroutineCall:
    case ApplyFunction::StepNext:
    case ApplyFunction::FailureAlarm:
        compileArithmetic(ins, s); // compile_cpm1.cpp
        break;
    default:
        notSimulated(ins);
        s.code = Code::Nop;
        break;
    }
}

// SetPAR N STATE VAR MIN MAX, FormatPAR N TYPE DIGITS DECIMALS FILL, PosPAR N ROW COLUMN ACCESS
// (PL110 manual 4.2.26..4.2.28): the field's words of 2.1.2 (PanelDisplay::fields: field N's
// first word, then state, area and number of the variable (number high, low), the minimum's
// and the maximum's area and number, type, digits, decimals, fill, row, column, access), set
// each scan the coil is on. A variable is coded as SM107's list codes it (PanelAreaCode); a
// constant limit is area 0 and the number itself.
void Compiler::panelField(const model::Instruction &ins, Step &s) {
    s.code = Code::MoveConstants;
    const model::PanelDisplay &display = m_target.panel.display;
    std::vector<const model::Operand *> ops;
    for (std::size_t k = 0; k < ins.spec->operands.size(); ++k)
        ops.push_back(operand(ins, k));
    if (m_failed || m_muted || std::find(ops.begin(), ops.end(), nullptr) != ops.end())
        return;
    const qint64 field = ops[0]->constant.value;
    if (field < 1 || field > static_cast<qint64>(display.fields.size())) {
        error(ins, CompilerTr::tr("the display has no field %1").arg(field));
        return;
    }
    const auto first =
        model::parseAddress(m_target, display.fields[static_cast<std::size_t>(field - 1)].first);
    const auto *base = std::get_if<model::Address>(&first);
    if (!base)
        return;
    // A variable as its area's code in SM107's list and its number.
    const auto listed = [&](const model::Operand &o, std::int32_t *code, qint64 *number) {
        if (o.kind == model::Operand::Kind::Constant) {
            *code = 0;
            *number = o.constant.value;
            return true;
        }
        const QString &area = m_target.area(o.address.area).key;
        for (const model::PanelAreaCode &c : display.areaCodes)
            if (c.area == area && o.address.bit < 0) {
                *code = c.code;
                *number = o.address.index;
                return true;
            }
        error(ins,
              CompilerTr::tr("%1 is not a variable a display field can show").arg(describe(o)));
        return false;
    };
    std::vector<std::int32_t> words;
    int offset = 0;
    const auto value = [&](const model::Operand *o) {
        words.push_back(static_cast<std::int32_t>(o->constant.value));
    };
    const auto coded = [&](const model::Operand &o) {
        std::int32_t code = 0;
        qint64 number = 0;
        if (!listed(o, &code, &number))
            return false;
        words.push_back(code);
        words.push_back(static_cast<std::int32_t>((number >> 16) & 0xffff));
        words.push_back(static_cast<std::int32_t>(number & 0xffff));
        return true;
    };
    switch (ins.spec->function) {
    case model::ApplyFunction::PanelFieldSet:
        value(ops[1]);
        if (!coded(*ops[2]) || !coded(*ops[3]) || !coded(*ops[4]))
            return;
        break;
    case model::ApplyFunction::PanelFieldFormat:
        offset = 10;
        for (std::size_t k = 1; k < 5; ++k)
            value(ops[k]);
        break;
    default:
        offset = 14;
        for (std::size_t k = 1; k < 4; ++k)
            value(ops[k]);
        break;
    }
    model::Address at = *base;
    at.index += offset;
    s.dest = m_layout->word(at);
    s.width = m_target.area(at.area).wordBits;
    s.slot = static_cast<int>(m_program->constants.size());
    s.count = static_cast<int>(words.size());
    m_program->constants.insert(m_program->constants.end(), words.begin(), words.end());
}

} // namespace rung::simulator::detail
