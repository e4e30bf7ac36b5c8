// The ladder view's live overlay: a MonitorSource's snapshots drawn over the rungs on screen,
// repainting only the rungs whose overlay changed (snapshotChanged comes at most 30 times a
// second), the values in the tooltips, and the context menu that forces and writes devices.
// The view does not know which origin feeds the source; a source that goes Offline keeping
// its snapshot (an online PLC that stopped answering) is drawn as stale.

#include "ladder_view.h"

#include "model/image/power_flow.h"
#include "monitor_commands.h"

#include "model/target/address.h"

#include <QContextMenuEvent>
#include <QMenu>
#include <QScrollBar>
#include <QToolTip>

#include <algorithm>

namespace rung::editor {

void LadderView::setMonitorSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    m_commands->setTarget(&m_document->target());
    m_commands->setSource(source);
    m_overlays.clear();
    m_shown.reset();
    m_watched.clear();
    if (source) {
        connect(source, &model::MonitorSource::snapshotChanged, this, &LadderView::snapshotArrived);
        // Offline and back: the same values drawn stale, or live again.
        connect(source, &model::MonitorSource::runStateChanged, this, [this] {
            m_overlays.clear();
            viewport()->update();
        });
        m_shown = monitoredSnapshot();
        tellWatched();
    }
    viewport()->update();
}

std::shared_ptr<const model::Snapshot> LadderView::monitoredSnapshot() const {
    if (!m_source)
        return nullptr;
    std::shared_ptr<const model::Snapshot> snapshot = m_source->snapshot();
    if (!snapshot || !snapshot->layout || &snapshot->layout->target() != &m_document->target())
        return nullptr;
    return snapshot;
}

bool LadderView::staleValues() const {
    return m_source && m_source->runState() == model::MonitorSource::RunState::Offline;
}

std::pair<int, int> LadderView::visibleRungs() const {
    const int count = static_cast<int>(m_document->ladder().rungs.size());
    if (count == 0 || m_top.size() < 2)
        return {0, 0};
    const double top = verticalScrollBar()->value();
    const double bottom = top + viewport()->height();
    const int first = std::max(0, rungAt(top));
    int last = first;
    while (last < count && m_top[static_cast<std::size_t>(last)] <= bottom)
        ++last;
    return {first, last};
}

void LadderView::snapshotArrived() {
    const std::shared_ptr<const model::Snapshot> snapshot = monitoredSnapshot();
    m_shown = snapshot;
    if (!snapshot) {
        if (!m_overlays.empty()) {
            m_overlays.clear();
            viewport()->update();
        }
        return;
    }
    // A tooltip of this view that is still up shows the values as they are now, not as they
    // were when it opened (another widget's tooltip is left alone).
    if (!m_tipText.isEmpty() && QToolTip::isVisible() && QToolTip::text() == m_tipText) {
        if (const QString text = toolTipText(m_tipCell); text != m_tipText && !text.isEmpty()) {
            m_tipText = text;
            QToolTip::showText(m_tipAt, text, viewport());
        }
    }
    const model::ProgramFlow flow(m_document->ladder(), m_document->listing(), *snapshot);
    const bool stale = staleValues();
    const auto [first, last] = visibleRungs();
    std::erase_if(m_overlays, [first = first, last = last](const auto &entry) {
        return entry.first < first || entry.first >= last;
    });
    const int scroll = verticalScrollBar()->value();
    for (int i = first; i < last; ++i) {
        model::RungOverlay overlay = flow.rung(i, stale);
        const auto it = m_overlays.find(i);
        if (it != m_overlays.end() && it->second == overlay)
            continue; // nothing on this rung changed: not repainted
        m_overlays[i] = std::move(overlay);
        const double y = m_top[static_cast<std::size_t>(i)] - scroll;
        const double height =
            m_top[static_cast<std::size_t>(i) + 1] - m_top[static_cast<std::size_t>(i)];
        // The rung's band: its drawing stays inside it (the gap below it included).
        viewport()->update(QRect(0, static_cast<int>(std::floor(y)), viewport()->width(),
                                 static_cast<int>(std::ceil(height))));
    }
}

model::RungOverlay LadderView::overlay(int rung) const {
    const std::shared_ptr<const model::Snapshot> snapshot = monitoredSnapshot();
    if (!snapshot)
        return {};
    return model::ProgramFlow(m_document->ladder(), m_document->listing(), *snapshot)
        .rung(rung, staleValues());
}

void LadderView::tellWatched() {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    const auto &rungs = m_document->ladder().rungs;
    const auto [first, last] = visibleRungs();
    const auto take = [&devices](const std::vector<model::Operand> &operands) {
        for (const model::Operand &o : operands)
            if (o.kind == model::Operand::Kind::Device && o.address.valid())
                devices.push_back(o.address);
    };
    for (int i = first; i < last; ++i) {
        const model::Rung &r = rungs[static_cast<std::size_t>(i)];
        for (const model::Cell &c : r.cells)
            if (c.kind == model::CellKind::Contact)
                take(c.contact.operands);
        for (const auto &out : r.outputs)
            if (out)
                take(out->operands);
    }
    std::sort(devices.begin(), devices.end());
    devices.erase(std::unique(devices.begin(), devices.end()), devices.end());
    if (devices == m_watched)
        return;
    m_watched = devices;
    m_source->setWatched(this, std::move(devices));
}

