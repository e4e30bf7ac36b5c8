#include "model/ladder/ladder.h"

#include <algorithm>

namespace rung::model {

Rung::Rung(int rowCount, int columnCount) {
    resize(rowCount, columnCount);
}

void Rung::widenKeepingWires(int newRows, int newColumns) {
    const int oldColumns = columns;
    std::vector<bool> reached(static_cast<std::size_t>(rows), false);
    for (int r = 0; r < rows && oldColumns > 0; ++r)
        reached[static_cast<std::size_t>(r)] = cell(r, oldColumns - 1).kind != CellKind::Empty;
    if (oldColumns == 0)
        for (int r = 0; r < rows; ++r)
            if (outputs[static_cast<std::size_t>(r)])
                for (int input : boxInputRows(r))
                    if (input < rows)
                        reached[static_cast<std::size_t>(input)] = true;
    resize(newRows, newColumns);
    for (std::size_t r = 0; r < reached.size(); ++r)
        if (reached[r])
            for (int c = oldColumns; c < columns; ++c)
                cell(static_cast<int>(r), c) = Cell{CellKind::Wire, {}};
}

void Rung::resize(int newRows, int newColumns) {
    newRows = std::max(1, newRows);
    newColumns = std::max(0, newColumns);
    std::vector<Cell> newCells(static_cast<std::size_t>(newRows * newColumns));
    std::vector<std::uint8_t> newLinks(static_cast<std::size_t>(newRows * (newColumns + 1)), 0);
    const int keepRows = std::min(rows, newRows);
    const int keepColumns = std::min(columns, newColumns);
    const bool hadGrid = cells.size() == static_cast<std::size_t>(rows * columns) &&
                         links.size() == static_cast<std::size_t>(rows * (columns + 1));
    if (hadGrid) {
        for (int r = 0; r < keepRows; ++r) {
            for (int c = 0; c < keepColumns; ++c)
                newCells[static_cast<std::size_t>(r * newColumns + c)] = cell(r, c);
            for (int c = 0; c <= keepColumns; ++c)
                newLinks[static_cast<std::size_t>(r * (newColumns + 1) + c)] =
                    links[static_cast<std::size_t>(r * (columns + 1) + c)];
        }
        // The output node column keeps its links when the grid narrows or widens.
        if (keepColumns != columns || keepColumns != newColumns)
            for (int r = 0; r < keepRows; ++r)
                newLinks[static_cast<std::size_t>(r * (newColumns + 1) + newColumns)] =
                    links[static_cast<std::size_t>(r * (columns + 1) + columns)];
    }
    rows = newRows;
    columns = newColumns;
    cells = std::move(newCells);
    links = std::move(newLinks);
    outputs.resize(static_cast<std::size_t>(rows));
    inputRows.erase(
        std::remove_if(inputRows.begin(), inputRows.end(), [&](int r) { return r >= rows; }),
        inputRows.end());
}

void Rung::insertRow(int row) {
    row = std::clamp(row, 0, rows);
    Rung copy = *this;
    resize(rows + 1, columns);
    for (int r = rows - 1; r >= 0; --r) {
        const int from = r > row ? r - 1 : r;
        if (r == row) {
            for (int c = 0; c < columns; ++c)
                cell(r, c) = Cell{};
            for (int c = 0; c <= columns; ++c)
                // A link passing through the inserted row stays continuous.
                setLink(r, c, r > 0 && copy.link(r - 1, c) && r - 1 < copy.rows - 1);
            outputs[static_cast<std::size_t>(r)].reset();
            continue;
        }
        for (int c = 0; c < columns; ++c)
            cell(r, c) = copy.cell(from, c);
        for (int c = 0; c <= columns; ++c)
            setLink(r, c, copy.link(from, c));
        outputs[static_cast<std::size_t>(r)] = copy.outputs[static_cast<std::size_t>(from)];
    }
    for (int &r : inputRows)
        if (r >= row)
            ++r;
}

void Rung::removeRow(int row) {
    if (rows <= 1 || row < 0 || row >= rows)
        return;
    Rung copy = *this;
    for (int r = row; r < rows - 1; ++r) {
        for (int c = 0; c < columns; ++c)
            cell(r, c) = copy.cell(r + 1, c);
        for (int c = 0; c <= columns; ++c)
            setLink(r, c, copy.link(r + 1, c));
        outputs[static_cast<std::size_t>(r)] = copy.outputs[static_cast<std::size_t>(r + 1)];
    }
    inputRows.erase(std::remove(inputRows.begin(), inputRows.end(), row), inputRows.end());
    for (int &r : inputRows)
        if (r > row)
            --r;
    resize(rows - 1, columns);
}

void Rung::insertColumn(int column) {
    column = std::clamp(column, 0, columns);
    Rung copy = *this;
    resize(rows, columns + 1);
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            if (c == column) {
                // A new cell inside a wired row continues the wire.
                const bool wired = c > 0 && c - 1 < copy.columns && c < copy.columns &&
                                   copy.cell(r, c - 1).kind != CellKind::Empty &&
                                   copy.cell(r, c).kind != CellKind::Empty;
                cell(r, c) = wired ? Cell{CellKind::Wire, {}} : Cell{};
            } else {
                cell(r, c) = copy.cell(r, c > column ? c - 1 : c);
            }
        }
        for (int c = 0; c <= columns; ++c)
            setLink(r, c, c == column + 1 ? false : copy.link(r, c > column ? c - 1 : c));
    }
}

