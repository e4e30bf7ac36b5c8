#include "logic_oracle.h"

#include "model/ladder/rung_graph.h"

#include <algorithm>
#include <variant>

// Both evaluators share the reading of contacts and the meaning of outputs, so they differ
// only in how they combine contacts: the listing as a stack machine, the ladder as power
// flowing left to right through the model's graph of the grid (detail::buildGraph). A test
// oracle: the program itself runs listings in the simulator.

namespace rung::model {

namespace {

class Image {
public:
    Image(const Target *target, const BitReader &read, OutputImage &written)
        : m_read(read)
        , m_written(written) {
        // The always-ON relay (VPC r88, CPM1 253.13) is ON whatever the caller reads: the
        // converter loads it inside an interlock.
        if (target)
            m_alwaysOn = systemAddress(*target, SystemRole::AlwaysOn);
    }

    bool bit(const Operand &o) const {
        if (o.kind != Operand::Kind::Device)
            return o.kind == Operand::Kind::Constant && o.constant.value != 0;
        if (o.address == m_alwaysOn)
            return true;
        const auto it = m_written.find(o.address);
        return it != m_written.end() ? it->second : m_read(o.address);
    }

    // Edges read as plain bits; a compare reads its first operand (a stand-in that both
    // evaluators share, enough to prove that conversion keeps the wiring).
    bool contact(const Contact &c) const {
        if (c.operands.empty())
            return false;
        const bool v = bit(c.operands.front());
        return c.mode == ContactMode::Negated ? !v : v;
    }

