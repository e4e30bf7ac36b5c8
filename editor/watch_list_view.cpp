#include "watch_list_view.h"

#include "document.h"

#include "model/image/monitor_source.h"
#include "model/target/address.h"
#include "model/target/word_text.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QHeaderView>
#include <QKeyEvent>
#include <QMenu>

namespace rung::editor {

WatchListView::WatchListView(Document *document, QWidget *parent)
    : QTreeWidget(parent)
    , m_document(document) {
    setObjectName(QStringLiteral("watchLists"));
    setTexts();
    header()->hide();
    setRootIsDecorated(true);
    // Only the value column is edited, and only on purpose (editValue): the device column is
    // the list's content, changed by add and remove.
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    connect(document, &Document::programChanged, this, &WatchListView::refresh);
    connect(this, &QTreeWidget::itemDoubleClicked, this,
            [this](QTreeWidgetItem *item, int) { editValue(item); });
    connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem *item, int column) {
        if (m_showing || column != 1)
            return;
        writeValue(item, item->text(1));
        showValues(); // the value as the source has it, until the next snapshot
    });
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
        // The device column as wide as its texts (Italian "Lista di osservazione" was cut at
        // the default width); the value takes the rest.
        header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
        connect(source, &model::MonitorSource::snapshotChanged, this, &WatchListView::showValues);
        connect(source, &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                    if (!ok)
                        emit message(error);
                });
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
    m_showing = true;
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem *list = topLevelItem(i);
        for (int k = 0; k < list->childCount(); ++k) {
            QTreeWidgetItem *item = list->child(k);
            // The value being typed stays as typed: a snapshot would overwrite the editor.
            if (item == m_editing && state() == QAbstractItemView::EditingState)
                continue;
            item->setFlags(item->flags() | Qt::ItemIsEditable);
            item->setText(1, snapshot ? valueText(*snapshot, item->text(0)) : QString());
        }
    }
    m_showing = false;
}

std::optional<model::Address> WatchListView::addressOf(const QTreeWidgetItem *item) const {
    if (!item || !item->parent())
        return std::nullopt;
    const auto parsed = model::parseAddress(m_document->target(), item->text(0));
    if (const auto *a = std::get_if<model::Address>(&parsed))
        return *a;
    return std::nullopt;
}

bool WatchListView::isBit(const model::Address &address) const {
    return address.bit >= 0 || (address.valid() && m_document->target().area(address.area).kind ==
                                                       model::AreaKind::Bit);
}

bool WatchListView::refuseElement(const model::Address &address, const QString &device) {
    const model::AreaKind kind = m_document->target().area(address.area).kind;
    if (address.bit >= 0 || (kind != model::AreaKind::Timer && kind != model::AreaKind::Counter))
        return false;
    // The scan engine computes a timer's or counter's current value from the element's own
    // state every scan, so a written value would be gone at the next scan: say so instead.
    emit message(tr("%1 is a timer or counter: its current value follows the program and "
                    "cannot be written here")
                     .arg(device));
    return true;
}

void WatchListView::editValue(QTreeWidgetItem *item) {
    const auto address = addressOf(item);
    if (!m_source || !address || refuseElement(*address, item->text(0)))
        return;
    if (isBit(*address)) {
        const auto snapshot = m_source->snapshot();
        m_source->writeBit(*address, !(snapshot && snapshot->bit(*address)));
        return;
    }
    // The editor opens on the number alone, not on "12 of 50, OFF".
    const auto snapshot = m_source->snapshot();
    m_showing = true;
    item->setText(1, snapshot ? model::formatWord(m_document->target(), snapshot->value(*address))
                              : QString());
    m_showing = false;
    m_editing = item;
    setCurrentItem(item, 1);
    editItem(item, 1);
}

bool WatchListView::writeValue(QTreeWidgetItem *item, const QString &text) {
    const auto address = addressOf(item);
    if (!m_source || !address)
        return false;
    if (refuseElement(*address, item->text(0)))
        return false;
    const QString typed = text.trimmed();
    if (isBit(*address)) {
        const bool on = typed == QLatin1String("1") ||
                        typed.compare(QLatin1String("ON"), Qt::CaseInsensitive) == 0 ||
                        typed.compare(tr("ON"), Qt::CaseInsensitive) == 0;
        const bool off = typed == QLatin1String("0") ||
                         typed.compare(QLatin1String("OFF"), Qt::CaseInsensitive) == 0 ||
                         typed.compare(tr("OFF"), Qt::CaseInsensitive) == 0;
        if (!on && !off) {
            emit message(
                tr("\"%1\" is no value for %2: type ON or OFF (1 or 0)").arg(typed, item->text(0)));
            return false;
        }
        m_source->writeBit(*address, on);
        return true;
    }
    // A number, 0x... and, on the CPM1, #0012 as its listing writes a word (word_text.h).
    const std::optional<qint64> value = model::parseWordValue(m_document->target(), typed);
    if (!value) {
        emit message(tr("\"%1\" is no value for %2: type a whole number (0x before a "
                        "hexadecimal one)")
                         .arg(typed, item->text(0)));
        return false;
    }
    m_source->writeWord(*address, *value);
    return true;
}

QList<QAction *> WatchListView::deviceActions(QTreeWidgetItem *item, QObject *parent) {
    QList<QAction *> actions;
    const auto address = addressOf(item);
    if (!m_source || !address)
        return actions;
    const auto add = [&actions, parent](const QString &text, auto run) {
        auto *a = new QAction(text, parent);
        connect(a, &QAction::triggered, a, run);
        actions << a;
    };
    const model::Address device = *address;
    QPointer<model::MonitorSource> source = m_source;
    if (isBit(device)) {
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
    } else {
        const model::AreaKind kind = m_document->target().area(device.area).kind;
        if (kind != model::AreaKind::Timer && kind != model::AreaKind::Counter)
            add(tr("Write Value..."), [this, item] { editValue(item); });
    }
    return actions;
}

void WatchListView::contextMenuEvent(QContextMenuEvent *event) {
    QTreeWidgetItem *item = itemAt(viewport()->mapFromGlobal(event->globalPos()));
    QMenu menu;
    const QList<QAction *> actions = deviceActions(item, &menu);
    if (actions.isEmpty()) {
        QTreeWidget::contextMenuEvent(event);
        return;
    }
    menu.addActions(actions);
    menu.exec(event->globalPos());
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
                   .arg(model::formatWord(m_document->target(), snapshot.value(*address)),
                        model::formatWord(m_document->target(), snapshot.setValue(*address)),
                        snapshot.bit(*address) ? tr("ON") : tr("OFF"));
    else
        text = model::formatWord(m_document->target(), snapshot.value(*address));
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
    m_editing = nullptr;
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
    if (event->key() == Qt::Key_F2 && m_source && currentItem()) {
        editValue(currentItem());
        return;
    }
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        removeSelected();
        return;
    }
    QTreeWidget::keyPressEvent(event);
}

} // namespace rung::editor
