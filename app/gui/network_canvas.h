#pragma once

// The drawing of the Network view (network_view.h): where each station's box, its ports' rows,
// the simulated devices and the wires' buses go (NetworkLayout, at zoom 1), painted, and what
// the mouse does on them (select, drag a wire from port to port, double-click a station, the
// context menu); the edits themselves are the view's.

#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QStringList>
#include <QWidget>

#include <utility>
#include <vector>

namespace rung::app {

class NetworkView;

// What is drawn where, at zoom 1.
struct NetworkLayout {
    struct Row {
        QString end;      // "station/PORT" or a device's name
        QStringList text; // its lines
        QString bridge;   // "" : none
        bool set = true;  // the port's settings name it (else: the defaults, drawn lighter)
        bool problem = false;
        QString tip;
        QRectF rect;
        QPointF anchor;
    };
    struct Box {
        QString name;
        bool device = false;
        QStringList head; // name, then the lines under it
        bool problem = false;
        QRectF rect;
        std::vector<Row> rows;
    };
    struct Bus {
        QString wire;
        double y = 0;
        std::vector<std::pair<QPointF, double>> drops; // an anchor and its drop's x
        bool framed = true; // false: CPU Link / Parallel Link, no frames (dashed)
    };
    QStringList title;
    QRectF titleRect;
    QString comment; // the network's comment, wrapped under the title
    QRectF commentRect;
    std::vector<Box> boxes;
    std::vector<Bus> buses;
    QSizeF size;
};

class NetworkCanvas : public QWidget {
public:
    explicit NetworkCanvas(NetworkView *view);
    void relayout();
    const NetworkLayout &layout() const { return m_layout; }
    QString itemAt(QPointF p) const; // p at zoom 1

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void contextMenuEvent(QContextMenuEvent *event) override;
    bool event(QEvent *event) override;

private:
    QPointF unzoomed(QPoint p) const;
    NetworkView *m_view;
    NetworkLayout m_layout;
    QString m_dragFrom;
    QPointF m_dragTo;
    QPoint m_pressAt;
    bool m_dragging = false;
};

} // namespace rung::app
