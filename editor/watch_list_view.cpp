#include "watch_list_view.h"

#include "document.h"

#include "model/image/monitor_source.h"
#include "model/target/address.h"

#include <QHeaderView>
#include <QKeyEvent>

namespace rung::editor {

WatchListView::WatchListView(Document *document, QWidget *parent)
    : QTreeWidget(parent)
    , m_document(document) {
    setObjectName(QStringLiteral("watchLists"));
    setTexts();
    header()->hide();
    setRootIsDecorated(true);
    connect(document, &Document::programChanged, this, &WatchListView::refresh);
    refresh();
}

void WatchListView::setMonitorSource(model::MonitorSource *source) {
    if (m_source == source)
        return;
    if (m_source) {
        disconnect(m_source, nullptr, this, nullptr);
        m_source->setWatched(this, {});
    }
    m_source = source;
    setColumnCount(source ? 2 : 1);
    setTexts();
    if (source) {
        header()->show();
        connect(source, &model::MonitorSource::snapshotChanged, this, &WatchListView::showValues);
        tellWatched();
        showValues();
    } else {
        header()->hide();
    }
}

void WatchListView::setTexts() {
    setHeaderLabels(m_source ? QStringList{tr("Watch list"), tr("Value")}
                             : QStringList{tr("Watch list")});
    setAccessibleName(tr("Watch lists"));
}

void WatchListView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        setTexts();
        showValues(); // "ON", "OFF", "(forced)" in the new language
    }
    QTreeWidget::changeEvent(event);
}

void WatchListView::tellWatched() {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    for (const model::WatchList &list : m_document->project().watchLists)
        for (const QString &device : list.devices) {
            const auto address = model::parseAddress(m_document->target(), device);
            if (const auto *a = std::get_if<model::Address>(&address))
                devices.push_back(*a);
        }
    m_source->setWatched(this, std::move(devices));
}

void WatchListView::showValues() {
    if (!m_source)
        return;
    const std::shared_ptr<const model::Snapshot> snapshot = m_source->snapshot();
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem *list = topLevelItem(i);
        for (int k = 0; k < list->childCount(); ++k) {
            QTreeWidgetItem *item = list->child(k);
            item->setText(1, snapshot ? valueText(*snapshot, item->text(0)) : QString());
        }
    }
}

QString WatchListView::valueText(const model::Snapshot &snapshot, const QString &device) const {
    const auto parsed = model::parseAddress(m_document->target(), device);
    const auto *address = std::get_if<model::Address>(&parsed);
    if (!address || !snapshot.layout || &snapshot.layout->target() != &m_document->target())
        return tr("not a device");
    const model::AreaKind kind = snapshot.layout->area(address->area).kind;
    QString text;
    if (kind == model::AreaKind::Bit || address->bit >= 0)
        text = snapshot.bit(*address) ? tr("ON") : tr("OFF");
    else if (kind == model::AreaKind::Timer || kind == model::AreaKind::Counter)
        // Current value against the preset, and the done bit.
        text = tr("%1 of %2, %3")
                   .arg(snapshot.value(*address))
                   .arg(snapshot.setValue(*address))
                   .arg(snapshot.bit(*address) ? tr("ON") : tr("OFF"));
    else
        text = QString::number(snapshot.value(*address));
    return snapshot.forced(*address) ? tr("%1 (forced)").arg(text) : text;
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
    tellWatched();
    showValues();
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
