#include "watch_list_view.h"

#include "device_mime.h"
#include "document.h"
#include "model/image/power_flow.h"

#include "model/image/monitor_source.h"
#include "model/target/address.h"

#include <QAction>
#include <QContextMenuEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QHeaderView>
#include <QKeyEvent>
#include <QMenu>

#include <algorithm>
#include <set>

namespace rung::editor {

namespace {

constexpr int kAddressRole = Qt::UserRole + 1;

QVariant addressData(const model::Address &a) {
    return QVariantList{a.area, a.index, a.bit};
}

} // namespace

WatchListView::WatchListView(Document *document, QWidget *parent)
    : QTreeWidget(parent)
    , m_document(document) {
    setObjectName(QStringLiteral("watchLists"));
    setColumnCount(Columns);
    setTexts();
    setRootIsDecorated(true);
    setUniformRowHeights(true);
    setAlternatingRowColors(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
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
    connect(document, &Document::programChanged, this, &WatchListView::refresh);
    connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem *item, int column) {
        if (column == FormatColumn)
            chooseFormat(item);
        else if (column == ForceColumn)
            chooseForce(item);
        else
            editValue(item);
    });
    connect(this, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem *item, int column) {
        if (m_showing || column != ValueColumn)
            return;
        // The row shows what the source holds, never the text typed: a write can be refused
        // (a past scan is read-only) or wait for the user's yes (the first write to a PLC),
        // and a value nobody wrote must not stand in the table meanwhile.
        const QString typed = item->text(ValueColumn);
        m_editing = nullptr;
        showValues();
        writeValue(item, typed);
        showValues(); // the value as the source has it, until the next snapshot
    });
    refresh();
}

void WatchListView::setMonitorSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    if (source) {
        connect(source, &model::MonitorSource::snapshotChanged, this, &WatchListView::showValues);
        connect(source, &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                    if (!ok)
                        emit message(error);
                });
        tellWatched();
    }
    showValues();
}

void WatchListView::setTexts() {
    setHeaderLabels({tr("Device"), tr("Symbol"), tr("Value"), tr("Format"), tr("Forced")});
    headerItem()->setToolTip(ValueColumn, tr("Double-click or F2: write a value; a bit flips"));
    headerItem()->setToolTip(FormatColumn, tr("Double-click: show the word in decimal, signed, "
                                              "hexadecimal, binary or BCD"));
    headerItem()->setToolTip(ForceColumn, tr("Double-click: force a bit ON or OFF, or release it"));
    setAccessibleName(tr("Watch lists"));
}

void WatchListView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange) {
        setTexts();
        showValues(); // "ON", "OFF", the format names in the new language
    }
    QTreeWidget::changeEvent(event);
}

void WatchListView::tellWatched() {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    for (int i = 0; i < topLevelItemCount(); ++i)
        for (int k = 0; k < topLevelItem(i)->childCount(); ++k)
            if (const auto a = addressOf(topLevelItem(i)->child(k)))
                devices.push_back(*a);
    m_source->setWatched(this, std::move(devices));
}

std::optional<model::Address> WatchListView::addressOf(const QTreeWidgetItem *item) const {
    if (!item || !item->parent())
        return std::nullopt;
    const QVariantList a = item->data(DeviceColumn, kAddressRole).toList();
    if (a.size() != 3)
        return std::nullopt;
    return model::Address{a[0].toInt(), a[1].toInt(), a[2].toInt()};
}

bool WatchListView::isBit(const model::Address &address) const {
    return address.bit >= 0 || (address.valid() && m_document->target().area(address.area).kind ==
                                                       model::AreaKind::Bit);
}

int WatchListView::bitsOf(const model::Address &address) const {
    return m_document->target().area(address.area).wordBits;
}

model::ValueFormat WatchListView::format(const QTreeWidgetItem *item) const {
    if (!item || !item->parent())
        return model::ValueFormat::Decimal;
    const int list = indexOfTopLevelItem(item->parent());
    const auto &lists = m_document->project().watchLists;
    if (list < 0 || list >= static_cast<int>(lists.size()))
        return model::ValueFormat::Decimal;
    const model::WatchList &watch = lists[static_cast<std::size_t>(list)];
    const QString device = item->text(DeviceColumn);
    // A CPM1's timers, counters and most channels hold BCD digits (W353): shown as digits
    // until the user picks another format, as Omron's tools monitor a channel.
    if (!watch.formats.contains(device) && m_document->target().constants.bcdSetValues)
        return model::ValueFormat::Bcd;
    return watch.format(device);
}