void Rung::removeColumn(int column) {
    if (column < 0 || column >= columns)
        return;
    Rung copy = *this;
    for (int r = 0; r < rows; ++r) {
        for (int c = column; c < columns - 1; ++c)
            cell(r, c) = copy.cell(r, c + 1);
        for (int c = column + 1; c <= columns; ++c)
            setLink(r, c, copy.link(r, c));
    }
    // Node column `column` and `column + 1` merge: keep a link if either had one.
    for (int r = 0; r < rows; ++r)
        setLink(r, column, copy.link(r, column) || copy.link(r, column + 1));
    for (int r = 0; r < rows; ++r)
        for (int c = column + 1; c < columns; ++c)
            setLink(r, c, copy.link(r, c + 1));
    resize(rows, columns - 1);
}

std::vector<int> Rung::boxInputRows(int row) const {
    const auto &out = outputs[static_cast<std::size_t>(row)];
    const int k = out && out->spec ? std::max(1, out->spec->inputs) : 1;
    if (k > 1 && !inputRows.empty() && inputRows.front() == row)
        return inputRows;
    std::vector<int> result;
    for (int i = 0; i < k && row + i < rows; ++i)
        result.push_back(row + i);
    return result;
}

bool Rung::coveredByBox(int row) const {
    for (int r = 0; r < row; ++r) {
        const auto &out = outputs[static_cast<std::size_t>(r)];
        if (!out || !out->spec || out->spec->inputs <= 1)
            continue;
        const std::vector<int> in = boxInputRows(r);
        if (!in.empty() && row > r && row <= in.back())
            return true;
    }
    return false;
}

bool operator==(const Rung &a, const Rung &b) {
    if (a.rows != b.rows || a.columns != b.columns || a.cells != b.cells || a.links != b.links ||
        a.comment != b.comment || a.outputs.size() != b.outputs.size())
        return false;
    // Box inputs compare by the rows they name, whether implied or listed.
    for (int r = 0; r < a.rows; ++r)
        if (a.outputs[static_cast<std::size_t>(r)] && a.boxInputRows(r) != b.boxInputRows(r))
            return false;
    for (std::size_t i = 0; i < a.outputs.size(); ++i) {
        const auto &x = a.outputs[i];
        const auto &y = b.outputs[i];
        if (x.has_value() != y.has_value())
            return false;
        if (x && !x->sameAs(*y))
            return false;
    }
    return true;
}

} // namespace rung::model
