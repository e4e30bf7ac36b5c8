#include "model/listing/il.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <algorithm>
#include <map>

// The listing parser. Every family's listing goes through the same steps: strip comments,
// read an optional step number, match the longest mnemonic the target's table knows, then
// read the operands the instruction's signature asks for. What differs between families
// (infix compares and transfers on VPC, fused timer numbers, "TIM 000" operands on CPM1)
// is read off the table, not written here per family.

namespace rung::model {

namespace {

constexpr int kMaxErrors = 1000;
// No instruction has more than a handful of operands; a line with more tokens is an error
// anyway, and not copying the rest keeps a huge line from costing memory.
constexpr std::size_t kMaxTokens = 16;
// Longer tokens are no mnemonic, address or constant of any family.
constexpr qsizetype kMaxTokenLength = 64;

// A quoted text (PL110 MOVTXT's "TESTO DISPLAY") may be longer than any other operand: a
// display of 8 x 21 characters and then some, so that a text too long for its words is told
// by the check that counts them, not cut here.
constexpr qsizetype kMaxTextLength = 1024;

struct Token {
    QString text;   // a quoted token: the characters between the quotes, "" read as "
    int column = 0; // 1-based
    bool quoted = false;
    bool unterminated = false; // a quoted token without its closing quote
};

// Where a quoted text that starts at `open` ends: the index of its closing quote, -1 when the
// line ends first. A quote written twice inside it is one quote of the text.
qsizetype closingQuote(QStringView line, qsizetype open) {
    for (qsizetype i = open + 1; i < line.size(); ++i) {
        if (line[i] != QLatin1Char('"'))
            continue;
        if (i + 1 < line.size() && line[i + 1] == QLatin1Char('"')) {
            ++i;
            continue;
        }
        return i;
    }
    return -1;
}

std::vector<Token> tokenize(QStringView line, int firstColumn) {
    std::vector<Token> tokens;
    qsizetype i = 0;
    while (i < line.size()) {
        while (i < line.size() && line[i].isSpace())
            ++i;
        if (i >= line.size())
            break;
        const qsizetype start = i;
        if (line[i] == QLatin1Char('"')) {
            const qsizetype close = closingQuote(line, i);
            const qsizetype end = close < 0 ? line.size() : close;
            QString text = line.mid(start + 1, std::min(end - start - 1, kMaxTextLength + 1))
                               .toString()
                               .replace(QLatin1String("\"\""), QLatin1String("\""));
            tokens.push_back(
                {std::move(text), firstColumn + static_cast<int>(start), true, close < 0});
            i = close < 0 ? line.size() : close + 1;
        } else {
            while (i < line.size() && !line[i].isSpace())
                ++i;
            tokens.push_back({line.mid(start, std::min(i - start, kMaxTokenLength + 1)).toString(),
                              firstColumn + static_cast<int>(start)});
        }
        if (tokens.size() > kMaxTokens)
            break;
    }
    return tokens;
}

// Where the comment of a line starts (';' or '//' outside a quoted text), -1: none.
qsizetype commentStart(QStringView line) {
    for (qsizetype i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (c == QLatin1Char('"')) {
            const qsizetype close = closingQuote(line, i);
            if (close < 0)
                return -1;
            i = close;
        } else if (c == QLatin1Char(';') ||
                   (c == QLatin1Char('/') && i + 1 < line.size() && line[i + 1] == c)) {
            return i;
        }
    }
    return -1;
}

bool allDigits(QStringView s) {
    return !s.isEmpty() && std::all_of(s.begin(), s.end(),
                                       [](QChar c) { return c.isDigit() && c.unicode() <= '9'; });
}

bool isLetters(QStringView s) {
    return !s.isEmpty() && std::all_of(s.begin(), s.end(), [](QChar c) { return c.isLetter(); });
}

// Levenshtein distance, for "did you mean" on unknown mnemonics.
int distance(const QString &a, const QString &b) {
    std::vector<int> row(static_cast<std::size_t>(b.size()) + 1);
    for (std::size_t j = 0; j < row.size(); ++j)
        row[j] = static_cast<int>(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        int previous = row[0];
        row[0] = static_cast<int>(i);
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const int saved = row[static_cast<std::size_t>(j)];
            const int cost = a[i - 1].toUpper() == b[j - 1].toUpper() ? 0 : 1;
            row[static_cast<std::size_t>(j)] =
                std::min({row[static_cast<std::size_t>(j)] + 1,
                          row[static_cast<std::size_t>(j - 1)] + 1, previous + cost});
            previous = saved;
        }
    }
    return row.back();
}

class Parser {
    Q_DECLARE_TR_FUNCTIONS(rung::model::InstructionList)

public:
    Parser(const Target &target, const ModelVariant *model)
        : m_target(target)
        , m_model(model) {
        m_result.list.target = &target;
    }

