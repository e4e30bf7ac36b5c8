#include "random_program.h"

#include "model/target/address.h"

#include <QStringList>

#include <algorithm>
#include <random>

namespace rung::testing {

using namespace rung::model;

namespace {

struct Node {
    enum Kind { Leaf, Series, Parallel } kind = Leaf;
    QString device;
    bool negated = false;
    ContactMode edge = ContactMode::Normal; // Rising / Falling: an edge contact
    QString compare;                        // a compare contact: "<" and its operands
    std::vector<Node> items;
};

class Generator {
public:
    Generator(const Target &t, std::uint64_t seed, const RandomProgramOptions &o)
        : m_t(t)
        , m_rng(seed)
        , m_o(o) {
        pool(true, false, 12, &m_inputs);
        pool(true, true, 10, &m_outputs);
        pool(false, true, 10, &m_relays);
        switch (m_t.family) {
        case Family::Vpc:
            m_registers = {"p00", "p01", "p02", "p03"};
            break;
        case Family::Vigor:
            m_registers = {"D0", "D1", "D2", "D3"};
            break;
        case Family::Cpm1:
            m_registers = {"DM 0000", "DM 0001", "DM 0002", "DM 0003"};
            break;
        case Family::Pl110:
            m_registers = {"V1", "V2", "V3", "V4"};
            break;
        }
        m_compare = m_t.family != Family::Cpm1; // CPM1's table has no compare contact
    }

    QString run() {
        for (int r = 0; r < m_o.rungs; ++r)
            rung();
        if (m_o.end)
            line(mn(Op::End));
        return m_lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
    }

private:
    // Devices of the first area that matches: physical inputs, physical outputs, or internal
    // relays. Channel areas give their bits.
    void pool(bool physical, bool writable, int count, QStringList *out) {
        for (int i = 0; i < static_cast<int>(m_t.areas.size()); ++i) {
            const Area &a = m_t.area(i);
            // B (PL110) is written only by its own coil OUTB, not by OUT (OP005).
            if (a.physical != physical || a.writable != writable || a.system ||
                a.onlyWrittenBy != ApplyFunction::None)
                continue;
            if (a.kind != AreaKind::Bit && a.kind != AreaKind::Channel)
                continue;
            for (int k = 0; k < count; ++k) {
                Address addr{i, a.first, -1};
                if (a.numbering == Numbering::ChannelBit) {
                    addr.index = a.first + k / 16;
                    addr.bit = k % 16;
                    if (addr.index > a.last)
                        break;
                } else {
                    addr.index = a.first + k;
                    if (addr.index > a.last)
                        break;
                }
                out->append(formatAddress(m_t, addr));
            }
            return;
        }
    }

    int pick(int n) { return std::uniform_int_distribution<int>(0, n - 1)(m_rng); }
    bool chance(int percent) { return pick(100) < percent; }

    QString mn(Op op, ContactMode mode = ContactMode::Normal) const {
        const InstructionSpec *s = m_t.findInstruction(op, mode);
        return s ? s->mnemonic : QString();
    }

    void line(const QString &text) { m_lines << text; }

    Node leaf() {
        if (m_o.extended && chance(20)) {
            Node n;
            const int k = pick(3);
            if (k == 0 && m_t.findInstruction(Op::Load, ContactMode::Rising) &&
                m_t.findInstruction(Op::And, ContactMode::Rising)) {
                n.device = m_inputs[pick(static_cast<int>(m_inputs.size()))];
                n.edge = chance(50) ? ContactMode::Rising : ContactMode::Falling;
                return n;
            }
            if (k == 1 && !m_registers.isEmpty() && m_compare) {
                n.compare = compareText();
                return n;
            }
            if (!m_timerContacts.isEmpty()) {
                n.device = m_timerContacts[pick(static_cast<int>(m_timerContacts.size()))];
                n.negated = chance(30);
                return n;
            }
        }
        Node n;
        n.device = m_readable[static_cast<std::size_t>(pick(static_cast<int>(m_readable.size())))];
        n.negated = chance(30);
        return n;
    }

    Node expr(int depth) {
        if (depth <= 0 || chance(35))
            return leaf();
        Node n;
        n.kind = chance(50) ? Node::Series : Node::Parallel;
        const int count = 2 + pick(2);
        for (int i = 0; i < count; ++i) {
            Node item = expr(depth - 1);
            if (item.kind == n.kind) // keep the tree flat: nested same kinds are one
                for (Node &x : item.items)
                    n.items.push_back(std::move(x));
            else
                n.items.push_back(std::move(item));
        }
        return n;
    }

