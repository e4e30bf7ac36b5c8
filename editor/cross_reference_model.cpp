#include "cross_reference_model.h"

#include "device_mime.h"
#include "document.h"

namespace rung::editor {

namespace {

// A use's row carries its device's row plus one as its internal id; a top-level row, 0.
constexpr quintptr kTopLevel = 0;

} // namespace

CrossReferenceModel::CrossReferenceModel(Document *document, QObject *parent)
    : QAbstractItemModel(parent)
    , m_document(document) {
    connect(document, &Document::programChanged, this, [this] {
        m_stale = true;
        if (m_following)
            refresh();
    });
}

void CrossReferenceModel::setFilter(const QString &filter) {
    m_filter = filter;
    refresh();
}

void CrossReferenceModel::setMaxUses(int maxUses) {
    m_maxUses = std::max(0, maxUses);
    refresh();
}

void CrossReferenceModel::setFollowing(bool following) {
    m_following = following;
    if (following && m_stale)
        refresh();
}

void CrossReferenceModel::refresh() {
    beginResetModel();
    const model::ToListingResult &listing = m_document->listing();
    m_uses =
        model::crossReference(m_document->target(), m_document->modelVariant(),
                              listing.list.instructions, listing.rungFirst, m_filter, m_maxUses);
    m_stale = false;
    endResetModel();
}

void CrossReferenceModel::retranslate() {
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
    const int rows = rowCount();
    if (rows == 0)
        return;
    emit dataChanged(index(0, 0), index(rows - 1, ColumnCount - 1));
    for (int d = 0; d < static_cast<int>(m_uses.devices.size()); ++d) {
        const QModelIndex device = index(d, 0);
        if (const int uses = rowCount(device); uses > 0)
            emit dataChanged(index(0, 0, device), index(uses - 1, ColumnCount - 1, device));
    }
}

bool CrossReferenceModel::isNote(const QModelIndex &index) const {
    return index.isValid() && index.internalId() == kTopLevel &&
           index.row() == static_cast<int>(m_uses.devices.size());
}

QModelIndex CrossReferenceModel::index(int row, int column, const QModelIndex &parent) const {
    if (!hasIndex(row, column, parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, kTopLevel);
    return createIndex(row, column, static_cast<quintptr>(parent.row()) + 1);
}

QModelIndex CrossReferenceModel::parent(const QModelIndex &child) const {
    if (!child.isValid() || child.internalId() == kTopLevel)
        return {};
    return createIndex(static_cast<int>(child.internalId() - 1), 0, kTopLevel);
}

int CrossReferenceModel::rowCount(const QModelIndex &parent) const {
    const int devices = static_cast<int>(m_uses.devices.size());
    if (!parent.isValid())
        return devices + (m_uses.capped ? 1 : 0);
    if (parent.column() != 0 || parent.internalId() != kTopLevel || parent.row() >= devices)
        return 0; // a use, or the note, has no rows under it
    return static_cast<int>(m_uses.devices[static_cast<std::size_t>(parent.row())].uses.size());
}

int CrossReferenceModel::columnCount(const QModelIndex &) const {
    return ColumnCount;
}

const model::CrossReference::Device *CrossReferenceModel::deviceOf(const QModelIndex &index) const {
    if (!index.isValid())
        return nullptr;
    const std::size_t row = index.internalId() == kTopLevel
                                ? static_cast<std::size_t>(index.row())
                                : static_cast<std::size_t>(index.internalId() - 1);
    return row < m_uses.devices.size() ? &m_uses.devices[row] : nullptr;
}

QString CrossReferenceModel::summary(const model::CrossReference::Device &device) const {
    int counts[3] = {0, 0, 0};
    for (const model::CrossReference::Use &u : device.uses)
        ++counts[static_cast<int>(u.use)];
    QStringList parts;
    for (const model::DeviceUse use :
         {model::DeviceUse::Contact, model::DeviceUse::Coil, model::DeviceUse::Box})
        if (const int count = counts[static_cast<int>(use)]; count > 0)
            parts << QStringLiteral("%1 × %2").arg(count).arg(word(use));
    return parts.join(QStringLiteral(", "));
}

QString CrossReferenceModel::word(model::DeviceUse use) {
    switch (use) {
    case model::DeviceUse::Contact:
        return tr("contact");
    case model::DeviceUse::Coil:
        return tr("coil");
    case model::DeviceUse::Box:
        break;
    }
    return tr("box");
}

QVariant CrossReferenceModel::deviceData(const model::CrossReference::Device &device, int column,
                                         int role) const {
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole)
        return {};
    // The tooltips are the texts whole: a narrow dock ends a long name in "...".
    const model::Symbol *symbol = m_document->project().symbol(device.address);
    switch (column) {
    case DeviceColumn: {
        const QString name = model::formatAddress(m_document->target(), device.address);
        return symbol && !symbol->name.isEmpty() ? QStringLiteral("%1  %2").arg(name, symbol->name)
                                                 : name;
    }
    case UseColumn:
        return summary(device);
    case InstructionColumn:
        if (symbol && !symbol->comment.isEmpty())
            return symbol->comment;
        break;
    }
    return {};
}

QVariant CrossReferenceModel::useData(const model::CrossReference::Use &use, int column,
                                      int role) const {
    if (role == Qt::ToolTipRole && column == InstructionColumn)
        return use.instruction;
    if (role != Qt::DisplayRole)
        return {};
    switch (column) {
    case DeviceColumn:
        return tr("rung %1").arg(use.rung + 1);
    case StepColumn:
        return QStringLiteral("%1").arg(use.step, 4, 10, QLatin1Char('0'));
    case UseColumn:
        return word(use.use);
    case InstructionColumn:
        return use.instruction;
    }
    return {};
}

QVariant CrossReferenceModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || !checkIndex(index, CheckIndexOption::IndexIsValid))
        return {};
    if (isNote(index)) {
        if (index.column() == DeviceColumn && (role == Qt::DisplayRole || role == Qt::ToolTipRole))
            return tr("The first %1 uses; type a device or a prefix for the rest").arg(m_maxUses);
        return {};
    }
    const model::CrossReference::Device *device = deviceOf(index);
    if (!device)
        return {};
    if (role == DeviceRole)
        return model::formatAddress(m_document->target(), device->address);
    if (index.internalId() == kTopLevel)
        return deviceData(*device, index.column(), role);
    const model::CrossReference::Use &use = device->uses[static_cast<std::size_t>(index.row())];
    if (role == RungRole)
        return use.rung;
    return useData(use, index.column(), role);
}

QVariant CrossReferenceModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    // The rows under a device say "rung N" themselves: the first title names the device only
    // ("Device / rung" took the room of a column and a half in Hungarian).
    switch (section) {
    case DeviceColumn:
        return tr("Device");
    case StepColumn:
        return tr("Step");
    case UseColumn:
        return tr("Use");
    case InstructionColumn:
        return tr("Instruction");
    }
    return {};
}

Qt::ItemFlags CrossReferenceModel::flags(const QModelIndex &index) const {
    if (!index.isValid())
        return Qt::NoItemFlags;
    if (isNote(index))
        return Qt::ItemIsEnabled;
    return Qt::ItemIsEnabled | Qt::ItemIsSelectable | Qt::ItemIsDragEnabled;
}

QStringList CrossReferenceModel::mimeTypes() const {
    return {deviceMimeType()};
}

QMimeData *CrossReferenceModel::mimeData(const QModelIndexList &indexes) const {
    QStringList devices;
    for (const QModelIndex &index : indexes) {
        const QString device = index.data(DeviceRole).toString();
        if (!device.isEmpty() && !devices.contains(device))
            devices << device;
    }
    return devices.isEmpty() ? nullptr : deviceMimeData(devices);
}

} // namespace rung::editor