    ParseResult run(const QString &text) {
        int lineNumber = 0;
        qsizetype pos = 0;
        while (pos <= text.size()) {
            qsizetype end = text.indexOf(QLatin1Char('\n'), pos);
            if (end < 0)
                end = text.size();
            ++lineNumber;
            QStringView line = QStringView(text).mid(pos, end - pos);
            if (line.endsWith(QLatin1Char('\r')))
                line.chop(1);
            parseLine(line, lineNumber);
            if (m_tooMany)
                break;
            pos = end + 1;
        }
        resolveBankAliases();
        return std::move(m_result);
    }

private:
    void error(int line, int column, const QString &message) {
        if (m_result.errors.size() >= kMaxErrors) {
            if (!m_tooMany)
                m_result.errors.push_back(
                    {line, column, tr("Too many errors; the rest of the listing was not read")});
            m_tooMany = true;
            return;
        }
        m_result.errors.push_back({line, column, message});
    }

    void parseLine(QStringView line, int lineNumber) {
        // Comments: ';' or '//' to the end of the line. A comment on a line of its own is
        // kept for the instruction that follows (rung comments travel IL -> ladder -> IL).
        // Not inside a quoted text: MOVTXT V0 1 "A;B" holds a semicolon.
        const qsizetype cut = commentStart(line);
        QStringView code = cut >= 0 ? line.left(cut) : line;
        QString comment;
        if (cut >= 0) {
            const qsizetype skip = line[cut] == QLatin1Char(';') ? 1 : 2;
            comment = line.mid(cut + skip).trimmed().toString();
        }
        if (cut >= 0 && code.trimmed().isEmpty()) {
            // The first line's "; target: vigor" is the file's header, read by
            // declaredTarget(): not a comment of the program's first rung.
            if (lineNumber == 1 && !declaredTarget(line.toString()).isEmpty())
                return;
            m_result.list.comments.emplace_back(static_cast<int>(m_result.list.instructions.size()),
                                                comment);
            return;
        }
        std::vector<Token> tokens = tokenize(code, 1);
        if (tokens.empty())
            return;
        // An optional step number as the VPC console and printouts show: "0002 LD p01<p00".
        if (tokens.size() > 1 && allDigits(tokens[0].text) && !allDigits(tokens[1].text))
            tokens.erase(tokens.begin());
        // "0002:" forms from other printouts.
        if (tokens.size() > 1 && tokens[0].text.endsWith(QLatin1Char(':')) &&
            allDigits(QStringView(tokens[0].text).chopped(1)))
            tokens.erase(tokens.begin());

        Instruction ins;
        ins.line = lineNumber;
        ins.column = tokens[0].column;
        ins.comment = std::move(comment);
        std::size_t used = 0;
        QString fusedNumber;
        if (tokens[0].quoted || tokens[0].text.size() > kMaxTokenLength ||
            !matchMnemonic(tokens, &ins.spec, &used, &fusedNumber)) {
            // A section header may hold spaces ("[Interrupt 1]"): quote it whole.
            Token shown = tokens[0];
            if (shown.text.startsWith(QLatin1Char('[')) && !shown.text.contains(QLatin1Char(']')))
                for (std::size_t k = 1; k < tokens.size(); ++k) {
                    shown.text += QLatin1Char(' ') + tokens[k].text;
                    if (tokens[k].text.contains(QLatin1Char(']')))
                        break;
                }
            reportUnknown(shown, lineNumber);
            return;
        }
        std::vector<Token> operands(tokens.begin() + static_cast<std::ptrdiff_t>(used),
                                    tokens.end());
        if (!fusedNumber.isEmpty())
            operands.insert(operands.begin(), Token{fusedNumber, tokens[0].column + 3});
        m_lineAliases.clear();
        if (!readOperands(&ins, operands, lineNumber, tokens[0]))
            return;
        ins.step = m_step;
        m_step += instructionSteps(m_target, ins);
        for (std::size_t k : m_lineAliases)
            m_bankAliases.emplace_back(m_result.list.instructions.size(), k);
        m_result.list.instructions.push_back(std::move(ins));
    }

