// The ladder view's selections (whole rungs, a run of cells in a row) and what the cursor
// offers: the device under it and the cell editor's completions.

#include "ladder_view.h"

#include "document.h"

#include "model/target/address.h"

#include <QStringListModel>

#include <algorithm>
#include <set>

namespace rung::editor {

std::pair<int, int> LadderView::selectedRungs() const {
    const int rungs = static_cast<int>(m_document->ladder().rungs.size());
    if (m_anchorRung < 0 || m_anchorRung >= rungs)
        return {m_cursor.rung, rungs > 0 ? 1 : 0};
    const int first = std::min(m_anchorRung, m_cursor.rung);
    return {first, std::max(m_anchorRung, m_cursor.rung) - first + 1};
}

void LadderView::selectRungs(int first, int last) {
    const int rungs = static_cast<int>(m_document->ladder().rungs.size());
    if (rungs == 0)
        return;
    m_anchorRung = std::clamp(first, 0, rungs - 1);
    setCursor({std::clamp(last, 0, rungs - 1), 0, 0});
    viewport()->update();
}

void LadderView::clearSelection() {
    if (m_anchorRung < 0 && m_anchorColumn < 0)
        return;
    m_anchorRung = -1;
    m_anchorColumn = -1;
    viewport()->update();
}

LadderView::CellRun LadderView::selectedCells() const {
    const int grid = metrics().gridColumns;
    if (m_anchorColumn < 0 || m_cursor.column >= grid)
        return {};
    return {m_cursor.rung, m_cursor.row, std::min(m_anchorColumn, m_cursor.column),
            std::max(m_anchorColumn, m_cursor.column)};
}

void LadderView::selectCells(int first, int last) {
    const int grid = metrics().gridColumns;
    m_anchorRung = -1;
    m_anchorColumn = std::clamp(first, 0, grid - 1);
    setCursor({m_cursor.rung, m_cursor.row, std::clamp(last, 0, grid - 1)});
    viewport()->update();
}

model::Rung LadderView::copyCells() const {
    const CellRun run = selectedCells();
    const auto &rungs = m_document->ladder().rungs;
    if (!run.valid() || run.rung >= static_cast<int>(rungs.size()))
        return model::Rung(1, 0);
    const model::Rung &rung = rungs[static_cast<std::size_t>(run.rung)];
    model::Rung fragment(1, run.last - run.first + 1);
    for (int c = run.first; c <= run.last; ++c)
        if (run.row < rung.rows && c < rung.columns)
            fragment.cell(0, c - run.first) = rung.cell(run.row, c);
    return fragment;
}

void LadderView::clearCells() {
    const CellRun run = selectedCells();
    const auto &rungs = m_document->ladder().rungs;
    if (!run.valid() || run.rung >= static_cast<int>(rungs.size()))
        return;
    model::Rung rung = rungs[static_cast<std::size_t>(run.rung)];
    bool changed = false;
    for (int c = run.first; c <= std::min(run.last, rung.columns - 1); ++c)
        if (run.row < rung.rows && rung.cell(run.row, c).kind != model::CellKind::Empty) {
            rung.cell(run.row, c) = model::Cell{};
            changed = true;
        }
    clearSelection();
    if (changed)
        m_document->setRung(run.rung, rung, tr("Delete cells"));
}

void LadderView::pasteCells(const model::Rung &fragment) {
    const int grid = metrics().gridColumns;
    if (fragment.rows < 1 || fragment.columns < 1 || m_cursor.column >= grid)
        return;
    model::Rung rung = currentRung();
    const int width = fragment.columns;
    rung.resize(std::max(rung.rows, m_cursor.row + 1),
                std::max(rung.columns, m_cursor.column + width));
    for (int c = 0; c < width; ++c)
        rung.cell(m_cursor.row, m_cursor.column + c) = fragment.cell(0, c);
    clearSelection();
    m_document->setRung(m_cursor.rung, rung, tr("Paste cells"));
}

QString LadderView::deviceAtCursor() const {
    const auto &rungs = m_document->ladder().rungs;
    if (m_cursor.rung < 0 || m_cursor.rung >= static_cast<int>(rungs.size()))
        return {};
    const model::Rung &rung = rungs[static_cast<std::size_t>(m_cursor.rung)];
    if (m_cursor.row >= rung.rows)
        return {};
    const std::vector<model::Operand> *operands = nullptr;
    if (m_cursor.column >= metrics().gridColumns) {
        if (const auto &out = rung.outputs[static_cast<std::size_t>(m_cursor.row)])
            operands = &out->operands;
    } else if (m_cursor.column < rung.columns) {
        operands = &rung.cell(m_cursor.row, m_cursor.column).contact.operands;
    }
    if (operands)
        for (const model::Operand &o : *operands)
            if (o.kind == model::Operand::Kind::Device)
                return model::formatAddress(m_document->target(), o.address);
    return {};
}

QStringList LadderView::completions() const {
    return m_completions->stringList();
}

void LadderView::updateCompletions(const QString &text) {
    const model::Target &target = m_document->target();
    QStringList words;
    const int space = text.indexOf(QLatin1Char(' '));
    if (space < 0) {
        for (const model::InstructionSpec &s : target.instructions)
            words << s.mnemonic;
    } else {
        const QString mnemonic = text.left(space);
        for (const QString &device : m_document->knownDevices())
            words << mnemonic + QLatin1Char(' ') + device;
    }
    words.removeDuplicates();
    if (words != m_completions->stringList())
        m_completions->setStringList(words);
}

} // namespace rung::editor
