#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include "model/ladder/ladder_text.h"
#include <cmath>

// The power flow of an LD body as chains (an element's input: the factors from the rail to it),
// for the outputs (plcopen_outputs.cpp) it feeds (docs/plcopen.md "Import").

namespace rung::model::plcopen {

Factor Importer::leaf(const Element &e, const Contact &c) const {
    return {QStringLiteral("e%1").arg(e.id), Expr::leafOf(c)};
}

std::optional<Contact> Importer::contactOfVariable(const QString &variable, int line) {
    QString name = variable.trimmed();
    Contact c;
    // A timer's or counter's output Q (QU, QD: a CTUD's) as a contact: its done bit.
    const qsizetype dot = name.lastIndexOf(QLatin1Char('.'));
    const auto instance = [this](const QString &n) {
        if (const auto v = m_vars.constFind(n);
            v != m_vars.constEnd() && (isTimerType(v->type) || isCounterType(v->type)))
            return true;
        return std::any_of(m_elements.begin(), m_elements.end(),
                           [&n](const Element &b) { return b.instanceName == n; });
    };
    if (dot > 0 && instance(name.left(dot))) {
        const QString member = name.mid(dot + 1).toUpper();
        name.truncate(dot);
        if (member != QLatin1String("Q") && member != QLatin1String("QU") &&
            member != QLatin1String("QD")) {
            issue(line, variable,
                  PlcopenTr::tr("%1 as a contact is not imported: only a timer's or counter's "
                                "bit (Q) is")
                      .arg(variable));
            return std::nullopt;
        }
        if (const ImportedCounter *counter = importedCounter(name);
            counter && member != QLatin1String("Q") && member != counter->choice.form.done) {
            issue(line, variable,
                  PlcopenTr::tr("%1 is not imported: the bit of %2 %3 is %4")
                      .arg(variable, counter->choice.spec->mnemonic,
                           formatAddress(m_t, counter->device), counter->choice.form.done));
            return std::nullopt;
        }
    }
    const auto a = resolve(name, line, QStringLiteral("BOOL"));
    if (!a)
        return std::nullopt;
    Operand o;
    o.address = *a;
    c.operands.push_back(o);
    return c;
}

std::optional<Chain> Importer::chainIn(const Pin *p, const Element &owner) {
    if (!p || p->connections.empty()) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input is connected to nothing: not imported"));
        return std::nullopt;
    }
    if (p->negated) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input %1 is negated: not imported").arg(p->formal));
        return std::nullopt;
    }
    // A counter counts rising edges of CU and CD anyway; any other input on an edge is an edge
    // detection the box does not have.
    const bool countInput = isCounterType(owner.typeName) &&
                            (p->formal.compare(QLatin1String("CU"), Qt::CaseInsensitive) == 0 ||
                             p->formal.compare(QLatin1String("CD"), Qt::CaseInsensitive) == 0);
    if (!p->edge.isEmpty() && !(countInput && p->edge == QLatin1String("rising"))) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("its input %1 on a %2 edge is not imported").arg(p->formal, p->edge));
        return std::nullopt;
    }
    std::vector<Chain> chains;
    // Branches that meet, from top to bottom as drawn (the file's order where level).
    std::vector<Connection> connections = p->connections;
    const auto height = [this](const Connection &c) {
        const Element *e = element(c.ref);
        return !e ? 1e300 : e->kind == QLatin1String("leftPowerRail") ? -1e300 : e->y;
    };
    std::stable_sort(
        connections.begin(), connections.end(),
        [&](const Connection &a, const Connection &b) { return height(a) < height(b); });
    for (const Connection &c : connections) {
        auto chain = chainOf(c.ref, c.formal, owner);
        if (!chain)
            return std::nullopt;
        chains.push_back(std::move(*chain));
    }
    if (chains.size() == 1)
        return chains.front();
    // Chains that meet: their common start, then the OR of the rest, grouped again by
    // what each group shares (a branch point inside the OR stays one).
    Chain prefix;
    for (std::size_t k = 0;; ++k) {
        bool same = true;
        for (const Chain &ch : chains)
            if (k >= ch.size() || ch[k].key != chains.front()[k].key)
                same = false;
        if (!same)
            break;
        prefix.push_back(chains.front()[k]);
    }
    std::vector<const Chain *> all;
    for (const Chain &ch : chains)
        all.push_back(&ch);
    const Grouped rest = groupChains(all, prefix.size());
    if (rest.always)
        return prefix; // one way through needs nothing more: the OR holds
    prefix.push_back({rest.key, rest.expr});
    return prefix;
}