    // Whether `text` names its device by a prefix alias of the whole bank (CPM1 "TC 005",
    // Area::bankAlias) rather than by the area's own prefix.
    bool writtenAsBank(const Operand &o, const QString &text) const {
        if (o.kind != Operand::Kind::Device || !o.address.valid())
            return false;
        const Area &area = m_target.area(o.address.area);
        if (!area.bankAlias)
            return false;
        const QString written = QString(text).remove(QLatin1Char(' ')).toUpper();
        const auto startsWith = [&](const QString &prefix) {
            const QString p = QString(prefix).remove(QLatin1Char(' ')).toUpper();
            return !p.isEmpty() && written.startsWith(p) && written.size() > p.size() &&
                   written[p.size()].isDigit();
        };
        if (startsWith(area.prefix))
            return false;
        return std::any_of(area.prefixAliases.begin(), area.prefixAliases.end(), startsWith);
    }

    // A bank alias is the timer or the counter the program defines with that number (TC 005
    // is CNT 005 when a CNT 005 instruction counts); with no definition it stays the first
    // area of the bank, which the parser picked.
    void resolveBankAliases() {
        std::vector<Instruction> &list = m_result.list.instructions;
        std::map<std::pair<int, int>, int> defined; // (bank, number) -> area
        for (const Instruction &ins : list) {
            const Op op = ins.op();
            if ((op != Op::Timer && op != Op::Counter && op != Op::UpDownCounter) ||
                ins.operands.empty() || ins.operands[0].kind != Operand::Kind::Device ||
                !ins.operands[0].address.valid())
                continue;
            const Address &a = ins.operands[0].address;
            defined.emplace(std::pair{m_target.area(a.area).bank, a.index}, a.area);
        }
        for (const auto &[i, k] : m_bankAliases) {
            Address &a = list[i].operands[k].address;
            const auto it = defined.find({m_target.area(a.area).bank, a.index});
            if (it != defined.end())
                a.area = it->second;
        }
    }

    bool matchMnemonic(const std::vector<Token> &tokens, const InstructionSpec **spec,
                       std::size_t *used, QString *fusedNumber) const {
        // Two-word mnemonics first: "LD NOT", "AND LD", "OUT NOT", "KEEP (11)". A second word
        // with a digit outside brackets is an operand; skipping the lookup halves the work.
        if (tokens.size() >= 2 && !tokens[1].quoted &&
            (isLetters(tokens[1].text) || tokens[1].text.startsWith(QLatin1Char('(')))) {
            if (const InstructionSpec *s =
                    m_target.findInstruction(tokens[0].text + QLatin1Char(' ') + tokens[1].text)) {
                *spec = s;
                *used = 2;
                return true;
            }
        }
        if (const InstructionSpec *s = m_target.findInstruction(tokens[0].text)) {
            *spec = s;
            *used = 1;
            return true;
        }
        // Fused element numbers: VPC "TIM00", "CNT05".
        const QString &word = tokens[0].text;
        qsizetype letters = 0;
        while (letters < word.size() && word[letters].isLetter())
            ++letters;
        if (letters > 0 && letters < word.size() && allDigits(QStringView(word).mid(letters))) {
            const InstructionSpec *s = m_target.findInstruction(word.left(letters));
            if (s && s->fusedOperand) {
                *spec = s;
                *used = 1;
                *fusedNumber = word.mid(letters);
                return true;
            }
        }
        return false;
    }

