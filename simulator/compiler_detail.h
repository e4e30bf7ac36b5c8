#pragma once

// The compiler's working state, shared by compiler.cpp (the pass over the list, jumps and
// system devices) and compile_steps.cpp (one instruction to one step). Not part of the
// simulator's interface: include compiler.h instead.

#include "compiler.h"

#include "model/checks/operand_rules.h"
#include "model/checks/unmodelled.h"
#include "model/listing/structure.h"
#include "model/target/address.h"
#include "simulator/tr.h"

#include <QCoreApplication>

namespace rung::simulator::detail {

using model::AreaKind;
using model::Op;

// lupdate loses the scope of Tr::tr after some comparisons in inline member functions and
// files those texts under a context "Tr" that the program never asks for; the explicit
// context keeps them translatable.
inline QString trCompiler(const char *text) {
    return QCoreApplication::translate("rung::simulator::Compiler", text);
}

// Program::fast from Program::steps (compile_fast.cpp).
void buildFastSteps(Program &program);

// Blocks saved under the accumulator: every open block but the one in the accumulator.
constexpr int kMaxBlockDepth = model::kMaxOpenBlocks - 1;
constexpr int kMaxZoneElements = 65536;

class Compiler {
public:
    explicit Compiler(const model::InstructionList &list)
        : m_list(list)
        , m_target(*list.target)
        , m_sem(m_target.semantics) {
        auto program = std::make_shared<Program>();
        program->layout = std::make_shared<MemoryLayout>(m_target);
        m_program = program;
        m_layout = program->layout.get();
    }

