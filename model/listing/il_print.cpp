#include "model/listing/il.h"

#include <QRegularExpression>

// The canonical printer: one instruction a line, the table's canonical mnemonic, operands as
// formatAddress / formatConstant write them. Infix forms (VPC compares and transfers) and
// fused element numbers (VPC TIM00) are read off the instruction table.

namespace rung::model {

namespace {

bool mnemonicHasSymbol(const QString &mnemonic) {
    return mnemonic.contains(QLatin1Char('<')) || mnemonic.contains(QLatin1Char('>')) ||
           mnemonic.contains(QLatin1Char('='));
}

// K4M0, D0E0, K10F0: the digit count before, the index register after (operand_text.cpp).
QString withModifiers(const Target &target, const Operand &operand, QString text) {
    if (operand.digits > 0)
        text.prepend(QStringLiteral("K%1").arg(operand.digits));
    if (operand.index.valid())
        text += formatAddress(target, operand.index);
    return text;
}

// A text as a listing writes it: in double quotes, a quote inside it twice.
QString quoted(const QString &text) {
    return QLatin1Char('"') + QString(text).replace(QLatin1String("\""), QLatin1String("\"\"")) +
           QLatin1Char('"');
}

QString operandText(const Target &target, const InstructionSpec &spec, std::size_t index,
                    const Operand &operand) {
    if (operand.modified())
        return formatOperand(target, operand);
    switch (operand.kind) {
    case Operand::Kind::Text:
        return operand.text;
    case Operand::Kind::String:
        return quoted(operand.text);
    case Operand::Kind::Constant:
        if (index < spec.operands.size() && spec.operands[index].kind == OperandKind::Label)
            return QStringLiteral("%1").arg(operand.constant.value, 2, 10, QLatin1Char('0'));
        return formatConstant(target, operand.constant);
    case Operand::Kind::Device:
        break;
    }
    QString text = formatAddress(target, operand.address);
    const OperandKind kind =
        index < spec.operands.size() ? spec.operands[index].kind : OperandKind::BitSource;
    if (kind == OperandKind::TimerNumber || kind == OperandKind::CounterNumber) {
        // CPM1 "TIM 000 #0150": the mnemonic names the kind, the operand is the number.
        const QString prefix = target.area(operand.address.area).prefix;
        // Only multi-letter prefixes: Vigor's "TMR T0" keeps its T.
        if (prefix.trimmed().size() > 1 &&
            spec.mnemonic.startsWith(prefix.trimmed(), Qt::CaseInsensitive))
            return text.mid(prefix.size()).trimmed();
    }
    return text;
}

} // namespace

QString formatOperand(const Target &target, const Operand &operand) {
    switch (operand.kind) {
    case Operand::Kind::Device:
        return withModifiers(target, operand, formatAddress(target, operand.address));
    case Operand::Kind::Constant:
        return withModifiers(target, operand, formatConstant(target, operand.constant));
    case Operand::Kind::Text:
        return operand.text;
    case Operand::Kind::String:
        return quoted(operand.text);
    }
    return {};
}

QString printInstruction(const Target &target, const Instruction &instruction) {
    const InstructionSpec *spec = instruction.spec;
    if (!spec)
        return QStringLiteral("NOP");
    const auto &ops = instruction.operands;
    if (spec->fusedOperand && !ops.empty() && ops[0].kind == Operand::Kind::Device) {
        // VPC "TIM00": the element number is part of the mnemonic.
        const Area &a = target.area(ops[0].address.area);
        QString number = formatAddress(target, ops[0].address).mid(a.prefix.size());
        QString out = spec->mnemonic + number;
        for (std::size_t i = 1; i < ops.size(); ++i)
            out += QLatin1Char(' ') + operandText(target, *spec, i, ops[i]);
        return out;
    }
    if (spec->op == Op::Transfer && ops.size() == 2) {
        const char *symbol = spec->transfer == TransferOp::Add        ? "+"
                             : spec->transfer == TransferOp::Subtract ? "-"
                                                                      : ",";
        return spec->mnemonic + QLatin1Char(' ') + operandText(target, *spec, 0, ops[0]) +
               QLatin1String(symbol) + operandText(target, *spec, 1, ops[1]);
    }
    if (spec->compare != CompareOp::None && !mnemonicHasSymbol(spec->mnemonic) && ops.size() == 2) {
        return spec->mnemonic + QLatin1Char(' ') + operandText(target, *spec, 0, ops[0]) +
               QLatin1String(compareSymbol(spec->compare)) + operandText(target, *spec, 1, ops[1]);
    }
    QString out = spec->mnemonic;
    for (std::size_t i = 0; i < ops.size(); ++i)
        out += QLatin1Char(' ') + operandText(target, *spec, i, ops[i]);
    return out;
}

PrintedListing printListing(const InstructionList &list, const PrintOptions &options) {
    return printListing(list, list.comments, options);
}

PrintedListing printListing(const InstructionList &list,
                            const std::vector<std::pair<int, QString>> &comments,
                            const PrintOptions &options) {
    PrintedListing printed;
    if (!list.target)
        return printed;
    const Target &target = *list.target;
    QString &out = printed.text;
    const int count = static_cast<int>(list.instructions.size());
    printed.instructionLine.reserve(static_cast<std::size_t>(count));
    printed.firstLine.reserve(static_cast<std::size_t>(count) + 1);
    int line = 1;
    const auto endLine = [&](int instruction) {
        out += QLatin1Char('\n');
        printed.instructionOfLine.push_back(instruction);
        ++line;
    };
    // A comment is one line of text: a line break inside one (any of \n, \r\n, \r, which
    // the editor shows as breaks) prints as a comment line of its own, never as code.
    static const QRegularExpression lineBreak(QStringLiteral("\r\n|\r|\n"));
    std::size_t comment = 0;
    int step = 0;
    for (int i = 0; i <= count; ++i) {
        printed.firstLine.push_back(line);
        while (options.comments && comment < comments.size() && comments[comment].first <= i) {
            for (const QString &part : comments[comment].second.split(lineBreak)) {
                out += QLatin1String("; ") + part;
                endLine(-1);
            }
            ++comment;
        }
        if (i == count)
            break;
        const Instruction &ins = list.instructions[static_cast<std::size_t>(i)];
        if (options.stepNumbers)
            out += QStringLiteral("%1 ").arg(step, 4, 10, QLatin1Char('0'));
        out += printInstruction(target, ins);
        if (options.comments && !ins.comment.isEmpty())
            out +=
                QLatin1String(" ; ") + QString(ins.comment).replace(lineBreak, QStringLiteral(" "));
        printed.instructionLine.push_back(line);
        endLine(i);
        step += instructionSteps(target, ins);
    }
    return printed;
}

int PrintedListing::instructionAt(int line) const {
    if (line < 1 || line > static_cast<int>(instructionOfLine.size()))
        return -1;
    return instructionOfLine[static_cast<std::size_t>(line - 1)];
}

QString printInstructionList(const InstructionList &list, const PrintOptions &options) {
    return printListing(list, options).text;
}

int instructionSteps(const Target &target, const Instruction &instruction) {
    if (!instruction.spec)
        return 1;
    int steps = instruction.spec->steps;
    // 32-bit counters take two more steps than the table's 16-bit form (FX family rule).
    if (instruction.spec->op == Op::Counter && !instruction.operands.empty() &&
        instruction.operands[0].kind == Operand::Kind::Device &&
        instruction.operands[0].address.area >= 0 &&
        target.area(instruction.operands[0].address.area).wordBits == 32)
        steps += 2;
    return steps;
}

double timerBaseMs(const Target &target, const Instruction &instruction) {
    if (!instruction.spec || instruction.spec->op != Op::Timer)
        return 0;
    // The instruction's own base (CPM1 TIMH), else the timer area's (Vigor T200.. 10 ms),
    // else the target's.
    const Operand *timer = instruction.operands.empty() ? nullptr : &instruction.operands[0];
    const double areaBase = timer && timer->kind == Operand::Kind::Device && timer->address.valid()
                                ? target.area(timer->address.area).timerBaseMs
                                : 0;
    double base = instruction.spec->timerBaseMs > 0 ? instruction.spec->timerBaseMs
                  : areaBase > 0                    ? areaBase
                                                    : target.defaultTimerBaseMs;
    // PL110 TON / TOFF / TONR T PT [BASE] (PL110 manual 4.2.4): the allowed bases are the operand's
    // allowedValues in the table, checked before anything runs.
    if (target.semantics.timerCountsInWord && instruction.operands.size() > 2 &&
        instruction.operands[2].kind == Operand::Kind::Constant)
        base = static_cast<double>(instruction.operands[2].constant.value);
    return base;
}

bool timerCountsDown(const Target &target, const Address &timer) {
    return timer.valid() && target.area(timer.area).kind == AreaKind::Timer &&
           timer.index < target.semantics.downTimersBelow;
}

} // namespace rung::model