    void reportUnknown(const Token &token, int lineNumber) {
        if (token.text.startsWith(QLatin1Char('['))) {
            // PLProg's sections (PL110 manual 5.4 "[Init]", "[Main]", the timed interrupts of
            // SM16/SM17): a listing is one main program, so say what to write instead.
            QString firstScan;
            for (const SystemDevice &d : m_target.systemDevices)
                if (d.role == SystemRole::FirstScan)
                    firstScan = d.device;
            if (firstScan.isEmpty())
                error(lineNumber, token.column,
                      tr("Program sections such as '%1' are not supported: a listing is one "
                         "main program, run at every scan")
                          .arg(token.text.left(40)));
            else
                error(lineNumber, token.column,
                      tr("Program sections such as '%1' are not supported: a listing is one "
                         "main program, run at every scan; put what runs once under LD %2 (ON "
                         "in the first scan). Interrupt programs are not supported")
                          .arg(token.text.left(40), firstScan));
            return;
        }
        QString best;
        int bestDistance = 3;
        for (const InstructionSpec &s : m_target.instructions) {
            QStringList names = s.aliases;
            names.prepend(s.mnemonic);
            for (const QString &n : names) {
                const int d = distance(token.text.left(16), n);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = n;
                }
            }
        }
        const QString shown = token.text.left(40);
        if (best.isEmpty())
            error(lineNumber, token.column,
                  tr("Unknown instruction '%1' for %2").arg(shown, m_target.displayName));
        else
            error(lineNumber, token.column,
                  tr("Unknown instruction '%1' for %2; did you mean %3?")
                      .arg(shown, m_target.displayName, best));
    }

    // Specs sharing this spec's mnemonic that take an infix operand: VPC compares
    // ("LD p01<p00") and transfers ("OUT p21,p12").
    const InstructionSpec *infixVariant(const InstructionSpec *base, CompareOp compare,
                                        TransferOp transfer) const {
        for (const InstructionSpec &s : m_target.instructions) {
            if (s.mnemonic != base->mnemonic && !s.aliases.contains(base->mnemonic))
                continue;
            if (compare != CompareOp::None && s.compare == compare && s.mode == base->mode &&
                s.op == base->op)
                return &s;
            if (transfer != TransferOp::None && s.op == Op::Transfer && s.transfer == transfer &&
                s.negated == base->negated)
                return &s;
        }
        return nullptr;
    }

    bool readInfix(Instruction *ins, const Token &token, int lineNumber) {
        const InstructionSpec *base = ins->spec;
        QStringView text = token.text;
        // Transfers: "d,s", "d+s", "d-s".
        for (auto [symbol, transfer] : {std::pair{',', TransferOp::Assign},
                                        {'+', TransferOp::Add},
                                        {'-', TransferOp::Subtract}}) {
            const qsizetype at = text.indexOf(QLatin1Char(symbol), 1);
            if (at < 0)
                continue;
            const InstructionSpec *s = infixVariant(base, CompareOp::None, transfer);
            if (!s)
                continue;
            ins->spec = s;
            return readPair(ins, token, at, 1, lineNumber);
        }
        if (const std::optional<CompareAt> c = findCompare(text)) {
            const InstructionSpec *s = infixVariant(base, c->op, TransferOp::None);
            if (!s) {
                error(lineNumber, token.column + static_cast<int>(c->at),
                      tr("%1 cannot compare values").arg(base->mnemonic));
                return false;
            }
            ins->spec = s;
            return readPair(ins, token, c->at, static_cast<int>(c->length), lineNumber);
        }
        return true; // not infix: the caller reads it as a plain operand
    }

