#include "model/exchange/plcopen_import.h"
#include "model/tr.h"

#include "model/convert/convert.h"
#include "model/target/address.h"

#include <QCoreApplication>
#include <QRegularExpression>

#include <cmath>

// The outputs grouped into rungs (a trie of their chains: branch points where they part), the
// rungs' comments, the symbols, and everything of the file not imported, listed.

namespace rung::model::plcopen {

void Importer::insert(Node &node, const Chain &chain, std::size_t k, int outputIndex) {
    if (k == chain.size()) {
        Item item;
        item.output = true;
        item.outputIndex = outputIndex;
        node.items.push_back(std::move(item));
        return;
    }
    // Only into the last item: the outputs keep their order.
    if (!node.items.empty() && !node.items.back().output &&
        node.items.back().factor.key == chain[k].key) {
        insert(*node.items.back().child, chain, k + 1, outputIndex);
        return;
    }
    Item item;
    item.factor = chain[k];
    item.child = std::make_unique<Node>();
    insert(*item.child, chain, k + 1, outputIndex);
    node.items.push_back(std::move(item));
}

Branch Importer::branchOf(const Item &edge) {
    std::vector<Expr> cond;
    if (!edge.factor.expr.empty())
        cond.push_back(edge.factor.expr);
    const Node *node = edge.child.get();
    while (node->items.size() == 1 && !node->items.front().output) {
        if (!node->items.front().factor.expr.empty())
            cond.push_back(node->items.front().factor.expr);
        node = node->items.front().child.get();
    }
    Branch b;
    b.cond = cond.empty() ? Expr() : detail::seriesOf(std::move(cond));
    for (const Item &item : node->items) {
        Branch::Item out;
        if (item.output) {
            out.output = m_outputs[static_cast<std::size_t>(item.outputIndex)].instruction;
        } else {
            out.isOutput = false;
            out.child.push_back(branchOf(item));
        }
        b.items.push_back(std::move(out));
    }
    return b;
}

void Importer::buildProgram() {
    // Every output, in the file's order of execution: executionOrderId, else top to bottom,
    // left to right.
    std::vector<const Element *> order;
    for (const Element &e : m_elements)
        if (consumesPower(e))
            order.push_back(&e);
    std::stable_sort(order.begin(), order.end(), [](const Element *a, const Element *b) {
        if (a->order != b->order && a->order > 0 && b->order > 0)
            return a->order < b->order;
        if (a->y != b->y)
            return a->y < b->y;
        return a->x < b->x;
    });
    // Timers and counters first, so that what reads their Q knows whether they are there.
    std::map<int, std::vector<Output>> built;
    for (const bool instances : {true, false})
        for (const Element *e : order) {
            if (isInstanceBlock(*e) != instances)
                continue;
            std::vector<Output> outs;
            if (e->instruction.isEmpty() && isCounterType(e->typeName)) {
                if (!counterOutputs(*e, &outs))
                    outs.clear();
            } else if (auto out = outputOf(*e)) {
                outs.push_back(std::move(*out));
            }
            if (outs.empty()) {
                if (instances)
                    m_failedBlocks.insert(e->id);
                continue;
            }
            m_used.insert(e->id);
            built[e->id] = std::move(outs);
        }
    for (const Element *e : order)
        if (const auto it = built.find(e->id); it != built.end())
            for (Output &out : it->second)
                m_outputs.push_back(std::move(out));
    noteCounters();
    Project p;
    p.target = &m_t;
    p.model = !m_fileModel.isEmpty() && m_t.model(m_fileModel) ? m_fileModel
              : m_model                                        ? m_model->name
                                                               : m_t.defaultModel().name;
    p.program.target = &m_t;
    // Rungs: a box with several inputs alone; otherwise consecutive outputs whose chains
    // start at one rail (Rung Studio's files: one rail a rung) or with one first element.
    std::vector<double> rungTop;
    std::size_t k = 0;
    while (k < m_outputs.size()) {
        const Output &first = m_outputs[k];
        if (first.multi) {
            RungLogic logic;
            for (const Chain &c : first.inputs) {
                std::vector<Expr> items;
                for (const Factor &f : c)
                    if (!f.expr.empty())
                        items.push_back(f.expr);
                logic.boxInputs.push_back(detail::seriesOf(std::move(items)));
            }
            logic.box = first.instruction;
            p.program.rungs.push_back(detail::layoutRung(logic));
            rungTop.push_back(first.element->y);
            m_rungLine.push_back(first.element->line);
            ++k;
            continue;
        }
        auto startOf = [this](const Chain &c) {
            if (c.empty())
                return QString();
            if (m_own || c.size() == 1 || !c.front().key.startsWith(QLatin1String("rail")))
                return c.front().key;
            return c.front().key + QLatin1Char('/') + c[1].key;
        };
        const QString start = startOf(first.chain);
        Node root;
        std::size_t j = k;
        while (j < m_outputs.size() && !m_outputs[j].multi &&
               (j == k || (!start.isEmpty() && startOf(m_outputs[j].chain) == start))) {
            insert(root, m_outputs[j].chain, 0, static_cast<int>(j));
            ++j;
        }
        RungLogic logic;
        if (root.items.size() == 1 && !root.items.front().output) {
            logic.root = branchOf(root.items.front());
        } else {
            Item top;
            top.child = std::make_unique<Node>(std::move(root));
            logic.root = branchOf(top);
        }
        p.program.rungs.push_back(detail::layoutRung(logic));
        rungTop.push_back(first.element->y);
        m_rungLine.push_back(first.element->line);
        k = j;
    }
    for (const Output &o : m_outputs)
        if (o.setValue && !o.instruction.operands.empty())
            p.setValues[o.instruction.operands.front().address] = *o.setValue;
    // An IEC program has no END: the target's is added after the last rung.
    if (const InstructionSpec *end = m_t.findInstruction(Op::End);
        end && (p.program.rungs.empty() || !endsWithEnd(p.program.rungs.back()))) {
        RungLogic logic;
        Branch::Item item;
        item.output.spec = end;
        logic.root.items.push_back(item);
        p.program.rungs.push_back(detail::layoutRung(logic));
    }
    attachComments(p, rungTop);
    collectSymbols(p);
    reportUnused();
    proposeDevices();
    checkListing(p);
    // Rung Studio's file keeps the listing beside the ladder: a ladder changed by another tool
    // no longer gives it. The ladder is the program; the note says the listing was not taken.
    if (!m_listing.isEmpty() && m_result.issues.empty() && m_result.unmapped.empty() &&
        printInstructionList(ladderToList(p.program).list).trimmed() != m_listing.trimmed())
        note(PlcopenTr::tr("the instruction list in the file differs from its ladder (another tool "
                           "changed the ladder?): the ladder is imported"));
    m_result.project = std::move(p);
}

bool Importer::endsWithEnd(const Rung &r) {
    for (const auto &o : r.outputs)
        if (o && o->op() == Op::End)
            return true;
    return false;
}

void Importer::attachComments(Project &p, const std::vector<double> &rungTop) {
    for (const Element &e : m_elements) {
        if (e.kind != QLatin1String("comment"))
            continue;
        m_used.insert(e.id);
        if (rungTop.empty() || e.comment.isEmpty())
            continue;
        std::size_t r = 0;
        while (r < rungTop.size() && rungTop[r] < e.y)
            ++r;
        if (r == rungTop.size())
            r = rungTop.size() - 1; // below the last rung: the last rung's
        QString &c = p.program.rungs[r].comment;
        c = c.isEmpty() ? e.comment : c + QLatin1Char('\n') + e.comment;
    }
}

// The device of a variable the ladder did not name through resolve(): Rung Studio's note
// of it, its location, a name that is a device. Nothing is listed as unmapped for it.
std::optional<Address> Importer::quietDevice(const QString &name, const VariableInfo &v) const {
    if (const auto it = m_resolved.find(name); it != m_resolved.end())
        return it->second;
    if (const auto it = m_mapping.devices.find(name); it != m_mapping.devices.end())
        if (const auto parsed = parseAddress(m_t, it->second, m_model);
            std::holds_alternative<Address>(parsed))
            return std::get<Address>(parsed);
    if (!v.device.isEmpty())
        if (const auto parsed = parseAddress(m_t, v.device, m_model);
            std::holds_alternative<Address>(parsed))
            return std::get<Address>(parsed);
    if (!v.location.isEmpty())
        if (const auto a = deviceOfLocation(m_t, v.location, m_model))
            return a;
    return deviceOfIecName(m_t, name, m_model);
}

// The symbols, in the order of the file's variables: Rung Studio's own (its note of the
// symbol), or another tool's variable named otherwise than its device (the name, its
// documentation the comment). A variable the ladder does not use and no rule maps to a
// device is listed.
void Importer::collectSymbols(Project &p) {
    for (const QString &name : m_varOrder) {
        // A variable an element names whose element waits for another variable's device (a
        // counter's CV to it, the counter not mapped yet): it needs one too.
        if (!m_resolved.contains(name) && !m_vars[name].used && m_vars[name].constant.isEmpty() &&
            m_vars[name].type.compare(QLatin1String("R_TRIG"), Qt::CaseInsensitive) != 0 &&
            m_vars[name].type.compare(QLatin1String("F_TRIG"), Qt::CaseInsensitive) != 0 &&
            std::any_of(m_elements.begin(), m_elements.end(), [&name](const Element &e) {
                return e.variable == name || e.instanceName == name ||
                       e.variable.startsWith(name + QLatin1Char('.'));
            }))
            resolve(name, m_vars[name].line, m_vars[name].type);
        const VariableInfo &v = m_vars[name];
        if (!v.constant.isEmpty())
            continue; // a literal where the ladder names it, no device
        const bool named = m_resolved.contains(name) || v.used;
        const auto a = quietDevice(name, v);
        if (!a) {
            if (named)
                continue; // listed as unmapped already
            if (isTimerType(v.type) || isCounterType(v.type) || v.type == QLatin1String("R_TRIG") ||
                v.type == QLatin1String("F_TRIG"))
                continue; // an instance its block names
            issue(v.line, QStringLiteral("variable %1").arg(name),
                  PlcopenTr::tr("the ladder does not use it and it names no device: not imported"));
            continue;
        }
        if (v.setValue)
            p.setValues[*a] = *v.setValue;
        Symbol s;
        s.address = *a;
        if (!v.symbol.isEmpty() || !v.device.isEmpty()) {
            if (v.symbol.isEmpty())
                continue; // Rung Studio's own device without a symbol
            s.name = v.symbol;
            s.comment = v.symbolComment;
        } else if (name.compare(iecName(m_t, *a), Qt::CaseInsensitive) != 0 ||
                   !v.documentation.isEmpty()) {
            s.name = name;
            s.comment = v.documentation;
        } else {
            continue;
        }
        if (!p.symbol(*a))
            p.symbols.push_back(s);
    }
}

// An element, not imported, whose output this element's inputs take.
const Element *Importer::sourceNotImported(const Element &e) const {
    for (const Pin &p : e.inputs)
        for (const Connection &c : p.connections)
            if (const Element *src = element(c.ref); src && !m_used.contains(src->id) &&
                                                     src->kind != QLatin1String("leftPowerRail") &&
                                                     src->kind != QLatin1String("inVariable"))
                return src;
    return nullptr;
}

// A block, not imported, that this element's output feeds.
const Element *Importer::blockFedBy(const Element &e) const {
    for (const Element &b : m_elements) {
        if (b.kind != QLatin1String("block") || m_used.contains(b.id))
            continue;
        for (const Pin &p : b.inputs)
            for (const Connection &c : p.connections)
                if (c.ref == e.id)
                    return &b;
    }
    return nullptr;
}

void Importer::reportUnused() {
    // The operand variables of a block that is not imported go with it.
    std::set<int> ofBlocks;
    for (const Element &e : m_elements) {
        if (e.kind != QLatin1String("block") || m_used.contains(e.id))
            continue;
        for (const Pin &p : e.inputs)
            for (const Connection &c : p.connections)
                if (const Element *src = element(c.ref);
                    src && src->kind == QLatin1String("inVariable"))
                    ofBlocks.insert(src->id);
        for (const Element &o : m_elements)
            if (o.kind == QLatin1String("outVariable") && !o.inputs.empty())
                for (const Connection &c : o.inputs.front().connections)
                    if (c.ref == e.id)
                        ofBlocks.insert(o.id);
    }
    // An element that names a variable without a device waits for one (the unmapped list says
    // so), and so do the elements its power comes from or goes to.
    std::set<QString> unmapped;
    for (const UnmappedVariable &u : m_result.unmapped)
        unmapped.insert(u.name);
    const auto waits = [&](const Element &e) {
        QString variable = e.variable;
        if (variable.endsWith(QLatin1String(".Q"), Qt::CaseInsensitive))
            variable.chop(2);
        if (unmapped.contains(variable) || unmapped.contains(e.instanceName))
            return true;
        for (const Pin &p : e.inputs)
            for (const Connection &c : p.connections)
                if (const Element *src = element(c.ref); src &&
                                                         src->kind == QLatin1String("inVariable") &&
                                                         unmapped.contains(src->variable))
                    return true;
        return false;
    };
    std::set<int> waiting;
    for (const Element &e : m_elements)
        if (!m_used.contains(e.id) && waits(e))
            waiting.insert(e.id);
    for (bool grew = !waiting.empty(); grew;) {
        grew = false;
        for (const Element &e : m_elements) {
            if (m_used.contains(e.id) || waiting.contains(e.id))
                continue;
            const Element *s = sourceNotImported(e);
            const Element *b = blockFedBy(e);
            if ((s && waiting.contains(s->id)) || (b && waiting.contains(b->id)))
                grew = waiting.insert(e.id).second || grew;
        }
    }
    for (const Element &e : m_elements) {
        if (ofBlocks.contains(e.id) || waiting.contains(e.id))
            continue;
        if (m_used.contains(e.id) || e.kind == QLatin1String("leftPowerRail") ||
            e.kind == QLatin1String("rightPowerRail") || e.kind == QLatin1String("comment"))
            continue;
        // An element that failed said so already; one no output reaches is said here.
        bool reported = false;
        for (const ImportIssue &i : m_result.issues)
            if (i.line == e.line)
                reported = true;
        if (reported)
            continue;
        if (e.kind == QLatin1String("jump") || e.kind == QLatin1String("label") ||
            e.kind == QLatin1String("return"))
            issue(e.line, describe(e),
                  PlcopenTr::tr("IEC jumps, labels and returns are not imported: %1's own jumps "
                                "work otherwise; write them in Rung Studio")
                      .arg(m_t.displayName));
        else if (e.kind == QLatin1String("block"))
            issue(e.line, describe(e),
                  PlcopenTr::tr("this block is not imported: contacts, coils, TON, TOF, CTU, "
                                "CTD, CTUD, MOVE, the comparisons, NOT, R_TRIG and F_TRIG are "
                                "(docs/plcopen.md)"));
        else if (const Element *source = sourceNotImported(e))
            issue(e.line, describe(e),
                  PlcopenTr::tr("its power comes from %1 (line %2), which is not imported")
                      .arg(describe(*source))
                      .arg(source->line));
        else if (const Element *block = blockFedBy(e))
            issue(e.line, describe(e),
                  PlcopenTr::tr("its power goes to %1 (line %2), which is not imported")
                      .arg(describe(*block))
                      .arg(block->line));
        else
            issue(e.line, describe(e), PlcopenTr::tr("no output uses it: not imported"));
    }
}

// A free device for each variable without one: of the kind its type needs.
void Importer::proposeDevices() {
    std::set<Address> taken = m_usedDevices;
    // Areas that share element numbers (VPC t / c, CPM1 TIM / CNT): a number taken in one is
    // taken in all (Area::bank).
    const auto takenInBank = [&](const Address &a) {
        const int bank = m_t.area(a.area).bank;
        if (bank < 0)
            return false;
        return std::any_of(taken.begin(), taken.end(), [&](const Address &t) {
            return t.index == a.index && t.area != a.area && m_t.area(t.area).bank == bank;
        });
    };
    for (UnmappedVariable &u : m_result.unmapped) {
        const QString t = u.type.toUpper();
        AreaKind kind = AreaKind::Bit;
        if (isTimerType(t))
            kind = AreaKind::Timer;
        else if (isCounterType(t))
            kind = AreaKind::Counter;
        else if (t != QLatin1String("BOOL") && !t.isEmpty())
            kind = AreaKind::Word;
        // A word: the data memory first, as %MWn names it (PL110 V, not its display's DISP).
        if (kind == AreaKind::Word)
            if (const int data = dataMemoryArea(m_t); data >= 0)
                if (const auto range = m_t.range(data, m_model))
                    for (int n = range->first; n <= range->second && u.proposed.isEmpty(); ++n)
                        if (const Address candidate{data, n, -1}; taken.insert(candidate).second)
                            u.proposed = formatAddress(m_t, candidate);
        // Areas of the kind first; then the bits (or the words) of channel areas, where the
        // target keeps its work bits in channels (CPM1 200.00); memory kept over a power loss
        // last (the VPC's timers and counters are all kept, VPC user's manual, III).
        for (int pass = 0; pass < 4 && u.proposed.isEmpty(); ++pass) {
            const bool retentiveToo = pass >= 2;
            const AreaKind wanted = pass % 2 == 0 ? kind : AreaKind::Channel;
            if (pass % 2 == 1 && kind != AreaKind::Bit && kind != AreaKind::Word)
                continue;
            for (std::size_t i = 0; i < m_t.areas.size() && u.proposed.isEmpty(); ++i) {
                const Area &a = m_t.areas[i];
                const bool plain = a.writable && !a.system && !a.physical && !a.indexRegister &&
                                   !a.presetsOf && !a.branchMemory &&
                                   a.onlyWrittenBy == ApplyFunction::None &&
                                   (!a.retentive || retentiveToo);
                if (a.kind != wanted || !plain)
                    continue;
                const auto range = m_t.range(static_cast<int>(i), m_model);
                if (!range)
                    continue;
                const int bits = pass % 2 == 1 && kind == AreaKind::Bit ? 16 : 0;
                for (int n = range->first; n <= range->second && u.proposed.isEmpty(); ++n)
                    for (int b = bits > 0 ? 0 : -1; b < std::max(0, bits); ++b) {
                        const Address candidate{static_cast<int>(i), n, b};
                        // A counter that counts as the file's does (VPC: c16.. count up).
                        const auto alike = [&](int number) {
                            const auto c = counterChoices(m_t, counterKind(t),
                                                          {static_cast<int>(i), number, -1});
                            return !c.empty() && c.front().sameKind;
                        };
                        if (kind == AreaKind::Counter && !alike(n) && alike(range->second))
                            continue;
                        if (!takenInBank(candidate) && taken.insert(candidate).second) {
                            u.proposed = formatAddress(m_t, candidate);
                            break;
                        }
                    }
            }
        }
    }
}

void Importer::checkListing(const Project &p) {
    const ToListingResult listed = ladderToList(p.program);
    for (const Diagnostic &d : listed.problems)
        if (d.severity == Severity::Error) {
            const auto r = static_cast<std::size_t>(std::max(0, d.location.rung));
            issue(r < m_rungLine.size() ? m_rungLine[r] : 0,
                  QStringLiteral("rung %1").arg(d.location.rung + 1), d.message);
        }
}

} // namespace rung::model::plcopen
