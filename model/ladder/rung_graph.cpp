#include "model/ladder/rung_graph.h"
#include "model/ladder/reverse_current.h"

#include <algorithm>
#include <limits>
#include <map>
#include <numeric>

namespace rung::model::detail {

namespace {

constexpr int kMaxPaths = 256;

struct UnionFind {
    std::vector<int> parent;
    explicit UnionFind(int n)
        : parent(static_cast<std::size_t>(n)) {
        std::iota(parent.begin(), parent.end(), 0);
    }
    int find(int x) {
        while (parent[static_cast<std::size_t>(x)] != x) {
            parent[static_cast<std::size_t>(x)] =
                parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
            x = parent[static_cast<std::size_t>(x)];
        }
        return x;
    }
    void join(int a, int b) { parent[static_cast<std::size_t>(find(a))] = find(b); }
};

} // namespace

Graph buildGraph(const Rung &rung) {
    const int width = rung.columns + 1;
    UnionFind uf(rung.rows * width);
    auto node = [width](int r, int c) { return r * width + c; };
    for (int r = 1; r < rung.rows; ++r)
        uf.join(node(r, 0), node(0, 0));
    for (int r = 0; r < rung.rows; ++r) {
        for (int c = 0; c <= rung.columns; ++c)
            if (r + 1 < rung.rows && rung.link(r, c))
                uf.join(node(r, c), node(r + 1, c));
        for (int c = 0; c < rung.columns; ++c)
            if (rung.cell(r, c).kind == CellKind::Wire)
                uf.join(node(r, c), node(r, c + 1));
    }
    Graph g;
    g.nodes = rung.rows * width;
    g.rail = uf.find(node(0, 0));
    for (int r = 0; r < rung.rows; ++r) {
        for (int c = 0; c < rung.columns; ++c) {
            const Cell &cell = rung.cell(r, c);
            if (cell.kind != CellKind::Contact)
                continue;
            const int cellId = r * rung.columns + c;
            g.edges.push_back(Edge{uf.find(node(r, c)), uf.find(node(r, c + 1)),
                                   Expr::leafOf(cell.contact, cellId), r * 4096 + c});
        }
        g.outputNode.push_back(uf.find(node(r, rung.columns)));
    }
    return g;
}

namespace {

int firstCell(const Expr &e) {
    if (e.kind == Expr::Kind::Leaf)
        return e.cell;
    int best = std::numeric_limits<int>::max();
    for (const Expr &i : e.items)
        best = std::min(best, firstCell(i));
    return best;
}

// Reduces a two-terminal network by parallel and series steps; true when one edge is left.
// Each round merges every group of parallel edges, then joins every node with one edge in
// and one edge out; the result does not depend on the order of the joins (series() and
// parallel() flatten, branches are sorted by their top-left cell).
bool reduce(std::vector<Edge> edges, int source, int sink, Expr *out) {
    int nodes = std::max(source, sink) + 1;
    for (const Edge &e : edges)
        nodes = std::max({nodes, e.from + 1, e.to + 1});
    std::vector<int> inCount(static_cast<std::size_t>(nodes));
    std::vector<int> outCount(static_cast<std::size_t>(nodes));
    std::vector<int> inEdge(static_cast<std::size_t>(nodes));
    std::vector<int> outEdge(static_cast<std::size_t>(nodes));
    std::vector<std::size_t> order;
    for (bool changed = true; changed;) {
        changed = false;
        // Parallel edges between the same two nodes become one, branches in drawing order.
        order.resize(edges.size());
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return std::pair(edges[a].from, edges[a].to) < std::pair(edges[b].from, edges[b].to);
        });
        std::vector<Edge> next;
        next.reserve(edges.size());
        for (std::size_t i = 0; i < order.size();) {
            std::size_t j = i + 1;
            const Edge &first = edges[order[i]];
            while (j < order.size() && edges[order[j]].from == first.from &&
                   edges[order[j]].to == first.to)
                ++j;
            if (j - i == 1) {
                next.push_back(std::move(edges[order[i]]));
                i = j;
                continue;
            }
            // Branches in drawing order, each by its own top-left cell, so the order does
            // not depend on which branches were reduced first.
            std::vector<Expr> branches;
            int key = first.key;
            Edge merged{first.from, first.to, {}, key};
            for (std::size_t k = i; k < j; ++k) {
                Edge &m = edges[order[k]];
                merged.key = std::min(merged.key, m.key);
                if (m.expr.kind == Expr::Kind::Parallel)
                    for (Expr &b : m.expr.items)
                        branches.push_back(std::move(b));
                else
                    branches.push_back(std::move(m.expr));
            }
            std::vector<std::pair<int, std::size_t>> byCell;
            byCell.reserve(branches.size());
            for (std::size_t k = 0; k < branches.size(); ++k)
                byCell.emplace_back(firstCell(branches[k]), k);
            std::stable_sort(byCell.begin(), byCell.end(),
                             [](const auto &a, const auto &b) { return a.first < b.first; });
            merged.expr.kind = Expr::Kind::Parallel;
            merged.expr.items.reserve(branches.size());
            for (const auto &[cell, k] : byCell)
                merged.expr.items.push_back(std::move(branches[k]));
            next.push_back(std::move(merged));
            changed = true;
            i = j;
        }
        edges = std::move(next);
        // A node with one edge in and one edge out joins them in series.
        std::fill(inCount.begin(), inCount.end(), 0);
        std::fill(outCount.begin(), outCount.end(), 0);
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const auto to = static_cast<std::size_t>(edges[i].to);
            const auto from = static_cast<std::size_t>(edges[i].from);
            ++inCount[to];
            inEdge[to] = static_cast<int>(i);
            ++outCount[from];
            outEdge[from] = static_cast<int>(i);
        }
        std::vector<bool> dead(edges.size(), false);
        for (int n = 0; n < nodes; ++n) {
            const auto un = static_cast<std::size_t>(n);
            if (n == source || n == sink || inCount[un] != 1 || outCount[un] != 1)
                continue;
            const auto a = static_cast<std::size_t>(inEdge[un]);
            const auto b = static_cast<std::size_t>(outEdge[un]);
            if (a == b)
                continue; // a loop on n
            // a: x -> n, b: n -> y become a: x -> y; y's single in-edge (if it has one) is a.
            Edge &in = edges[a];
            Edge &outE = edges[b];
            in.expr = series(std::move(in.expr), std::move(outE.expr));
            in.key = std::min(in.key, outE.key);
            in.to = outE.to;
            const auto y = static_cast<std::size_t>(in.to);
            if (inEdge[y] == static_cast<int>(b))
                inEdge[y] = static_cast<int>(a);
            if (outEdge[static_cast<std::size_t>(in.from)] == static_cast<int>(b))
                outEdge[static_cast<std::size_t>(in.from)] = static_cast<int>(a);
            dead[b] = true;
            inCount[un] = outCount[un] = 0;
            changed = true;
        }
        if (changed) {
            std::vector<Edge> alive;
            alive.reserve(edges.size());
            for (std::size_t i = 0; i < edges.size(); ++i)
                if (!dead[i])
                    alive.push_back(std::move(edges[i]));
            edges = std::move(alive);
        }
    }
    if (edges.size() == 1 && edges[0].from == source && edges[0].to == sink) {
        *out = std::move(edges[0].expr);
        return true;
    }
    return false;
}

