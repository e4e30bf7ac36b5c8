#pragma once

// The rows of the Traffic view (docs/network.md, "The Traffic view"): every transmission of a
// network with its virtual time, wire, sender and receiver, decoded (network/traffic_decode.h)
// beside its bytes. Records come in batches on the UI thread (append); the model keeps the
// last maxRows() of them and counts what it let go, so a view can say so.

#include "network/traffic_decode.h"

#include <QAbstractTableModel>

#include <deque>
#include <map>
#include <memory>
#include <vector>

namespace rung::app {

class NetworkTrafficModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column {
        Time,
        Wire,
        Sender,
        Receiver,
        Protocol,
        Station,
        Command,
        Address,
        Count,
        Data,
        Error,
        Note,
        Bytes,
        ColumnCount
    };
    enum Role {
        StartUsRole = Qt::UserRole + 1, // qint64: the frame's start on the virtual clock
        FailedRole,                     // bool: an error code, a problem or a fault's note
        OwnersRole,                     // QStringList: the sender's and receivers' stations
        WireRole,                       // QString: the wire's name
    };
    static constexpr int DefaultMaxRows = 100'000;

    explicit NetworkTrafficModel(QObject *parent = nullptr);
    ~NetworkTrafficModel() override;

    // Learns the network's wiring for the decoder and starts over with no rows. Call it
    // while the network is not running (after Network::build).
    void setNetwork(const network::Network &network);
    // Decodes the records in order and adds them; beyond maxRows() the oldest rows go.
    void append(std::vector<network::TrafficRecord> records);
    void clear();
    // Decodes the rows kept again, in the language now installed (a language switch); the
    // notes stay as the network wrote them.
    void retranslate();

    void setMaxRows(int rows);
    int maxRows() const { return m_maxRows; }
    // Rows let go since the last setNetwork() / clear() to stay within maxRows().
    qint64 droppedRows() const { return m_dropped; }

    const network::TrafficRecord &record(int row) const { return m_rows[std::size_t(row)].record; }
    const network::DecodedFrame &decoded(int row) const { return m_rows[std::size_t(row)].frame; }

    // "1.234.567": seconds, milliseconds, microseconds of virtual time.
    static QString timeText(qint64 us);
    // The cell's text as the table shows it (CSV writes the same).
    QString text(int row, int column) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

signals:
    // Older rows were let go; total since the last start over.
    void rowsDropped(qint64 total);

private:
    struct Row {
        network::TrafficRecord record;
        network::DecodedFrame frame;
        QStringList owners;
    };
    void dropOldest(int rows);
    Row decodeRow(network::TrafficRecord record) const;

    // Rows are numbered from the start (an id); m_firstId is the first kept row's. The last
    // request of each wire, by id: a request that comes while it is unanswered marks it.
    qint64 m_firstId = 0;
    std::map<QString, qint64> m_lastRequest;

    std::unique_ptr<network::TrafficDecoder> m_decoder;
    std::deque<Row> m_rows;
    int m_maxRows = DefaultMaxRows;
    qint64 m_dropped = 0;
};

} // namespace rung::app