    QString compareText() {
        static const char *const symbols[] = {"=", "<", ">"};
        const char *sym = symbols[pick(3)];
        const QString a = m_registers[pick(static_cast<int>(m_registers.size()))];
        const QString b = m_registers[pick(static_cast<int>(m_registers.size()))];
        if (m_t.family == Family::Vpc)
            return QStringLiteral(" %1%2%3").arg(a, QLatin1String(sym), b);
        return QStringLiteral("%1 %2 %3").arg(QLatin1String(sym), a, b);
    }

    void contact(Op op, const Node &n) {
        if (!n.compare.isEmpty()) {
            line(mn(op) + n.compare);
            return;
        }
        if (n.edge != ContactMode::Normal) {
            line(mn(op, n.edge) + QLatin1Char(' ') + n.device);
            return;
        }
        line(mn(op, n.negated ? ContactMode::Negated : ContactMode::Normal) + QLatin1Char(' ') +
             n.device);
    }

    void load(const Node &n) {
        switch (n.kind) {
        case Node::Leaf:
            contact(Op::Load, n);
            return;
        case Node::Series: {
            load(n.items[0]);
            const bool stacked = m_o.fuzzy && chance(30);
            int pending = 0;
            for (std::size_t i = 1; i < n.items.size(); ++i) {
                if (n.items[i].kind == Node::Leaf && pending == 0) {
                    contact(Op::And, n.items[i]);
                    continue;
                }
                load(n.items[i]);
                if (stacked && i + 1 < n.items.size() && pending < 3) {
                    ++pending; // combined at the end: "LD.. LD.. ANB ANB"
                    continue;
                }
                line(mn(Op::AndBlock));
                for (; pending > 0; --pending)
                    line(mn(Op::AndBlock));
            }
            return;
        }
        case Node::Parallel: {
            const bool bad = m_o.fuzzy && chance(30);
            load(n.items[0]);
            int pending = 0;
            for (std::size_t i = 1; i < n.items.size(); ++i) {
                if (n.items[i].kind == Node::Leaf && !bad) {
                    contact(Op::Or, n.items[i]);
                    continue;
                }
                load(n.items[i]);
                if (bad && i + 1 < n.items.size()) {
                    ++pending; // "LD X0 LD X1 LD X2 ORB ORB"
                    continue;
                }
                line(mn(Op::OrBlock));
                for (; pending > 0; --pending)
                    line(mn(Op::OrBlock));
            }
            return;
        }
        }
    }

    // A condition added after a branch point: AND-chains or a block and ANB.
    void andOn(const Node &n) {
        if (n.kind == Node::Leaf)
            return contact(Op::And, n);
        if (n.kind == Node::Series) {
            for (const Node &i : n.items)
                andOn(i);
            return;
        }
        load(n);
        line(mn(Op::AndBlock));
    }

    QString coil() {
        QString d;
        do {
            const bool relay = !m_relays.isEmpty() && chance(40);
            const QStringList &from = relay ? m_relays : m_outputs;
            d = from[pick(static_cast<int>(from.size()))];
        } while (m_written.contains(d) &&
                 m_written.size() < m_outputs.size() + m_relays.size() - 1);
        m_written << d;
        return d;
    }

    // A timer or a move box with a random condition, in the target's own syntax.
    bool extendedRung() {
        m_readable.clear();
        for (const QStringList *p : {&m_inputs, &m_relays})
            for (const QString &d : *p)
                m_readable.push_back(d);
        const int n = m_timers++;
        switch (m_t.family) {
        case Family::Vpc:
            if (chance(50) && n < 8) {
                load(expr(2));
                line(QStringLiteral("TIM%1").arg(n * 2 + (chance(50) ? 16 : 0), 2, 10,
                                                 QLatin1Char('0')));
                m_timerContacts << QStringLiteral("t%1").arg(n * 2, 2, 10, QLatin1Char('0'));
                return true;
            }
            load(expr(2));
            line(QStringLiteral("OUT %1%2%3")
                     .arg(m_registers[pick(4)], QLatin1String(chance(50) ? "," : "+"),
                          m_registers[pick(4)]));
            return true;
        case Family::Vigor:
            load(expr(2));
            if (chance(50)) {
                line(QStringLiteral("TMR T%1 K%2").arg(n).arg(1 + pick(4)));
                m_timerContacts << QStringLiteral("T%1").arg(n);
            } else {
                line(QStringLiteral("MOV K%1 %2").arg(pick(4)).arg(m_registers[pick(4)]));
            }
            return true;
        case Family::Cpm1:
            load(expr(2));
            if (chance(50)) {
                line(QStringLiteral("TIM %1 #%2")
                         .arg(n, 3, 10, QLatin1Char('0'))
                         .arg(1 + pick(4), 4, 10, QLatin1Char('0')));
                m_timerContacts << QStringLiteral("TIM %1").arg(n, 3, 10, QLatin1Char('0'));
            } else {
                line(QStringLiteral("MOV(21) #%1 %2")
                         .arg(pick(4), 4, 10, QLatin1Char('0'))
                         .arg(m_registers[pick(4)]));
            }
            return true;
        case Family::Pl110:
            load(expr(2));
            if (chance(30))
                line(chance(50) ? QStringLiteral("P") : QStringLiteral("N"));
            if (chance(50)) {
                line(QStringLiteral("TON T%1 %2 100").arg(n + 1).arg(1 + pick(4)));
                m_timerContacts << QStringLiteral("T%1").arg(n + 1);
            } else {
                line(QStringLiteral("MOV %1 %2").arg(pick(4)).arg(m_registers[pick(4)]));
            }
            return true;
        }
        return false;
    }

