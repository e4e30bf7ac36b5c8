#include "model/checks/checks_list_detail.h"
#include "model/tr.h"

#include <algorithm>

// Fuzzy forms (FZ001..FZ006), block limits (FZ003) and the branch stack (ST001..ST003) in
// one walk of the listing, with the rewrites offered as fixes (docs/diagnostics.md).

namespace rung::model::detail {

ListChecker::SpanForm &ListChecker::rungForm(int index) {
    const auto span = spanOf(index);
    auto it = m_forms.find(span.first);
    if (it == m_forms.end())
        it = m_forms
                 .emplace(span.first, SpanForm{span.first, span.second,
                                               canonicalForm(m_list, span.first, span.second)})
                 .first;
    return it->second;
}

bool ListChecker::isFuzzy(int index) {
    if (!m_withForms)
        return false;
    const RungForm &form = rungForm(index).form;
    return form.known && !form.canonical;
}

QString ListChecker::printed(const std::vector<Instruction> &instructions) const {
    InstructionList part;
    part.target = m_list.target;
    part.instructions = instructions;
    PrintOptions o;
    o.comments = false;
    return printInstructionList(part, o);
}

// A fix replacing the lines of the rung [first, last) with this listing text.
void ListChecker::offer(Finding &f, int first, int last, const QString &listing,
                        const QString &label) {
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

void ListChecker::offerCanonical(Finding &f, int index) {
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
bool ListChecker::betterForm(int first, int last, const std::vector<Instruction> &rewrite,
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
void ListChecker::blocksAndStack() {
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
                        ? ChecksTr::tr("Stacked %1: combine each block with %1 as soon as it is "
                                       "complete")
                              .arg(name(i))
                        : ChecksTr::tr("Stacked %1: %n blocks are open; an OR chain needs less "
                                       "stack",
                                       nullptr, static_cast<int>(blocks.size()))
                              .arg(name(i)));
                offerCanonical(f, i);
            } else if (fuzzy && singleOr) {
                Finding &f = add("FZ002", Severity::Warning, i,
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
                Finding &f =
                    add(orBlock ? "FZ005" : "FZ004", Severity::Warning, i,
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
                          orBlock ? ChecksTr::tr("Put the single device below the block and drop "
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
            if (i + 1 < size() && isOutput(at(i + 1).op()) && !isUnconditional(at(i + 1).op()) &&
                at(i + 1).op() != Op::Push) {
                if (auto lifted = liftOutput(m_list, spanOf(i), i); lifted && isFuzzy(i)) {
                    Finding &f = add(
                        "FZ006", Severity::Warning, i + 1,
                        ChecksTr::tr("An output with no contacts of its own belongs on top of the "
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
            const bool rungEnds = i + 1 >= size() || loadsAfterOutput(m_list.instructions, i + 1) ||
                                  isUnconditional(at(i + 1).op());
            if (rungEnds && mps > 0) {
                add("ST003", Severity::Error, i,
                    ChecksTr::tr("%n MPS left without MPP at the end of the rung", nullptr, mps));
                mps = 0;
            }
        }
    }
}

} // namespace rung::model::detail