// The OR of chains that share their first k factors: grouped by factor k in the order the
// groups first appear, each group its factor and the OR of what follows it.
Importer::Grouped Importer::groupChains(const std::vector<const Chain *> &chains, std::size_t k) {
    Grouped out;
    std::vector<std::pair<QString, std::vector<const Chain *>>> groups;
    for (const Chain *ch : chains) {
        if (ch->size() == k) {
            out.always = true;
            return out;
        }
        const QString &key = (*ch)[k].key;
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&key](const auto &g) { return g.first == key; });
        if (it == groups.end()) {
            groups.push_back({key, {}});
            it = groups.end() - 1;
        }
        it->second.push_back(ch);
    }
    QStringList keys;
    for (const auto &[key, members] : groups) {
        const Factor &f = (*members.front())[k];
        const Grouped tail = groupChains(members, k + 1);
        Expr item = tail.always ? f.expr : detail::series(f.expr, tail.expr);
        if (item.empty()) {
            out.always = true; // a branch from a rail alone
            return out;
        }
        out.expr = detail::parallel(std::move(out.expr), std::move(item));
        keys << (tail.always ? key : key + QLatin1Char(',') + tail.key);
    }
    out.key =
        groups.size() == 1 ? keys.front() : QStringLiteral("(%1)").arg(keys.join(QLatin1Char('|')));
    return out;
}

std::optional<Chain> Importer::chainOf(int id, const QString &formal, const Element &from) {
    const Element *e = element(id);
    if (!e) {
        issue(from.line, describe(from),
              PlcopenTr::tr("it is connected to element %1, which the file does not have").arg(id));
        return std::nullopt;
    }
    const QString key = QStringLiteral("%1/%2").arg(id).arg(formal);
    if (const auto it = m_chains.find(key); it != m_chains.end())
        return it->second;
    if (!m_visiting.insert(key).second) {
        issue(e->line, describe(*e), PlcopenTr::tr("the power flow runs in a loop: not imported"));
        return std::nullopt;
    }
    auto chain = computeChain(*e, formal);
    m_visiting.erase(key);
    // A timer or counter whose Q is read is imported when its own output is, not here.
    if (chain && !consumesPower(*e))
        m_used.insert(e->id);
    m_chains[key] = chain;
    return chain;
}

std::optional<Chain> Importer::computeChain(const Element &e, const QString &formal) {
    if (e.kind == QLatin1String("leftPowerRail"))
        return Chain{{QStringLiteral("rail%1").arg(e.id), Expr()}};
    if (e.kind == QLatin1String("coil"))
        return chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
    if (e.kind == QLatin1String("contact")) {
        auto in = chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
        if (!in)
            return std::nullopt;
        auto c = contactOfVariable(e.variable, e.line);
        if (!c)
            return std::nullopt;
        if (e.negated && !e.edge.isEmpty() && e.edge != QLatin1String("none")) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("a contact both negated and on an edge is not imported"));
            return std::nullopt;
        }
        c->mode = e.negated                            ? ContactMode::Negated
                  : e.edge == QLatin1String("rising")  ? ContactMode::Rising
                  : e.edge == QLatin1String("falling") ? ContactMode::Falling
                                                       : ContactMode::Normal;
        if (!m_t.findInstruction(Op::And, c->mode)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no such contact").arg(m_t.displayName));
            return std::nullopt;
        }
        in->push_back(leaf(e, *c));
        return in;
    }
    if (e.kind == QLatin1String("inVariable")) // a BOOL variable as power
        if (auto c = contactOfVariable(e.variable, e.line))
            return Chain{leaf(e, *c)};
    if (e.kind == QLatin1String("continuation")) {
        for (const Element &c : m_elements)
            if (c.kind == QLatin1String("connector") && c.name == e.name) {
                m_used.insert(c.id);
                return chainIn(c.inputs.empty() ? nullptr : &c.inputs.front(), c);
            }
        issue(e.line, describe(e), PlcopenTr::tr("no connector is named %1").arg(e.name));
        return std::nullopt;
    }
    if (e.kind == QLatin1String("block"))
        return blockChain(e, formal);
    issue(e.line, describe(e),
          PlcopenTr::tr("a %1 carries no power flow %2 can take").arg(e.kind, m_t.displayName));
    return std::nullopt;
}

