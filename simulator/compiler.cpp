#include "compiler_detail.h"
#include "simulator/tr.h"

#include <algorithm>
#include <variant>
#include <vector>

namespace rung::simulator {

namespace detail {

// The first `count` inputs of the physical input area, which a TEST-mode image word stands
// for (PL110 manual 2.1.2: SM37.0 -> I1 ... SM37.7 -> I8).
void Compiler::compileInputTestBits(int count) {
    for (std::size_t k = 0; k < m_target.areas.size(); ++k) {
        const model::Area &area = m_target.areas[k];
        if (!area.physical || area.writable || area.kind != AreaKind::Bit)
            continue;
        for (int n = 0; n < count && area.first + n <= area.last; ++n)
            m_program->inputTestBits.push_back(
                m_layout->bit(model::Address{static_cast<int>(k), area.first + n, -1}));
        return;
    }
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
            b.unitUs = d.unitUs;
            if (b.word >= 0)
                m_program->system.push_back(b);
            break;
        case model::SystemRole::InputTest:
            m_program->inputTest = m_layout->bit(a);
            break;
        case model::SystemRole::InputTestImage:
            m_program->inputTestWord = m_layout->word(a);
            compileInputTestBits(d.inputs);
            break;
        case model::SystemRole::InstructionError:
        case model::SystemRole::Carry:
        case model::SystemRole::Greater:
        case model::SystemRole::Equal:
        case model::SystemRole::Less:
        case model::SystemRole::StepStart:
            bindFlag(d.role, m_layout->bit(a)); // compile_cpm1.cpp
            break;
        case model::SystemRole::Other:
        case model::SystemRole::ByteMode:    // read by CCD (compile_words.cpp)
        case model::SystemRole::HexDigits:   // read by SMOV (compile_comm.cpp)
        case model::SystemRole::AlarmNumber: // written by FAL(06) (compile_cpm1.cpp)
        // Communication (compile_comm.cpp, engine_comm.cpp; the network drives CPU Link's and
        // Parallel Link's).
        case model::SystemRole::LinkCycleDone:
        case model::SystemRole::RsSendRequest:
        case model::SystemRole::RsReceiveDone:
        case model::SystemRole::RsTimeout:
        case model::SystemRole::CommError:
        case model::SystemRole::CommErrorCode:
        case model::SystemRole::RsSendLeft:
        case model::SystemRole::RsReceived:
        case model::SystemRole::CommTimeout:
        case model::SystemRole::CpuLinkFailed:
        case model::SystemRole::CpuLinkTimeout:
        case model::SystemRole::CpuLinkSlaves:
        case model::SystemRole::CpuLinkRange:
        case model::SystemRole::CpuLinkRetries:
        case model::SystemRole::NetworkScanTime:
        case model::SystemRole::NetworkScanMax:
        case model::SystemRole::CpuLinkErrorCount:
        case model::SystemRole::CpuLinkErrorCode:
        case model::SystemRole::ParallelMaster:
        case model::SystemRole::ParallelSlave:
        case model::SystemRole::ParallelNormal:
        case model::SystemRole::ParallelHighSpeed:
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
    auto addr = [&](const QString &text) -> model::Address {
        if (text.isEmpty())
            return {};
        const auto parsed = model::parseAddress(m_target, text);
        return std::holds_alternative<model::Address>(parsed) ? std::get<model::Address>(parsed)
                                                              : model::Address{};
    };
    // The port's bits, LSB first; a model with fewer bit devices shows fewer bits. Only
    // port.bits bits exist, so the word's value shows modulo 2^bits.
    auto bits = [&](const model::ParallelPort &port, std::vector<BitRef> &into) {
        model::Address a = addr(port.firstBit);
        for (int k = 0; a.valid() && k < port.bits; ++k, ++a.index) {
            const BitRef r = m_layout->bit(a);
            if (!r.valid())
                return;
            into.push_back(r);
        }
    };
    if (const model::Address o = addr(m_sem.parallelOut.word); o.valid()) {
        m_program->parallelOutWord = m_layout->word(o);
        bits(m_sem.parallelOut, m_program->parallelOutBits);
    }
    if (const model::Address i = addr(m_sem.parallelIn.word); i.valid()) {
        m_program->parallelInWord = m_layout->word(i);
        bits(m_sem.parallelIn, m_program->parallelInBits);
    }
    // Timers / counters that run only while a system bit allows (Area::enabledBy).
    for (int k = 0; k < m_layout->areaCount(); ++k) {
        const AreaLayout &l = m_layout->area(k);
        const model::Area &area = m_target.area(k);
        if (!area.enabledBy || l.stateBase < 0)
            continue;
        const model::Address gate = addr(QString::fromLatin1(area.enabledBy));
        if (m_program->gates.empty())
            m_program->gates.resize(static_cast<std::size_t>(m_layout->elementStateCount()));
        for (int e = 0; e < l.count; ++e)
            m_program->gates[static_cast<std::size_t>(l.stateBase + e)] =
                ElementGate{m_layout->bit(gate), area.enabledWhenOn};
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

// Jumps go to their JPE / JME as model::pairBlocks pairs them (the checks' NE* rules): a
// program whose jumps do not pair cannot run.
void Compiler::resolveJumps() {
    const model::BlockPairs pairs = model::pairBlocks(m_list);
    for (const model::BlockProblem &p : pairs.problems) {
        if (!p.aboutJump)
            continue;
        const model::Instruction &ins =
            m_list.instructions[static_cast<std::size_t>(p.instruction)];
        error(ins, p.message, QString::fromLatin1(p.code));
    }
    for (std::size_t k = 0; k < m_list.instructions.size(); ++k)
        if (m_list.instructions[k].op() == Op::Jump && pairs.partner[k] > static_cast<int>(k))
            m_program->steps[k].slot = pairs.partner[k];
    resolveSubroutines(pairs); // compile_cpm1.cpp
}

CompileResult Compiler::run() {
    m_program->deferredBitWrites = m_sem.deferredBitWrites;
    m_program->timerMax = m_target.limits.timerMax;
    m_program->counterMin = static_cast<std::int32_t>(m_target.limits.counterMin);
    m_program->counterMax = static_cast<std::int32_t>(m_target.limits.counterMax);
    m_program->scanTimeMax = m_target.limits.scanTimeMax;
    m_program->steps.resize(m_list.instructions.size());
    m_program->lines.resize(m_list.instructions.size());
    compileSystem();
    compilePanel(); // compile_panel.cpp
    compilePorts(); // compile_comm.cpp
    // MPS levels are the PLC's (Limits::stackDepth, ST001); the engine's stack holds any
    // target's (kMaxStackDepthOfAnyTarget).
    const int pushLimit =
        std::clamp(m_target.limits.stackDepth, 1, model::kMaxStackDepthOfAnyTarget);
    // The load that starts a rung starts the block stack afresh (model::rungSpans).
    std::vector<bool> rungStart(m_list.instructions.size(), false);
    for (const model::RungSpan &span : model::rungSpans(m_list.instructions))
        rungStart[static_cast<std::size_t>(span.first)] = true;
    for (std::size_t k = 0; k < m_list.instructions.size(); ++k) {
        const model::Instruction &ins = m_list.instructions[k];
        Step &s = m_program->steps[k];
        m_program->lines[k] = ins.line;
        m_rungStart = rungStart[k];
        m_muted = false;
        if (!ins.spec) {
            error(ins, CompilerTr::tr("unknown instruction"));
            continue;
        }
        const model::InstructionSpec &spec = *ins.spec;
        reportBreaches(ins);
        reportUnmodelled(ins);
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
            break;
        case Op::Push:
            s.code = Code::Push;
            if (++m_push > pushLimit) {
                error(ins,
                      CompilerTr::tr("more than %1 nested %2").arg(pushLimit).arg(spec.mnemonic));
                m_push = pushLimit;
            }
            m_program->maxPushDepth = std::max(m_program->maxPushDepth, m_push);
            break;
        case Op::ReadStack:
        case Op::Pop:
            s.code = spec.op == Op::ReadStack ? Code::ReadStack : Code::Pop;
            if (m_push == 0)
                error(ins, CompilerTr::tr("%1 without MPS before it").arg(spec.mnemonic));
            else if (spec.op == Op::Pop)
                --m_push;
            break;
        case Op::Invert:
            // NOT, and PL110 P / N (PL110 manual 4.2.18), which edge-detect the power flow at
            // their place in the rung: the mode tells them apart.
            if (spec.mode == model::ContactMode::Rising ||
                spec.mode == model::ContactMode::Falling) {
                edgeStep(s, Code::EdgeFlow, spec.mode == model::ContactMode::Falling);
            } else {
                s.code = Code::Invert;
            }
            break;
        case Op::Out:
            s.code = Code::Out;
            s.bit = bitOf(ins, 0);
            if (spec.negated)
                s.flags |= kNegated;
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
            break;
        case Op::Reset: {
            s.code = Code::Reset;
            const model::Operand *o = operand(ins, 0);
            if (o && isDevice(*o)) {
                const ResetTarget t = resetTargetOf(o->address);
                if (!t.bit.valid() && t.word < 0)
                    error(ins, CompilerTr::tr("%1 cannot be reset").arg(describe(*o)));
                s.slot = static_cast<int>(m_program->resets.size());
                s.count = 1;
                m_program->resets.push_back(t);
            } else if (o) {
                error(ins, CompilerTr::tr("%1 is not a device").arg(describe(*o)));
            }
            break;
        }
        case Op::PulseRise:
        case Op::PulseFall:
            s.bit = bitOf(ins, 0);
            edgeStep(s, Code::Pulse, spec.op == Op::PulseFall);
            break;
        case Op::Keep:
            s.code = Code::Keep;
            s.bit = bitOf(ins, 0);
            popBlocks(ins, 1);
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
            // Four-digit decimal words (VPC user's manual, III): a result outside 0..9999 wraps
            // modulo 10000 and is a runtime diagnostic.
            if (m_target.limits.decimalDigits == 4)
                s.flags |= kDecimal4;
            s.dest = destOf(ins, 0, true, &s.width);
            s.x = sourceOf(ins, 1);
            if (s.dest == m_program->parallelOutWord && s.dest >= 0)
                m_program->writesParallelOut = true;
            break;
        case Op::Apply:
            compileApply(ins, s);
            if (s.dest == m_program->parallelOutWord && s.dest >= 0)
                m_program->writesParallelOut = true;
            break;
        case Op::Interlock:
            s.code = Code::Interlock;
            break;
        case Op::InterlockClear:
            s.code = Code::InterlockClear;
            break;
        case Op::Jump:
            s.code = Code::Jump;
            break;
        case Op::JumpEnd:
            s.code = Code::JumpEnd;
            break;
        case Op::StepLadder: {
            s.code = Code::StepLadder;
            s.bit = bitOf(ins, 0);
            m_stlBit = s.bit;
            m_stlArea = ins.operands.empty() ? -1 : ins.operands[0].address.area;
            break;
        }
        case Op::Return:
            s.code = Code::Return;
            m_stlArea = -1;
            break;
        case Op::End:
            s.code = Code::End;
            break;
        case Op::Nop:
            s.code = Code::Nop;
            break;
        case Op::SubroutineStart:
        case Op::SubroutineReturn:
        case Op::StepDefine:
            compileControl(ins, s); // compile_cpm1.cpp
            break;
        }
        if (spec.differentiated) {
            // "@MOV(21)": once on the rising edge of its condition (kDifferentiated).
            s.flags |= kDifferentiated;
            s.slot = m_program->edgeSlots++;
        }
        if (m_resolve)
            s.flags |= kResolve;
        m_resolve = false;
        if (s.flags & (kResolve | kDifferentiated))
            m_program->specialSteps = true;
    }
    m_muted = false;
    resolveJumps();
    if (!m_program->comms.empty())
        compileCommDevices(); // compile_comm.cpp
    CompileResult result;
    result.diagnostics = std::move(m_diagnostics);
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const model::Diagnostic &a, const model::Diagnostic &b) {
                         return a.location.line < b.location.line;
                     });
    if (!m_failed) {
        buildFastSteps(*m_program);
        result.program = m_program;
    }
    return result;
}

} // namespace detail

using detail::Compiler;

CompileResult compileProgram(const model::InstructionList &list) {
    if (!list.target) {
        CompileResult r;
        model::Diagnostic d;
        d.code = QStringLiteral("SIM001");
        d.message = CompilerTr::tr("the program has no target");
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
