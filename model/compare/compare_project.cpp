#include "model/compare/compare.h"

#include "model/compare/rung_matching.h"

#include <QCoreApplication>

#include <map>

// Around the rungs: symbols, set values, watch lists and what a project keeps as typed.

namespace rung::model {

namespace {

using Kind = ItemDifference::Kind;

ItemDifference item(Kind kind, const QString &key, const QString &field, const QString &before,
                    const QString &after, const QString &subject = {}) {
    ItemDifference d;
    d.kind = kind;
    d.key = key;
    d.field = field;
    d.before = before;
    d.after = after;
    d.subject = subject;
    return d;
}

std::vector<ItemDifference> compareSymbols(const Target &t, const Project &a, const Project &b) {
    // By device, in the order of the devices; the first row of a device counts.
    std::map<Address, const Symbol *> inA;
    std::map<Address, const Symbol *> inB;
    for (const Symbol &s : a.symbols)
        inA.emplace(s.address, &s);
    for (const Symbol &s : b.symbols)
        inB.emplace(s.address, &s);
    std::map<Address, bool> devices;
    for (const auto &[address, s] : inA)
        devices[address] = true;
    for (const auto &[address, s] : inB)
        devices[address] = true;
    std::vector<ItemDifference> out;
    for (const auto &[address, unused] : devices) {
        const QString device = formatAddress(t, address);
        const auto x = inA.find(address);
        const auto y = inB.find(address);
        if (y == inB.end()) {
            out.push_back(item(Kind::Removed, device, QStringLiteral("name"), x->second->name, {}));
            if (!x->second->comment.isEmpty())
                out.push_back(
                    item(Kind::Removed, device, QStringLiteral("comment"), x->second->comment, {}));
        } else if (x == inA.end()) {
            out.push_back(item(Kind::Added, device, QStringLiteral("name"), {}, y->second->name));
            if (!y->second->comment.isEmpty())
                out.push_back(
                    item(Kind::Added, device, QStringLiteral("comment"), {}, y->second->comment));
        } else {
            if (x->second->name.trimmed() != y->second->name.trimmed())
                out.push_back(item(Kind::Changed, device, QStringLiteral("name"), x->second->name,
                                   y->second->name));
            if (x->second->comment.simplified() != y->second->comment.simplified())
                out.push_back(item(Kind::Changed, device, QStringLiteral("comment"),
                                   x->second->comment, y->second->comment));
        }
    }
    return out;
}

std::vector<ItemDifference> compareSetValues(const Target &t, const Project &a, const Project &b) {
    std::vector<ItemDifference> out;
    std::map<Address, bool> devices;
    for (const auto &[address, v] : a.setValues)
        devices[address] = true;
    for (const auto &[address, v] : b.setValues)
        devices[address] = true;
    for (const auto &[address, unused] : devices) {
        const QString device = formatAddress(t, address);
        const auto x = a.setValues.find(address);
        const auto y = b.setValues.find(address);
        if (y == b.setValues.end())
            out.push_back(item(Kind::Removed, device, QStringLiteral("value"),
                               QString::number(x->second), {}));
        else if (x == a.setValues.end())
            out.push_back(
                item(Kind::Added, device, QStringLiteral("value"), {}, QString::number(y->second)));
        else if (x->second != y->second)
            out.push_back(item(Kind::Changed, device, QStringLiteral("value"),
                               QString::number(x->second), QString::number(y->second)));
    }
    return out;
}

std::vector<ItemDifference> compareWatchLists(const Project &a, const Project &b) {
    std::vector<ItemDifference> out;
    // By name; lists of one name in their order (the second "Main" with the second).
    std::vector<bool> used(b.watchLists.size(), false);
    auto devices = [](const WatchList &w) { return w.devices.join(QStringLiteral(", ")); };
    for (const WatchList &x : a.watchLists) {
        std::size_t k = 0;
        while (k < b.watchLists.size() && (used[k] || b.watchLists[k].name != x.name))
            ++k;
        if (k == b.watchLists.size()) {
            out.push_back(item(Kind::Removed, x.name, QStringLiteral("devices"), devices(x), {}));
            continue;
        }
        used[k] = true;
        const WatchList &y = b.watchLists[k];
        for (const QString &d : x.devices)
            if (!y.devices.contains(d))
                out.push_back(item(Kind::Removed, x.name, QStringLiteral("device"), d, {}, d));
        for (const QString &d : y.devices)
            if (!x.devices.contains(d))
                out.push_back(item(Kind::Added, x.name, QStringLiteral("device"), {}, d, d));
        QStringList keptX;
        QStringList keptY;
        for (const QString &d : x.devices)
            if (y.devices.contains(d))
                keptX << d;
        for (const QString &d : y.devices)
            if (x.devices.contains(d))
                keptY << d;
        if (keptX != keptY)
            out.push_back(
                item(Kind::Changed, x.name, QStringLiteral("order"), devices(x), devices(y)));
        for (const QString &d : keptY)
            if (x.format(d) != y.format(d))
                out.push_back(item(Kind::Changed, x.name, QStringLiteral("format"),
                                   valueFormatKey(x.format(d)), valueFormatKey(y.format(d)), d));
    }
    for (std::size_t k = 0; k < b.watchLists.size(); ++k)
        if (!used[k])
            out.push_back(item(Kind::Added, b.watchLists[k].name, QStringLiteral("devices"), {},
                               devices(b.watchLists[k])));
    return out;
}

std::vector<ItemDifference> comparePending(const Project &a, const Project &b) {
    std::vector<ItemDifference> out;
    // The list as typed is compared line by line without the spaces around them: a list
    // that differs only in its layout is the same list.
    auto lines = [](const QString &text) {
        QStringList kept;
        for (const QString &line : text.split(QLatin1Char('\n')))
            if (!line.simplified().isEmpty())
                kept << line.simplified();
        return kept;
    };
    if (lines(a.pendingListing) != lines(b.pendingListing)) {
        const Kind kind = a.pendingListing.isEmpty()   ? Kind::Added
                          : b.pendingListing.isEmpty() ? Kind::Removed
                                                       : Kind::Changed;
        out.push_back(item(kind, QStringLiteral("pendingListing"), QStringLiteral("text"),
                           a.pendingListing, b.pendingListing));
    }
    auto rows = [](const std::vector<PendingSymbol> &symbols) {
        QStringList r;
        for (const PendingSymbol &s : symbols)
            r << QStringLiteral("%1 %2 %3")
                     .arg(s.device.simplified(), s.name.simplified(), s.comment.simplified());
        return r;
    };
    const QStringList x = rows(a.pendingSymbols);
    const QStringList y = rows(b.pendingSymbols);
    for (const QString &r : x)
        if (!y.contains(r))
            out.push_back(item(Kind::Removed, QStringLiteral("pendingSymbols"),
                               QStringLiteral("row"), r, {}));
    for (const QString &r : y)
        if (!x.contains(r))
            out.push_back(
                item(Kind::Added, QStringLiteral("pendingSymbols"), QStringLiteral("row"), {}, r));
    return out;
}

} // namespace

bool Comparison::equal() const {
    for (const RungDifference &r : rungs)
        if (r.status != RungStatus::Same)
            return false;
    return modelA == modelB && symbols.empty() && setValues.empty() && watchLists.empty() &&
           pending.empty();
}

int Comparison::count(RungStatus status) const {
    return static_cast<int>(
        std::count_if(rungs.begin(), rungs.end(),
                      [status](const RungDifference &r) { return r.status == status; }));
}

Comparison compareProjects(const Project &a, const Project &b) {
    Comparison c;
    c.target = a.target;
    c.modelA = a.model;
    c.modelB = b.model;
    const Target &t = *a.target;
    LadderProgram pa = a.program;
    LadderProgram pb = b.program;
    pa.target = pb.target = a.target;
    c.rungs = compareRungs(t, comparedRungs(pa), comparedRungs(pb));
    c.symbols = compareSymbols(t, a, b);
    c.setValues = compareSetValues(t, a, b);
    c.watchLists = compareWatchLists(a, b);
    c.pending = comparePending(a, b);
    return c;
}

} // namespace rung::model
