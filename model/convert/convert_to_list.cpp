#include "model/convert/convert.h"
#include "model/ladder/rung_graph.h"
#include "model/tr.h"

#include <algorithm>

#include <QCoreApplication>

// Ladder -> IL in the canonical form (docs/conversion.md): each block is combined as soon as
// it is complete (ANB right after the block), OR chains instead of stacked ORB, outputs at a
// branch point without stack instructions where none is needed, MPS/MRD/MPP on Vigor. Targets
// without a branch stack (VPC, CPM1) repeat a branch condition only where that cannot change
// its value; elsewhere the branch point is held by IL/ILC (docs/conversion.md).

namespace rung::model {

using detail::Branch;
using detail::Expr;

bool ToListingResult::ok() const {
    return !hasErrors(problems);
}

namespace {

class Emitter {
public:
    Emitter(const Target &target, int rungIndex, int columns, std::vector<Instruction> *out,
            std::vector<CellOrigin> *origin, std::vector<Diagnostic> *problems)
        : m_target(target)
        , m_rung(rungIndex)
        , m_columns(std::max(1, columns))
        , m_outputColumn(columns)
        , m_out(out)
        , m_origin(origin)
        , m_problems(problems) {}

    bool failed() const { return m_failed; }

    // Inside an interlock the program opened in an earlier rung: a generated IL/ILC would
    // end it (IL does not nest on VPC or CPM1).
    void setInInterlock(bool on) { m_inInterlock = on; }

    void emitRung(const detail::RungLogic &logic, bool inStep) {
        if (!logic.boxInputs.empty()) {
            for (const Expr &e : logic.boxInputs) {
                if (e.empty())
                    return fail(-1, ConvertTr::tr("%1 has an input with no condition")
                                        .arg(logic.box.spec->mnemonic));
                emitLoad(e);
            }
            emitOutput(logic.box, logic.boxRow);
            return;
        }
        for (const Branch::Item &item : logic.root.items) {
            if (item.isOutput) {
                // Inside a step (STL .. RET) an output may hang on the step bus itself.
                if (!isUnconditional(item.output.op()) && !inStep)
                    return fail(
                        -1, ConvertTr::tr("%1 has no condition").arg(item.output.spec->mnemonic));
                emitOutput(item.output, item.row);
                continue;
            }
            const Branch &child = item.child.front();
            emitLoad(child.cond);
            emitItems(child, detail::seriesItems(child.cond));
        }
    }

private:
    void fail(int row, const QString &message) {
        Diagnostic d;
        d.code = QStringLiteral("CV010");
        d.location.rung = m_rung;
        d.location.row = row;
        d.message = message;
        m_problems->push_back(d);
        m_failed = true;
    }

    // Every instruction goes out with its origin: a cell id (row * columns + column) for a
    // contact, an output row, or neither for what belongs to the rung as a whole.
    void push(Instruction ins, int row, int column) {
        m_out->push_back(std::move(ins));
        m_origin->push_back(CellOrigin{m_rung, row, column});
    }

    void emitContact(Op op, const Contact &c, int cell) {
        const InstructionSpec *spec = c.invert
                                          ? m_target.findInstruction(Op::Invert, c.mode)
                                          : m_target.findInstruction(op, c.mode, c.compare, false);
        if (!spec) {
            fail(-1, c.invert ? ConvertTr::tr("%1 has no INV element").arg(m_target.displayName)
                              : ConvertTr::tr("%1 has no such contact").arg(m_target.displayName));
            return;
        }
        Instruction ins;
        ins.spec = spec;
        if (!c.invert)
            ins.operands = c.operands;
        if (cell < 0)
            push(std::move(ins), -1, -1);
        else
            push(std::move(ins), cell / m_columns, cell % m_columns);
    }

    void emitBare(Op op) {
        Instruction ins;
        ins.spec = m_target.findInstruction(op);
        if (!ins.spec) {
            fail(-1, ConvertTr::tr("%1 has no branch stack").arg(m_target.displayName));
            return;
        }
        push(std::move(ins), -1, -1);
    }

