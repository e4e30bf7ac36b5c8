#include "model/convert/convert.h"
#include "model/ladder/network.h"
#include "model/listing/structure.h"
#include "model/tr.h"

#include <QCoreApplication>

// IL -> ladder. The listing is read as a stack machine whose values are networks: LD pushes a
// block, AND/OR/ANB/ORB combine blocks, MPS/MRD/MPP mark branch points, an output attaches
// to the branch point it is evaluated at. Any valid order of blocks ("fuzzy syntax") gives the
// same networks; the layout then draws them on the grid (docs/conversion.md).

namespace rung::model {

using detail::Branch;
using detail::Expr;
using detail::RungLogic;

bool ToLadderResult::ok() const {
    return !hasErrors(problems);
}

namespace {

// ---- layout ------------------------------------------------------------------------------

int widthOf(const Expr &e) {
    switch (e.kind) {
    case Expr::Kind::Leaf:
        return 1;
    case Expr::Kind::Series: {
        int w = 0;
        for (const Expr &i : e.items)
            w += widthOf(i);
        return w;
    }
    case Expr::Kind::Parallel: {
        int w = 0;
        for (const Expr &i : e.items)
            w = std::max(w, widthOf(i));
        return w;
    }
    }
    return 0;
}

int heightOf(const Expr &e) {
    switch (e.kind) {
    case Expr::Kind::Leaf:
        return 1;
    case Expr::Kind::Series: {
        int h = 1;
        for (const Expr &i : e.items)
            h = std::max(h, heightOf(i));
        return h;
    }
    case Expr::Kind::Parallel: {
        int h = 0;
        for (const Expr &i : e.items)
            h += heightOf(i);
        return h;
    }
    }
    return 1;
}

void wire(Rung &rung, int row, int from, int to) {
    for (int c = from; c < to; ++c)
        rung.cell(row, c).kind = CellKind::Wire;
}

void link(Rung &rung, int nodeColumn, int fromRow, int toRow) {
    for (int r = fromRow; r < toRow; ++r)
        rung.setLink(r, nodeColumn, true);
}

void place(const Expr &e, Rung &rung, int row, int col) {
    switch (e.kind) {
    case Expr::Kind::Leaf:
        rung.cell(row, col).kind = CellKind::Contact;
        rung.cell(row, col).contact = e.leaf;
        return;
    case Expr::Kind::Series:
        for (const Expr &i : e.items) {
            place(i, rung, row, col);
            col += widthOf(i);
        }
        return;
    case Expr::Kind::Parallel: {
        const int w = widthOf(e);
        int r = row;
        int lastTop = row;
        for (const Expr &i : e.items) {
            place(i, rung, r, col);
            wire(rung, r, col + widthOf(i), col + w);
            lastTop = r;
            r += heightOf(i);
        }
        // At the rail the rows are already joined: a link there would be a second spelling
        // of the same ladder, which the text form and the grid equality could not tell apart.
        if (col > 0)
            link(rung, col, row, lastTop);
        link(rung, col + w, row, lastTop);
        return;
    }
    }
}

int branchWidth(const Branch &b) {
    int w = 0;
    for (const Branch::Item &i : b.items)
        if (!i.isOutput)
            w = std::max(w, branchWidth(i.child.front()));
    return widthOf(b.cond) + w;
}

int branchHeight(const Branch &b) {
    int h = 0;
    for (const Branch::Item &i : b.items)
        h += i.isOutput ? 1 : branchHeight(i.child.front());
    return std::max({1, h, heightOf(b.cond)});
}

void placeBranch(const Branch &b, Rung &rung, int row, int col) {
    place(b.cond, rung, row, col);
    const int x = col + widthOf(b.cond);
    int r = row;
    int lastTop = row;
    for (const Branch::Item &i : b.items) {
        lastTop = r;
        if (i.isOutput) {
            wire(rung, r, x, rung.columns);
            rung.outputs[static_cast<std::size_t>(r)] = i.output;
            r += 1;
        } else {
            placeBranch(i.child.front(), rung, r, x);
            r += branchHeight(i.child.front());
        }
    }
    link(rung, x, row, lastTop);
}

Rung layout(const RungLogic &logic) {
    if (!logic.boxInputs.empty()) {
        int w = 1;
        int h = 0;
        for (const Expr &e : logic.boxInputs) {
            w = std::max(w, widthOf(e));
            h += heightOf(e);
        }
        Rung rung(h, w);
        int r = 0;
        for (const Expr &e : logic.boxInputs) {
            place(e, rung, r, 0);
            wire(rung, r, widthOf(e), w);
            rung.inputRows.push_back(r);
            r += heightOf(e);
        }
        rung.outputs[0] = logic.box;
        return rung;
    }
    Rung rung(branchHeight(logic.root), branchWidth(logic.root));
    placeBranch(logic.root, rung, 0, 0);
    return rung;
}

// ---- reading the listing -----------------------------------------------------------------

class Reader {
public:
    // draw = false: the problems only, no rung laid out (every problem is found while
    // reading; layout() finds none).
    Reader(const InstructionList &list, bool draw)
        : m_list(list)
        , m_draw(draw) {
        m_result.ladder.target = list.target;
    }

