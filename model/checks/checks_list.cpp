#include "model/checks/checks.h"
#include "model/checks/checks_internal.h"
#include "model/checks/operand_rules.h"
#include "model/checks/unmodelled.h"
#include "model/convert/convert.h"
#include "model/ladder/network.h"
#include "model/listing/structure.h"
#include "model/tr.h"

#include <QCoreApplication>

#include <algorithm>
#include <map>
#include <optional>

// The listing checks (docs/diagnostics.md). Each finding remembers the instruction it is
// about, so the ladder checks can show it on the rung that instruction came from.

namespace rung::model::detail {

namespace {

class ListChecker {
public:
    ListChecker(const InstructionList &list, const CheckOptions &options, bool verifyMoves = true)
        : m_verifyMoves(verifyMoves)
        , m_list(list)
        , m_t(*list.target)
        , m_model(options.model ? options.model : &list.target->defaultModel())
        , m_formOnly(options.formOnly)
        , m_parsedLinesOnly(options.parsedLinesOnly)
        , m_source(options.source) {}

    void setForms(bool on) { m_withForms = on; }

    std::vector<Finding> run() {
        spans();
        if (m_parsedLinesOnly) {
            operands();
            duplicates();
            return std::move(m_found);
        }
        blocksAndStack();
        if (m_formOnly) {
            std::erase_if(m_found, [](const Finding &f) {
                return !f.diagnostic.code.startsWith(QLatin1String("FZ"));
            });
            return std::move(m_found);
        }
        endAndNesting(m_list, m_found);
        offerEnd();
        operands();
        switchedElements(m_list, m_found);
        duplicates();
        length();
        // Read only here: a form-only check (betterForm) needs no reading of the whole list.
        structure(listToLadderProblems(m_list));
        return std::move(m_found);
    }

private:
    Finding &add(const char *code, Severity severity, int index, const QString &message) {
        return addFinding(m_found, m_list, code, severity, index, message);
    }

    // EN001 (END is missing): END on a line of its own after the last instruction's line, that
    // line kept as typed.
    void offerEnd() {
        const InstructionSpec *end = m_t.findInstruction(Op::End);
        if (!end || !m_source || size() == 0)
            return;
        for (Finding &f : m_found) {
            const int line = f.diagnostic.location.line;
            if (f.diagnostic.code != QLatin1String("EN001") || line <= 0)
                continue;
            if (m_sourceLines.isEmpty())
                m_sourceLines = m_source->split(QLatin1Char('\n'));
            QString last = m_sourceLines.value(line - 1);
            if (last.endsWith(QLatin1Char('\r')))
                last.chop(1);
            Fix fix;
            fix.label = ChecksTr::tr("Append %1").arg(end->mnemonic);
            fix.firstLine = fix.lastLine = line;
            fix.listing = last + QLatin1Char('\n') + end->mnemonic + QLatin1Char('\n');
            f.diagnostic.fix = std::move(fix);
        }
    }

    const Instruction &at(int i) const { return m_list.instructions[static_cast<std::size_t>(i)]; }
    int size() const { return static_cast<int>(m_list.instructions.size()); }
    QString name(int i) const { return at(i).spec ? at(i).spec->mnemonic : QString(); }

    // The rungs as the converter reads them (model::rungSpans).
    void spans() { m_spans = rungSpans(m_list.instructions); }

    std::pair<int, int> spanOf(int index) const {
        const RungSpan span = model::spanOf(m_spans, index);
        return {span.first, span.last};
    }

    // The rung holding `index` as the converter writes it back (cached by its span).
    struct SpanForm {
        int first = 0;
        int last = 0;
        RungForm form;
        // Several findings of one rung offer the same rewrite: printed once.
        std::optional<QString> printed;
        // How often each fuzzy form occurs in the rung as written (betterForm), by code.
        std::map<QString, qsizetype> formCounts;
    };