void WatchListView::showValues() {
    const std::shared_ptr<const model::Snapshot> snapshot =
        m_source ? m_source->snapshot() : nullptr;
    const model::Snapshot *ours =
        snapshot && snapshot->layout && &snapshot->layout->target() == &m_document->target()
            ? snapshot.get()
            : nullptr;
    m_showing = true;
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem *list = topLevelItem(i);
        for (int k = 0; k < list->childCount(); ++k)
            showRow(list->child(k), m_source ? ours : nullptr);
    }
    m_showing = false;
}

void WatchListView::showRow(QTreeWidgetItem *item, const model::Snapshot *snapshot) {
    const auto address = addressOf(item);
    const model::Target &t = m_document->target();
    if (!address) {
        item->setText(ValueColumn, tr("not a device"));
        return;
    }
    const model::AreaKind kind = t.area(address->area).kind;
    const bool bit = isBit(*address);
    const bool element =
        !bit && (kind == model::AreaKind::Timer || kind == model::AreaKind::Counter);
    const model::ValueFormat f = format(item);
    item->setText(FormatColumn, bit ? QString() : model::valueFormatName(f));
    // The value being typed stays as typed: a snapshot would overwrite the editor.
    if (item == m_editing && state() == QAbstractItemView::EditingState)
        return;
    item->setFlags(item->flags() | Qt::ItemIsEditable);
    if (!snapshot) {
        item->setText(ValueColumn, QString());
        item->setText(ForceColumn, QString());
        return;
    }
    const int bits = bitsOf(*address);
    QString text;
    if (bit)
        text = snapshot->bit(*address) ? tr("ON") : tr("OFF");
    else if (element) {
        // Current value against the preset (a constant one as the program has it; "?" online
        // where no protocol area holds it), and the done bit.
        const std::optional<qint64> preset =
            model::ProgramFlow::presetWordOf(t, m_boxes.value(item), *address, *snapshot);
        text = tr("%1 of %2, %3")
                   .arg(model::formatValue(snapshot->value(*address), bits, f),
                        preset ? model::formatValue(*preset, bits, f) : QStringLiteral("?"),
                        snapshot->bit(*address) ? tr("ON") : tr("OFF"));
    } else
        text = model::formatValue(snapshot->value(*address), bits, f);
    const bool forced = snapshot->forced(*address);
    item->setText(ValueColumn, forced ? tr("%1 (forced)").arg(text) : text);
    item->setText(ForceColumn,
                  forced && bit ? (snapshot->bit(*address) ? tr("ON") : tr("OFF")) : QString());
    QFont font = item->font(ValueColumn);
    font.setBold(forced);
    item->setFont(ValueColumn, font);
    item->setFont(ForceColumn, font);
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
    if (!m_source || !address || refuseElement(*address, item->text(DeviceColumn)))
        return;
    const auto snapshot = m_source->snapshot();
    if (isBit(*address)) {
        m_source->writeBit(*address, !(snapshot && snapshot->bit(*address)));
        return;
    }
    // The editor opens on the value alone, in the row's format, not on "12 (forced)".
    m_showing = true;
    item->setText(ValueColumn, snapshot ? model::formatValue(snapshot->value(*address),
                                                             bitsOf(*address), format(item))
                                        : QString());
    m_showing = false;
    m_editing = item;
    setCurrentItem(item, ValueColumn);
    editItem(item, ValueColumn);
}

bool WatchListView::writeValue(QTreeWidgetItem *item, const QString &text) {
    const auto address = addressOf(item);
    if (!m_source || !address)
        return false;
    const QString device = item->text(DeviceColumn);
    if (refuseElement(*address, device))
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
                tr("\"%1\" is no value for %2: type ON or OFF (1 or 0)").arg(typed, device));
            return false;
        }
        m_source->writeBit(*address, on);
        return true;
    }
    const int bits = bitsOf(*address);
    const model::ValueFormat f = format(item);
    const auto value = model::parseValue(typed, bits, f);
    if (const auto *v = std::get_if<std::int64_t>(&value)) {
        m_source->writeWord(*address, *v);
        return true;
    }
    QString hint;
    switch (f) {
    case model::ValueFormat::Decimal:
    case model::ValueFormat::Signed:
        hint = tr("type a whole number (0x before a hexadecimal one)");
        break;
    case model::ValueFormat::Hex:
        hint = tr("type up to %1 hexadecimal digits").arg(bits / 4);
        break;
    case model::ValueFormat::Binary:
        hint = tr("type up to %1 binary digits (0 and 1)").arg(bits);
        break;
    case model::ValueFormat::Bcd:
        hint = tr("type up to %1 decimal digits (BCD)").arg(bits / 4);
        break;
    }
    bool number = false;
    typed.toLongLong(&number);
    if (number && (f == model::ValueFormat::Decimal || f == model::ValueFormat::Signed))
        hint = tr("a %1-bit word holds %2..%3")
                   .arg(bits)
                   .arg(-(qint64{1} << (bits - 1)))
                   .arg((qint64{1} << bits) - 1);
    emit message(tr("\"%1\" is no value for %2: %3").arg(typed, device, hint));
    return false;
}