    // One rung per span of model::rungSpans. After an error the rest of that part is skipped
    // up to the next load after an output, where the user's next rung starts: its errors are
    // found too (the program is checked whole), though no rung of the broken span is drawn.
    ToLadderResult run() {
        const auto &ins = m_list.instructions;
        for (const RungSpan &span : rungSpans(ins)) {
            bool outputSince = false;
            for (int i = span.first; i < span.last; ++i) {
                const Instruction &at = ins[static_cast<std::size_t>(i)];
                if (m_broken) {
                    if (!(outputSince && at.op() == Op::Load)) {
                        outputSince = outputSince || isOutput(at.op());
                        continue;
                    }
                    finishRung(false);
                    m_spanBroken = true;
                    outputSince = false;
                }
                step(at, i);
            }
            finishRung(span.last == static_cast<int>(ins.size()));
            m_spanBroken = false;
        }
        return std::move(m_result);
    }

private:
    struct Node {
        Expr cond;
        std::vector<std::pair<bool, int>> items; // (isOutput, output index or node index)
    };

    // The bottom block continues a branch point (after an output, MPS, MRD or MPP): joining
    // it in parallel with another block would put contacts from the rail in parallel with
    // the branch point's own contacts, which the branch tree cannot draw.
    void anchoredProblem(const Instruction &at) {
        problem(at, "CV009",
                ConvertTr::tr("%1 joins the condition of a branch point in parallel with another "
                              "block; the ladder cannot draw this: repeat the shared contacts in "
                              "this branch instead")
                    .arg(at.spec->mnemonic));
    }

    void problem(const Instruction &at, const char *code, const QString &message) {
        Diagnostic d;
        d.code = QString::fromLatin1(code);
        d.severity = Severity::Error;
        d.location.line = at.line;
        d.location.column = at.column;
        d.message = message;
        m_result.problems.push_back(d);
        m_broken = true;
    }

    bool started() const { return m_first >= 0; }

    void begin(int index, const Instruction &ins) {
        if (m_first < 0) {
            m_first = index;
            m_firstLine = ins.line;
            m_nodes.assign(1, Node{});
            m_cur = 0;
        }
    }

    Contact contactOf(const Instruction &ins) const {
        Contact c;
        c.mode = ins.spec->mode;
        c.compare = ins.spec->compare;
        c.operands = ins.operands;
        c.invert = ins.op() == Op::Invert;
        return c;
    }

    int addChild(Expr cond) {
        m_nodes.push_back(Node{std::move(cond), {}});
        const int child = static_cast<int>(m_nodes.size()) - 1;
        m_nodes[static_cast<std::size_t>(m_cur)].items.emplace_back(false, child);
        return child;
    }

    // The outputs are kept only to build the rung: the problems need none of them.
    void addOutput(const Instruction &ins) {
        if (!m_draw)
            return;
        m_outputs.push_back(ins);
        m_nodes[static_cast<std::size_t>(m_cur)].items.emplace_back(
            true, static_cast<int>(m_outputs.size()) - 1);
    }