    SpanForm &rungForm(int index) {
        const auto span = spanOf(index);
        auto it = m_forms.find(span.first);
        if (it == m_forms.end())
            it = m_forms
                     .emplace(span.first, SpanForm{span.first, span.second,
                                                   canonicalForm(m_list, span.first, span.second)})
                     .first;
        return it->second;
    }

    bool isFuzzy(int index) {
        if (!m_withForms)
            return false;
        const RungForm &form = rungForm(index).form;
        return form.known && !form.canonical;
    }

    QString printed(const std::vector<Instruction> &instructions) const {
        InstructionList part;
        part.target = m_list.target;
        part.instructions = instructions;
        PrintOptions o;
        o.comments = false;
        return printInstructionList(part, o);
    }

    // A fix replacing the lines of the rung [first, last) with this listing text.
    void offer(Finding &f, int first, int last, const QString &listing, const QString &label) {
        const int line = at(first).line;
        if (line <= 0 || listing.isEmpty())
            return;
        Fix fix;
        fix.label = label;
        fix.firstLine = line;
        fix.lastLine = at(last - 1).line;
        fix.listing = listing;
        f.diagnostic.fix = std::move(fix);
    }

    void offerCanonical(Finding &f, int index) {
        SpanForm &span = rungForm(index);
        if (!span.form.known || span.form.canonical || span.form.rewrite.empty())
            return;
        if (!span.printed)
            span.printed = printed(span.form.rewrite);
        offer(f, span.first, span.last, *span.printed,
              ChecksTr::tr("Rewrite the rung in the canonical form"));
    }

    // Whether the rung [first, last) rewritten as `rewrite` has the form `code` less often: in a
    // rung of stacked blocks, moving one single contact may only give the next join the same
    // form, and that is no fix.
    bool betterForm(int first, int last, const std::vector<Instruction> &rewrite,
                    const char *code) {
        if (!m_verifyMoves)
            return true;
        const auto count = [&](std::vector<Instruction> instructions) {
            InstructionList part;
            part.target = m_list.target;
            part.instructions = std::move(instructions);
            CheckOptions o;
            o.model = m_model;
            o.formOnly = true;
            const auto found = ListChecker(part, o, false).run();
            return std::count_if(found.begin(), found.end(), [&](const Finding &f) {
                return f.diagnostic.code == QLatin1String(code);
            });
        };
        SpanForm &span = rungForm(first);
        auto [before, fresh] = span.formCounts.try_emplace(QString::fromLatin1(code), 0);
        if (fresh)
            before->second =
                count({m_list.instructions.begin() + first, m_list.instructions.begin() + last});
        return count(rewrite) < before->second;
    }

