#include "network_traffic_model.h"

#include <QBrush>
#include <QColor>
#include <QFontDatabase>

namespace rung::app {

using network::DecodedFrame;

NetworkTrafficModel::NetworkTrafficModel(QObject *parent)
    : QAbstractTableModel(parent) {}

NetworkTrafficModel::~NetworkTrafficModel() = default;

void NetworkTrafficModel::setNetwork(const network::Network &network) {
    beginResetModel();
    m_decoder = std::make_unique<network::TrafficDecoder>(network);
    m_rows.clear();
    m_dropped = 0;
    m_firstId = 0;
    m_lastRequest.clear();
    endResetModel();
}

void NetworkTrafficModel::clear() {
    beginResetModel();
    m_rows.clear();
    m_dropped = 0;
    m_firstId = 0;
    m_lastRequest.clear();
    if (m_decoder)
        m_decoder->reset();
    endResetModel();
}

void NetworkTrafficModel::retranslate() {
    if (m_decoder && !m_rows.empty()) {
        m_decoder->reset();
        std::map<QString, std::size_t> last;
        for (std::size_t i = 0; i < m_rows.size(); ++i) {
            Row &row = m_rows[i];
            row.frame = m_decoder->decode(row.record);
            const auto it = last.find(row.record.wire);
            if (row.frame.previousUnanswered && it != last.end() &&
                m_rows[it->second].frame.problem.isEmpty())
                m_rows[it->second].frame.problem = network::TrafficDecoder::noReplyText();
            if (row.frame.kind == DecodedFrame::Kind::Request)
                last[row.record.wire] = i;
        }
        emit dataChanged(index(0, 0), index(int(m_rows.size()) - 1, ColumnCount - 1));
    }
    emit headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

void NetworkTrafficModel::setMaxRows(int rows) {
    m_maxRows = std::max(1, rows);
    if (int(m_rows.size()) > m_maxRows)
        dropOldest(int(m_rows.size()) - m_maxRows);
}

void NetworkTrafficModel::dropOldest(int rows) {
    beginRemoveRows({}, 0, rows - 1);
    m_rows.erase(m_rows.begin(), m_rows.begin() + rows);
    endRemoveRows();
    m_firstId += rows;
    m_dropped += rows;
    emit rowsDropped(m_dropped);
}

NetworkTrafficModel::Row NetworkTrafficModel::decodeRow(network::TrafficRecord record) const {
    Row row;
    row.frame = m_decoder ? m_decoder->decode(record) : DecodedFrame{};
    row.owners << (m_decoder ? m_decoder->ownerOf(record.sender) : record.sender);
    for (const QString &end : row.frame.receiver.split(QStringLiteral(", "), Qt::SkipEmptyParts))
        if (const QString owner = m_decoder ? m_decoder->ownerOf(end) : end;
            !row.owners.contains(owner))
            row.owners << owner;
    row.record = std::move(record);
    return row;
}

void NetworkTrafficModel::append(std::vector<network::TrafficRecord> records) {
    if (records.empty())
        return;
    // Every record is decoded, in order, even those the cap lets go at once: a reply is read
    // against the request before it.
    const qint64 firstNew = m_firstId + qint64(m_rows.size());
    std::vector<Row> rows;
    rows.reserve(records.size());
    std::vector<qint64> marked; // rows already shown that turned out unanswered
    const auto markUnanswered = [](DecodedFrame &f) {
        if (f.problem.isEmpty())
            f.problem = network::TrafficDecoder::noReplyText();
    };
    for (network::TrafficRecord &r : records) {
        const qint64 id = firstNew + qint64(rows.size());
        rows.push_back(decodeRow(std::move(r)));
        const Row &row = rows.back();
        const auto last = m_lastRequest.find(row.record.wire);
        if (row.frame.previousUnanswered && last != m_lastRequest.end()) {
            if (last->second >= firstNew) {
                markUnanswered(rows[std::size_t(last->second - firstNew)].frame);
            } else if (last->second >= m_firstId) {
                markUnanswered(m_rows[std::size_t(last->second - m_firstId)].frame);
                marked.push_back(last->second);
            }
        }
        if (row.frame.kind == DecodedFrame::Kind::Request)
            m_lastRequest[row.record.wire] = id;
    }
    const qint64 excessNew = qint64(rows.size()) - m_maxRows;
    if (excessNew > 0) {
        rows.erase(rows.begin(), rows.begin() + excessNew);
        m_dropped += excessNew;
    }
    const int overflow = int(m_rows.size() + rows.size()) - m_maxRows;
    if (overflow > 0)
        dropOldest(overflow); // emits with the new rows let go counted too
    else if (excessNew > 0)
        emit rowsDropped(m_dropped);
    if (excessNew > 0)
        m_firstId += excessNew; // every old row went too: the first kept is a new one
    for (qint64 id : marked)
        if (id >= m_firstId && id < m_firstId + qint64(m_rows.size())) {
            const int row = int(id - m_firstId);
            emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
        }
    const int first = int(m_rows.size());
    beginInsertRows({}, first, first + int(rows.size()) - 1);
    for (Row &row : rows)
        m_rows.push_back(std::move(row));
    endInsertRows();
}

QString NetworkTrafficModel::timeText(qint64 us) {
    return QStringLiteral("%1.%2.%3")
        .arg(us / 1'000'000)
        .arg(us / 1000 % 1000, 3, 10, QLatin1Char('0'))
        .arg(us % 1000, 3, 10, QLatin1Char('0'));
}

int NetworkTrafficModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int NetworkTrafficModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QString NetworkTrafficModel::text(int row, int column) const {
    const Row &r = m_rows[std::size_t(row)];
    const DecodedFrame &f = r.frame;
    switch (column) {
    case Time:
        return timeText(r.record.startUs);
    case Wire:
        return r.record.wire;
    case Sender:
        return r.record.sender;
    case Receiver:
        return f.receiver;
    case Protocol:
        return f.protocol;
    case Station:
        return f.station >= 0 ? QString::number(f.station) : QString();
    case Command:
        if (f.commandText.isEmpty())
            return {};
        // The arrow says which way: a request goes to the slave, a reply comes back.
        return (f.kind == DecodedFrame::Kind::Reply ? QStringLiteral("\u2190 ")
                                                    : QStringLiteral("\u2192 ")) +
               f.commandText;
    case Address:
        return f.address;
    case Count:
        return f.count >= 0 ? QString::number(f.count) : QString();
    case Data:
        return f.data;
    case Error:
        return f.errorCode >= 0 ? f.errorText : f.problem;
    case Note:
        return r.record.note;
    case Bytes:
        return QString::fromLatin1(r.record.bytes.toHex(' ').toUpper());
    default:
        return {};
    }
}

QVariant NetworkTrafficModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= int(m_rows.size()) || index.column() >= ColumnCount)
        return {};
    const Row &r = m_rows[std::size_t(index.row())];
    const DecodedFrame &f = r.frame;
    switch (role) {
    case Qt::DisplayRole:
        return text(index.row(), index.column());
    case Qt::ToolTipRole:
        switch (index.column()) {
        case Command:
            if (f.kind == DecodedFrame::Kind::Request)
                return tr("Request: %1").arg(f.commandText);
            if (f.kind == DecodedFrame::Kind::Reply)
                return tr("Reply: %1").arg(f.commandText);
            return {};
        case Error:
        case Note:
        case Data:
        case Bytes:
        case Receiver:
        case Address: {
            const QString t = text(index.row(), index.column());
            return t.isEmpty() ? QVariant() : QVariant(t);
        }
        default:
            return {};
        }
    case Qt::ForegroundRole:
        if (index.column() == Error && f.failed())
            return QBrush(QColor(0xB0, 0x00, 0x20));
        if (index.column() == Note && !r.record.note.isEmpty())
            return QBrush(QColor(0x9A, 0x4A, 0x00));
        return {};
    case Qt::BackgroundRole:
        // A fault or a collision changed the frame: the whole row says so.
        if (!r.record.note.isEmpty())
            return QBrush(QColor(0xFF, 0xE8, 0xCC));
        if (f.failed())
            return QBrush(QColor(0xFF, 0xE4, 0xE4));
        return {};
    case Qt::FontRole:
        if (index.column() == Bytes || index.column() == Time)
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        return {};
    case Qt::TextAlignmentRole:
        if (index.column() == Time || index.column() == Station || index.column() == Count)
            return int(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case StartUsRole:
        return r.record.startUs;
    case FailedRole:
        return f.failed() || !r.record.note.isEmpty();
    case OwnersRole:
        return r.owners;
    case WireRole:
        return r.record.wire;
    default:
        return {};
    }
}

QVariant NetworkTrafficModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || section < 0 || section >= ColumnCount)
        return {};
    if (role == Qt::ToolTipRole) {
        switch (section) {
        case Time:
            return tr("When the frame's first byte left: virtual time, seconds.milliseconds."
                      "microseconds");
        case Receiver:
            return tr("The station or device the frame is for; a reply's is the master");
        case Address:
            return tr("The address as the receiving PLC's device, with the address on the wire");
        case Count:
            return tr("Bytes (Computer Link), registers or bits (MODBUS), words, present values or "
                      "flags (Host Link), characters (text)");
        case Error:
            return tr("The PLC's error or exception code, or what is wrong with the frame");
        case Note:
            return tr("A fault or a collision that changed the frame");
        default:
            return {};
        }
    }
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case Time:
        return tr("Time (s)");
    case Wire:
        return tr("Wire");
    case Sender:
        return tr("Sender");
    case Receiver:
        return tr("Receiver");
    case Protocol:
        return tr("Protocol");
    case Station:
        return tr("Station");
    case Command:
        return tr("Command");
    case Address:
        return tr("Address");
    case Count:
        return tr("Count");
    case Data:
        return tr("Data");
    case Error:
        return tr("Error");
    case Note:
        return tr("Note");
    case Bytes:
        return tr("Bytes");
    default:
        return {};
    }
}

} // namespace rung::app