    void emitOutput(Instruction ins, int row) {
        ins.line = 0;
        ins.column = 0;
        // Every device operand counts as written: an application box's source too, which is
        // only ever more careful.
        for (const Operand &o : ins.operands)
            if (o.kind == Operand::Kind::Device)
                m_written.push_back(o.address);
        push(std::move(ins), row, row < 0 ? -1 : m_outputColumn);
    }

    // Same element (a bit of a channel and the channel count as the same).
    static bool overlaps(const Address &a, const Address &b) {
        return a.area == b.area && a.index == b.index && (a.bit < 0 || b.bit < 0 || a.bit == b.bit);
    }

    bool readsWritten(const Expr &e) const {
        if (e.kind != Expr::Kind::Leaf) {
            return std::any_of(e.items.begin(), e.items.end(),
                               [this](const Expr &i) { return readsWritten(i); });
        }
        for (const Operand &o : e.leaf.operands)
            if (o.kind == Operand::Kind::Device)
                for (const Address &w : m_written)
                    if (overlaps(o.address, w))
                        return true;
        return false;
    }

    static bool holdsFlowControl(const Branch &b) {
        for (const Branch::Item &i : b.items) {
            if (!i.isOutput) {
                if (holdsFlowControl(i.child.front()))
                    return true;
                continue;
            }
            switch (i.output.op()) {
            case Op::Interlock:
            case Op::InterlockClear:
            case Op::Jump:
            case Op::JumpEnd:
            case Op::StepLadder:
            case Op::Return:
            case Op::End:
                return true;
            default:
                break;
            }
        }
        return false;
    }

    bool interlockUsable(const Branch &b) const {
        return m_target.findInstruction(Op::Interlock) &&
               m_target.findInstruction(Op::InterlockClear) && alwaysOn() && !holdsFlowControl(b);
    }

    // The always-ON contact (VPC r88, CPM1 253.13): an output straight at the interlocked
    // branch point after a branch with contacts loads it, and the interlock does the rest.
    std::optional<Contact> alwaysOn() const {
        const Address on = systemAddress(m_target, SystemRole::AlwaysOn);
        if (!on.valid())
            return std::nullopt;
        Contact c;
        Operand o;
        o.address = on;
        c.operands = {o};
        return c;
    }

    void emitLoad(const Expr &e) {
        switch (e.kind) {
        case Expr::Kind::Leaf:
            if (e.leaf.invert)
                return fail(-1, ConvertTr::tr("A block cannot start with INV"));
            return emitContact(Op::Load, e.leaf, e.cell);
        case Expr::Kind::Series:
            if (e.items.empty())
                return fail(-1, ConvertTr::tr("An output has no condition"));
            emitLoad(e.items.front());
            for (std::size_t i = 1; i < e.items.size(); ++i)
                emitAnd(e.items[i]);
            return;
        case Expr::Kind::Parallel:
            emitLoad(e.items.front());
            for (std::size_t i = 1; i < e.items.size(); ++i)
                emitOr(e.items[i]);
            return;
        }
    }

    void emitAnd(const Expr &e) {
        if (e.kind == Expr::Kind::Leaf)
            return emitContact(Op::And, e.leaf, e.cell);
        if (e.kind == Expr::Kind::Series) {
            for (const Expr &i : e.items)
                emitAnd(i);
            return;
        }
        emitLoad(e);
        emitBare(Op::AndBlock);
    }

    void emitOr(const Expr &e) {
        if (e.kind == Expr::Kind::Leaf && !e.leaf.invert)
            return emitContact(Op::Or, e.leaf, e.cell);
        emitLoad(e);
        emitBare(Op::OrBlock);
    }

    void emitCond(const Expr &cond) {
        for (const Expr &i : detail::seriesItems(cond))
            emitAnd(i);
    }

