#pragma once

// The ladder grid: the program as the user draws it. A program is a list of rungs; a rung
// is a grid of cells (rows x columns of contacts and wires), vertical links between rows at
// the node columns, and the outputs (coils and boxes) at the right.

#include "model/listing/il.h"

#include <QString>

#include <optional>
#include <vector>

namespace rung::model {

enum class CellKind : std::uint8_t { Empty, Wire, Contact };

struct Contact {
    ContactMode mode = ContactMode::Normal;
    CompareOp compare = CompareOp::None; // != None: a compare contact with two operands
    std::vector<Operand> operands;
    bool invert = false; // the INV (Vigor) / NOT (PL110) element: inverts the power flow
    friend bool operator==(const Contact &, const Contact &) = default;
};

struct Cell {
    CellKind kind = CellKind::Empty;
    Contact contact; // CellKind::Contact
    friend bool operator==(const Cell &, const Cell &) = default;
};

// Node columns: a rung with C contact columns has node columns 0..C; node column 0 is the
// left rail, node column c sits between cell column c-1 and c, node column C feeds the
// output column. A vertical link joins the nodes of row r and row r+1 at one node column.
struct Rung {
    int rows = 1;
    int columns = 0;
    std::vector<Cell> cells;         // rows * columns, row-major
    std::vector<std::uint8_t> links; // rows * (columns + 1): link from row r down to r+1
    std::vector<std::optional<Instruction>>
        outputs; // per row; a box with k inputs sits on its
                 // first input row and covers the k-1 rows below
    // A box with k > 1 inputs (LR, KEEP, two-input counters, CNTR) stands alone in its rung;
    // inputRows holds the row of each input, first = the box's row. Empty: rows r..r+k-1.
    std::vector<int> inputRows;
    QString comment;

    Rung() = default;
    Rung(int rows, int columns);

    Cell &cell(int row, int column) {
        return cells[static_cast<std::size_t>(row * columns + column)];
    }
    const Cell &cell(int row, int column) const {
        return cells[static_cast<std::size_t>(row * columns + column)];
    }
    bool link(int row, int nodeColumn) const {
        return links[static_cast<std::size_t>(row * (columns + 1) + nodeColumn)] != 0;
    }
    void setLink(int row, int nodeColumn, bool on) {
        links[static_cast<std::size_t>(row * (columns + 1) + nodeColumn)] = on ? 1 : 0;
    }
    void resize(int newRows, int newColumns); // keeps what fits
    // Grows the rung without breaking it: a row that reached the old right end (its last cell
    // holds something, or the rung had no cells and the row feeds an output) is wired on
    // through the new cells, so its coil keeps its condition.
    void widenKeepingWires(int newRows, int newColumns);
    void insertRow(int row);
    void removeRow(int row);
    void insertColumn(int column);
    void removeColumn(int column);
    // Rows that hold a box input other than the box's own first row.
    bool coveredByBox(int row) const;
    // The rows feeding the box at `row` (one row for a coil).
    std::vector<int> boxInputRows(int row) const;
    friend bool operator==(const Rung &, const Rung &);
};

struct LadderProgram {
    const Target *target = nullptr;
    std::vector<Rung> rungs;
};

} // namespace rung::model
