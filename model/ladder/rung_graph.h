#pragma once

// A rung read as an electrical graph: nodes are the grid's node points joined by wires and
// vertical links, contacts are edges that conduct left to right. Internal to model/.

#include "model/ladder/network.h"

#include <vector>

namespace rung::model::detail {

// A contact: an edge between the nodes on its left and right, conducting left to right.
struct Edge {
    int from = 0;
    int to = 0;
    Expr expr;   // the contact as a leaf (Expr::cell: row * columns + column)
    int key = 0; // drawing order: first row, then column, of the edge's top-left leaf
};

struct Graph {
    int rail = 0;                // the left rail's node
    int nodes = 0;               // node ids are below this
    std::vector<Edge> edges;     // one per contact, in row then column order
    std::vector<int> outputNode; // per row: the node at the output column
};

// The grid as a graph: wires and vertical links join node points into nodes.
Graph buildGraph(const Rung &rung);

struct InputNetwork {
    int row = 0;            // the output row (or box input row) this network feeds
    bool connected = false; // some left-to-right path reaches it from the rail
    bool seriesParallel = true;
    Expr expr;              // the network when series-parallel (empty: straight from the rail)
    Expr paths;             // every left-to-right path, factored: the reverse-current fix
    std::vector<int> cells; // cell ids (row * columns + column) on some path
};

// One entry per output row, and per input row of a multi-input box, in row order.
std::vector<InputNetwork> analyzeRung(const Rung &rung);

// The branch tree of a rung's single-input outputs from their networks (row order kept;
// adjacent outputs that share leading elements of the same cells share a branch point).
// Pass the networks with std::move where they are not needed afterwards: their expressions
// move into the tree.
RungLogic logicOf(const Rung &rung, std::vector<InputNetwork> networks, bool useFixes);

} // namespace rung::model::detail