    // Fuzzy forms (PLC concepts (WPLSoft family) 1.7, 1.8), block limits, and the branch stack.
    void blocksAndStack() {
        struct Block {
            int first = 0;      // instruction index that opened it
            bool single = true; // one contact only
        };
        std::vector<Block> blocks;
        int mps = 0;
        int run = 0;
        Op runOp = Op::Nop;
        for (int i = 0; i < size(); ++i) {
            const Op op = at(i).op();
            if (joinsBlocks(op)) {
                run = op == runOp ? run + 1 : 1;
                runOp = op;
                if (m_t.limits.maxBlocksInRow > 0 && run == m_t.limits.maxBlocksInRow + 1)
                    add("FZ003", Severity::Error, i,
                        ChecksTr::tr("More than %1 %2 in a row: the PLC rejects the program")
                            .arg(m_t.limits.maxBlocksInRow)
                            .arg(name(i)));
            } else {
                run = 0;
                runOp = Op::Nop;
            }
            switch (op) {
            case Op::Load:
                if (spanOf(i).first == i)
                    blocks.clear(); // a new rung
                blocks.push_back({i, true});
                break;
            case Op::And:
            case Op::Or:
            case Op::Invert:
                if (!blocks.empty())
                    blocks.back().single = false;
                break;
            case Op::AndBlock:
            case Op::OrBlock: {
                if (blocks.size() < 2)
                    break; // the conversion reports the missing block
                const Block second = blocks.back();
                const Block first = blocks[blocks.size() - 2];
                // Whether the rung is written in a fuzzy form costs a round trip through the
                // ladder: asked only where one of the forms below could be reported.
                const bool stacked = blocks.size() > 2;
                const bool singleOr = op == Op::OrBlock && second.single;
                const bool singleFirst = first.single && first.first + 1 == second.first &&
                                         !stackBetween(m_list, first.first, i);
                // Otherwise: the nesting the drawing needs, written as the converter writes it.
                const bool fuzzy = (stacked || singleOr || singleFirst) && isFuzzy(i);
                if (fuzzy && stacked) {
                    Finding &f = add(
                        op == Op::AndBlock ? "FZ001" : "FZ002", Severity::Warning, i,
                        // In the family's words: CPM1 and VPC write AND LD / OR LD.
                        op == Op::AndBlock
                            ? ChecksTr::tr(
                                  "Stacked %1: combine each block with %1 as soon as it is "
                                  "complete")
                                  .arg(name(i))
                            : ChecksTr::tr("Stacked %1: %n blocks are open; an OR chain needs less "
                                           "stack",
                                           nullptr, static_cast<int>(blocks.size()))
                                  .arg(name(i)));
                    offerCanonical(f, i);
                } else if (fuzzy && singleOr) {
                    Finding &f =
                        add("FZ002", Severity::Warning, i,
                            ChecksTr::tr("A single contact joined with %1 is simpler as %2")
                                .arg(name(i), m_t.findInstruction(Op::Or)
                                                  ? m_t.findInstruction(Op::Or)->mnemonic
                                                  : QString()));
                    offerCanonical(f, i);
                } else if (fuzzy && op == Op::AndBlock && !inSeries(m_list, first.first, i) &&
                           rungForm(i).form.known && !rungForm(i).form.rewrite.empty()) {
                    // A block with a branch after a single contact: moving the contact behind
                    // the block would drop the ANB but reorder what needs no move. The rung as
                    // the ladder draws it keeps the contact in front, the block in its simplest
                    // form (LD X0 / LD X1 / OR X2 / ANB).
                    Finding &f = add("FZ004", Severity::Warning, i,
                                     ChecksTr::tr("The block after a single contact can be written "
                                                  "shorter; the contact stays in front of the %1")
                                         .arg(name(i)));
                    offerCanonical(f, i);
                } else if (fuzzy) {
                    const bool orBlock = op == Op::OrBlock;
                    // A block of contacts in series stays where it is written (moveBehind).
                    const bool series = !orBlock && inSeries(m_list, first.first, i);
                    Finding &f = add(
                        orBlock ? "FZ005" : "FZ004", Severity::Warning, i,
                        orBlock ? ChecksTr::tr(
                                      "A single device in parallel with a block belongs on the "
                                      "lower row: the block first, then an OR, drops the %1")
                                      .arg(name(i))
                        : series
                            ? ChecksTr::tr("Contacts in series need no %1: each can follow the "
                                           "one before it as %2")
                                  .arg(name(i), m_t.findInstruction(Op::And)
                                                    ? m_t.findInstruction(Op::And)->mnemonic
                                                    : QString())
                            : ChecksTr::tr("The block after a single contact can move to the front "
                                           "and drop the %1")
                                  .arg(name(i)));
                    const auto [rungFirst, rungLast] = spanOf(i);
                    const auto moved =
                        moveBehind(m_list, spanOf(i), first.first, i, orBlock ? Op::Or : Op::And);
                    if (!moved ||
                        !betterForm(rungFirst, rungLast, *moved, orBlock ? "FZ005" : "FZ004")) {
                        m_found.pop_back(); // moving it would only make the next join the same
                    } else {
                        offer(f, rungFirst, rungLast, printed(*moved),
                              orBlock
                                  ? ChecksTr::tr("Put the single device below the block and drop "
                                                 "the %1")
                                        .arg(name(i))
                              : series ? ChecksTr::tr("Join the contacts in series and drop the %1")
                                             .arg(name(i))
                                       : ChecksTr::tr("Move the block to the front and drop the %1")
                                             .arg(name(i)));
                    }
                }
                blocks.pop_back();
                blocks.back().single = false;
                break;
            }
            case Op::Push:
                ++mps;
                if (mps == m_t.limits.stackDepth + 1)
                    add("ST001", Severity::Error, i,
                        ChecksTr::tr("MPS nests more than %1 deep").arg(m_t.limits.stackDepth));
                break;
            case Op::ReadStack:
            case Op::Pop:
                if (mps == 0)
                    add("ST002", Severity::Error, i,
                        ChecksTr::tr("%1 without a matching MPS").arg(name(i)));
                else if (op == Op::Pop)
                    --mps;
                if (i + 1 < size() && isOutput(at(i + 1).op()) &&
                    !isUnconditional(at(i + 1).op()) && at(i + 1).op() != Op::Push) {
                    if (auto lifted = liftOutput(m_list, spanOf(i), i); lifted && isFuzzy(i)) {
                        Finding &f =
                            add("FZ006", Severity::Warning, i + 1,
                                ChecksTr::tr(
                                    "An output with no contacts of its own belongs on top of the "
                                    "branch and needs no %1")
                                    .arg(name(i)));
                        const auto [rungFirst, rungLast] = spanOf(i);
                        offer(f, rungFirst, rungLast, printed(*lifted),
                              ChecksTr::tr("Put the output on top and drop the %1").arg(name(i)));
                    }
                }
                break;
            default:
                break;
            }
            if (isOutput(op)) {
                const bool rungEnds = i + 1 >= size() ||
                                      loadsAfterOutput(m_list.instructions, i + 1) ||
                                      isUnconditional(at(i + 1).op());
                if (rungEnds && mps > 0) {
                    add("ST003", Severity::Error, i,
                        ChecksTr::tr("%n MPS left without MPP at the end of the rung", nullptr,
                                     mps));
                    mps = 0;
                }
            }
        }
    }

