// The ladder view's function keys, as GX Works and WPLSoft have them:
//   F5 / F6            normally open / normally closed contact
//   Shift+F5 / F6      the same in parallel (OR / ORI: linked to the row above)
//   Shift+F7 / F8      rising / falling edge contact (LDP / LDF)
//   Alt+F7 / F8        rising / falling edge contact in parallel (ORP / ORF)
//   F7 / F8            coil / any instruction in the output column
//   F9 / Shift+F9      horizontal wire / vertical link
//   Ctrl+F9 / Ctrl+F10 delete the wire / the vertical link at the cursor
// and the keys that move the cursor, edit cells, rows and rungs, and open the context menu.
// A contact key opens the cell editor with the target's mnemonic, so the user types only the
// operand; the mnemonic decides the contact's kind and OR its link to the row above.

#include "ladder_view.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QScrollBar>

namespace rung::editor {

void LadderView::keyPressEvent(QKeyEvent *event) {
    if (event->key() == Qt::Key_Escape && !m_tool.isEmpty()) {
        armTool({});
        return;
    }
    const LadderMetrics m = metrics();
    const auto mods = event->modifiers();
    // Shift with Up/Down/PgUp/PgDn selects whole rungs from where it started (as in GX and
    // WPLSoft); moving without Shift drops the selection.
    // Shift with Left/Right selects a run of cells in the row.
    const int key = event->key();
    if (key == Qt::Key_Up || key == Qt::Key_Down || key == Qt::Key_PageUp ||
        key == Qt::Key_PageDown) {
        m_anchorColumn = -1;
        if (mods & Qt::ShiftModifier) {
            if (m_anchorRung < 0)
                m_anchorRung = m_cursor.rung;
        } else if (m_anchorRung >= 0) {
            m_anchorRung = -1;
        }
        viewport()->update();
    } else if (key == Qt::Key_Left || key == Qt::Key_Right || key == Qt::Key_Home ||
               key == Qt::Key_End) {
        m_anchorRung = -1;
        if ((mods & Qt::ShiftModifier) && m_cursor.column < m.gridColumns) {
            if (m_anchorColumn < 0)
                m_anchorColumn = m_cursor.column;
        } else {
            m_anchorColumn = -1;
        }
        viewport()->update();
    }
    // The context menu at the cursor (the device commands while monitored): the Menu key, or
    // Shift+F10 as on Windows; F10 alone is the Simulation menu's Run.
    if (key == Qt::Key_Menu || (key == Qt::Key_F10 && mods == Qt::ShiftModifier)) {
        showMonitorMenu(m_cursor, viewport()->mapToGlobal(cellRectOnScreen(m_cursor).center()));
        return;
    }
    const auto &rungs = m_document->ladder().rungs;
    CellCursor c = m_cursor;
    const int rows = rungs.empty() ? 1 : rungs[static_cast<std::size_t>(c.rung)].rows;
    switch (event->key()) {
    case Qt::Key_Escape:
        m_editor->hide();
        return;
    case Qt::Key_Left:
        c.column = c.column >= m.gridColumns ? lastColumn(c.rung) : std::max(0, c.column - 1);
        return setCursor(c);
    case Qt::Key_Right:
        if (m_anchorColumn >= 0 && c.column >= lastColumn(c.rung))
            return; // a cell selection stays among the contacts
        c.column = c.column >= lastColumn(c.rung) ? m.gridColumns : c.column + 1;
        return setCursor(c);
    case Qt::Key_Home:
        c.column = 0;
        return setCursor(c);
    case Qt::Key_End:
        c.column = m.gridColumns;
        return setCursor(c);
    case Qt::Key_Up:
        if (c.row > 0) {
            --c.row;
        } else if (c.rung > 0) {
            --c.rung;
            c.row = rungs[static_cast<std::size_t>(c.rung)].rows - 1;
        }
        return setCursor(c);
    case Qt::Key_Down:
        if (c.row < rows) {
            ++c.row;
        } else if (c.rung + 1 < static_cast<int>(rungs.size())) {
            ++c.rung;
            c.row = 0;
        }
        return setCursor(c);
    case Qt::Key_PageDown:
        c.rung = std::min(static_cast<int>(rungs.size()) - 1, c.rung + 10);
        c.row = 0;
        return setCursor(c);
    case Qt::Key_PageUp:
        c.rung = std::max(0, c.rung - 10);
        c.row = 0;
        return setCursor(c);
    case Qt::Key_F5:
    case Qt::Key_F6:
    case Qt::Key_F7:
    case Qt::Key_F8:
    case Qt::Key_F9:
    case Qt::Key_F10:
        if (functionKey(event)) // ladder_view_keys.cpp
            return;
        break;
    case Qt::Key_Delete:
        if (selectedCells().valid() && !(mods & (Qt::ShiftModifier | Qt::ControlModifier)))
            return clearCells();
        if (mods & Qt::ShiftModifier)
            return deleteRung();
        if (mods & Qt::ControlModifier)
            return deleteRow();
        return clearCell();
    case Qt::Key_Insert:
        if (mods & Qt::ShiftModifier)
            return insertRung();
        if (mods & Qt::ControlModifier)
            return insertRow();
        return insertColumn();
    case Qt::Key_Return:
    case Qt::Key_Enter:
        return openEditor(QString());
    default:
        break;
    }
    const QString text = event->text();
    if (!text.isEmpty() && text[0].isPrint() && !(mods & (Qt::ControlModifier | Qt::AltModifier))) {
        openEditor(text);
        return;
    }
    QAbstractScrollArea::keyPressEvent(event);
}

bool LadderView::functionKey(QKeyEvent *event) {
    const Qt::KeyboardModifiers mods =
        event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier | Qt::AltModifier);
    const bool plain = mods == Qt::NoModifier;
    const bool shift = mods == Qt::ShiftModifier;
    const bool alt = mods == Qt::AltModifier;
    const bool ctrl = mods == Qt::ControlModifier;
    auto contact = [this](model::Op op, model::ContactMode mode) {
        QString mnemonic = mnemonicFor(op, mode);
        // PL110 has no edge contacts on a device, but P / N on the power flow.
        if (mnemonic.isEmpty() && op == model::Op::Load && mode != model::ContactMode::Normal)
            mnemonic = mnemonicFor(model::Op::Invert, mode);
        if (mnemonic.isEmpty()) {
            emit message(tr("%1 has no such contact").arg(m_document->target().displayName));
            return true;
        }
        openEditor(mnemonic + QLatin1Char(' '));
        return true;
    };
    auto inOutputColumn = [this](const QString &initial) {
        CellCursor c = m_cursor;
        c.column = metrics().gridColumns;
        setCursor(c);
        openEditor(initial);
        return true;
    };
    switch (event->key()) {
    case Qt::Key_F5:
    case Qt::Key_F6: {
        const model::ContactMode mode =
            event->key() == Qt::Key_F5 ? model::ContactMode::Normal : model::ContactMode::Negated;
        if (plain)
            return contact(model::Op::Load, mode);
        if (shift)
            return contact(model::Op::Or, mode);
        return false;
    }
    case Qt::Key_F7:
    case Qt::Key_F8: {
        const model::ContactMode edge =
            event->key() == Qt::Key_F7 ? model::ContactMode::Rising : model::ContactMode::Falling;
        if (shift)
            return contact(model::Op::Load, edge);
        if (alt)
            return contact(model::Op::Or, edge);
        if (!plain)
            return false;
        return inOutputColumn(event->key() == Qt::Key_F7
                                  ? mnemonicFor(model::Op::Out) + QLatin1Char(' ')
                                  : QString());
    }
    case Qt::Key_F9:
        if (plain)
            placeWire();
        else if (shift)
            toggleLink();
        else if (ctrl)
            deleteWire();
        else
            return false;
        return true;
    case Qt::Key_F10:
        if (!ctrl)
            return false;
        deleteLink();
        return true;
    default:
        return false;
    }
}