Expr factor(std::vector<std::vector<Expr>> paths) {
    for (const auto &p : paths)
        if (p.empty())
            return Expr{};
    Expr result;
    std::vector<bool> used(paths.size(), false);
    for (std::size_t i = 0; i < paths.size(); ++i) {
        if (used[i])
            continue;
        std::vector<std::vector<Expr>> rest;
        for (std::size_t k = i; k < paths.size(); ++k) {
            if (used[k] || paths[k][0].cell != paths[i][0].cell)
                continue;
            used[k] = true;
            rest.emplace_back(paths[k].begin() + 1, paths[k].end());
        }
        result = parallel(std::move(result), series(paths[i][0], factor(std::move(rest))));
    }
    return result;
}

void collectPaths(const std::vector<const Edge *> &edges, int at, int sink, std::vector<Expr> &path,
                  std::vector<std::vector<Expr>> &paths, std::vector<int> &visiting) {
    if (paths.size() >= static_cast<std::size_t>(kMaxPaths))
        return;
    if (at == sink) {
        paths.push_back(path);
        return;
    }
    if (std::find(visiting.begin(), visiting.end(), at) != visiting.end())
        return; // a loop: no left-to-right path goes round it
    visiting.push_back(at);
    for (const Edge *e : edges) {
        if (e->from != at)
            continue;
        path.push_back(e->expr);
        collectPaths(edges, e->to, sink, path, paths, visiting);
        path.pop_back();
    }
    visiting.pop_back();
}