void WatchListView::chooseFormat(QTreeWidgetItem *item) {
    const auto address = addressOf(item);
    if (!address || isBit(*address))
        return;
    QMenu menu;
    for (const model::ValueFormat f : model::kValueFormats) {
        QAction *a = menu.addAction(model::valueFormatName(f));
        a->setCheckable(true);
        a->setChecked(f == format(item));
        connect(a, &QAction::triggered, this, [this, item, f] { setFormat(item, f); });
    }
    menu.exec(viewport()->mapToGlobal(visualItemRect(item).bottomLeft() +
                                      QPoint(header()->sectionPosition(FormatColumn), 0)));
}

void WatchListView::chooseForce(QTreeWidgetItem *item) {
    QMenu menu;
    const QList<QAction *> actions = deviceActions(item, &menu);
    // The force actions only: Set ON / Set OFF write once.
    for (QAction *a : actions)
        if (a->text() != tr("Set ON") && a->text() != tr("Set OFF"))
            menu.addAction(a);
    if (menu.isEmpty())
        return;
    menu.exec(viewport()->mapToGlobal(visualItemRect(item).bottomLeft() +
                                      QPoint(header()->sectionPosition(ForceColumn), 0)));
}

void WatchListView::setFormat(QTreeWidgetItem *item, model::ValueFormat f) {
    if (!item || !item->parent() || f == format(item))
        return;
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    const int list = indexOfTopLevelItem(item->parent());
    if (list < 0 || list >= static_cast<int>(lists.size()))
        return;
    const QString device = item->text(DeviceColumn);
    lists[static_cast<std::size_t>(list)].formats[device] = f;
    m_document->setWatchLists(lists, tr("Show %1 as %2").arg(device, model::valueFormatName(f)));
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
        // Greyed, saying why, where the PLC has no force command.
        if (const QString why = source ? source->forceRefusal() : QString(); !why.isEmpty())
            for (qsizetype k = actions.size() - 3; k < actions.size(); ++k) {
                actions[k]->setEnabled(false);
                actions[k]->setToolTip(why);
            }
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
    menu.setToolTipsVisible(true); // a greyed entry says why
    menu.addActions(deviceActions(item, &menu));
    const auto address = addressOf(item);
    if (address && !isBit(*address)) {
        QMenu *show = menu.addMenu(tr("Show As"));
        for (const model::ValueFormat f : model::kValueFormats) {
            QAction *a = show->addAction(model::valueFormatName(f));
            a->setCheckable(true);
            a->setChecked(f == format(item));
            connect(a, &QAction::triggered, this, [this, item, f] { setFormat(item, f); });
        }
    }
    if (item && item->parent()) {
        menu.addSeparator();
        menu.addAction(tr("Remove"), this, &WatchListView::removeSelected);
    }
    if (menu.isEmpty()) {
        QTreeWidget::contextMenuEvent(event);
        return;
    }
    menu.exec(event->globalPos());
}

void WatchListView::refresh() {
    const auto &lists = m_document->project().watchLists;
    // Rebuilt only when it changed, so the selection and expansion survive ordinary edits.
    bool same = topLevelItemCount() == static_cast<int>(lists.size());
    for (int i = 0; same && i < topLevelItemCount(); ++i) {
        const QTreeWidgetItem *item = topLevelItem(i);
        const auto &list = lists[static_cast<std::size_t>(i)];
        same = item->text(DeviceColumn) == list.name && item->childCount() == list.devices.size();
        for (int k = 0; same && k < item->childCount(); ++k)
            same = item->child(k)->text(DeviceColumn) == list.devices[k];
    }
    const model::Target &t = m_document->target();
    if (!same) {
        m_editing = nullptr;
        clear();
        for (const model::WatchList &list : lists) {
            auto *item = new QTreeWidgetItem(this, {list.name});
            item->setFirstColumnSpanned(true);
            QFont bold = item->font(DeviceColumn);
            bold.setBold(true);
            item->setFont(DeviceColumn, bold);
            for (const QString &device : list.devices) {
                auto *row = new QTreeWidgetItem(item, {device});
                const auto parsed = model::parseAddress(t, device);
                if (const auto *a = std::get_if<model::Address>(&parsed))
                    row->setData(DeviceColumn, kAddressRole, addressData(*a));
            }
            item->setExpanded(true);
        }
        tellWatched();
    }
    // Symbols and formats change without the rows changing.
    m_program = m_document->sharedInstructions();
    m_boxes.clear();
    for (int i = 0; i < topLevelItemCount(); ++i)
        for (int k = 0; k < topLevelItem(i)->childCount(); ++k) {
            QTreeWidgetItem *row = topLevelItem(i)->child(k);
            const auto a = addressOf(row);
            if (const model::Instruction *box =
                    a ? model::ProgramFlow::boxOf(*m_program, *a) : nullptr)
                m_boxes.insert(row, box);
            const model::Symbol *symbol = a ? m_document->project().symbol(*a) : nullptr;
            row->setText(SymbolColumn, symbol ? symbol->name : QString());
            row->setToolTip(SymbolColumn, symbol ? symbol->comment : QString());
        }
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
    if (!device.isEmpty())
        addDevices({device});
}

