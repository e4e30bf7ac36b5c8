#include "watch_list_view.h"

#include "document.h"

#include <QHeaderView>
#include <QKeyEvent>

namespace rung::editor {

WatchListView::WatchListView(Document *document, QWidget *parent)
    : QTreeWidget(parent)
    , m_document(document) {
    setObjectName(QStringLiteral("watchLists"));
    setHeaderLabels({tr("Watch list")});
    header()->hide();
    setRootIsDecorated(true);
    setAccessibleName(tr("Watch lists"));
    connect(document, &Document::programChanged, this, &WatchListView::refresh);
    refresh();
}

void WatchListView::refresh() {
    const auto &lists = m_document->project().watchLists;
    // Rebuilt only when it changed, so the selection and expansion survive ordinary edits.
    bool same = topLevelItemCount() == static_cast<int>(lists.size());
    for (int i = 0; same && i < topLevelItemCount(); ++i) {
        const QTreeWidgetItem *item = topLevelItem(i);
        const auto &list = lists[static_cast<std::size_t>(i)];
        same = item->text(0) == list.name && item->childCount() == list.devices.size();
        for (int k = 0; same && k < item->childCount(); ++k)
            same = item->child(k)->text(0) == list.devices[k];
    }
    if (same)
        return;
    clear();
    for (const model::WatchList &list : lists) {
        auto *item = new QTreeWidgetItem(this, {list.name});
        for (const QString &device : list.devices)
            new QTreeWidgetItem(item, {device});
        item->setExpanded(true);
    }
}

int WatchListView::selectedList() const {
    const QTreeWidgetItem *item = currentItem();
    if (!item)
        return -1;
    if (item->parent())
        item = item->parent();
    return indexOfTopLevelItem(const_cast<QTreeWidgetItem *>(item));
}

void WatchListView::addDevice(const QString &device) {
    if (device.isEmpty())
        return;
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    const int index = std::max(0, selectedList());
    if (lists.empty())
        lists.push_back(model::WatchList{tr("Watch 1"), {}});
    model::WatchList &list =
        lists[static_cast<std::size_t>(std::min<int>(index, static_cast<int>(lists.size()) - 1))];
    if (list.devices.contains(device))
        return;
    list.devices << device;
    m_document->setWatchLists(lists, tr("Add %1 to the watch list").arg(device));
}

void WatchListView::removeSelected() {
    const QTreeWidgetItem *item = currentItem();
    if (!item || !item->parent())
        return;
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    const int list = indexOfTopLevelItem(item->parent());
    const int row = item->parent()->indexOfChild(const_cast<QTreeWidgetItem *>(item));
    if (list < 0 || list >= static_cast<int>(lists.size()))
        return;
    const QString device = item->text(0);
    lists[static_cast<std::size_t>(list)].devices.removeAt(row);
    m_document->setWatchLists(lists, tr("Remove %1 from the watch list").arg(device));
}

void WatchListView::keyPressEvent(QKeyEvent *event) {
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        removeSelected();
        return;
    }
    QTreeWidget::keyPressEvent(event);
}

} // namespace rung::editor