    bool readPair(Instruction *ins, const Token &token, qsizetype at, int symbolLength,
                  int lineNumber) {
        const Token left{token.text.left(at), token.column};
        const Token right{token.text.mid(at + symbolLength),
                          token.column + static_cast<int>(at) + symbolLength};
        const auto &specs = ins->spec->operands;
        const OperandKind leftKind = specs.empty() ? OperandKind::WordSource : specs[0].kind;
        const OperandKind rightKind = specs.size() < 2 ? OperandKind::WordSource : specs[1].kind;
        if (right.text.isEmpty()) {
            error(lineNumber, right.column,
                  tr("A second operand is missing after '%1'").arg(token.text));
            return false;
        }
        Operand a;
        Operand b;
        if (!readOperand(leftKind, left, lineNumber, &a) ||
            !readOperand(rightKind, right, lineNumber, &b) ||
            !constantFits(*ins, leftKind, a, left, lineNumber) ||
            !constantFits(*ins, rightKind, b, right, lineNumber))
            return false;
        ins->operands = {a, b};
        return true;
    }

    bool readOperands(Instruction *ins, std::vector<Token> tokens, int lineNumber,
                      const Token &mnemonic) {
        for (const Token &t : tokens) {
            if (t.text.size() > (t.quoted ? kMaxTextLength : kMaxTokenLength)) {
                error(lineNumber, t.column,
                      tr("'%1...' is too long for an operand").arg(t.text.left(20)));
                return false;
            }
            if (t.unterminated) {
                error(lineNumber, t.column,
                      tr("The text \"%1\" has no closing quote; a quote inside a text is "
                         "written twice (\"\")")
                          .arg(t.text.left(20)));
                return false;
            }
        }
        // An infix operand is one token holding two operands.
        if (tokens.size() == 1 && !tokens[0].quoted) {
            const bool contact = isContact(ins->spec->op);
            const bool output = ins->spec->op == Op::Out;
            const QString &t = tokens[0].text;
            const bool looksInfix =
                (contact && (t.contains(QLatin1Char('<')) || t.contains(QLatin1Char('>')) ||
                             t.contains(QLatin1Char('=')))) ||
                (output &&
                 (t.indexOf(QLatin1Char(','), 1) > 0 || t.indexOf(QLatin1Char('+'), 1) > 0 ||
                  t.indexOf(QLatin1Char('-'), 1) > 0));
            if (looksInfix) {
                const InstructionSpec *before = ins->spec;
                if (!readInfix(ins, tokens[0], lineNumber))
                    return false;
                if (ins->spec != before)
                    return true;
            }
        }
        // "TIM 000" written with a space is one operand (CPM1 "LD TIM 000").
        for (std::size_t i = 0; i + 1 < tokens.size(); ++i) {
            if (!tokens[i].quoted && !tokens[i + 1].quoted && isLetters(tokens[i].text) &&
                allDigits(QStringView(tokens[i + 1].text).left(1))) {
                const bool isPrefix =
                    std::any_of(m_target.areas.begin(), m_target.areas.end(), [&](const Area &a) {
                        const auto same = [&](const QString &p) {
                            return !p.isEmpty() &&
                                   p.trimmed().compare(tokens[i].text, Qt::CaseInsensitive) == 0;
                        };
                        return same(a.prefix) ||
                               std::any_of(a.prefixAliases.begin(), a.prefixAliases.end(), same);
                    });
                if (isPrefix) {
                    tokens[i].text += QLatin1Char(' ') + tokens[i + 1].text;
                    tokens.erase(tokens.begin() + static_cast<std::ptrdiff_t>(i) + 1);
                }
            }
        }
        // Operands may also be separated by commas: "MOV K10,D0".
        if (tokens.size() < ins->spec->operands.size()) {
            std::vector<Token> split;
            for (const Token &t : tokens) {
                if (t.quoted) {
                    split.push_back(t);
                    continue;
                }
                int offset = 0;
                for (const QString &part : t.text.split(QLatin1Char(','))) {
                    if (!part.isEmpty() && split.size() <= kMaxTokens)
                        split.push_back({part, t.column + offset});
                    offset += static_cast<int>(part.size()) + 1;
                }
            }
            tokens = std::move(split);
        }
        const auto &specs = ins->spec->operands;
        std::size_t required = 0;
        for (const OperandSpec &s : specs)
            if (!s.optional)
                ++required;
        if (tokens.size() < required) {
            error(lineNumber,
                  tokens.empty() ? mnemonic.column + static_cast<int>(mnemonic.text.size()) + 1
                                 : tokens.back().column,
                  tr("%1 needs %n operand(s): %2", nullptr, static_cast<int>(required))
                      .arg(ins->spec->mnemonic, ins->spec->operandHelp
                                                    ? QString::fromLatin1(ins->spec->operandHelp)
                                                    : QString()));
            return false;
        }
        if (tokens.size() > specs.size()) {
            const Token &extra = tokens[specs.size()];
            error(lineNumber, extra.column,
                  specs.empty() ? tr("%1 takes no operand").arg(ins->spec->mnemonic)
                                : tr("Unexpected '%1': %2 takes %n operand(s)", nullptr,
                                     static_cast<int>(specs.size()))
                                      .arg(extra.text.left(40), ins->spec->mnemonic));
            return false;
        }
        bool ok = true;
        for (std::size_t i = 0; i < tokens.size(); ++i) {
            Operand o;
            if (readOperand(specs[i].kind, tokens[i], lineNumber, &o)) {
                if (writtenAsBank(o, tokens[i].text))
                    m_lineAliases.push_back(ins->operands.size());
                ins->operands.push_back(o);
            } else {
                ok = false;
            }
        }
        // A constant fits the width of the instruction's devices, wherever they stand: MOV
        // 100000 VD0 is 32-bit (the constant is read before the double word).
        for (std::size_t i = 0; ok && i < tokens.size(); ++i)
            ok = constantFits(*ins, specs[i].kind, ins->operands[i], tokens[i], lineNumber);
        return ok;
    }

