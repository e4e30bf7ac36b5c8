// The ladder view's mouse: click selects a cell, double-click edits it, a drag along a row
// draws wires and a drag down a column draws vertical links (as in WPLSoft and GX), Ctrl+wheel
// zooms. With a palette tool armed a click places that tool's element (as in CX-Programmer).

#include "ladder_view.h"

#include "device_mime.h"
#include "document.h"

#include "model/listing/il.h"
#include "model/target/address.h"

#include <QApplication>
#include <QDrag>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QScrollBar>
#include <QToolTip>
#include <QWheelEvent>

namespace rung::editor {

CellCursor LadderView::cellAt(QPointF position) const {
    const LadderMetrics m = metrics();
    const double y = position.y() + verticalScrollBar()->value();
    const double x = position.x() + horizontalScrollBar()->value();
    const int rung = rungAt(y);
    if (rung < 0)
        return {-1, 0, 0};
    const model::Rung &r = m_document->ladder().rungs[static_cast<std::size_t>(rung)];
    // Drawn line -> block and row (a folded rung repeats its rows once per block).
    const int line = std::max(
        0, static_cast<int>((y - m_top[static_cast<std::size_t>(rung)] - m.commentBlock(r)) /
                            m.rowHeight));
    const int stride = std::max(1, m.blockStride(r));
    const int blocks = m.blocks(r);
    const int block = std::min(line / stride, blocks - 1);
    const int row = line - block * stride;
    const int shown = m.shownColumns();
    const int inBlock = std::max(0, static_cast<int>((x - m.gutter) / m.cellWidth));
    if (inBlock >= shown) // the output column, or the end of an earlier block
        return {rung, row, block == blocks - 1 ? m.gridColumns : block * shown + shown - 1};
    return {rung, row, std::min(block * shown + inBlock, m.gridColumns)};
}

void LadderView::armTool(const QKeySequence &key) {
    if (key == m_tool)
        return;
    m_tool = key;
    viewport()->setCursor(m_tool.isEmpty() ? Qt::ArrowCursor : Qt::CrossCursor);
    emit toolArmed(m_tool);
}

bool LadderView::applyTool(const CellCursor &cell) {
    const QKeyCombination combination = m_tool[0];
    QKeyEvent key(QEvent::KeyPress, combination.key(), combination.keyboardModifiers());
    setCursor(cell);
    return functionKey(&key);
}

void LadderView::mousePressEvent(QMouseEvent *event) {
    setFocus();
    if (!m_tool.isEmpty() && event->button() == Qt::RightButton) {
        armTool({}); // a right click puts the tool away, as in drawing programs
        return;
    }
    const CellCursor cell = cellAt(event->position());
    if (cell.rung < 0)
        return;
    m_editor->hide();
    // The left of the gutter, where the breakpoint dot is drawn, sets or clears one on the
    // rung (as a click beside a line does in CODESYS and the list pane).
    if (event->button() == Qt::LeftButton && m_tool.isEmpty() &&
        event->position().x() + horizontalScrollBar()->value() < metrics().gutter * 0.4) {
        setCursor({cell.rung, 0, 0});
        emit breakpointToggleRequested(cell.rung);
        return;
    }
    if (!m_tool.isEmpty() && event->button() == Qt::LeftButton) {
        clearSelection();
        m_dragFrom = {-1, 0, 0};
        applyTool(cell);
        return;
    }
    // Shift+click extends a rung selection; a plain click drops it.
    if (event->modifiers() & Qt::ShiftModifier) {
        if (m_anchorRung < 0)
            m_anchorRung = m_cursor.rung;
        viewport()->update();
    } else {
        clearSelection();
    }
    const QPointF before = cellRectOnScreen(cell).topLeft();
    setCursor(cell);
    m_pressAt = event->position();
    m_pressShift = QPointF(cellRectOnScreen(cell).topLeft()) - before;
    m_dragFrom = event->button() == Qt::LeftButton ? cell : CellCursor{-1, 0, 0};
    m_contextCell = event->button() == Qt::RightButton ? cell : CellCursor{-1, 0, 0};
    m_pressDevice = event->button() == Qt::LeftButton ? deviceAtCursor() : QString();
}

bool LadderView::draggedFarEnough(QPointF position) const {
    return (position - m_pressAt).manhattanLength() >= QApplication::startDragDistance();
}

void LadderView::mouseMoveEvent(QMouseEvent *event) {
    if (m_dragFrom.rung < 0 || !(event->buttons() & Qt::LeftButton))
        return;
    if (!draggedFarEnough(event->position()))
        return;
    // Inside the view a drag draws wires; out of it, a drag from an element carries its
    // device to the watch table or the timing chart.
    if (!m_pressDevice.isEmpty() && !viewport()->rect().contains(event->position().toPoint())) {
        m_dragFrom = {-1, 0, 0};
        auto *drag = new QDrag(this);
        drag->setMimeData(deviceMimeData({m_pressDevice}));
        m_pressDevice.clear();
        drag->exec(Qt::CopyAction);
        return;
    }
    const CellCursor cell = cellAt(event->position() + m_pressShift);
    if (cell.rung == m_dragFrom.rung && !(cell == m_cursor))
        setCursor(cell); // the cursor follows the drag: it shows where the wire will end
}

void LadderView::mouseReleaseEvent(QMouseEvent *event) {
    const CellCursor from = m_dragFrom;
    m_dragFrom = {-1, 0, 0};
    // A click that moved less than the drag distance is a click, whatever cell it ends on.
    if (from.rung < 0 || event->button() != Qt::LeftButton || !draggedFarEnough(event->position()))
        return;
    const CellCursor to = cellAt(event->position() + m_pressShift);
    if (to.rung == from.rung && !(to == from))
        drawDrag(from, to);
}

void LadderView::drawDrag(const CellCursor &from, const CellCursor &to) {
    const LadderMetrics m = metrics();
    model::Rung rung = m_document->ladder().rungs[static_cast<std::size_t>(from.rung)];
    const bool horizontal =
        std::abs(to.column - from.column) >= std::abs(to.row - from.row) && from.row == to.row;
    if (horizontal) {
        // Wires over the empty cells between the two, never over an element; the output
        // column takes no wire (the row is wired to it by itself).
        const int first = std::min(from.column, to.column);
        const int last = std::min(std::max(from.column, to.column), m.gridColumns - 1);
        const model::Rung before = rung;
        rung.widenKeepingWires(std::max(rung.rows, from.row + 1), std::max(rung.columns, last + 1));
        for (int c = first; c <= last; ++c) {
            model::Cell &cell = rung.cell(from.row, c);
            if (cell.kind == model::CellKind::Empty)
                cell = model::Cell{model::CellKind::Wire, {}};
        }
        const bool changed = !(rung == before);
        if (changed)
            m_document->setRung(from.rung, rung, tr("Draw a wire"));
        return;
    }
    if (from.column != to.column)
        return; // a diagonal drag draws nothing: the user meant neither
    // Links at the node left of the column (the output column's node is the row's end).
    const int node = from.column >= m.gridColumns ? rung.columns : from.column;
    const int top = std::min(from.row, to.row);
    const int bottom = std::max(from.row, to.row);
    rung.widenKeepingWires(std::max(rung.rows, bottom + 1), std::max(rung.columns, node));
    for (int r = top; r < bottom; ++r)
        rung.setLink(r, node, true);
    m_document->setRung(from.rung, rung, tr("Draw a vertical link"));
}

void LadderView::mouseDoubleClickEvent(QMouseEvent *event) {
    if (!m_tool.isEmpty())
        return; // the first click placed the tool's element; its editor stays as it is
    mousePressEvent(event);
    m_dragFrom = {-1, 0, 0};
    openEditor(QString());
}

bool LadderView::viewportEvent(QEvent *event) {
    if (event->type() != QEvent::ToolTip)
        return QAbstractScrollArea::viewportEvent(event);
    // Hovering an element shows its device with the symbol's name and comment.
    const auto *help = static_cast<QHelpEvent *>(event);
    const CellCursor cell = cellAt(help->pos());
    const QString text = toolTipText(cell);
    m_tipCell = cell;
    m_tipAt = help->globalPos();
    m_tipText = text;
    if (text.isEmpty())
        QToolTip::hideText();
    else
        QToolTip::showText(help->globalPos(), text, viewport());
    return true;
}

QString LadderView::toolTipText(const CellCursor &cell) const {
    QString text = elementHelp(cell);
    if (const QString live = liveHelp(cell); !live.isEmpty())
        text += (text.isEmpty() ? QString() : QStringLiteral("\n")) + live;
    return text;
}

QString LadderView::elementHelp(const CellCursor &cell) const {
    const auto &rungs = m_document->ladder().rungs;
    if (cell.rung < 0 || cell.rung >= static_cast<int>(rungs.size()))
        return {};
    const model::Rung &rung = rungs[static_cast<std::size_t>(cell.rung)];
    if (cell.row >= rung.rows)
        return {};
    const std::vector<model::Operand> *operands = nullptr;
    if (cell.column >= metrics().gridColumns) {
        if (const auto &out = rung.outputs[static_cast<std::size_t>(cell.row)])
            operands = &out->operands;
    } else if (cell.column < rung.columns) {
        operands = &rung.cell(cell.row, cell.column).contact.operands;
    }
    QStringList lines;
    const model::Target &target = m_document->target();
    // A compare contact's cell is too narrow for the whole comparison: here it is in full.
    bool compare = false;
    if (cell.column < metrics().gridColumns && cell.column < rung.columns) {
        const model::Contact &c = rung.cell(cell.row, cell.column).contact;
        compare = c.compare != model::CompareOp::None && c.operands.size() >= 2;
        if (compare)
            lines << QStringLiteral("%1%2 %3 %4")
                         .arg(c.mode == model::ContactMode::Negated ? QStringLiteral("NOT ")
                                                                    : QString(),
                              model::formatOperand(target, c.operands[0]),
                              QLatin1String(model::compareSymbol(c.compare)),
                              model::formatOperand(target, c.operands[1]));
    }
    for (const model::Operand &o : operands ? *operands : std::vector<model::Operand>{}) {
        if (o.kind != model::Operand::Kind::Device)
            continue;
        QString line = model::formatAddress(target, o.address);
        if (const model::Symbol *s = m_document->project().symbol(o.address)) {
            if (!s->name.isEmpty())
                line += QStringLiteral(" — ") + s->name;
            if (!s->comment.isEmpty())
                line += QStringLiteral(": ") + s->comment;
        }
        // Under a comparison a bare address would only repeat it.
        if (!compare || line != model::formatAddress(target, o.address))
            lines << line;
    }
    return lines.join(QLatin1Char('\n'));
}

void LadderView::wheelEvent(QWheelEvent *event) {
    if (event->modifiers() & Qt::ControlModifier) {
        setZoom(m_zoom * (event->angleDelta().y() > 0 ? 1.1 : 1 / 1.1));
        return;
    }
    QAbstractScrollArea::wheelEvent(event);
}

} // namespace rung::editor
