#pragma once

// The timing chart of a network: bits and words of any station on one time axis ("s5/D10"
// beside "master/D0"), so a value is seen leaving one PLC and arriving in another, with the
// scans between. Each row reads its station's history (network_session.h: every station
// records the devices asked for, from the scan after it was asked); what ran before that, a
// row added after the fact reads from the network's history (network_history.h: every
// station's words at every slice, as far as it reaches back). The drawing is the single program's
// chart's canvas (editor/timing_canvas.h): zoom with Ctrl+wheel, scroll with the wheel, two
// cursors. Its trigger (STATION/CONDITION, "s2/D10 > 100") is the network's one trigger
// (network_debug_controller.h, also set by Simulation > Stop When...): the chart asks for it
// to be armed and shows what is armed; "Stop the network" pauses every station right after
// the scan in which it becomes true, cursor A on that moment; "Only mark" marks the moments.

#include "model/image/timing_data.h"
#include "model/image/trigger.h"

#include <QPointer>
#include <QWidget>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace rung::editor {
class TimingCanvas;
}
namespace rung::network {
class NetworkSession;
class StationSource;
} // namespace rung::network

namespace rung::app {

class NetworkChart : public QWidget {
    Q_OBJECT

public:
    explicit NetworkChart(QWidget *parent = nullptr);

    void setSession(network::NetworkSession *session);
    // Adds "STATION/DEVICE" (a device listed already is not added twice); false with the
    // reason in message().
    bool addDevice(const QString &text);
    void removeRow(int row);
    QStringList devices() const;
    editor::TimingCanvas *canvas() const { return m_canvas; }
    // The values drawn for a row, as the chart read them last (for the tests and the readout).
    const model::TimingWindow &window() const { return m_window; }
    void setFollow(bool follow);
    // Cursor A at this virtual time, the view centred on it, following stopped (a frame
    // chosen in the Traffic view).
    void placeCursor(qint64 timeMs);

    // The network's trigger as armed (empty: none): the field, the action and Arm show it.
    void showTrigger(const QString &condition, model::Trigger::Action action);
    // It became true after this scan (virtual time); `stopped`: the network paused there,
    // cursor A is put on it.
    void showTriggerFired(quint64 scan, qint64 timeMs, bool stopped);
    QLineEdit *triggerField() const { return m_trigger; }
    QComboBox *triggerAction() const { return m_triggerAction; }
    QPushButton *armButton() const { return m_arm; }
    // The readout under the chart: cursor A, the trigger.
    QString readoutText() const;

signals:
    void message(const QString &text);
    // The user put cursor A on this virtual time.
    void cursorMoved(qint64 timeMs);
    // Arm (or Enter in the field) and disarm: the window arms the network's trigger.
    void armRequested(const QString &condition, model::Trigger::Action action);
    void disarmRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh();
    // A row's values from before its station's recorder knew them, read from the network's
    // history as far as the recorder's first value (recorderFromMs, -1: none yet).
    struct Past {
        std::uint64_t generation = 0; // NetworkHistory::generation() it was read from
        qint64 throughUs = -1;        // the newest instant read
        qint64 throughMs = -1;        // the station's virtual time then
        std::vector<model::HistoryRecorder::Change> changes;
    };
    void readPast(std::size_t row, qint64 recorderFromMs);
    // The moments the armed condition became true before it was armed, read from the
    // network's history (the recorder marks those after): a marking trigger armed after the
    // fact marks what already happened too, at the history's slices.
    void readPastMarks();

    QPointer<network::NetworkSession> m_session;
    std::vector<model::TimingChannel> m_channels; // device "s5/D10"
    std::vector<QPointer<network::StationSource>> m_stations;
    std::vector<Past> m_past; // per row
    model::TimingWindow m_window;
    editor::TimingCanvas *m_canvas;
    QLineEdit *m_add;
    QCheckBox *m_follow;
    QLineEdit *m_trigger;
    QComboBox *m_triggerAction;
    QPushButton *m_arm;
    QLabel *m_readout;
    QString m_armed; // the condition armed ("" none)
    bool m_armedStops = true;
    std::vector<model::HistoryRecorder::Mark> m_pastMarks; // readPastMarks()
    std::uint64_t m_pastMarksGeneration = 0;
    QString m_triggerStatus; // "Armed: ...", or when it became true
    double m_msPerPixel = 10.0;
    qint64 m_endMs = 0;
};

} // namespace rung::app
