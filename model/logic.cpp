#include "logic.h"
#include "rung_graph.h"

// Both evaluators share the reading of contacts and the meaning of outputs, so they differ
// only in how they combine contacts: the listing as a stack machine, the ladder as power
// flowing left to right through the grid.

namespace rung::model {

namespace {

class Image {
public:
    Image(const BitReader &read, OutputImage &written)
        : m_read(read)
        , m_written(written) {}

    bool bit(const Operand &o) const {
        if (o.kind != Operand::Kind::Device)
            return o.kind == Operand::Kind::Constant && o.constant.value != 0;
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
    Image image(read, written);
    std::vector<bool> blocks;
    std::vector<bool> stack;
    bool afterOutput = false;
    for (const Instruction &ins : list.instructions) {
        if (!ins.spec)
            continue;
        // A load right after an output, with no branch pending, starts a new rung.
        const bool newRung = afterOutput && stack.empty();
        afterOutput = false;
        switch (ins.op()) {
        case Op::Load:
            if (newRung)
                blocks.clear();
            blocks.push_back(image.contact(contactOf(ins)));
            continue;
        case Op::And:
            if (!blocks.empty())
                blocks.back() = blocks.back() && image.contact(contactOf(ins));
            continue;
        case Op::Or:
            if (!blocks.empty())
                blocks.back() = blocks.back() || image.contact(contactOf(ins));
            continue;
        case Op::Invert:
            if (!blocks.empty())
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
        default:
            break;
        }
        if (detail::isUnconditional(ins.op()))
            continue;
        const std::size_t k = static_cast<std::size_t>(std::max(1, ins.spec->inputs));
        if (blocks.size() < k)
            continue;
        std::vector<bool> in(blocks.end() - static_cast<std::ptrdiff_t>(k), blocks.end());
        image.apply(ins, in);
        if (k > 1)
            blocks.resize(blocks.size() - k);
        afterOutput = true;
    }
    return written;
}

OutputImage evaluateLadder(const LadderProgram &ladder, const BitReader &read) {
    OutputImage written;
    Image image(read, written);
    for (const Rung &rung : ladder.rungs) {
        // Power flows left to right through closed contacts; wires and links conduct both
        // ways. Contacts read the image as it stands when the rung starts.
        const int width = rung.columns + 1;
        std::vector<int> group(static_cast<std::size_t>(rung.rows * width));
        for (std::size_t i = 0; i < group.size(); ++i)
            group[i] = static_cast<int>(i);
        auto find = [&group](int x) {
            while (group[static_cast<std::size_t>(x)] != x)
                x = group[static_cast<std::size_t>(x)] =
                    group[static_cast<std::size_t>(group[static_cast<std::size_t>(x)])];
            return x;
        };
        auto join = [&](int a, int b) { group[static_cast<std::size_t>(find(a))] = find(b); };
        for (int r = 0; r < rung.rows; ++r) {
            join(r * width, 0);
            for (int c = 0; c <= rung.columns; ++c)
                if (r + 1 < rung.rows && rung.link(r, c))
                    join(r * width + c, (r + 1) * width + c);
            for (int c = 0; c < rung.columns; ++c)
                if (rung.cell(r, c).kind == CellKind::Wire)
                    join(r * width + c, r * width + c + 1);
        }
        std::vector<bool> closed(static_cast<std::size_t>(rung.rows * rung.columns), false);
        for (int r = 0; r < rung.rows; ++r)
            for (int c = 0; c < rung.columns; ++c) {
                const Cell &cell = rung.cell(r, c);
                closed[static_cast<std::size_t>(r * rung.columns + c)] =
                    cell.kind == CellKind::Contact && !cell.contact.invert &&
                    image.contact(cell.contact);
            }
        std::vector<bool> powered(group.size(), false);
        powered[static_cast<std::size_t>(find(0))] = true;
        for (bool changed = true; changed;) {
            changed = false;
            for (int r = 0; r < rung.rows; ++r)
                for (int c = 0; c < rung.columns; ++c) {
                    if (!closed[static_cast<std::size_t>(r * rung.columns + c)])
                        continue;
                    const int from = find(r * width + c);
                    const int to = find(r * width + c + 1);
                    if (powered[static_cast<std::size_t>(from)] &&
                        !powered[static_cast<std::size_t>(to)]) {
                        powered[static_cast<std::size_t>(to)] = true;
                        changed = true;
                    }
                }
        }
        for (int r = 0; r < rung.rows; ++r) {
            const auto &out = rung.outputs[static_cast<std::size_t>(r)];
            if (!out)
                continue;
            std::vector<bool> in;
            for (int row : rung.boxInputRows(r))
                in.push_back(powered[static_cast<std::size_t>(find(row * width + rung.columns))]);
            image.apply(*out, in);
        }
    }
    return written;
}

} // namespace rung::model
