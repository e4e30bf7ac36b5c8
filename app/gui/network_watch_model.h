#pragma once

// The watch table of a network: devices of any station, written STATION/DEVICE ("s5/D10"), so
// a user sees a value leave one PLC and arrive in another. Each row reads its station's latest
// snapshot; a value typed in a row is written to that station (a bit: 0 or 1). The values are
// told as dataChanged of the value column on the readers' beat, never a reset.

#include "model/image/monitor_source.h"
#include "model/target/target.h"

#include <QAbstractTableModel>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace rung::network {
class NetworkSession;
class StationSource;
} // namespace rung::network

namespace rung::app {

// A device as the network's tables take it, from its first station ("master/D0", the target's
// own example device); "STATION/DEVICE" without a network.
QString exampleStationDevice(const network::NetworkSession *session);

class NetworkWatchModel : public QAbstractTableModel {
    Q_OBJECT

public:
    enum Column { Device, Value, Station, ColumnCount };

    explicit NetworkWatchModel(QObject *parent = nullptr);

    // The stations the rows may name; rows of another session are dropped (said by the
    // caller: a new network is a new table).
    void setSession(network::NetworkSession *session);
    // Adds "STATION/DEVICE" (a device already listed is not added twice); false with what is
    // wrong (no slash, no such station: the stations named, no such device).
    bool addDevice(const QString &text, QString *error);
    void removeRow(int row);
    QStringList devices() const; // as written, "s5/D10"
    // The rows of `station` read `shown` in place of the station (its past while the network
    // window shows the history: network_history_controller.h); null: the station itself.
    // A value typed then goes to `shown`, which refuses it.
    void setShownSource(network::StationSource *station, model::MonitorSource *shown);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;

private:
    struct Row {
        QPointer<network::StationSource> station;
        QString device; // as the target writes it
        model::Address address;
        bool bit = false;
    };
    void refreshValues();
    model::MonitorSource *source(const Row &row) const;

    QPointer<network::NetworkSession> m_session;
    std::vector<Row> m_rows;
    std::vector<std::pair<QPointer<network::StationSource>, QPointer<model::MonitorSource>>>
        m_shown;
    QTimer m_beat; // coalesces the stations' snapshots into one repaint a beat
};

} // namespace rung::app