    void step(const Instruction &ins, int index) {
        const Op op = ins.op();
        if (op == Op::StepLadder)
            m_inStep = true;
        else if (op == Op::Return)
            m_inStep = false;
        if (isUnconditional(op)) {
            finishRung(false);
            begin(index, ins);
            addOutput(ins);
            m_hadOutput = true;
            finishRung(false);
            return;
        }
        begin(index, ins);
        switch (op) {
        case Op::Load:
            m_blocks.push_back(Expr::leafOf(contactOf(ins)));
            return;
        case Op::And:
        case Op::Invert:
            if (m_blocks.empty())
                return problem(
                    ins, "CV001",
                    ConvertTr::tr("%1 has no block to continue; start the rung with a load")
                        .arg(ins.spec->mnemonic));
            m_blocks.back() = detail::series(m_blocks.back(), Expr::leafOf(contactOf(ins)));
            return;
        case Op::Or:
            if (m_blocks.empty() || m_blocks.back().empty())
                return problem(
                    ins, "CV001",
                    ConvertTr::tr("%1 has no block to join in parallel").arg(ins.spec->mnemonic));
            if (m_blocks.size() == 1 && m_anchored)
                return anchoredProblem(ins);
            m_blocks.back() = detail::parallel(m_blocks.back(), Expr::leafOf(contactOf(ins)));
            return;
        case Op::AndBlock:
        case Op::OrBlock: {
            if (m_blocks.size() < 2)
                return problem(ins, "CV002",
                               ConvertTr::tr("%1 needs two blocks, but %n is open", nullptr,
                                             static_cast<int>(m_blocks.size()))
                                   .arg(ins.spec->mnemonic));
            Expr b = std::move(m_blocks.back());
            m_blocks.pop_back();
            Expr a = std::move(m_blocks.back());
            if (op == Op::OrBlock && (a.empty() || b.empty()))
                return problem(
                    ins, "CV001",
                    ConvertTr::tr("%1 has no block to join in parallel").arg(ins.spec->mnemonic));
            if (op == Op::OrBlock && m_blocks.size() == 1 && m_anchored)
                return anchoredProblem(ins);
            m_blocks.back() = op == Op::AndBlock ? detail::series(std::move(a), std::move(b))
                                                 : detail::parallel(std::move(a), std::move(b));
            return;
        }
        case Op::Push:
            if (m_blocks.size() != 1)
                return problem(ins, "CV003",
                               ConvertTr::tr("MPS needs exactly one open block, but %n is open",
                                             nullptr, static_cast<int>(m_blocks.size())));
            if (!m_blocks[0].empty())
                m_cur = addChild(std::move(m_blocks[0]));
            m_mps.push_back(m_cur);
            m_blocks.assign(1, Expr{});
            m_anchored = true;
            return;
        case Op::ReadStack:
        case Op::Pop:
            if (m_mps.empty())
                return problem(ins, "CV004",
                               ConvertTr::tr("%1 without a matching MPS").arg(ins.spec->mnemonic));
            m_cur = m_mps.back();
            if (op == Op::Pop)
                m_mps.pop_back();
            m_blocks.assign(1, Expr{});
            m_anchored = true;
            return;
        default:
            break;
        }
        // An output instruction.
        const int inputs = std::max(1, ins.spec->inputs);
        if (inputs > 1) {
            if (m_hadOutput || !m_mps.empty() ||
                m_blocks.size() != static_cast<std::size_t>(inputs)) {
                return problem(ins, "CV005",
                               ConvertTr::tr("%1 needs %2 input blocks, but %3 are open")
                                   .arg(ins.spec->mnemonic)
                                   .arg(inputs)
                                   .arg(m_blocks.size()));
            }
            for (const Expr &e : m_blocks)
                if (e.empty())
                    return problem(
                        ins, "CV006",
                        ConvertTr::tr("%1 has an input with no condition").arg(ins.spec->mnemonic));
            m_box = ins;
            m_boxInputs = std::move(m_blocks);
            m_blocks.clear();
            m_hadOutput = true;
            finishRung(false);
            return;
        }
        if (m_blocks.empty() && m_inStep && !m_hadOutput) {
            // Inside a step (STL .. RET) an output may hang on the step bus itself.
            begin(index, ins);
            m_blocks.assign(1, Expr{});
        }
        if (m_blocks.empty())
            return problem(ins, "CV006",
                           ConvertTr::tr("%1 has no condition").arg(ins.spec->mnemonic));
        if (m_blocks.size() != 1)
            return problem(ins, "CV005",
                           m_blocks.empty()
                               ? ConvertTr::tr("%1 has no condition").arg(ins.spec->mnemonic)
                               : ConvertTr::tr("%1 needs one block, but %2 are open")
                                     .arg(ins.spec->mnemonic)
                                     .arg(m_blocks.size()));
        if (m_blocks[0].empty() && m_cur == 0 && !m_inStep)
            return problem(ins, "CV006",
                           ConvertTr::tr("%1 has no condition").arg(ins.spec->mnemonic));
        if (!m_blocks[0].empty())
            m_cur = addChild(std::move(m_blocks[0]));
        addOutput(ins);
        m_blocks.assign(1, Expr{});
        m_anchored = true;
        m_hadOutput = true;
    }