void LadderView::scrollContentsBy(int dx, int dy) {
    QAbstractScrollArea::scrollContentsBy(dx, dy);
    tellWatched();
}

QMenu *LadderView::monitorMenu(const CellCursor &cell, QWidget *parent) {
    const auto &rungs = m_document->ladder().rungs;
    if (cell.rung < 0 || cell.rung >= static_cast<int>(rungs.size()))
        return nullptr;
    const model::Rung &rung = rungs[static_cast<std::size_t>(cell.rung)];
    if (cell.row < 0 || cell.row >= rung.rows)
        return nullptr;
    const model::Target &target = m_document->target();
    MonitorTargets devices;
    if (cell.column >= metrics().gridColumns) {
        if (const auto &out = rung.outputs[static_cast<std::size_t>(cell.row)])
            devices = monitorTargets(target, *out);
    } else if (cell.column < rung.columns) {
        const model::Cell &c = rung.cell(cell.row, cell.column);
        if (c.kind == model::CellKind::Contact && !c.contact.invert)
            devices = monitorTargets(target, c.contact.operands, model::Op::Load);
    }
    m_commands->setTarget(&target);
    auto *menu = new QMenu(parent);
    menu->setObjectName(QStringLiteral("monitorMenu"));
    if (!m_commands->addActions(menu, devices)) {
        delete menu;
        return nullptr;
    }
    return menu;
}

void LadderView::showMonitorMenu(const CellCursor &cell, QPoint globalPos) {
    QMenu *menu = monitorMenu(cell, this);
    if (!menu)
        return;
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->popup(globalPos);
}

void LadderView::contextMenuEvent(QContextMenuEvent *event) {
    if (!m_tool.isEmpty())
        return; // the right button put the tool away (mousePressEvent)
    CellCursor cell = m_cursor;
    if (event->reason() == QContextMenuEvent::Mouse) {
        const QPoint at = viewport()->mapFromGlobal(event->globalPos());
        if (m_contextCell.rung >= 0 && !draggedFarEnough(at)) {
            cell = m_contextCell; // the press chose it, in the layout before the row moved
        } else {
            cell = cellAt(at);
            if (cell.rung < 0)
                return;
            setCursor(cell);
        }
        m_contextCell = {-1, 0, 0};
    }
    const QRect at = cellRectOnScreen(cell);
    showMonitorMenu(cell, event->reason() == QContextMenuEvent::Mouse
                              ? event->globalPos()
                              : viewport()->mapToGlobal(at.center()));
}

QString LadderView::liveHelp(const CellCursor &cell) const {
    const std::shared_ptr<const model::Snapshot> snapshot = monitoredSnapshot();
    const auto &rungs = m_document->ladder().rungs;
    if (!snapshot || cell.rung < 0 || cell.rung >= static_cast<int>(rungs.size()))
        return {};
    const model::Rung &rung = rungs[static_cast<std::size_t>(cell.rung)];
    if (cell.row < 0 || cell.row >= rung.rows)
        return {};
    const model::Target &target = m_document->target();
    std::vector<model::Operand> operands;
    const model::Instruction *box = nullptr;
    if (cell.column >= metrics().gridColumns) {
        if (const auto &out = rung.outputs[static_cast<std::size_t>(cell.row)]) {
            operands = out->operands;
            box = &*out;
        }
    } else if (cell.column < rung.columns &&
               rung.cell(cell.row, cell.column).kind == model::CellKind::Contact) {
        operands = rung.cell(cell.row, cell.column).contact.operands;
    }
    QStringList lines;
    for (const model::Operand &o : operands) {
        if (o.kind != model::Operand::Kind::Device || !o.address.valid())
            continue;
        const model::AreaKind kind = target.area(o.address.area).kind;
        QString value;
        if (o.address.bit < 0 &&
            (kind == model::AreaKind::Timer || kind == model::AreaKind::Counter)) {
            // The box's own preset where the PLC holds none that can be read.
            const bool ownBox = box && &o == &operands.front();
            const std::optional<qint64> set =
                model::ProgramFlow::presetOf(target, ownBox ? box : nullptr, o.address, *snapshot);
            //: a timer's or counter's live state in a tooltip: current value, set value, done bit
            value = tr("current %1, set %2, %3")
                        .arg(model::ProgramFlow::presentOf(target, o.address, *snapshot))
                        .arg(set ? QString::number(*set) : QStringLiteral("?"))
                        .arg(snapshot->bit(o.address) ? tr("ON") : tr("OFF"));
            if (ownBox && box->op() == model::Op::Timer)
                value +=
                    QStringLiteral("; ") + model::ProgramFlow::timerText(target, *box, *snapshot);
        } else {
            value = model::ProgramFlow::wordText(*snapshot, o.address);
        }
        if (snapshot->forced(o.address))
            value = tr("%1 (forced)").arg(value);
        lines << QStringLiteral("%1 = %2").arg(model::formatAddress(target, o.address), value);
    }
    if (staleValues() && !lines.isEmpty())
        lines << tr("The last values known: the source is offline");
    return lines.join(QLatin1Char('\n'));
}

} // namespace rung::editor
