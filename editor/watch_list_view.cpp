#include "watch_list_view.h"

#include "device_mime.h"
#include "keep_typed_delegate.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QHeaderView>
#include <QKeyEvent>
#include <QMenu>
#include <QStyledItemDelegate>

#include <algorithm>

namespace rung::editor {

namespace {

// Draws a list's name and a forced device's value and force bold, and keeps what the user
// types (KeepTypedDelegate).
class WatchDelegate : public KeepTypedDelegate {
public:
    using KeepTypedDelegate::KeepTypedDelegate;

protected:
    void initStyleOption(QStyleOptionViewItem *option, const QModelIndex &index) const override {
        QStyledItemDelegate::initStyleOption(option, index);
        const bool list = !index.parent().isValid();
        const bool forced = (index.column() == WatchListModel::ValueColumn ||
                             index.column() == WatchListModel::ForceColumn) &&
                            index.data(WatchListModel::ForcedRole).toBool();
        if (list || forced) {
            option->font.setBold(true);
            option->fontMetrics = QFontMetrics(option->font);
        }
    }
};

} // namespace

WatchListView::WatchListView(Document *document, QWidget *parent)
    : QTreeView(parent)
    , m_model(new WatchListModel(document, this)) {
    setObjectName(QStringLiteral("watchLists"));
    setItemDelegate(new WatchDelegate(this));
    setModel(m_model);
    setAccessibleName(tr("Watch lists"));
    setRootIsDecorated(true);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    // Only the value column is edited, and only on purpose (editValue): the device column is
    // the list's content, changed by add and remove.
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    // Rows are dragged out (to the timing chart) and devices dropped in; nothing moves.
    setDragEnabled(true);
    setAcceptDrops(true);
    setDropIndicatorShown(false);
    setDragDropMode(QAbstractItemView::DragDrop);
    setDefaultDropAction(Qt::CopyAction);
    // The format and the force beside the value, not at the far edge of a wide dock.
    header()->setStretchLastSection(true);
    header()->setSectionResizeMode(QHeaderView::Interactive);
    header()->resizeSection(DeviceColumn, 110);
    header()->resizeSection(SymbolColumn, 130);
    header()->resizeSection(ValueColumn, 300);
    header()->resizeSection(FormatColumn, 110);
    connect(m_model, &WatchListModel::message, this, &WatchListView::message);
    connect(this, &QTreeView::doubleClicked, this, [this](const QModelIndex &index) {
        if (index.column() == FormatColumn)
            chooseFormat(index);
        else if (index.column() == ForceColumn)
            chooseForce(index);
        else if (m_model->isDevice(index))
            editValue(index);
    });
    showLists(0, m_model->rowCount() - 1);
}

void WatchListView::setMonitorSource(model::MonitorSource *source) {
    m_model->setMonitorSource(source);
}

void WatchListView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        m_model->retranslate(); // the headers, "ON", "OFF", the format names
        setAccessibleName(tr("Watch lists"));
    }
    QTreeView::changeEvent(event);
}

void WatchListView::showLists(int first, int last) {
    for (int row = first; row <= last; ++row) {
        setFirstColumnSpanned(row, {}, true);
        expand(m_model->index(row, 0));
    }
}

void WatchListView::rowsInserted(const QModelIndex &parent, int first, int last) {
    QTreeView::rowsInserted(parent, first, last);
    if (!parent.isValid())
        showLists(first, last);
}

void WatchListView::reset() {
    QTreeView::reset();
    showLists(0, m_model->rowCount() - 1);
}

model::ValueFormat WatchListView::format(const QModelIndex &index) const {
    return m_model->format(index);
}

void WatchListView::setFormat(const QModelIndex &index, model::ValueFormat f) {
    m_model->setFormat(index, f);
}

bool WatchListView::writeValue(const QModelIndex &index, const QString &text) {
    return m_model->writeValue(index, text);
}

void WatchListView::editValue(const QModelIndex &index) {
    if (!m_model->checkWritable(index))
        return;
    if (m_model->isBit(index)) {
        m_model->flipBit(index);
        return;
    }
    const QModelIndex value = index.siblingAtColumn(ValueColumn);
    setCurrentIndex(value);
    edit(value);
}

void WatchListView::addFormats(QMenu *menu, const QModelIndex &index) {
    const QPersistentModelIndex row(index);
    for (const model::ValueFormat f : model::kValueFormats) {
        QAction *a = menu->addAction(model::valueFormatName(f));
        a->setCheckable(true);
        a->setChecked(f == format(index));
        connect(a, &QAction::triggered, this, [this, row, f] { setFormat(row, f); });
    }
}

void WatchListView::chooseFormat(const QModelIndex &index) {
    if (!m_model->address(index) || m_model->isBit(index))
        return;
    QMenu menu;
    addFormats(&menu, index);
    menu.exec(
        viewport()->mapToGlobal(visualRect(index.siblingAtColumn(FormatColumn)).bottomLeft()));
}