    void apply(const Instruction &ins, const std::vector<bool> &in) {
        if (!ins.spec || ins.operands.empty() || in.empty() ||
            ins.operands.front().kind != Operand::Kind::Device)
            return;
        const Address &a = ins.operands.front().address;
        switch (ins.op()) {
        case Op::Out:
            m_written[a] = ins.spec->negated ? !in[0] : in[0];
            return;
        case Op::Set:
            if (in[0])
                m_written[a] = true;
            return;
        case Op::Reset:
            if (in[0])
                m_written[a] = false;
            return;
        case Op::Keep:
            if (in.size() >= 2) {
                if (in[1])
                    m_written[a] = false;
                else if (in[0])
                    m_written[a] = true;
            }
            return;
        case Op::PulseRise:
        case Op::PulseFall:
        case Op::Timer:
            m_written[a] = in[0];
            return;
        case Op::Counter:
            m_written[a] = in.size() >= 2 ? in[0] && !in[1] : in[0];
            return;
        case Op::UpDownCounter:
            if (in.size() >= 3)
                m_written[a] = (in[0] != in[1]) && !in[2];
            return;
        default:
            return;
        }
    }

private:
    const BitReader &m_read;
    OutputImage &m_written;
    Address m_alwaysOn; // invalid when the target has none
};

Contact contactOf(const Instruction &ins) {
    Contact c;
    c.mode = ins.spec->mode;
    c.compare = ins.spec->compare;
    c.operands = ins.operands;
    return c;
}

} // namespace

OutputImage evaluateList(const InstructionList &list, const BitReader &read) {
    OutputImage written;
    Image image(list.target, read, written);
    std::vector<bool> blocks;
    std::vector<bool> stack;
    // IL..ILC and STL..RET: every load (and OR) is ANDed with the interlock condition and
    // the step's state, as the simulator runs them (docs/simulator.md).
    bool interlock = true;
    bool step = true;
    bool gate = true;
    for (const Instruction &ins : list.instructions) {
        if (!ins.spec)
            continue;
        // As on the PLC a load pushes whatever the accumulator holds, even after an output:
        // a later AND LD may join it ("OUT Y0 LD X1 OR X2 ANB OUT Y1").
        switch (ins.op()) {
        case Op::Load:
            blocks.push_back(gate && image.contact(contactOf(ins)));
            continue;
        case Op::And:
            if (!blocks.empty())
                blocks.back() = blocks.back() && image.contact(contactOf(ins));
            continue;
        case Op::Or:
            if (!blocks.empty())
                blocks.back() = blocks.back() || (gate && image.contact(contactOf(ins)));
            continue;
        case Op::Invert:
            // PL110's P / N pass the power flow (edges read as plain bits).
            if (!blocks.empty() && ins.spec->mode == ContactMode::Normal)
                blocks.back() = !blocks.back();
            continue;
        case Op::AndBlock:
        case Op::OrBlock:
            if (blocks.size() >= 2) {
                const bool b = blocks.back();
                blocks.pop_back();
                blocks.back() = ins.op() == Op::AndBlock ? blocks.back() && b : blocks.back() || b;
            }
            continue;
        case Op::Push:
            if (!blocks.empty())
                stack.push_back(blocks.back());
            continue;
        case Op::ReadStack:
        case Op::Pop:
            if (!stack.empty() && !blocks.empty()) {
                blocks.back() = stack.back();
                if (ins.op() == Op::Pop)
                    stack.pop_back();
            }
            continue;
        case Op::End:
            return written;
        case Op::InterlockClear:
            interlock = true;
            gate = step;
            continue;
        case Op::StepLadder:
        case Op::Return:
            // The step bus: outputs may hang on it straight away.
            step = ins.op() == Op::Return || (!ins.operands.empty() && image.bit(ins.operands[0]));
            gate = interlock && step;
            blocks.assign(1, gate);
            continue;
        default:
            break;
        }
        if (isUnconditional(ins.op()))
            continue;
        const std::size_t k = static_cast<std::size_t>(std::max(1, ins.spec->inputs));
        if (blocks.size() < k)
            continue;
        std::vector<bool> in(blocks.end() - static_cast<std::ptrdiff_t>(k), blocks.end());
        if (ins.op() == Op::Interlock) {
            interlock = in[0];
            gate = interlock && step;
        }
        image.apply(ins, in);
        if (k > 1)
            blocks.resize(blocks.size() - k);
    }
    return written;
}

OutputImage evaluateLadder(const LadderProgram &ladder, const BitReader &read) {
    OutputImage written;
    Image image(ladder.target, read, written);
    bool interlock = true; // IL..ILC and STL..RET, as in evaluateList
    bool step = true;
    bool gate = true;
    for (const Rung &rung : ladder.rungs) {
        // Power flows left to right through closed contacts; wires and links conduct both
        // ways. The outputs act in row order, as the listing runs them, and a contact is read
        // just before the first output it feeds: a branch point's contacts once for all its
        // branches, a branch's own contacts after the branches above it have written.
        // The model's own graph of the grid (the converter reads the same one): nodes
        // joined by wires and links, one edge per contact.
        const detail::Graph g = detail::buildGraph(rung);
        const std::size_t cellCount = static_cast<std::size_t>(rung.rows * rung.columns);
        std::vector<int> from(cellCount, -1);
        std::vector<int> to(cellCount, -1);
        for (const detail::Edge &e : g.edges) {
            from[static_cast<std::size_t>(e.expr.cell)] = e.from;
            to[static_cast<std::size_t>(e.expr.cell)] = e.to;
        }
        const int rail = g.rail;
        // flood(start, forward, conducts): the groups reached from start.
        // Inverters that see no power feed their right side, as if from the rail.
        std::vector<int> sources;
        auto flood = [&](int start, bool forward, const std::vector<char> &conducts) {
            std::vector<char> reached(static_cast<std::size_t>(g.nodes), 0);
            reached[static_cast<std::size_t>(start)] = 1;
            if (forward && start == rail)
                for (int source : sources)
                    reached[static_cast<std::size_t>(source)] = 1;
            for (bool changed = true; changed;) {
                changed = false;
                for (std::size_t i = 0; i < cellCount; ++i) {
                    if (from[i] < 0 || !conducts[i])
                        continue;
                    const int a = forward ? from[i] : to[i];
                    const int b = forward ? to[i] : from[i];
                    if (reached[static_cast<std::size_t>(a)] &&
                        !reached[static_cast<std::size_t>(b)]) {
                        reached[static_cast<std::size_t>(b)] = 1;
                        changed = true;
                    }
                }
            }
            return reached;
        };
        const std::vector<char> all(cellCount, 1);
        const std::vector<char> fromRail = flood(rail, true, all);
        std::vector<char> frozen(cellCount, 0);
        std::vector<char> closed(cellCount, 0);
        for (int r = 0; r < rung.rows; ++r) {
            const auto &out = rung.outputs[static_cast<std::size_t>(r)];
            if (!out)
                continue;
            std::vector<bool> in;
            for (int row : rung.boxInputRows(r)) {
                const int node = g.outputNode[static_cast<std::size_t>(row)];
                const std::vector<char> toOutput = flood(node, false, all);
                std::vector<std::size_t> inverters;
                for (std::size_t i = 0; i < cellCount; ++i) {
                    if (frozen[i] || from[i] < 0 || !fromRail[static_cast<std::size_t>(from[i])] ||
                        !toOutput[static_cast<std::size_t>(to[i])])
                        continue;
                    frozen[i] = 1;
                    const Cell &cell = rung.cells[i];
                    // PL110's P / N conduct here: edges read as plain bits.
                    if (cell.contact.invert && cell.contact.mode == ContactMode::Normal)
                        inverters.push_back(i);
                    else
                        closed[i] = cell.contact.invert || image.contact(cell.contact);
                }
                // An INV / NOT never passes power through; when none reaches it, it feeds its
                // right side (the listing inverts the block so far). Left to right, so an
                // inverter sees the ones before it.
                std::stable_sort(inverters.begin(), inverters.end(),
                                 [&](std::size_t x, std::size_t y) {
                                     return x % static_cast<std::size_t>(rung.columns) <
                                            y % static_cast<std::size_t>(rung.columns);
                                 });
                for (std::size_t i : inverters)
                    if (!flood(rail, true, closed)[static_cast<std::size_t>(from[i])])
                        sources.push_back(to[i]);
                in.push_back(gate && flood(rail, true, closed)[static_cast<std::size_t>(node)]);
            }
            if (out->op() == Op::Interlock && !in.empty()) {
                interlock = in[0];
            } else if (out->op() == Op::InterlockClear) {
                interlock = true;
            } else if (out->op() == Op::StepLadder || out->op() == Op::Return) {
                step = out->op() == Op::Return ||
                       (!out->operands.empty() && image.bit(out->operands[0]));
            }
            gate = interlock && step;
            image.apply(*out, in);
        }
    }
    return written;
}

} // namespace rung::model
