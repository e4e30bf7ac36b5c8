// The rows of the watch lists' model: they follow the document's lists (an edit, an undo, a
// redo) with the signals of the rows that changed, and the edits that change the lists (add,
// remove, a format) are undo steps of the document.

#include "watch_list_model.h"

#include "document.h"

#include "model/image/power_flow.h"
#include "model/target/address.h"

#include <algorithm>
#include <set>
#include <utility>

namespace rung::editor {

namespace {

// A longest common subsequence of the middle costs its two lengths' product; past this the
// middle is replaced whole (a view loses the selection there, nothing else).
constexpr qint64 kMaxDiffCells = qint64{1} << 22;

// Which rows of `a` and `b` a change keeps: the common ends first (an add, a remove, an undo
// of either changes one place), then a longest common subsequence of what lies between.
std::pair<std::vector<bool>, std::vector<bool>> keptRows(const QStringList &a,
                                                         const QStringList &b) {
    const int n = static_cast<int>(a.size());
    const int m = static_cast<int>(b.size());
    std::vector<bool> keptA(static_cast<std::size_t>(n)), keptB(static_cast<std::size_t>(m));
    const auto keep = [&](int i, int j) {
        keptA[static_cast<std::size_t>(i)] = true;
        keptB[static_cast<std::size_t>(j)] = true;
    };
    int head = 0;
    while (head < n && head < m && a[head] == b[head])
        keep(head, head), ++head;
    int tail = 0;
    while (tail < n - head && tail < m - head && a[n - 1 - tail] == b[m - 1 - tail])
        keep(n - 1 - tail, m - 1 - tail), ++tail;
    const int rn = n - head - tail;
    const int rm = m - head - tail;
    if (rn == 0 || rm == 0 || qint64{rn} * rm > kMaxDiffCells)
        return {keptA, keptB};
    // length[i][j]: the longest common subsequence of a[head+i..] and b[head+j..].
    const auto width = static_cast<std::size_t>(rm + 1);
    std::vector<int> length(static_cast<std::size_t>(rn + 1) * width, 0);
    const auto at = [&](int i, int j) -> int & {
        return length[static_cast<std::size_t>(i) * width + static_cast<std::size_t>(j)];
    };
    for (int i = rn - 1; i >= 0; --i)
        for (int j = rm - 1; j >= 0; --j)
            at(i, j) = a[head + i] == b[head + j] ? at(i + 1, j + 1) + 1
                                                  : std::max(at(i + 1, j), at(i, j + 1));
    for (int i = 0, j = 0; i < rn && j < rm;) {
        if (a[head + i] == b[head + j])
            keep(head + i++, head + j++);
        else if (at(i + 1, j) >= at(i, j + 1))
            ++i;
        else
            ++j;
    }
    return {keptA, keptB};
}

} // namespace

void WatchListModel::tellWatched(bool always) {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    for (const List &list : m_lists)
        for (const Row &row : list.rows)
            if (row.address)
                devices.push_back(*row.address);
    if (!always && devices == m_told)
        return;
    m_told = devices;
    m_source->setWatched(this, std::move(devices));
}

WatchListModel::Row WatchListModel::makeRow(const QString &device) const {
    Row row;
    row.device = device;
    const auto parsed = model::parseAddress(*m_target, device);
    if (const auto *a = std::get_if<model::Address>(&parsed))
        row.address = *a;
    return row;
}

void WatchListModel::derive(Row &row, const model::WatchList &list) const {
    const model::Symbol *symbol =
        row.address ? m_document->project().symbol(*row.address) : nullptr;
    row.symbol = symbol ? symbol->name : QString();
    row.comment = symbol ? symbol->comment : QString();
    // A CPM1's timers, counters and most channels hold BCD digits (W353): shown as digits
    // until the user picks another format, as Omron's tools monitor a channel.
    row.format = !list.formats.contains(row.device) && m_target->constants.bcdSetValues
                     ? model::ValueFormat::Bcd
                     : list.format(row.device);
    row.box = row.address ? model::ProgramFlow::boxOf(*m_program, *row.address) : nullptr;
}

void WatchListModel::patch(const QModelIndex &parent, const QStringList &before,
                           const QStringList &after, const std::function<void(int, int)> &remove,
                           const std::function<void(int, int)> &insert) {
    const auto [keptBefore, keptAfter] = keptRows(before, after);
    for (int last = static_cast<int>(before.size()) - 1; last >= 0; --last) {
        if (keptBefore[static_cast<std::size_t>(last)])
            continue;
        int first = last;
        while (first > 0 && !keptBefore[static_cast<std::size_t>(first - 1)])
            --first;
        beginRemoveRows(parent, first, last);
        remove(first, last);
        endRemoveRows();
        last = first;
    }
    for (int first = 0; first < static_cast<int>(after.size()); ++first) {
        if (keptAfter[static_cast<std::size_t>(first)])
            continue;
        int last = first;
        while (last + 1 < static_cast<int>(after.size()) &&
               !keptAfter[static_cast<std::size_t>(last + 1)])
            ++last;
        beginInsertRows(parent, first, last);
        insert(first, last);
        endInsertRows();
        first = last;
    }
}

void WatchListModel::follow() {
    const auto &lists = m_document->project().watchLists;
    // The rows' boxes point into the program before until they are derived again below.
    const auto before = std::exchange(m_program, m_document->sharedInstructions());
    const auto fresh = [this](const model::WatchList &watch) {
        List list{watch.name, {}};
        for (const QString &device : watch.devices) {
            list.rows.push_back(makeRow(device));
            derive(list.rows.back(), watch);
        }
        return list;
    };
    if (&m_document->target() != m_target) {
        // Another family: every address means something else.
        beginResetModel();
        m_target = &m_document->target();
        m_lists.clear();
        for (const model::WatchList &watch : lists)
            m_lists.push_back(fresh(watch));
        endResetModel();
        tellWatched();
        return;
    }
    QStringList names, newNames;
    for (const List &list : m_lists)
        names << list.name;
    for (const model::WatchList &watch : lists)
        newNames << watch.name;
    patch(
        {}, names, newNames,
        [this](int first, int last) {
            m_lists.erase(m_lists.begin() + first, m_lists.begin() + last + 1);
        },
        [&](int first, int last) {
            for (int k = first; k <= last; ++k)
                m_lists.insert(m_lists.begin() + k, fresh(lists[static_cast<std::size_t>(k)]));
        });
    for (int i = 0; i < static_cast<int>(lists.size()); ++i)
        followRows(i, lists[static_cast<std::size_t>(i)]);
    // The symbols, formats and boxes change without the rows changing.
    for (int i = 0; i < static_cast<int>(lists.size()); ++i) {
        std::vector<Row> &rows = m_lists[static_cast<std::size_t>(i)].rows;
        int first = -1, last = -1;
        for (int k = 0; k < static_cast<int>(rows.size()); ++k) {
            Row &row = rows[static_cast<std::size_t>(k)];
            const Row old = row;
            derive(row, lists[static_cast<std::size_t>(i)]);
            if (row.symbol != old.symbol || row.comment != old.comment ||
                row.format != old.format || row.box != old.box) {
                first = first < 0 ? k : first;
                last = k;
            }
        }
        if (first >= 0)
            emit dataChanged(index(first, SymbolColumn, index(i, 0)),
                             index(last, ForceColumn, index(i, 0)));
    }
    tellWatched();
}

void WatchListModel::followRows(int list, const model::WatchList &now) {
    std::vector<Row> &rows = m_lists[static_cast<std::size_t>(list)].rows;
    QStringList devices;
    for (const Row &row : rows)
        devices << row.device;
    if (devices == now.devices)
        return;
    patch(
        index(list, 0), devices, now.devices,
        [&rows](int first, int last) { rows.erase(rows.begin() + first, rows.begin() + last + 1); },
        [&](int first, int last) {
            for (int k = first; k <= last; ++k) {
                Row row = makeRow(now.devices[k]);
                derive(row, now);
                rows.insert(rows.begin() + k, std::move(row));
            }
        });
}

bool WatchListModel::addDevices(const QStringList &texts, int list) {
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
    if (lists.empty())
        lists.push_back(model::WatchList{tr("Watch 1"), {}, {}});
    const int last = static_cast<int>(lists.size()) - 1;
    model::WatchList &watch = lists[static_cast<std::size_t>(std::clamp(list, 0, last))];
    QStringList added;
    for (const QString &device : devices)
        if (!watch.devices.contains(device) && !added.contains(device))
            added << device;
    if (added.isEmpty())
        return true;
    watch.devices << added;
    const QString what = added.size() == 1
                             ? added.front()
                             : QStringLiteral("%1..%2").arg(added.front(), added.back());
    m_document->setWatchLists(lists, tr("Add %1 to the watch list").arg(what));
    return true;
}

void WatchListModel::removeDevices(const QModelIndexList &indexes) {
    std::set<std::pair<int, int>> rows; // (list, row)
    for (const QModelIndex &index : indexes)
        if (isDevice(index))
            rows.insert({listOf(index), index.row()});
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    QStringList removed;
    for (auto it = rows.rbegin(); it != rows.rend(); ++it) {
        const auto [list, row] = *it;
        if (list >= static_cast<int>(lists.size()))
            continue;
        model::WatchList &l = lists[static_cast<std::size_t>(list)];
        removed.prepend(l.devices[row]);
        l.formats.erase(l.devices[row]);
        l.devices.removeAt(row);
    }
    if (removed.isEmpty())
        return;
    m_document->setWatchLists(
        lists,
        tr("Remove %1 from the watch list")
            .arg(removed.size() == 1 ? removed.front() : removed.join(QStringLiteral(", "))));
}

void WatchListModel::setFormat(const QModelIndex &index, model::ValueFormat f) {
    const Row *row = rowAt(index);
    const int list = listOf(index);
    std::vector<model::WatchList> lists = m_document->project().watchLists;
    if (!row || f == row->format || list >= static_cast<int>(lists.size()))
        return;
    const QString device = row->device;
    lists[static_cast<std::size_t>(list)].formats[device] = f;
    m_document->setWatchLists(lists, tr("Show %1 as %2").arg(device, model::valueFormatName(f)));
}

} // namespace rung::editor
