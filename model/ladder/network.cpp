#include "model/ladder/network.h"

namespace rung::model::detail {

namespace {

Expr combine(Expr::Kind kind, Expr a, Expr b) {
    if (a.empty())
        return b;
    if (b.empty())
        return a;
    // Chains grow one element at a time: the left operand's list is reused, not copied.
    Expr out;
    out.kind = kind;
    if (a.kind == kind)
        out.items = std::move(a.items);
    else
        out.items.push_back(std::move(a));
    if (b.kind == kind) {
        out.items.reserve(out.items.size() + b.items.size());
        for (Expr &item : b.items)
            out.items.push_back(std::move(item));
    } else {
        out.items.push_back(std::move(b));
    }
    return out;
}

} // namespace

Expr series(Expr a, Expr b) {
    return combine(Expr::Kind::Series, std::move(a), std::move(b));
}

Expr parallel(Expr a, Expr b) {
    return combine(Expr::Kind::Parallel, std::move(a), std::move(b));
}

bool sameExpr(const Expr &a, const Expr &b, bool byCell) {
    if (a.kind != b.kind)
        return false;
    if (a.kind == Expr::Kind::Leaf)
        return byCell ? a.cell == b.cell : a.leaf == b.leaf;
    if (a.items.size() != b.items.size())
        return false;
    for (std::size_t i = 0; i < a.items.size(); ++i)
        if (!sameExpr(a.items[i], b.items[i], byCell))
            return false;
    return true;
}

std::vector<Expr> seriesItems(const Expr &e) {
    if (e.kind == Expr::Kind::Series)
        return e.items;
    return {e};
}

std::vector<Expr> seriesItems(Expr &&e) {
    if (e.kind == Expr::Kind::Series)
        return std::move(e.items);
    std::vector<Expr> one;
    one.push_back(std::move(e));
    return one;
}

Expr seriesOf(std::vector<Expr> items) {
    if (items.size() == 1)
        return std::move(items.front());
    Expr e;
    e.kind = Expr::Kind::Series;
    e.items = std::move(items);
    return e;
}

} // namespace rung::model::detail