    Branch build(int node) const {
        Branch b;
        b.cond = m_nodes[static_cast<std::size_t>(node)].cond;
        for (const auto &[isOutput, index] : m_nodes[static_cast<std::size_t>(node)].items) {
            Branch::Item item;
            item.isOutput = isOutput;
            if (isOutput)
                item.output = m_outputs[static_cast<std::size_t>(index)];
            else
                item.child.push_back(build(index));
            b.items.push_back(std::move(item));
        }
        return b;
    }

    void finishRung(bool atEnd) {
        if (m_first < 0) {
            reset();
            return;
        }
        const Instruction &firstIns = m_list.instructions[static_cast<std::size_t>(m_first)];
        if (!m_broken) {
            const bool open = !(m_blocks.empty() || (m_blocks.size() == 1 && m_blocks[0].empty()));
            if (open || !m_hadOutput) {
                problem(atEnd ? m_list.instructions.back() : firstIns, "CV007",
                        ConvertTr::tr("The rung starting on line %1 ends without an output")
                            .arg(firstIns.line));
            } else if (!m_mps.empty()) {
                problem(firstIns, "CV008",
                        ConvertTr::tr("The rung starting on line %1 leaves %n MPS without MPP",
                                      nullptr, static_cast<int>(m_mps.size()))
                            .arg(firstIns.line));
            }
        }
        if (m_draw && !m_broken && !m_spanBroken) {
            RungLogic logic;
            if (!m_boxInputs.empty()) {
                logic.boxInputs = m_boxInputs;
                logic.box = m_box;
            } else {
                logic.root = build(0);
            }
            Rung rung = layout(logic);
            rung.comment = commentsFor(m_first);
            m_result.ladder.rungs.push_back(std::move(rung));
            m_result.rungLine.push_back(m_firstLine);
        }
        reset();
    }

    QString commentsFor(int firstIndex) {
        QStringList lines;
        const auto &comments = m_list.comments;
        while (m_comment < comments.size() && comments[m_comment].first <= firstIndex) {
            lines << comments[m_comment].second;
            ++m_comment;
        }
        return lines.join(QLatin1Char('\n'));
    }

    void reset() {
        m_first = -1;
        m_nodes.clear();
        m_outputs.clear();
        m_blocks.clear();
        m_mps.clear();
        m_boxInputs.clear();
        m_cur = 0;
        m_anchored = false;
        m_hadOutput = false;
        m_broken = false;
    }

    const InstructionList &m_list;
    const bool m_draw;
    ToLadderResult m_result;
    std::vector<Node> m_nodes;
    std::vector<Instruction> m_outputs;
    std::vector<Expr> m_blocks;
    std::vector<int> m_mps;
    std::vector<Expr> m_boxInputs;
    Instruction m_box;
    int m_cur = 0;
    bool m_anchored = false; // m_blocks[0] continues the branch point m_cur
    int m_first = -1;
    int m_firstLine = 0;
    bool m_hadOutput = false;
    bool m_inStep = false; // between STL and RET
    bool m_broken = false;
    bool m_spanBroken = false; // an earlier part of this span had an error: draw none of it
    std::size_t m_comment = 0;
};

} // namespace

namespace detail {
Rung layoutRung(const RungLogic &logic) {
    return layout(logic);
}
} // namespace detail

ToLadderResult listToLadder(const InstructionList &list) {
    return Reader(list, true).run();
}

std::vector<Diagnostic> listToLadderProblems(const InstructionList &list) {
    return Reader(list, false).run().problems;
}

} // namespace rung::model