    Location location(int i) const {
        Location l;
        l.line = at(i).line;
        l.column = at(i).column;
        return l;
    }

    // The system devices the PLC itself drives (always-on, clocks, first scan, scan times).
    const SystemDevice *driveBySystem(const Address &a) {
        if (!m_systemParsed) {
            m_systemParsed = true;
            for (const SystemDevice &d : m_t.systemDevices) {
                if (!drivenByPlc(d))
                    continue;
                const auto parsed = parseAddress(m_t, d.device, nullptr);
                if (const Address *at = std::get_if<Address>(&parsed))
                    m_systemDriven.emplace(*at, &d);
            }
        }
        const auto it = m_systemDriven.find(a);
        return it == m_systemDriven.end() ? nullptr : it->second;
    }

    // The instructions that drive a relay (a bit); RST and the zone reset also clear timers,
    // counters and registers.
    static bool drivesABit(Op op) {
        return op == Op::Out || op == Op::Set || op == Op::Keep || op == Op::PulseRise ||
               op == Op::PulseFall;
    }

    // Moves the finding to the column of `device` on the instruction's line, when the source
    // text is at hand.
    void atOperand(Finding &f, int i, const QString &device) {
        if (!m_source || at(i).line <= 0)
            return;
        if (m_sourceLines.isEmpty())
            m_sourceLines = m_source->split(QLatin1Char('\n'));
        const QString line = m_sourceLines.value(at(i).line - 1);
        const qsizetype found =
            line.indexOf(device, std::max(0, at(i).column), Qt::CaseInsensitive);
        if (found >= 0)
            f.diagnostic.location.column = static_cast<int>(found) + 1;
    }