// A block's output as power: a comparison, NOT, an edge (R_TRIG / F_TRIG), a timer's or a
// counter's Q (its done bit), ENO (the power at EN).
std::optional<Chain> Importer::blockChain(const Element &e, const QString &formal) {
    const QString out = formal.isEmpty() ? QString() : formal.toUpper();
    if (out == QLatin1String("ENO"))
        return chainIn(pin(e, "EN"), e);
    if (!e.contact.isEmpty()) {
        QString why;
        const auto c = contactFromText(m_t, e.contact, &why, m_model);
        if (!c) {
            issue(e.line, describe(e), why);
            return std::nullopt;
        }
        const Pin *in = e.inputs.empty() ? nullptr : &e.inputs.front();
        auto chain = chainIn(in, e);
        if (!chain)
            return std::nullopt;
        for (const Pin &p : e.inputs)
            for (const Connection &conn : p.connections)
                if (const Element *src = element(conn.ref);
                    src && src->kind == QLatin1String("inVariable"))
                    m_used.insert(src->id);
        chain->push_back(leaf(e, *c));
        return chain;
    }
    if (const auto op = compareOf(e.typeName)) {
        const Pin *a = pin(e, "IN1");
        const Pin *b = pin(e, "IN2");
        if (!a || !b) {
            issue(e.line, describe(e), PlcopenTr::tr("a comparison needs IN1 and IN2"));
            return std::nullopt;
        }
        const auto x = pinExpression(*a, e.line);
        const auto y = pinExpression(*b, e.line);
        if (!x || !y)
            return std::nullopt;
        const auto ox = operandOf(*x, e.line);
        const auto oy = operandOf(*y, e.line);
        if (!ox || !oy)
            return std::nullopt;
        Contact c;
        c.compare = *op;
        c.operands = {*ox, *oy};
        if (!m_t.findInstruction(Op::And, ContactMode::Normal, *op)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no compare contact %2")
                      .arg(m_t.displayName, QLatin1String(compareSymbol(*op))));
            return std::nullopt;
        }
        Chain chain;
        if (const Pin *en = pin(e, "EN"); en && !en->connections.empty()) {
            auto in = chainIn(en, e);
            if (!in)
                return std::nullopt;
            chain = *in;
        } else {
            chain = railChain();
        }
        chain.push_back(leaf(e, c));
        return chain;
    }
    if (e.typeName.compare(QLatin1String("NOT"), Qt::CaseInsensitive) == 0 ||
        e.typeName.compare(QLatin1String("R_TRIG"), Qt::CaseInsensitive) == 0 ||
        e.typeName.compare(QLatin1String("F_TRIG"), Qt::CaseInsensitive) == 0) {
        const bool edge = !e.typeName.startsWith(QLatin1String("N"), Qt::CaseInsensitive);
        Contact c;
        c.invert = true;
        c.mode = !edge ? ContactMode::Normal
                 : e.typeName.startsWith(QLatin1String("R"), Qt::CaseInsensitive)
                     ? ContactMode::Rising
                     : ContactMode::Falling;
        if (!m_t.findInstruction(Op::Invert, c.mode)) {
            issue(e.line, describe(e),
                  PlcopenTr::tr("%1 has no element for %2 in the power flow")
                      .arg(m_t.displayName, e.typeName));
            return std::nullopt;
        }
        auto chain = chainIn(e.inputs.empty() ? nullptr : &e.inputs.front(), e);
        if (!chain)
            return std::nullopt;
        chain->push_back(leaf(e, c));
        return chain;
    }
    if ((isTimerType(e.typeName) || isCounterType(e.typeName)) &&
        (out.isEmpty() || out == QLatin1String("Q") || out == QLatin1String("QU") ||
         out == QLatin1String("QD"))) {
        // Q: the element's done bit, a contact of its device; none when the block is not
        // imported (what reads it is listed with it).
        if (m_failedBlocks.contains(e.id))
            return std::nullopt;
        auto c =
            contactOfVariable(out.isEmpty() ? e.instanceName : e.instanceName + '.' + out, e.line);
        if (!c)
            return std::nullopt;
        return Chain{{QStringLiteral("q%1").arg(e.id), Expr::leafOf(*c)}};
    }
    issue(e.line, describe(e),
          PlcopenTr::tr("output %1 of %2 as power flow is not imported")
              .arg(formal.isEmpty() ? QStringLiteral("OUT") : formal, e.typeName));
    return std::nullopt;
}