    void rung() {
        if (m_o.extended && chance(25) && extendedRung())
            return;
        // Outputs first, so the rung's contacts can leave out what the rung writes.
        m_written.clear();
        const int kind = pick(10);
        const bool stack = m_t.limits.allowsStack && m_o.branches;
        const InstructionSpec *box = nullptr;
        for (const InstructionSpec &s : m_t.instructions)
            if (s.op == Op::Keep && s.inputs == 2)
                box = &s;
        const int coilCount = kind < 3 ? 1 : 3;
        m_readable.clear();
        // Choose the written devices, then the readable ones.
        std::vector<QString> written;
        for (int i = 0; i < coilCount; ++i)
            written.push_back(coil());
        // A rung may read what it writes itself (a latch, a branch that reads the coil of
        // the branch above, a shared condition that an earlier branch changes): conversion
        // must keep the order in which the listing reads and writes.
        for (const QStringList *p : {&m_inputs, &m_relays})
            for (const QString &d : *p)
                m_readable.push_back(d);
        for (const QString &d : written)
            if (std::find(m_readable.begin(), m_readable.end(), d) == m_readable.end())
                m_readable.push_back(d);
        auto out = [&](const QString &d) {
            const int k = pick(10);
            if (k == 0 && !mn(Op::Set).isEmpty())
                line(mn(Op::Set) + QLatin1Char(' ') + d);
            else if (k == 1 && !mn(Op::Reset).isEmpty())
                line(mn(Op::Reset) + QLatin1Char(' ') + d);
            else
                line(mn(Op::Out) + QLatin1Char(' ') + d);
        };
        if (kind == 9 && box && m_o.boxes) {
            load(expr(m_o.maxDepth - 1));
            load(expr(m_o.maxDepth - 1));
            line(box->mnemonic + QLatin1Char(' ') + written[0]);
            return;
        }
        load(expr(m_o.maxDepth));
        if (coilCount == 1 || !m_o.branches) {
            out(written[0]);
            return;
        }
        if (stack && kind >= 6) {
            line(mn(Op::Push));
            andOn(expr(1));
            out(written[0]);
            line(mn(Op::ReadStack));
            andOn(expr(1));
            out(written[1]);
            line(mn(Op::Pop));
            if (chance(50))
                andOn(expr(1));
            out(written[2]);
            return;
        }
        const QString il = mn(Op::Interlock);
        const QString ilc = mn(Op::InterlockClear);
        if (!stack && kind >= 7 && !il.isEmpty() && !ilc.isEmpty()) {
            // VPC's and CPM1's branch form: the interlock holds the branch point.
            line(il);
            for (int i = 0; i < 3; ++i) {
                if (i == 0 && chance(30)) {
                    out(written[0]); // an output straight on the interlocked condition
                    continue;
                }
                load(expr(1));
                out(written[static_cast<std::size_t>(i)]);
            }
            line(ilc);
            return;
        }
        // Parallel outputs, then a continuation that adds a condition.
        // Without MPS a new block after an output would start the next rung: AND only.
        out(written[0]);
        out(written[1]);
        andOn(leaf());
        if (chance(50))
            andOn(leaf());
        out(written[2]);
    }

    const Target &m_t;
    std::mt19937_64 m_rng;
    RandomProgramOptions m_o;
    QStringList m_inputs, m_outputs, m_relays, m_lines, m_written;
    std::vector<QString> m_readable;
    QStringList m_registers, m_timerContacts;
    bool m_compare = false;
    int m_timers = 0;
};

} // namespace

QString randomProgram(const Target &target, std::uint64_t seed,
                      const RandomProgramOptions &options) {
    return Generator(target, seed, options).run();
}

} // namespace rung::testing