    // Moves the finding to the column of operand k when it is a constant or a word (SBIT V3
    // 16: the 16), found as a whole word after the mnemonic; the mnemonic's column otherwise.
    void atWordOperand(Finding &f, int i, std::size_t k) {
        const Instruction &ins = at(i);
        if (!m_source || ins.line <= 0 || k >= ins.operands.size())
            return;
        if (m_sourceLines.isEmpty())
            m_sourceLines = m_source->split(QLatin1Char('\n'));
        const auto written = [this](const Operand &o) {
            return o.kind == Operand::Kind::Constant ? formatConstant(m_t, o.constant)
                   : o.kind == Operand::Kind::Text   ? o.text.trimmed()
                                                     : formatOperand(m_t, o);
        };
        const QString wanted = written(ins.operands[k]);
        int skip = 0; // earlier operands written the same way
        for (std::size_t j = 0; j < k; ++j)
            if (written(ins.operands[j]).compare(wanted, Qt::CaseInsensitive) == 0)
                ++skip;
        QString line = m_sourceLines.value(ins.line - 1);
        if (const qsizetype comment = line.indexOf(QLatin1Char(';')); comment >= 0)
            line.truncate(comment);
        qsizetype pos = std::max(0, ins.column - 1);
        bool mnemonic = true;
        while (pos < line.size()) {
            while (pos < line.size() && line[pos].isSpace())
                ++pos;
            qsizetype end = pos;
            while (end < line.size() && !line[end].isSpace())
                ++end;
            if (end == pos)
                break;
            if (!mnemonic &&
                QStringView(line).mid(pos, end - pos).compare(wanted, Qt::CaseInsensitive) == 0 &&
                skip-- == 0) {
                f.diagnostic.location.column = static_cast<int>(pos) + 1;
                return;
            }
            mnemonic = false;
            pos = end;
        }
    }