// `consume`: the graph's last use, so the relevant edges are moved out of it, not copied.
InputNetwork analyze(const Rung &rung, Graph &g, int row, bool consume) {
    InputNetwork net;
    net.row = row;
    const int sink = g.outputNode[static_cast<std::size_t>(row)];
    if (sink == g.rail) {
        net.connected = true;
        return net;
    }
    // Edges on some rail -> sink path: reachable forward from the rail and backward from the sink.
    std::vector<char> forward(static_cast<std::size_t>(g.nodes), 0);
    std::vector<char> backward(static_cast<std::size_t>(g.nodes), 0);
    forward[static_cast<std::size_t>(g.rail)] = 1;
    backward[static_cast<std::size_t>(sink)] = 1;
    for (bool grew = true; grew;) {
        grew = false;
        for (const Edge &e : g.edges)
            if (e.from != e.to && forward[static_cast<std::size_t>(e.from)] &&
                !forward[static_cast<std::size_t>(e.to)]) {
                forward[static_cast<std::size_t>(e.to)] = 1;
                grew = true;
            }
    }
    for (bool grew = true; grew;) {
        grew = false;
        for (auto it = g.edges.rbegin(); it != g.edges.rend(); ++it)
            if (it->from != it->to && backward[static_cast<std::size_t>(it->to)] &&
                !backward[static_cast<std::size_t>(it->from)]) {
                backward[static_cast<std::size_t>(it->from)] = 1;
                grew = true;
            }
    }
    std::vector<Edge> relevant;
    for (Edge &e : g.edges)
        if (e.from != e.to && forward[static_cast<std::size_t>(e.from)] &&
            backward[static_cast<std::size_t>(e.to)]) {
            net.cells.push_back(e.expr.cell);
            relevant.push_back(consume ? std::move(e) : e);
        }
    net.connected = forward[static_cast<std::size_t>(sink)] != 0;
    if (!net.connected)
        return net;
    net.seriesParallel = reduce(std::move(relevant), g.rail, sink, &net.expr);
    if (!net.seriesParallel) {
        // Not series-parallel (a bridge): rare, so the edges are looked up again here rather
        // than copied for every network.
        const Graph fresh = consume ? buildGraph(rung) : Graph{};
        std::vector<const Edge *> pointers;
        for (const Edge &e : consume ? fresh.edges : g.edges)
            if (e.from != e.to && forward[static_cast<std::size_t>(e.from)] &&
                backward[static_cast<std::size_t>(e.to)])
                pointers.push_back(&e);
        std::vector<Expr> path;
        std::vector<std::vector<Expr>> paths;
        std::vector<int> visiting;
        collectPaths(pointers, g.rail, sink, path, paths, visiting);
        net.paths = factor(std::move(paths));
    }
    return net;
}