// An output straight from the rail: the target's always-ON contact (W353's 253.13, Vigor's
// M8000...) stands in for the rail, as the PLC needs a condition.
Chain Importer::railChain() {
    Address on = systemAddress(m_t, SystemRole::AlwaysOn);
    if (!on.valid())
        on = systemAddress(m_t, SystemRole::Run); // PL110 SM0.0: ON while the program runs
    if (!on.valid())
        return {};
    Contact c;
    Operand o;
    o.address = on;
    c.operands.push_back(o);
    return {{QStringLiteral("always"), Expr::leafOf(c)}};
}

std::optional<Chain> Importer::neverChain(const Element &owner) {
    // The always-ON bit negated (railChain's).
    Address on = systemAddress(m_t, SystemRole::AlwaysOn);
    if (!on.valid())
        on = systemAddress(m_t, SystemRole::Run);
    if (!on.valid() || !m_t.findInstruction(Op::And, ContactMode::Negated)) {
        issue(owner.line, describe(owner),
              PlcopenTr::tr("%1 has no contact that is never ON for an input left FALSE")
                  .arg(m_t.displayName));
        return std::nullopt;
    }
    Contact c;
    c.mode = ContactMode::Negated;
    Operand o;
    o.address = on;
    c.operands.push_back(o);
    return Chain{{QStringLiteral("never"), Expr::leafOf(c)}};
}

bool Importer::enAlwaysOn(const Element &e) {
    const Pin *en = pin(e, "EN");
    if (!en || (en->connections.empty() && en->expression.isEmpty()))
        return true;
    if (boolLiteral(en->expression).value_or(false))
        return true;
    const auto chain = chainIn(en, e);
    if (!chain)
        return false;
    if (std::all_of(chain->begin(), chain->end(), [](const Factor &f) {
            return f.expr.empty() || f.key == QLatin1String("always");
        }))
        return true;
    issue(e.line, describe(e),
          PlcopenTr::tr("its EN has a condition: while EN is OFF an IEC block stops where it "
                        "stands, which %1's timers and counters do not; not imported")
              .arg(m_t.displayName));
    return false;
}

std::optional<Chain> Importer::powerPin(const Pin *p, const Element &owner, bool *never) {
    *never = false;
    std::optional<QString> literal;
    if (p && !p->expression.isEmpty())
        literal = p->expression;
    else if (p && p->connections.size() == 1)
        if (const Element *src = element(p->connections.front().ref);
            src && src->kind == QLatin1String("inVariable") && boolLiteral(src->variable)) {
            m_used.insert(src->id);
            literal = src->variable;
        }
    if (!p || (p->connections.empty() && !literal)) {
        *never = true; // an IEC input left open is FALSE
        return std::nullopt;
    }
    if (literal) {
        if (const auto b = boolLiteral(*literal)) {
            if (*b)
                return railChain();
            *never = true;
            return std::nullopt;
        }
        issue(owner.line, describe(owner),
              PlcopenTr::tr("input %1 is %2, not power: not imported").arg(p->formal, *literal));
        return std::nullopt;
    }
    return chainIn(p, owner);
}

} // namespace rung::model::plcopen