    void operands() {
        std::map<int, std::pair<int, int>> bankUse; // number -> (timer use, counter use)
        for (int i = 0; i < size(); ++i) {
            const Instruction &ins = at(i);
            if (!ins.spec)
                continue;
            // The table's narrower rules, read by the simulator too: what it refuses, check does.
            // What the simulator will not model is said before a simulation is tried.
            if (ins.spec->function == ApplyFunction::NotSimulated)
                add("SIM100", Severity::Warning, i, notSimulatedMessage(*ins.spec));
            for (const UnmodelledUse &use : unmodelledUses(m_t, ins)) {
                Finding &f = add("SIM101", Severity::Warning, i, use.message);
                atOperand(f, i,
                          formatOperand(m_t, ins.operands[static_cast<std::size_t>(use.operand)]));
            }
            for (const OperandBreach &b : operandBreaches(m_t, ins)) {
                const Operand &o = ins.operands[static_cast<std::size_t>(b.operand)];
                Finding &f = add("OP005", Severity::Error, i, b.message);
                if (o.kind == Operand::Kind::Device)
                    atOperand(f, i, formatOperand(m_t, o));
                else
                    atWordOperand(f, i, static_cast<std::size_t>(b.operand));
            }
            for (std::size_t k = 0; k < ins.operands.size(); ++k) {
                const Operand &o = ins.operands[k];
                const OperandKind kind = k < ins.spec->operands.size() ? ins.spec->operands[k].kind
                                                                       : OperandKind::BitSource;
                if (o.kind == Operand::Kind::Constant && kind == OperandKind::SetValue) {
                    const qint64 v = o.constant.value;
                    const bool bcd = o.constant.style == Constant::Style::Bcd;
                    if ((bcd && (v < 0 || v > 9999)) || (!bcd && (v < 0 || v > 32767)))
                        add("OP004", Severity::Error, i,
                            ChecksTr::tr("Set value %1 is out of range").arg(v));
                }
                if (o.kind != Operand::Kind::Device)
                    continue;
                const Area &area = m_t.area(o.address.area);
                const auto range = m_t.range(o.address.area, m_model);
                if (!range || o.address.index < range->first || o.address.index > range->second) {
                    // The address rules word the message ("o20 is beyond VPC2416's outputs").
                    auto check = parseAddress(m_t, formatAddress(m_t, o.address), m_model);
                    if (auto *e = std::get_if<AddressError>(&check))
                        add("OP001", Severity::Error, i, e->message);
                }
                const bool destination =
                    kind == OperandKind::BitDest || kind == OperandKind::WordDest;
                const QString device = formatOperand(m_t, o);
                // A digit-designated destination writes each of its bits (K4M9000: M9000..).
                const SystemDevice *driven = driveBySystem(o.address);
                for (int b = 1; destination && !driven && b < o.digits * 4; ++b)
                    driven = driveBySystem(offsetAddress(m_t, o.address, b, m_model));
                if (destination && !area.writable && ins.op() != Op::Reset) {
                    atOperand(
                        add("OP002", Severity::Error, i,
                            ChecksTr::tr("%1 cannot be written: the program only reads it (%2)")
                                .arg(device, QCoreApplication::translate("rung::model::Target",
                                                                         area.description))),
                        i, device);
                } else if (destination && driven) {
                    atOperand(
                        add("OP002", Severity::Error, i,
                            ChecksTr::tr("%1 cannot be written: the PLC drives it (%2)")
                                .arg(device, QCoreApplication::translate("rung::model::Target",
                                                                         driven->description))),
                        i, device);
                } else if (kind == OperandKind::BitDest && drivesABit(ins.op()) &&
                           (area.kind == AreaKind::Timer || area.kind == AreaKind::Counter ||
                            (area.kind == AreaKind::Word && o.address.bit < 0))) {
                    atOperand(add("OP002", Severity::Error, i,
                                  ChecksTr::tr("%1 cannot drive %2: %3 are not relays")
                                      .arg(name(i), device,
                                           QCoreApplication::translate("rung::model::Target",
                                                                       area.description))),
                              i, device);
                }
                if (area.bank >= 0 &&
                    (area.kind == AreaKind::Timer || area.kind == AreaKind::Counter)) {
                    auto &use = bankUse[o.address.index];
                    (area.kind == AreaKind::Timer ? use.first : use.second) = i + 1;
                }
            }
        }
        for (const auto &[n, use] : bankUse)
            if (use.first && use.second) {
                Finding &f =
                    add("OP003", Severity::Error, use.second - 1,
                        ChecksTr::tr(
                            "Number %1 is used as a timer and as a counter; they share one bank")
                            .arg(n));
                f.diagnostic.related.push_back(location(use.first - 1));
            }
    }

    void duplicates() {
        std::map<Address, int> driven;
        for (int i = 0; i < size(); ++i) {
            const Instruction &ins = at(i);
            if (!drivesCoil(ins.op()) || ins.operands.empty() ||
                ins.operands[0].kind != Operand::Kind::Device)
                continue;
            const Address a = ins.operands[0].address;
            if (a.valid() && m_t.area(a.area).branchMemory)
                continue; // OUT TR 0 in every rung that branches (W353)
            const auto it = driven.find(a);
            if (it == driven.end()) {
                driven.emplace(a, i);
                continue;
            }
            const bool error = m_t.limits.duplicateCoilIsError;
            Finding &f = add(
                "DC001", error ? Severity::Error : Severity::Warning, i,
                error
                    ? ChecksTr::tr("%1 is driven twice; a coil may be driven only once (the first "
                                   "is on line "
                                   "%2)")
                          .arg(formatAddress(m_t, a))
                          .arg(at(it->second).line)
                    : ChecksTr::tr("%1 is driven twice; the later one wins (first on line %2)")
                          .arg(formatAddress(m_t, a))
                          .arg(at(it->second).line));
            if (m_t.console.duplicate) // the VPC console's "Oper duplication"
                f.diagnostic.message =
                    ChecksTr::tr("%1 (the PLC says \"%2\")")
                        .arg(f.diagnostic.message, QString::fromLatin1(m_t.console.duplicate));
            f.diagnostic.related.push_back(location(it->second));
            f.related.push_back(it->second);
            const QString device = formatAddress(m_t, a);
            f.ladderMessage =
                error ? ChecksTr::tr(
                            "%1 is driven twice; a coil may be driven only once (the first is "
                            "in rung "
                            "%2)")
                            .arg(device, QStringLiteral("%1"))
                      : ChecksTr::tr("%1 is driven twice; the later one wins (first in rung %2)")
                            .arg(device, QStringLiteral("%1"));
        }
    }