bool LadderView::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_editor && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent *>(event)->key();
        if (key == Qt::Key_Return || key == Qt::Key_Enter) {
            commitEditor();
            return true;
        }
        if (key == Qt::Key_Escape) {
            m_editor->hide();
            setFocus();
            return true;
        }
    }
    return QAbstractScrollArea::eventFilter(watched, event);
}

void LadderView::deleteWire() {
    model::Rung rung = currentRung();
    if (m_cursor.row >= rung.rows || m_cursor.column >= rung.columns ||
        rung.cell(m_cursor.row, m_cursor.column).kind != model::CellKind::Wire) {
        emit message(tr("There is no wire under the cursor"));
        return;
    }
    rung.cell(m_cursor.row, m_cursor.column) = model::Cell{};
    m_document->setRung(m_cursor.rung, rung, tr("Delete a wire"));
}

void LadderView::deleteLink() {
    // The link at the cursor's left node, down to the next row (where Shift+F9 draws it).
    model::Rung rung = currentRung();
    const int node = m_cursor.column >= metrics().gridColumns
                         ? rung.columns
                         : std::min(m_cursor.column, rung.columns);
    if (m_cursor.row + 1 >= rung.rows || !rung.link(m_cursor.row, node)) {
        emit message(tr("There is no vertical link at the cursor"));
        return;
    }
    rung.setLink(m_cursor.row, node, false);
    m_document->setRung(m_cursor.rung, rung, tr("Delete a vertical link"));
}

} // namespace rung::editor