    // The items hanging off one branch point, the accumulator holding its condition.
    void emitItems(const Branch &b, const std::vector<Expr> &path) {
        if (m_target.limits.allowsStack)
            emitWithStack(b, path);
        else
            emitWithoutStack(b, path, m_inInterlock);
    }

    void emitWithStack(const Branch &b, const std::vector<Expr> &path) {
        bool pushed = false;
        bool modified = false;
        const std::size_t n = b.items.size();
        for (std::size_t i = 0; i < n; ++i) {
            const bool last = i + 1 == n;
            if (pushed) {
                if (last) {
                    emitBare(Op::Pop);
                    pushed = false;
                } else if (modified) {
                    emitBare(Op::ReadStack);
                }
            }
            modified = false;
            const Branch::Item &item = b.items[i];
            if (item.isOutput) {
                emitOutput(item.output, item.row);
                continue;
            }
            if (!last && !pushed) {
                emitBare(Op::Push);
                pushed = true;
            }
            const Branch &child = item.child.front();
            emitCond(child.cond);
            std::vector<Expr> deeper = path;
            for (const Expr &e : detail::seriesItems(child.cond))
                deeper.push_back(e);
            emitWithStack(child, deeper);
            modified = true;
        }
    }

    // No branch stack: outputs at the branch point share the condition; a later branch after
    // one that added contacts repeats the condition from the rail (or from the interlock).
    // That is exact only while the repeated contacts read nothing this rung has written so
    // far; otherwise the branch point is held by IL/ILC, which do not nest.
    void emitWithoutStack(const Branch &b, const std::vector<Expr> &path, bool inInterlock) {
        const std::size_t mark = m_out->size();
        const std::size_t writtenMark = m_written.size();
        const std::size_t problemMark = m_problems->size();
        const bool failedBefore = m_failed;
        if (emitRepeating(b, path, inInterlock))
            return;
        m_out->erase(m_out->begin() + static_cast<std::ptrdiff_t>(mark), m_out->end());
        m_origin->resize(mark);
        m_written.resize(writtenMark);
        m_problems->resize(problemMark);
        m_failed = failedBefore;
        if (inInterlock || !interlockUsable(b))
            return fail(-1,
                        ConvertTr::tr("A branch reads a device that an earlier branch of the same "
                                      "rung writes, and %1 cannot hold this branch point (IL does "
                                      "not nest); draw the branches as separate rungs")
                            .arg(m_target.displayName));
        emitBare(Op::Interlock);
        emitInterlocked(b);
        emitBare(Op::InterlockClear);
    }

    // Returns false when a repeated condition could read a device written since it was first
    // read.
    bool emitRepeating(const Branch &b, const std::vector<Expr> &path, bool inInterlock) {
        bool exact = true;
        bool intact = true;
        for (const Branch::Item &item : b.items) {
            if (!intact) {
                const Expr repeated = detail::seriesOf(path);
                if (readsWritten(repeated))
                    exact = false;
                emitLoad(repeated);
                intact = true;
            }
            if (item.isOutput) {
                emitOutput(item.output, item.row);
                continue;
            }
            const Branch &child = item.child.front();
            emitCond(child.cond);
            std::vector<Expr> deeper = path;
            for (const Expr &e : detail::seriesItems(child.cond))
                deeper.push_back(e);
            emitWithoutStack(child, deeper, inInterlock);
            intact = false;
        }
        return exact;
    }

    // After IL the accumulator holds the branch point's condition, and every later load is
    // ANDed with it: each branch starts with LD, an output after a branch loads always-ON.
    void emitInterlocked(const Branch &b) {
        bool intact = true;
        for (const Branch::Item &item : b.items) {
            if (item.isOutput) {
                if (!intact) {
                    emitContact(Op::Load, *alwaysOn(), -1);
                    intact = true;
                }
                emitOutput(item.output, item.row);
                continue;
            }
            // LD even straight after IL, as the VPC user's manual, VII, writes an interlock's
            // branches.
            const Branch &child = item.child.front();
            emitLoad(child.cond);
            emitWithoutStack(child, detail::seriesItems(child.cond), true);
            intact = false;
        }
    }