    CompileResult run();

private:
    void error(const model::Instruction &ins, const QString &message,
               const QString &code = QStringLiteral("SIM001")) {
        m_failed = true;
        if (m_muted)
            return;
        model::Diagnostic d;
        d.code = code;
        d.severity = model::Severity::Error;
        d.location.line = ins.line;
        d.location.column = ins.column;
        d.message = message;
        m_diagnostics.push_back(std::move(d));
    }
    // A constant preset of a timer/counter whose set value the program can address (PL110
    // PT/PV, PL110 manual 2.1.9/2.1.11) is loaded into that word at start, and the element reads
    // the word: writing PT1 changes T1's preset in force.
    void loadPresetFromMemory(const model::Address &element, Step &s) {
        if (s.x.index >= 0 || s.y.index < 0 || !m_layout->presetAddressable(element))
            return;
        m_program->presetLoads.emplace_back(s.y.index, s.x.constant);
        s.x.index = s.y.index;
    }
    // The table's operand rules (model::operandBreaches, which `check` reads as OP005): an
    // instruction that breaks one gets that message, and no second one of the compiler's own.
    void reportBreaches(const model::Instruction &ins) {
        m_muted = false;
        const std::vector<model::OperandBreach> breaches = model::operandBreaches(m_target, ins);
        for (const model::OperandBreach &b : breaches)
            error(ins, b.message);
        m_muted = !breaches.empty();
    }
    // A device the simulator keeps as plain memory (Target::unmodelled): `check` warns SIM101
    // with the same words.
    void reportUnmodelled(const model::Instruction &ins) {
        for (const model::UnmodelledUse &use : model::unmodelledUses(m_target, ins)) {
            model::Diagnostic d;
            d.code = QStringLiteral("SIM101");
            d.severity = model::Severity::Warning;
            d.location.line = ins.line;
            d.location.column = ins.column;
            d.message = use.message;
            m_diagnostics.push_back(std::move(d));
        }
    }
    void notSimulated(const model::Instruction &ins) {
        model::Diagnostic d;
        d.code = QStringLiteral("SIM100");
        d.severity = model::Severity::Warning;
        d.location.line = ins.line;
        d.location.column = ins.column;
        d.message = ins.spec ? model::notSimulatedMessage(*ins.spec) : QString();
        m_diagnostics.push_back(std::move(d));
    }
    QString describe(const model::Operand &o) const {
        if (o.modified())
            return model::formatOperand(m_target, o);
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
            error(ins, CompilerTr::tr("%1 is not a bit device").arg(describe(*o)));
        return r;
    }
    // A readable word: timers and counters give their current value.
    WordOperand sourceOf(const model::Instruction &ins, std::size_t i) {
        const model::Operand *o = operand(ins, i);
        WordOperand w;
        if (!o)
            return w;
        if (resolvedAtRunTime(*o)) {
            w.index = refFor(ins, *o, i, false);
            return w;
        }
        if (o->kind == model::Operand::Kind::Constant) {
            w.constant = static_cast<std::int32_t>(o->constant.value);
            // CPM1 "#0012" is the word 0012h (BCD digits, W353): MOV(21) #0012 DM 0000 stores
            // 0012h, which a timer set value DM 0000 reads as 12 - the move and the set value
            // read one word. Set values decode it (kBcd), as they decode a channel.
            if (o->constant.style == model::Constant::Style::Bcd && o->constant.value >= 0) {
                w.constant = static_cast<std::int32_t>(toBcd(o->constant.value));
                return w;
            }
            if (o->constant.value != w.constant)
                error(ins, CompilerTr::tr("constant %1 is out of range").arg(describe(*o)));
            return w;
        }
        w.index = isDevice(*o) ? m_layout->word(o->address) : -1;
        if (w.index < 0)
            error(ins, CompilerTr::tr("%1 is not a word device or a constant").arg(describe(*o)));
        return w;
    }
    // A writable word; setValue: timers/counters mean their set value (VPC transfers).
    std::int32_t destOf(const model::Instruction &ins, std::size_t i, bool setValue,
                        std::uint8_t *width) {
        const model::Operand *o = operand(ins, i);
        if (!o)
            return -1;
        if (resolvedAtRunTime(*o) && !(setValue && isTimerOrCounter(*o))) {
            *width = 16; // the engine gives the resolved word's own width
            return refFor(ins, *o, i, true);
        }
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
        if (resolvedAtRunTime(*o))
            return nextRef(ins, *o, i);
        // D199 is followed by D200 of the latched area, as the table's rule counts
        // (OperandSpec::words, model::runBreaks).
        const int w = m_layout->word(model::offsetAddress(m_target, o->address, 1));
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

    // A step that compares a value with the one it kept from the last scan (an edge slot).
    void edgeStep(Step &s, Code code, bool falling) {
        s.code = code;
        if (falling)
            s.flags |= kFalling;
        s.slot = m_program->edgeSlots++;
    }
    void popBlocks(const model::Instruction &ins, int n) {
        if (m_depth < n) {
            error(ins, CompilerTr::tr("%1 needs %2 open blocks before it")
                           .arg(ins.spec->mnemonic)
                           .arg(n + 1));
            m_depth = 0;
            return;
        }
        m_depth -= n;
    }

    // compile_operands.cpp: operands the engine resolves before the step runs (OperandRef).
    bool resolvedAtRunTime(const model::Operand &o) const;
    bool isTimerOrCounter(const model::Operand &o) const {
        return isDevice(o) && (kindOf(o) == AreaKind::Timer || kindOf(o) == AreaKind::Counter);
    }
    std::int32_t refFor(const model::Instruction &ins, const model::Operand &o, std::size_t i,
                        bool dest, int offset = 0);
    std::int32_t nextRef(const model::Instruction &ins, const model::Operand &o, std::size_t i);

    void compileContact(const model::Instruction &ins, Step &s);
    void compileTimer(const model::Instruction &ins, Step &s);
    void compileCounter(const model::Instruction &ins, Step &s);
    void compileApply(const model::Instruction &ins, Step &s);
    void panelField(const model::Instruction &ins, Step &s); // PL110 SetPAR / FormatPAR / PosPAR
    void compileWordLogic(const model::Instruction &ins, Step &s, std::size_t sources);
    // compile_words.cpp: Vigor DMOV and CCD.
    void compileDoubleMove(const model::Instruction &ins, Step &s);
    void compileCheckCode(const model::Instruction &ins, Step &s);
    // compile_comm.cpp: SWAP, ASCI, HEX, SMOV, VRRD, DDIV and the communication instructions.
    void compileText(const model::Instruction &ins, Step &s);
    void compileDoubleDivide(const model::Instruction &ins, Step &s);
    void compileComm(const model::Instruction &ins, Step &s);
    void compileCommDevices();
    // The PL110's port markers (Program::ports) and COM / EXP's operands.
    void compilePorts();
    std::int32_t portIndex(const QString &port) const;
    bool compileQuery(const model::Instruction &ins, CommStep *c);
    BitRef systemBit(model::SystemRole role);
    std::int32_t systemWord(model::SystemRole role);
    std::int32_t wordsToAreaEnd(const model::Operand &o) const;
    void compileSystem();
    // The front panel (model::FrontPanel): its power-on values, the PL110-2A's pages
    // (compile_panel.cpp).
    void compilePanel();
    // Omron CPM1 (compile_cpm1.cpp): the W353 application instructions, SBN / RET / STEP,
    // the arithmetic flags, and the subroutines' targets.
    void compileArithmetic(const model::Instruction &ins, Step &s);
    void compileControl(const model::Instruction &ins, Step &s);
    void bindFlag(model::SystemRole role, BitRef bit);
    void resolveSubroutines(const model::BlockPairs &pairs);
    void compileInputTestBits(int count);
    void resolveJumps();

    const model::InstructionList &m_list;
    const model::Target &m_target;
    const model::Semantics &m_sem; // the target's execution facts (target.h)
    std::shared_ptr<Program> m_program;
    const MemoryLayout *m_layout = nullptr;
    std::vector<model::Diagnostic> m_diagnostics;
    bool m_failed = false;
    bool m_muted = false;     // the instruction\'s operand rules already said what is wrong
    bool m_rungStart = false; // the instruction being compiled starts a rung
    bool m_resolve = false;   // the instruction has an OperandRef: its step gets kResolve
    int m_depth = 0;
    int m_push = 0;
    int m_stlArea = -1;
    BitRef m_stlBit;
    BitRef m_stepBit; // the control bit of the STEP(08) step being compiled
};

} // namespace rung::simulator::detail