void insert(Branch &node, const std::vector<Expr> &list, std::size_t pos, const Instruction &output,
            int row) {
    if (pos < list.size() && !node.items.empty() && !node.items.back().isOutput) {
        Branch &child = node.items.back().child.front();
        const std::vector<Expr> childList = seriesItems(child.cond);
        std::size_t p = 0;
        while (p < childList.size() && pos + p < list.size() &&
               sameExpr(childList[p], list[pos + p], true))
            ++p;
        if (p > 0) {
            if (p < childList.size()) {
                Branch lower;
                lower.cond =
                    seriesOf({childList.begin() + static_cast<std::ptrdiff_t>(p), childList.end()});
                lower.items = std::move(child.items);
                child.cond = seriesOf(
                    {childList.begin(), childList.begin() + static_cast<std::ptrdiff_t>(p)});
                child.items.clear();
                Branch::Item item;
                item.isOutput = false;
                item.child.push_back(std::move(lower));
                child.items.push_back(std::move(item));
            }
            insert(child, list, pos + p, output, row);
            return;
        }
    }
    Branch::Item item;
    if (pos == list.size()) {
        item.output = output;
        item.row = row;
        node.items.push_back(std::move(item));
        return;
    }
    Branch leaf;
    leaf.cond = seriesOf({list.begin() + static_cast<std::ptrdiff_t>(pos), list.end()});
    Branch::Item out;
    out.output = output;
    out.row = row;
    leaf.items.push_back(std::move(out));
    item.isOutput = false;
    item.child.push_back(std::move(leaf));
    node.items.push_back(std::move(item));
}

} // namespace

std::vector<InputNetwork> analyzeRung(const Rung &rung) {
    Graph g = buildGraph(rung);
    std::vector<int> inputs;
    for (int r = 0; r < rung.rows; ++r)
        if (rung.outputs[static_cast<std::size_t>(r)])
            for (int input : rung.boxInputRows(r))
                inputs.push_back(input);
    std::vector<InputNetwork> result;
    result.reserve(inputs.size());
    for (std::size_t k = 0; k < inputs.size(); ++k)
        result.push_back(analyze(rung, g, inputs[k], k + 1 == inputs.size()));
    return result;
}

RungLogic logicOf(const Rung &rung, std::vector<InputNetwork> networks, bool useFixes) {
    RungLogic logic;
    // The networks are the caller's copy: their expressions move into the branch tree.
    auto take = [useFixes](InputNetwork &n) {
        return std::move((!n.seriesParallel && useFixes) ? n.paths : n.expr);
    };
    std::size_t next = 0;
    for (int r = 0; r < rung.rows; ++r) {
        const auto &out = rung.outputs[static_cast<std::size_t>(r)];
        if (!out)
            continue;
        const std::vector<int> inputs = rung.boxInputRows(r);
        if (inputs.size() > 1) {
            logic.box = *out;
            logic.boxRow = r;
            for (std::size_t k = 0; k < inputs.size() && next < networks.size(); ++k)
                logic.boxInputs.push_back(take(networks[next++]));
            continue;
        }
        if (next >= networks.size())
            break;
        Expr e = take(networks[next++]);
        insert(logic.root, e.empty() ? std::vector<Expr>{} : seriesItems(std::move(e)), 0, *out, r);
    }
    return logic;
}

} // namespace rung::model::detail

namespace rung::model {

std::vector<ReverseCurrentFinding> findReverseCurrent(const Rung &rung) {
    const auto networks = detail::analyzeRung(rung);
    std::vector<ReverseCurrentFinding> findings;
    bool any = false;
    for (const auto &n : networks)
        any = any || (n.connected && !n.seriesParallel);
    if (!any)
        return findings;
    // logicOf takes a copy: the networks' rows and cells are read below.
    Rung corrected = detail::layoutRung(detail::logicOf(rung, networks, true));
    corrected.comment = rung.comment;
    for (const auto &n : networks) {
        if (!n.connected || n.seriesParallel)
            continue;
        ReverseCurrentFinding f;
        f.row = n.row;
        for (int id : n.cells)
            f.cells.emplace_back(id / std::max(1, rung.columns), id % std::max(1, rung.columns));
        std::sort(f.cells.begin(), f.cells.end());
        f.cells.erase(std::unique(f.cells.begin(), f.cells.end()), f.cells.end());
        f.corrected = corrected;
        findings.push_back(std::move(f));
    }
    return findings;
}

} // namespace rung::model
