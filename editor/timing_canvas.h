#pragma once

// The timing chart's drawing: a time axis, a row per channel (a bit as a step line, filled and
// heavy where ON; a word as a bus with its value in each segment), the trigger's marks, and
// two cursors. Draws into any painter, so PNG and SVG exports are the same drawing. The chart
// (timing_chart.h) owns the data and the view; the canvas turns mouse and wheel into requests.

#include "model/image/timing_data.h"

#include <QRectF>
#include <QWidget>

#include <optional>
#include <vector>

namespace rung::editor {

class TimingCanvas : public QWidget {
    Q_OBJECT

public:
    explicit TimingCanvas(QWidget *parent = nullptr);

    void setChannels(const std::vector<model::TimingChannel> *channels);
    void setWindow(model::TimingWindow window);
    // The right edge's time and the zoom (virtual milliseconds per pixel).
    void setView(qint64 endMs, double msPerPixel);
    qint64 endMs() const { return m_endMs; }
    double msPerPixel() const { return m_msPerPixel; }
    qint64 fromMs() const;                                       // the left edge's time
    int waveWidth() const;                                       // pixels the waves take
    void setCursorTime(int which, std::optional<qint64> timeMs); // 0: A, 1: B
    std::optional<qint64> cursorTime(int which) const { return m_cursor[which]; }
    void setPastMarks(std::vector<model::HistoryRecorder::Mark> marks);
    int selectedRow() const { return m_selected; }
    void setSelectedRow(int row);
    // What an empty chart says (the chart's hint, with the target's own devices).
    void setEmptyText(const QString &text) {
        m_emptyText = text;
        update();
    }

    // The whole drawing at this size (the widget's own, or an export's).
    void render(QPainter &painter, QSize size) const;
    // Where the ruler's numbers and the cursors' tags (their line across the ruler and their
    // letter) go when drawn at `size`; no number is drawn under a tag.
    std::vector<QRectF> rulerLabels(QSize size) const;
    std::vector<QRectF> cursorTags(QSize size) const;
    // The height every row needs: what an export takes.
    int contentHeight() const;

    QSize sizeHint() const override { return {600, 160}; }
    QSize minimumSizeHint() const override { return {200, 60}; }

signals:
    void cursorRequested(int which, qint64 timeMs);
    void zoomRequested(double factor, qint64 anchorMs);
    void scrollRequested(qint64 deltaMs);
    void rowMenuRequested(int row, const QPoint &globalPosition);
    void devicesDropped(const QStringList &devices);
    void removeRequested(int row);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dragMoveEvent(QDragMoveEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    int nameWidth() const;
    int rowTop(int row) const;
    int rowHeight(int row) const;
    int rowAt(int y) const;
    double xAt(qint64 timeMs, int left, int width, qint64 from) const;
    void paintAxis(QPainter &p, int left, int width, qint64 from, QSize size) const;
    void paintBit(QPainter &p, const QRect &r, std::size_t k, qint64 from) const;
    void paintWord(QPainter &p, const QRect &r, std::size_t k, qint64 from) const;

    const std::vector<model::TimingChannel> *m_channels = nullptr;
    model::TimingWindow m_window;
    std::vector<model::HistoryRecorder::Mark> m_pastMarks;
    qint64 m_endMs = 0;
    double m_msPerPixel = 10.0;
    std::optional<qint64> m_cursor[2];
    int m_selected = -1;
    int m_dragging = -1; // which cursor a drag moves
    QString m_emptyText;
};

} // namespace rung::editor