bool WatchListView::addDevices(const QStringList &texts) {
    const model::Target &t = m_document->target();
    QStringList devices;
    for (const QString &text : texts) {
        const auto parsed = model::parseAddressRange(t, text, m_document->modelVariant());
        if (const auto *error = std::get_if<model::AddressError>(&parsed)) {
            emit message(tr("Not added to the watch list: %1").arg(error->message));
            return false;
        }
        for (const model::Address &a : std::get<std::vector<model::Address>>(parsed))
            devices << model::formatAddress(t, a);
    }
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    const int index = std::max(0, selectedList());
    if (lists.empty())
        lists.push_back(model::WatchList{tr("Watch 1"), {}, {}});
    model::WatchList &list =
        lists[static_cast<std::size_t>(std::min<int>(index, static_cast<int>(lists.size()) - 1))];
    QStringList added;
    for (const QString &device : devices)
        if (!list.devices.contains(device) && !added.contains(device))
            added << device;
    if (added.isEmpty())
        return true;
    list.devices << added;
    const QString what = added.size() == 1
                             ? added.front()
                             : QStringLiteral("%1..%2").arg(added.front(), added.back());
    m_document->setWatchLists(lists, tr("Add %1 to the watch list").arg(what));
    return true;
}

QStringList WatchListView::selectedDevices() const {
    QStringList out;
    for (const QTreeWidgetItem *item : selectedItems())
        if (item->parent())
            out << item->text(DeviceColumn);
    return out;
}

void WatchListView::removeSelected() {
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    std::set<std::pair<int, int>> rows; // (list, row)
    for (const QTreeWidgetItem *item : selectedItems())
        if (item->parent())
            rows.insert({indexOfTopLevelItem(item->parent()),
                         item->parent()->indexOfChild(const_cast<QTreeWidgetItem *>(item))});
    if (rows.empty() && currentItem() && currentItem()->parent())
        rows.insert({indexOfTopLevelItem(currentItem()->parent()),
                     currentItem()->parent()->indexOfChild(currentItem())});
    if (rows.empty())
        return;
    QStringList removed;
    for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
        const auto [list, row] = *it;
        if (list < 0 || list >= static_cast<int>(lists.size()))
            continue;
        model::WatchList &l = lists[static_cast<std::size_t>(list)];
        removed.prepend(l.devices[row]);
        l.formats.erase(l.devices[row]);
        l.devices.removeAt(row);
    }
    m_document->setWatchLists(
        lists,
        tr("Remove %1 from the watch list")
            .arg(removed.size() == 1 ? removed.front() : removed.join(QStringLiteral(", "))));
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

QStringList WatchListView::mimeTypes() const {
    return {deviceMimeType(), QStringLiteral("text/plain")};
}

QMimeData *WatchListView::mimeData(const QList<QTreeWidgetItem *> &items) const {
    // In the table's order, whatever order the selection was made in.
    std::vector<std::pair<std::pair<int, int>, QString>> rows;
    for (const QTreeWidgetItem *item : items)
        if (item->parent())
            rows.push_back({{indexOfTopLevelItem(item->parent()),
                             item->parent()->indexOfChild(const_cast<QTreeWidgetItem *>(item))},
                            item->text(DeviceColumn)});
    std::sort(rows.begin(), rows.end());
    QStringList devices;
    for (const auto &row : rows)
        if (!devices.contains(row.second))
            devices << row.second;
    return devices.isEmpty() ? nullptr : deviceMimeData(devices);
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
    if (QTreeWidgetItem *target = itemAt(at))
        setCurrentItem(target->parent() ? target->parent() : target);
    const QStringList devices = devicesFromMime(data);
    return !devices.isEmpty() && addDevices(devices);
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
