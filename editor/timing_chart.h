#pragma once

// The timing chart (a dock): a logic analyser over the simulated time of chosen bits and
// words, read from a MonitorSource's history (any origin: the simulation now, an online PLC
// later). Zoom (Ctrl+wheel, + / -), scroll (wheel, arrows, the bar), follow the newest scan,
// two cursors with the time between them (click: A, Shift+click or right click: B; each
// snaps to a scan), a trigger ("Y0 rises", "D10 > 100") evaluated by the source on every
// recorded scan that stops the simulation or marks the moment, and exports to CSV, PNG and
// SVG. Devices come in by typing (ranges too), or dragged from the ladder or the watch table.

#include "model/image/timing_data.h"

#include "model/image/monitor_source.h"

#include <QPointer>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QScrollBar;
class QToolButton;

namespace rung::editor {

class Document;
class TimingCanvas;

class TimingChart : public QWidget {
    Q_OBJECT

public:
    explicit TimingChart(Document *document, QWidget *parent = nullptr);

    void setMonitorSource(model::MonitorSource *source);
    model::MonitorSource *monitorSource() const { return m_source; }

    // Adds devices and ranges ("Y0", "D0..D3"); false, with message(), when one is none.
    bool addDevices(const QStringList &texts);
    void removeChannel(int index);
    const std::vector<model::TimingChannel> &channels() const { return m_channels; }
    TimingCanvas *canvas() const { return m_canvas; }

    // The view: newest time on the right edge while following.
    void setFollow(bool follow);
    bool follows() const { return m_follow; }
    void zoom(double factor, std::optional<qint64> anchorMs = std::nullopt);
    void setMsPerPixel(double msPerPixel);
    // The view centred on this time, following stopped (a failed scenario's instant).
    void centreOn(qint64 timeMs);
    // A cursor (0: A, 1: B) at the scan nearest this time; cursorMoved() follows.
    void placeCursor(int which, qint64 timeMs);

    // Arms the trigger typed in the field (or the given text); false, with message(), when it
    // is no condition or there is no source. Disarm with armTrigger({}).
    bool armTrigger(const QString &text, model::Trigger::Action action);
    void disarmTrigger();

    // Writes the chart: CSV (writeCsv), PNG or SVG (the drawing as it is, every row). False
    // with *error saying why (a file that cannot be written).
    bool exportTo(const QString &path, const QString &format, QString *error) const;

signals:
    void message(const QString &text);
    // The user put a cursor on this scan (virtual time at its end): the state of that past
    // scan can be shown.
    void cursorMoved(int which, quint64 scan, qint64 timeMs);
    // The user asked for an export in this format ("csv", "png", "svg"): the window asks for
    // the file (adding the extension, confirming a replace) and calls exportTo.
    void exportRequested(const QString &format);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslate();
    void refresh(); // a snapshot: the newest time, the window's data
    void applyView();
    void updateReadout();
    void updateScrollBar();
    void watchChannels();
    void rowMenu(int row, const QPoint &at);
    void triggered(quint64 scan, qint64 timeMs);
    qint64 snapToScan(qint64 timeMs) const;

    Document *m_document;
    const model::Target *m_hintsTarget = nullptr; // whose devices the hints show
    QPointer<model::MonitorSource> m_source;
    std::vector<model::TimingChannel> m_channels;
    TimingCanvas *m_canvas;
    QScrollBar *m_scroll;
    QLineEdit *m_add;
    QToolButton *m_zoomIn;
    QToolButton *m_zoomOut;
    QToolButton *m_fit;
    QCheckBox *m_followBox;
    QToolButton *m_export;
    QLineEdit *m_trigger;
    QComboBox *m_triggerAction;
    QPushButton *m_arm;
    QLabel *m_readout;
    bool m_follow = true;
    double m_msPerPixel = 10.0;
    qint64 m_endMs = 0;
    qint64 m_latestMs = 0;
    quint64 m_latestScan = 0;
    qint64 m_periodMs = 10;
    qint64 m_earliestMs = 0;
    std::optional<model::Trigger> m_armed;
    QString m_triggerStatus;
    bool m_scrolling = false;
};

} // namespace rung::editor