    void length() {
        int steps = 0;
        for (const Instruction &ins : m_list.instructions)
            steps += instructionSteps(m_t, ins);
        const int limit =
            m_model->programSteps > 0 ? m_model->programSteps : m_t.limits.programSteps;
        if (limit > 0 && steps > limit)
            add("LN001", Severity::Error, size() - 1,
                ChecksTr::tr("The program needs %1 steps; %2 holds %3")
                    .arg(steps)
                    .arg(m_model->name)
                    .arg(limit));
    }

    // What keeps the listing from being drawn, as the conversion finds it, by the documented
    // codes: an output with no condition (OC001), blocks left open or missing (BL001). MRD/MPP
    // without MPS and MPS left open are ST002/ST003, which blocksAndStack() has reported.
    void structure(const std::vector<Diagnostic> &drawing) {
        const auto reported = [this](const char *code, const Location &at) {
            return std::any_of(m_found.begin(), m_found.end(), [&](const Finding &f) {
                return f.diagnostic.code == QLatin1String(code) &&
                       (f.diagnostic.location.line == at.line ||
                        QLatin1String(code) == QLatin1String("ST003"));
            });
        };
        for (const Diagnostic &d : drawing) {
            const bool stack = d.code == QLatin1String("CV004");
            const bool open = d.code == QLatin1String("CV008");
            if ((stack && reported("ST002", d.location)) || (open && reported("ST003", d.location)))
                continue;
            Finding f;
            f.diagnostic = d;
            f.diagnostic.code = d.code == QLatin1String("CV006") ? QStringLiteral("OC001")
                                : stack                          ? QStringLiteral("ST002")
                                : open                           ? QStringLiteral("ST003")
                                                                 : QStringLiteral("BL001");
            for (int i = 0; i < size(); ++i)
                if (at(i).line == d.location.line && at(i).column == d.location.column)
                    f.instruction = i;
            m_found.push_back(std::move(f));
        }
    }

    bool m_verifyMoves = true;
    bool m_withForms = true;
    const InstructionList &m_list;
    const Target &m_t;
    const ModelVariant *m_model;
    bool m_formOnly = false;
    bool m_parsedLinesOnly = false;
    const QString *m_source = nullptr;
    QStringList m_sourceLines; // split on the first operand finding
    std::vector<RungSpan> m_spans;
    bool m_systemParsed = false;
    std::map<Address, const SystemDevice *> m_systemDriven;
    std::map<int, SpanForm> m_forms; // by the rung's first instruction
    std::vector<Finding> m_found;
};

} // namespace

std::vector<Finding> checkListFindings(const InstructionList &list, const CheckOptions &options,
                                       bool forms) {
    if (!list.target)
        return {};
    ListChecker checker(list, options);
    checker.setForms(forms);
    return checker.run();
}

} // namespace rung::model::detail

namespace rung::model {

std::vector<Diagnostic> checkList(const InstructionList &list, const CheckOptions &options) {
    std::vector<Diagnostic> out;
    for (detail::Finding &f : detail::checkListFindings(list, options))
        out.push_back(std::move(f.diagnostic));
    sortDiagnostics(out);
    return out;
}

} // namespace rung::model