    // A constant must fit the word it is written into: what the PLC can store, not what makes
    // sense for the instruction: set values are the checks' business (OP004), which must see
    // them, so only their CPM1 BCD form is a syntax matter here.
    bool constantFits(const Instruction &ins, OperandKind kind, const Operand &o,
                      const Token &token, int lineNumber) {
        if (o.kind != Operand::Kind::Constant || kind == OperandKind::Label)
            return true;
        const Constant &c = o.constant;
        if (m_target.constants.bcdSetValues && kind == OperandKind::SetValue &&
            c.style != Constant::Style::Bcd) {
            error(lineNumber, token.column,
                  tr("%1: a set value is a BCD constant #0000..#9999 or a channel")
                      .arg(token.text.left(40)));
            return false;
        }
        if (kind == OperandKind::SetValue)
            return true;
        // 32-bit when the instruction is (Vigor DMOV H00310035 D4) or works on a 32-bit
        // device (Vigor C200..C255).
        const bool wide =
            (ins.spec && ins.spec->doubleWord) ||
            std::any_of(ins.operands.begin(), ins.operands.end(), [&](const Operand &x) {
                return x.kind == Operand::Kind::Device && x.address.area >= 0 &&
                       m_target.area(x.address.area).wordBits == 32;
            });
        qint64 low = wide ? -2147483648LL : -32768;
        qint64 high = wide ? 2147483647LL : 32767;
        if (c.style == Constant::Style::Hex) {
            low = 0;
            high = wide ? 0xFFFFFFFFLL : 0xFFFF;
        } else if (c.style == Constant::Style::Bcd) {
            low = 0;
            high = 9999; // four BCD digits
        } else if (const int digits = m_target.limits.decimalDigits; digits > 0) {
            low = 0;
            high = 1;
            for (int k = 0; k < digits; ++k)
                high *= 10;
            --high; // VPC: 0000..9999
        }
        if (c.value < low || c.value > high) {
            error(lineNumber, token.column,
                  tr("%1 is out of range: %2..%3 fit here")
                      .arg(token.text.left(40), formatConstant(m_target, {low, c.style}),
                           formatConstant(m_target, {high, c.style})));
            return false;
        }
        return true;
    }