void WatchListView::chooseForce(const QModelIndex &index) {
    QMenu menu;
    const QList<QAction *> actions = deviceActions(index, &menu);
    // The force actions only: Set ON / Set OFF write once.
    for (QAction *a : actions)
        if (a->text() != tr("Set ON") && a->text() != tr("Set OFF"))
            menu.addAction(a);
    if (menu.isEmpty())
        return;
    menu.exec(viewport()->mapToGlobal(visualRect(index.siblingAtColumn(ForceColumn)).bottomLeft()));
}

QList<QAction *> WatchListView::deviceActions(const QModelIndex &index, QObject *parent) {
    QList<QAction *> actions;
    const auto address = m_model->address(index);
    QPointer<model::MonitorSource> source = m_model->monitorSource();
    if (!source || !address)
        return actions;
    const auto add = [&actions, parent](const QString &text, auto run) {
        auto *a = new QAction(text, parent);
        connect(a, &QAction::triggered, a, run);
        actions << a;
    };
    const model::Address device = *address;
    if (m_model->isBit(index)) {
        add(tr("Set ON"), [source, device] {
            if (source)
                source->writeBit(device, true);
        });
        add(tr("Set OFF"), [source, device] {
            if (source)
                source->writeBit(device, false);
        });
        add(tr("Force ON"), [source, device] {
            if (source)
                source->force(device, true);
        });
        add(tr("Force OFF"), [source, device] {
            if (source)
                source->force(device, false);
        });
        add(tr("Release"), [source, device] {
            if (source)
                source->release(device);
        });
        // Greyed, saying why, where the PLC has no force command.
        if (const QString why = source->forceRefusal(); !why.isEmpty())
            for (qsizetype k = actions.size() - 3; k < actions.size(); ++k) {
                actions[k]->setEnabled(false);
                actions[k]->setToolTip(why);
            }
    } else if (!m_model->isElement(index)) {
        const QPersistentModelIndex row(index);
        add(tr("Write Value..."), [this, row] { editValue(row); });
    }
    return actions;
}

void WatchListView::contextMenuEvent(QContextMenuEvent *event) {
    const QModelIndex index = indexAt(viewport()->mapFromGlobal(event->globalPos()));
    QMenu menu;
    menu.setToolTipsVisible(true); // a greyed entry says why
    menu.addActions(deviceActions(index, &menu));
    if (m_model->address(index) && !m_model->isBit(index))
        addFormats(menu.addMenu(tr("Show As")), index);
    if (m_model->isDevice(index)) {
        menu.addSeparator();
        menu.addAction(tr("Remove"), this, &WatchListView::removeSelected);
    }
    if (menu.isEmpty()) {
        QTreeView::contextMenuEvent(event);
        return;
    }
    menu.exec(event->globalPos());
}

int WatchListView::selectedList() const {
    return m_model->listOf(currentIndex());
}

void WatchListView::addDevice(const QString &device) {
    if (!device.isEmpty())
        addDevices({device});
}

bool WatchListView::addDevices(const QStringList &texts) {
    return m_model->addDevices(texts, std::max(0, selectedList()));
}

QStringList WatchListView::selectedDevices() const {
    QModelIndexList rows = selectionModel()->selectedRows(DeviceColumn);
    std::sort(rows.begin(), rows.end(), [this](const QModelIndex &a, const QModelIndex &b) {
        return std::pair(m_model->listOf(a), a.row()) < std::pair(m_model->listOf(b), b.row());
    });
    QStringList out;
    for (const QModelIndex &index : rows)
        if (m_model->isDevice(index))
            out << m_model->device(index);
    return out;
}

void WatchListView::removeSelected() {
    QModelIndexList rows = selectionModel()->selectedIndexes();
    if (std::none_of(rows.begin(), rows.end(),
                     [this](const QModelIndex &i) { return m_model->isDevice(i); }))
        rows = {currentIndex()};
    m_model->removeDevices(rows);
}

void WatchListView::keyPressEvent(QKeyEvent *event) {
    if (event->key() == Qt::Key_F2 && monitorSource() && currentIndex().isValid()) {
        editValue(currentIndex());
        return;
    }
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        removeSelected();
        return;
    }
    QTreeView::keyPressEvent(event);
}

void WatchListView::dragEnterEvent(QDragEnterEvent *event) {
    if (event->source() == this || devicesFromMime(event->mimeData()).isEmpty()) {
        event->ignore();
        return;
    }
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

void WatchListView::dragMoveEvent(QDragMoveEvent *event) {
    if (event->source() == this) {
        event->ignore();
        return;
    }
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

bool WatchListView::dropDevices(const QMimeData *data, const QPoint &at) {
    // Into the list under the drop, else the selected one.
    if (const QModelIndex under = indexAt(at); under.isValid())
        setCurrentIndex(m_model->index(m_model->listOf(under), 0));
    return m_model->dropMimeData(data, Qt::CopyAction, -1, -1,
                                 m_model->index(std::max(0, selectedList()), 0));
}

void WatchListView::dropEvent(QDropEvent *event) {
    if (event->source() == this || !dropDevices(event->mimeData(), event->position().toPoint())) {
        event->ignore();
        return;
    }
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

} // namespace rung::editor