    const Target &m_target;
    int m_rung;
    int m_columns; // for cell ids
    int m_outputColumn;
    std::vector<Instruction> *m_out;
    std::vector<CellOrigin> *m_origin;
    std::vector<Diagnostic> *m_problems;
    bool m_failed = false;
    bool m_inInterlock = false;
    std::vector<Address> m_written; // devices the rung's outputs have written so far
};

} // namespace

ToListingResult ladderToList(const LadderProgram &ladder) {
    ToListingResult result;
    result.list.target = ladder.target;
    if (!ladder.target)
        return result;
    const Target &target = *ladder.target;
    bool inStep = false;
    bool inInterlock = false;
    for (std::size_t r = 0; r < ladder.rungs.size(); ++r) {
        const Rung &rung = ladder.rungs[r];
        const int rungIndex = static_cast<int>(r);
        result.rungFirst.push_back(static_cast<int>(result.list.instructions.size()));
        auto networks = detail::analyzeRung(rung);
        bool bad = false;
        int boxes = 0;
        int coils = 0;
        for (int row = 0; row < rung.rows; ++row) {
            const auto &o = rung.outputs[static_cast<std::size_t>(row)];
            if (o && o->spec)
                (rung.boxInputRows(row).size() > 1 ? boxes : coils) += 1;
        }
        if (boxes > 0 && boxes + coils > 1) {
            Diagnostic d;
            d.code = QStringLiteral("CV011");
            d.location.rung = rungIndex;
            d.message = ConvertTr::tr("A box with several inputs must stand alone in its rung");
            result.problems.push_back(d);
            bad = true;
        }
        for (const auto &n : networks) {
            Diagnostic d;
            d.location.rung = rungIndex;
            d.location.row = n.row;
            d.location.cell = rung.columns;
            if (!n.connected) {
                d.code = QStringLiteral("CV012");
                d.message =
                    ConvertTr::tr("Row %1 is not connected to the left rail").arg(n.row + 1);
            } else if (!n.seriesParallel) {
                d.code = QStringLiteral("RC001");
                d.message =
                    ConvertTr::tr("Reverse current: the network feeding row %1 can only close "
                                  "through an element crossed right to left")
                        .arg(n.row + 1);
                for (int id : n.cells)
                    d.related.push_back(Location{0, 0, rungIndex, id / std::max(1, rung.columns),
                                                 id % std::max(1, rung.columns)});
            } else {
                continue;
            }
            result.problems.push_back(d);
            bad = true;
        }
        if (bad)
            continue;
        std::vector<Instruction> emitted;
        std::vector<CellOrigin> origin;
        Emitter emitter(target, rungIndex, rung.columns, &emitted, &origin, &result.problems);
        emitter.setInInterlock(inInterlock);
        emitter.emitRung(detail::logicOf(rung, std::move(networks), false), inStep);
        if (emitter.failed())
            continue;
        for (const Instruction &ins : emitted) {
            if (ins.op() == Op::StepLadder)
                inStep = true;
            else if (ins.op() == Op::Return)
                inStep = false;
            else if (ins.op() == Op::Interlock)
                inInterlock = true;
            else if (ins.op() == Op::InterlockClear)
                inInterlock = false;
        }
        if (!rung.comment.isEmpty()) {
            const int at = static_cast<int>(result.list.instructions.size());
            for (const QString &line : rung.comment.split(QLatin1Char('\n')))
                result.list.comments.emplace_back(at, line);
        }
        int step = result.list.instructions.empty()
                       ? 0
                       : result.list.instructions.back().step +
                             instructionSteps(target, result.list.instructions.back());
        for (Instruction &ins : emitted) {
            ins.step = step;
            step += instructionSteps(target, ins);
            result.list.instructions.push_back(std::move(ins));
        }
        result.origin.insert(result.origin.end(), origin.begin(), origin.end());
    }
    result.rungFirst.push_back(static_cast<int>(result.list.instructions.size()));
    return result;
}

} // namespace rung::model