    bool looksConstant(const QString &t) const {
        if (t.isEmpty())
            return false;
        const QChar c = t[0].toUpper();
        const ConstantNotation &rules = m_target.constants;
        if (rules.prefixed && (c == QLatin1Char('K') || c == QLatin1Char('H')) && t.size() > 1 &&
            (t[1].isDigit() || t[1] == QLatin1Char('-') ||
             (c == QLatin1Char('H') && t[1].isLetterOrNumber())))
            return true;
        if (rules.bcd && c == QLatin1Char('#'))
            return true;
        if (rules.plain) {
            // A sign alone is an FM operator, not a number; PL110 also writes "#0" and, with
            // a sign, "#-1" (PL110 manual 4.2.20: IF VD8 == #-1).
            qsizetype digit = rules.hashPlain && c == QLatin1Char('#') ? 1 : 0;
            if (t.size() > digit && (t[digit] == QLatin1Char('-') || t[digit] == QLatin1Char('+')))
                ++digit;
            return t.size() > digit && t[digit].isDigit();
        }
        return false;
    }

    // Timer and counter numbers may be written without their prefix where the mnemonic names
    // the kind already: CPM1 "TIM 000", VPC fused "TIM00".
    QString withPrefix(OperandKind kind, const QString &text) const {
        if (!allDigits(text))
            return text;
        const AreaKind wanted =
            kind == OperandKind::TimerNumber ? AreaKind::Timer : AreaKind::Counter;
        for (const Area &a : m_target.areas)
            if (a.kind == wanted)
                return a.prefix + text;
        return text;
    }

    bool readOperand(OperandKind kind, const Token &token, int lineNumber, Operand *out) {
        const QString &t = token.text;
        // A text in quotes stands in a text slot only, and a text slot takes nothing else.
        if (token.quoted || kind == OperandKind::Text) {
            if (token.quoted && kind == OperandKind::Text) {
                out->kind = Operand::Kind::String;
                out->text = t;
                return true;
            }
            error(lineNumber, token.column,
                  token.quoted ? tr("\"%1\": a text in quotes is not expected here").arg(t.left(40))
                               : tr("%1: a text in double quotes is expected here, as \"%2\"")
                                     .arg(t.left(40), t.left(40)));
            return false;
        }
        if (t.size() > kMaxTokenLength) {
            error(lineNumber, token.column,
                  tr("'%1...' is too long for an operand").arg(t.left(20)));
            return false;
        }
        auto fail = [&](const AddressError &e) {
            error(lineNumber, token.column + e.column, e.message);
            return false;
        };
        if (hasOperandModifiers(m_target, t))
            return readModified(kind, token, lineNumber, out);
        switch (kind) {
        case OperandKind::Label: {
            if (!allDigits(t) || t.size() > 4) {
                error(lineNumber, token.column,
                      tr("%1: a label number is expected").arg(t.left(40)));
                return false;
            }
            // The range of jump numbers is a check (NE006), not a syntax error.
            const int label = t.toInt();
            out->kind = Operand::Kind::Constant;
            out->constant = Constant{label, Constant::Style::Plain};
            return true;
        }
        case OperandKind::Constant:
        case OperandKind::Count: {
            if (m_target.constants.wordsInConstantSlots && !looksConstant(t)) {
                // PL110 FM operators and time bases are words, kept verbatim.
                out->kind = Operand::Kind::Text;
                out->text = t;
                return true;
            }
            auto c = parseConstant(m_target, t);
            if (auto *e = std::get_if<AddressError>(&c))
                return fail(*e);
            out->kind = Operand::Kind::Constant;
            out->constant = std::get<Constant>(c);
            return true;
        }
        case OperandKind::WordSource:
        case OperandKind::SetValue:
            if (looksConstant(t)) {
                auto c = parseConstant(m_target, t);
                if (auto *e = std::get_if<AddressError>(&c))
                    return fail(*e);
                out->kind = Operand::Kind::Constant;
                out->constant = std::get<Constant>(c);
                return true;
            }
            break;
        default:
            break;
        }
        const bool number = kind == OperandKind::TimerNumber || kind == OperandKind::CounterNumber;
        if (!number && looksConstant(t) &&
            std::holds_alternative<Constant>(parseConstant(m_target, t))) {
            // "OUT K5": say what is wrong with it rather than that K5 is no device.
            error(lineNumber, token.column,
                  tr("%1 is a constant; a device is expected here").arg(t.left(40)));
            return false;
        }
        const QString text = number ? withPrefix(kind, t) : t;
        auto a = parseAddress(m_target, text, m_model);
        if (auto *e = std::get_if<AddressError>(&a)) {
            AddressError shifted = *e;
            shifted.column = std::max(0, shifted.column - static_cast<int>(text.size() - t.size()));
            return fail(shifted);
        }
        const Address address = std::get<Address>(a);
        const QString expected = expectedDevice(m_target, address, kind);
        if (!expected.isEmpty()) {
            error(lineNumber, token.column,
                  tr("%1: %2 is expected here").arg(t.left(40), expected));
            return false;
        }
        out->kind = Operand::Kind::Device;
        out->address = address;
        return true;
    }

