#pragma once

// The series-parallel form of a rung's logic, shared by both directions of the conversion
// and by the combinational evaluator. Internal to model/.

#include "model/ladder/ladder.h"

#include <vector>

namespace rung::model::detail {

struct Expr {
    enum class Kind : std::uint8_t { Series, Parallel, Leaf } kind = Kind::Series;
    Contact leaf;            // Kind::Leaf
    int cell = -1;           // Kind::Leaf from a ladder: row * columns + column (identity)
    std::vector<Expr> items; // Series / Parallel; an empty Series is "no condition"

    bool empty() const { return kind == Kind::Series && items.empty(); }
    static Expr leafOf(const Contact &c, int cell = -1) {
        Expr e;
        e.kind = Kind::Leaf;
        e.leaf = c;
        e.cell = cell;
        return e;
    }
};

// Series(a, b) and Parallel(a, b) flattened, so equal networks have one shape.
Expr series(Expr a, Expr b);
Expr parallel(Expr a, Expr b);

// Structural equality; with byCell, leaves compare by the cell they came from.
bool sameExpr(const Expr &a, const Expr &b, bool byCell);

// The top-level series elements (a non-series expression is a list of one).
std::vector<Expr> seriesItems(const Expr &e);
std::vector<Expr> seriesItems(Expr &&e);
Expr seriesOf(std::vector<Expr> items);

// One rung as a tree of branch points: a condition, then outputs and sub-branches in row
// order. A rung holding a multi-input box has `boxInputs` instead (one network per input).
struct Branch {
    Expr cond;
    struct Item {
        bool isOutput = true;
        Instruction output;
        int row = -1;              // the output's row on the ladder (-1: read from a listing)
        std::vector<Branch> child; // one element when !isOutput
    };
    std::vector<Item> items;
};

struct RungLogic {
    Branch root;
    std::vector<Expr> boxInputs; // non-empty: a multi-input box rung
    Instruction box;
    int boxRow = -1; // the box's row on the ladder
};

// Draws a rung's logic on the grid (convert_to_ladder.cpp).
Rung layoutRung(const RungLogic &logic);

} // namespace rung::model::detail
