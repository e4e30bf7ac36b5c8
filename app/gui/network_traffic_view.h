#pragma once

// The Traffic view of a network (docs/network.md, "The Traffic view"): every frame on its
// wires with its virtual time, sender and receiver, decoded beside its bytes; a wire chooser,
// a filter by station and "errors only"; a frame chosen moves the timing chart's cursor
// (frameChosen); Save... writes the frames shown as CSV or as text (the form of
// `rungstudio-cli simulate --traffic`). Records come in batches (append) on the UI thread;
// the table is one view over a model, so 100,000 frames stay responsive.

#include "network/network.h"

#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTableView;

namespace rung::app {

class NetworkTrafficModel;
class NetworkTrafficFilter;

class NetworkTrafficView : public QWidget {
    Q_OBJECT

public:
    explicit NetworkTrafficView(QWidget *parent = nullptr);
    ~NetworkTrafficView() override;

    // The network whose traffic comes (its wires and stations for the choosers, its wiring
    // for the decoder); starts over with no frames. `file` names it in a saved text. Call it
    // while the network is not running.
    void setNetwork(const network::Network &network, const QString &file = {});
    // Frames as the network's traffic sink gave them, in order.
    void append(std::vector<network::TrafficRecord> records);
    void clear();

    NetworkTrafficModel *model() const { return m_model; }
    QTableView *table() const { return m_table; }

    // The filters as the choosers set them: an empty wire or station is all of them.
    void setWireFilter(const QString &wire);
    void setStationFilter(const QString &station);
    void setErrorsOnly(bool on);
    // Frames the filters let through.
    int shownRows() const;

    // The frames shown (the filters apply), as CSV or as the CLI's traffic text; false with
    // the reason (translated) in *error. Save... asks for a file and calls one of them.
    bool saveCsv(const QString &path, QString *error) const;
    bool saveText(const QString &path, QString *error) const;

protected:
    void changeEvent(QEvent *event) override;

signals:
    // The user chose a frame: its start on the virtual clock, for the timing chart's cursor.
    void frameChosen(qint64 startUs);

private:
    void save();
    void retranslate();
    void fitColumns();
    // Widens the columns the user has not sized by hand to the texts of the rows first..last
    // of the table, up to each column's cap; never narrows one.
    void growColumns(int first, int last);
    int columnCap(int column) const;
    void updateStatus();
    void chooserChanged();

    NetworkTrafficModel *m_model;
    NetworkTrafficFilter *m_filter;
    QComboBox *m_wire;
    QComboBox *m_station;
    QCheckBox *m_errorsOnly;
    QLabel *m_wireLabel;
    QLabel *m_stationLabel;
    QLabel *m_status;
    QPushButton *m_save;
    QTableView *m_table;
    QString m_file;
    bool m_follow = true;       // keep the newest frame in sight while the user is at the bottom
    bool m_sizing = false;      // the view itself sets a column's width
    std::vector<bool> m_byHand; // columns the user sized: the view leaves them
};

} // namespace rung::app