    // K4Y0, D0E0, K10F0, as in PLC concepts (WPLSoft family): words, in the word slots of
    // application instructions and set values only.
    bool readModified(OperandKind kind, const Token &token, int lineNumber, Operand *out) {
        const QString &t = token.text;
        auto parsed = parseOperand(m_target, t, m_model);
        if (const AddressError *e = std::get_if<AddressError>(&parsed)) {
            error(lineNumber, token.column + e->column, e->message);
            return false;
        }
        const Operand o = std::get<Operand>(parsed);
        const bool wordSlot = kind == OperandKind::WordSource || kind == OperandKind::WordDest ||
                              kind == OperandKind::SetValue;
        if (!wordSlot) {
            error(lineNumber, token.column,
                  o.digits > 0 ? tr("%1 is a word (%2 bits); a single device is expected here")
                                     .arg(t.left(40))
                                     .arg(o.digits * 4)
                               : tr("%1: an index register modifies only the word operands of "
                                    "application instructions and set values")
                                     .arg(t.left(40)));
            return false;
        }
        if (kind == OperandKind::WordDest && o.kind == Operand::Kind::Constant) {
            error(lineNumber, token.column,
                  tr("%1 is a constant; a device is expected here").arg(t.left(40)));
            return false;
        }
        *out = o;
        return true;
    }

    const Target &m_target;
    const ModelVariant *m_model;
    ParseResult m_result;
    int m_step = 0;
    bool m_tooMany = false;
    std::vector<std::size_t> m_lineAliases; // operands of this line written as a bank
    std::vector<std::pair<std::size_t, std::size_t>> m_bankAliases; // (instruction, operand)
};

} // namespace

QString expectedDevice(const Target &target, const Address &address, OperandKind kind) {
    const Area &area = target.area(address.area);
    // The parser's context: the texts are its own.
    switch (kind) {
    case OperandKind::TimerNumber:
        return area.kind == AreaKind::Timer
                   ? QString()
                   : QCoreApplication::translate("rung::model::InstructionList", "a timer");
    case OperandKind::CounterNumber:
        return area.kind == AreaKind::Counter
                   ? QString()
                   : QCoreApplication::translate("rung::model::InstructionList", "a counter");
    case OperandKind::StepRelay:
        return area.prefix == QLatin1String("S")
                   ? QString()
                   : QCoreApplication::translate("rung::model::InstructionList", "a step relay");
    case OperandKind::BitSource:
        if ((area.kind == AreaKind::Word || area.kind == AreaKind::Channel) && address.bit < 0 &&
            area.numbering != Numbering::ChannelBit)
            return QCoreApplication::translate("rung::model::InstructionList", "a bit device");
        return {};
    default:
        return {};
    }
}

ParseResult parseInstructionList(const Target &target, const QString &text,
                                 const ModelVariant *model) {
    return Parser(target, model).run(text);
}

} // namespace rung::model
