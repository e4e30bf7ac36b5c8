#include "app/gui/network_canvas.h"

#include "app/gui/network_document.h"
#include "app/gui/network_view.h"

#include "model/comm/port_config.h"
#include "model/target/target.h"

#include <QContextMenuEvent>
#include <QCoreApplication>
#include <QFileInfo>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <QToolTip>

#include <algorithm>

namespace rung::app {

namespace {

constexpr double kNetMargin = 16;
constexpr double kNetGap = 72;     // between boxes: room for the wires' drops
constexpr double kNetPad = 8;      // inside a box
constexpr double kNetBusStep = 24; // between two wires' buses
constexpr double kNetMinBoxWidth = 200;

QString applicationName(const model::PortApplication *a) {
    return a ? QCoreApplication::translate("rung::model::Target", a->name) : QString();
}

} // namespace

NetworkCanvas::NetworkCanvas(NetworkView *view)
    : QWidget(view)
    , m_view(view) {
    setMouseTracking(true);
    setFocusPolicy(Qt::NoFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

QPointF NetworkCanvas::unzoomed(QPoint p) const {
    return QPointF(p) / m_view->zoom();
}

void NetworkCanvas::relayout() {
    const NetworkDocument &doc = *m_view->document();
    const auto &d = doc.description();
    NetworkLayout l;
    QFont bold = font();
    bold.setBold(true);
    const QFontMetricsF fm(font());
    const QFontMetricsF fmBold(bold);
    const double line = fm.height();

    l.title << NetworkView::tr("%1: scan period %2 ms").arg(doc.displayName()).arg(d.periodMs);
    if (d.comment.isString())
        l.comment = d.comment.toString();

    // The boxes' contents.
    for (const auto &s : d.stations) {
        NetworkLayout::Box box;
        box.name = s.name;
        const NetworkStationInfo info = doc.stationInfo(s.name);
        box.head << s.name << QStringLiteral("%1 %2").arg(info.target->displayName, info.model)
                 << QFileInfo(s.program).fileName();
        if (s.periodMs > 0)
            box.head << NetworkView::tr("scan period %1 ms").arg(s.periodMs);
        if (!info.problem.isEmpty()) {
            box.head << NetworkView::tr("program not readable");
            box.problem = true;
        }
        const model::ModelVariant *variant = info.target->model(info.model);
        for (const QString &port : doc.stationPorts(s.name)) {
            NetworkLayout::Row row;
            row.end = s.name + QLatin1Char('/') + port;
            row.set =
                s.ports.contains(port) || info.projectPorts.contains(port) || doc.wireOf(row.end);
            model::PortConfig config;
            QString why;
            if (model::readPortConfig(*info.target, variant, port,
                                      {{doc.effectivePortSettings(s.name, port), row.end}}, &config,
                                      &why)) {
                row.text << QStringLiteral("%1  %2").arg(port, applicationName(config.application));
                // A station number means something where the port answers or links; a
                // master's or a program's port has none.
                const model::PortApplication &a = *config.application;
                const bool numbered = a.answers || a.sharedLink == 1;
                QString second = numbered ? NetworkView::tr("station %1, %2 %3")
                                                .arg(config.station)
                                                .arg(config.line.baud)
                                                .arg(model::frameFormatText(config.line))
                                          : QStringLiteral("%1 %2")
                                                .arg(config.line.baud)
                                                .arg(model::frameFormatText(config.line));
                if (config.application->sharedLink == 1 && config.station == 0)
                    second += NetworkView::tr(", %1 slaves, range %2")
                                  .arg(config.slaves)
                                  .arg(config.range);
                if (config.application->sharedLink == 2)
                    second +=
                        QStringLiteral(", ") + (config.parallelMaster ? NetworkView::tr("master")
                                                                      : NetworkView::tr("slave"));
                row.text << second;
            } else {
                row.text << port << NetworkView::tr("settings refused");
                row.problem = true;
                row.tip = why;
            }
            row.bridge = m_view->bridgeText(row.end);
            if (const auto live = m_view->liveBridges().find(row.end);
                live != m_view->liveBridges().end() && !live->second.error.isEmpty()) {
                row.problem = true;
                row.tip = live->second.error;
            }
            box.rows.push_back(row);
        }
        l.boxes.push_back(box);
    }
    for (const auto &v : d.devices) {
        NetworkLayout::Box box;
        box.name = v.name;
        box.device = true;
        const bool modbus = v.kind == QLatin1String("modbus-slave");
        box.head << v.name
                 << (modbus ? NetworkView::tr("MODBUS slave (simulated)")
                            : NetworkView::tr("serial line (simulated)"));
        NetworkLayout::Row row;
        row.end = v.name;
        const QString line =
            QStringLiteral("%1 %2")
                .arg(v.json.value(QStringLiteral("baud")).toInt(19200))
                .arg(v.json.value(QStringLiteral("frame")).toString(QStringLiteral("8N1")));
        row.text << (modbus ? NetworkView::tr("station %1, %2")
                                  .arg(v.json.value(QStringLiteral("station")).toInt())
                                  .arg(line)
                            : line);
        box.rows.push_back(row);
        l.boxes.push_back(box);
    }

    // Sizes and places: one row of boxes, left to right, under the title.
    double x = kNetMargin;
    double top = kNetMargin;
    const double titleWidth = fmBold.horizontalAdvance(l.title.front());
    top += line * 1.6;
    if (!l.comment.isEmpty()) {
        // Wrapped, whole (the user wrote it), to the view's width or the boxes', whichever is
        // wider, so that it reads without scrolling sideways where the boxes do.
        double boxesWidth = 0;
        for (const auto &box : l.boxes) {
            double width = kNetMinBoxWidth;
            for (const QString &h : box.head)
                width = std::max(width, fmBold.horizontalAdvance(h) + 2 * kNetPad);
            boxesWidth += width + kNetGap;
        }
        const double width =
            std::max({320.0, boxesWidth - kNetGap, m_view->textWidth() - 2 * kNetMargin});
        const QRectF bounds =
            fm.boundingRect(QRectF(kNetMargin, top, width, 1e6), Qt::TextWordWrap, l.comment);
        l.commentRect = QRectF(kNetMargin, top, width, bounds.height());
        top += bounds.height() + line * 0.8;
    }
    double bottom = top;
    for (auto &box : l.boxes) {
        double width = kNetMinBoxWidth;
        for (const QString &h : box.head)
            width = std::max(width, fmBold.horizontalAdvance(h) + 2 * kNetPad);
        for (const auto &row : box.rows) {
            for (const QString &t : row.text)
                width = std::max(width, fm.horizontalAdvance(t) + 2 * kNetPad + 12);
            width = std::max(width, fm.horizontalAdvance(row.bridge) + 2 * kNetPad + 12);
        }
        double y = top + kNetPad + box.head.size() * line + kNetPad / 2;
        for (auto &row : box.rows) {
            const double h = (row.text.size() + (row.bridge.isEmpty() ? 0 : 1)) * line + kNetPad;
            row.rect = QRectF(x, y, width, h);
            row.anchor = QPointF(x + width, y + line * 0.5 + kNetPad / 2);
            y += h;
        }
        box.rect = QRectF(x, top, width, y - top + kNetPad / 2);
        bottom = std::max(bottom, box.rect.bottom());
        x += width + kNetGap;
    }
    l.titleRect = QRectF(kNetMargin, kNetMargin, titleWidth, line * 1.2);

    // The buses under the boxes; each wire's drops to the right of its ends' boxes.
    double busY = bottom + 2 * line;
    int index = 0;
    for (const auto &w : d.wires) {
        NetworkLayout::Bus bus;
        bus.wire = w.name;
        bus.y = busY;
        for (const QString &end : w.ends)
            for (const auto &box : l.boxes)
                for (const auto &row : box.rows)
                    if (row.end == end)
                        bus.drops.push_back({row.anchor, row.anchor.x() + 12 + 9 * (index % 6)});
        for (const QString &end : w.ends)
            if (end.contains(QLatin1Char('/'))) {
                const QString station = end.section(QLatin1Char('/'), 0, 0);
                const NetworkStationInfo info = doc.stationInfo(station);
                model::PortConfig config;
                QString why;
                const QString port = end.section(QLatin1Char('/'), 1);
                if (model::readPortConfig(*info.target, info.target->model(info.model), port,
                                          {{doc.effectivePortSettings(station, port), end}},
                                          &config, &why) &&
                    !config.application->published)
                    bus.framed = false;
            }
        l.buses.push_back(bus);
        busY += kNetBusStep;
        ++index;
    }
    l.size = QSizeF(std::max({x - kNetGap + kNetMargin + 80, titleWidth + 2 * kNetMargin,
                              l.commentRect.right() + kNetMargin}),
                    (l.buses.empty() ? bottom : busY) + kNetMargin + line);
    m_layout = std::move(l);
    setFixedSize((m_layout.size * m_view->zoom()).toSize());
    update();
}

QString NetworkCanvas::itemAt(QPointF p) const {
    for (const auto &box : m_layout.boxes) {
        for (const auto &row : box.rows)
            if (row.rect.adjusted(0, 0, 8, 0).contains(p))
                return row.end;
        if (box.rect.contains(p))
            return box.name;
    }
    for (const auto &bus : m_layout.buses) {
        double x0 = 1e9, x1 = -1e9;
        for (const auto &[anchor, dropX] : bus.drops) {
            x0 = std::min(x0, dropX);
            x1 = std::max(x1, dropX);
            if (std::abs(p.x() - dropX) <= 4 && p.y() >= anchor.y() && p.y() <= bus.y)
                return QStringLiteral("wire:") + bus.wire;
        }
        if (std::abs(p.y() - bus.y) <= 4 && p.x() >= x0 - 8 && p.x() <= x1 + 4)
            return QStringLiteral("wire:") + bus.wire;
    }
    return {};
}

void NetworkCanvas::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(m_view->zoom(), m_view->zoom());
    const QPalette pal = palette();
    const QColor accent = pal.color(QPalette::Highlight);
    const QColor ink = pal.color(QPalette::Text);
    QColor faint = ink;
    faint.setAlphaF(0.55);
    const QColor wrong(0xb0, 0x00, 0x20);
    QFont bold = font();
    bold.setBold(true);
    const double line = QFontMetricsF(font()).height();
    const QString selected = m_view->selection();

    p.setFont(bold);
    p.setPen(ink);
    p.drawText(m_layout.titleRect, Qt::AlignLeft | Qt::AlignVCenter, m_layout.title.front());
    if (!m_layout.comment.isEmpty()) {
        p.setFont(font());
        p.setPen(faint);
        p.drawText(m_layout.commentRect, Qt::TextWordWrap, m_layout.comment);
    }

    for (const auto &bus : m_layout.buses) {
        const bool on = selected == QStringLiteral("wire:") + bus.wire;
        QPen pen(on ? accent : ink, on ? 3 : 1.6);
        if (!bus.framed)
            pen.setStyle(Qt::DashLine);
        p.setPen(pen);
        double x0 = 1e9, x1 = -1e9;
        for (const auto &[anchor, dropX] : bus.drops) {
            p.drawPolyline(QPolygonF{anchor, QPointF(dropX, anchor.y()), QPointF(dropX, bus.y)});
            x0 = std::min(x0, dropX);
            x1 = std::max(x1, dropX);
        }
        if (!bus.drops.empty())
            p.drawLine(QPointF(x0 - 8, bus.y), QPointF(x1, bus.y));
        p.setFont(font());
        // The wire's name left of its bus; a link without frames says so after it.
        const QString label =
            NetworkView::tr("dashed: no frames on the wire (the manual does not publish them)");
        p.drawText(QRectF(x0 - 8 - 400 - 6, bus.y - line / 2, 400, line),
                   Qt::AlignRight | Qt::AlignVCenter, bus.wire);
        if (!bus.framed)
            p.drawText(QRectF(x0, bus.y + 2, 2000, line), Qt::AlignLeft | Qt::AlignTop, label);
    }

    for (const auto &box : m_layout.boxes) {
        const bool on = selected == box.name;
        p.setPen(QPen(on ? accent : ink, on ? 2.5 : 1.2));
        p.setBrush(box.device ? pal.color(QPalette::AlternateBase) : pal.color(QPalette::Window));
        p.drawRoundedRect(box.rect, 6, 6);
        double y = box.rect.top() + kNetPad;
        for (qsizetype i = 0; i < box.head.size(); ++i) {
            p.setFont(i == 0 ? bold : font());
            p.setPen(box.problem && i == box.head.size() - 1 ? wrong : (i < 2 ? ink : faint));
            p.drawText(QRectF(box.rect.left() + kNetPad, y, box.rect.width() - 2 * kNetPad, line),
                       Qt::AlignLeft | Qt::AlignVCenter, box.head[i]);
            y += line;
        }
        p.setFont(font());
        for (const auto &row : box.rows) {
            const bool rowOn = selected == row.end && !box.device;
            p.setPen(QPen(faint, 0.8));
            p.drawLine(row.rect.topLeft() + QPointF(4, 0), row.rect.topRight() - QPointF(4, 0));
            if (rowOn)
                p.fillRect(row.rect.adjusted(2, 1, -2, -1),
                           pal.color(QPalette::Highlight).lighter(170));
            double ty = row.rect.top() + kNetPad / 2;
            for (qsizetype i = 0; i < row.text.size(); ++i) {
                p.setPen(row.problem ? wrong : (row.set ? ink : faint));
                p.drawText(
                    QRectF(row.rect.left() + kNetPad, ty, row.rect.width() - kNetPad - 12, line),
                    Qt::AlignLeft | Qt::AlignVCenter, row.text[i]);
                ty += line;
            }
            if (!row.bridge.isEmpty()) {
                p.setPen(accent.darker(130));
                p.drawText(
                    QRectF(row.rect.left() + kNetPad, ty, row.rect.width() - kNetPad - 12, line),
                    Qt::AlignLeft | Qt::AlignVCenter, row.bridge);
            }
            p.setPen(QPen(ink, 1.2));
            p.setBrush(m_view->document()->wireOf(row.end) ? ink : pal.color(QPalette::Base));
            p.drawEllipse(row.anchor, 4.5, 4.5);
        }
    }

    if (m_dragging) {
        for (const auto &box : m_layout.boxes)
            for (const auto &row : box.rows)
                if (row.end == m_dragFrom) {
                    p.setPen(QPen(accent, 2, Qt::DashLine));
                    p.drawLine(row.anchor, m_dragTo);
                }
    }
}

bool NetworkCanvas::event(QEvent *event) {
    if (event->type() == QEvent::ToolTip) {
        auto *help = static_cast<QHelpEvent *>(event);
        const QPointF at = unzoomed(help->pos());
        for (const auto &box : m_layout.boxes)
            for (const auto &row : box.rows)
                if (row.rect.contains(at) && !row.tip.isEmpty()) {
                    QToolTip::showText(help->globalPos(), row.tip, this);
                    return true;
                }
        QToolTip::hideText();
        return true;
    }
    return QWidget::event(event);
}

void NetworkCanvas::mousePressEvent(QMouseEvent *event) {
    m_view->setFocus();
    const QString item = itemAt(unzoomed(event->pos()));
    m_view->select(item);
    m_pressAt = event->pos();
    m_dragging = false;
    m_dragFrom.clear();
    if (event->button() == Qt::LeftButton && !item.isEmpty() &&
        !item.startsWith(QLatin1String("wire:"))) {
        for (const auto &box : m_layout.boxes)
            for (const auto &row : box.rows)
                if (row.end == item)
                    m_dragFrom = item;
    }
}

void NetworkCanvas::mouseMoveEvent(QMouseEvent *event) {
    if (m_dragFrom.isEmpty() || !(event->buttons() & Qt::LeftButton))
        return;
    if ((event->pos() - m_pressAt).manhattanLength() > 6)
        m_dragging = true;
    m_dragTo = unzoomed(event->pos());
    update();
}

void NetworkCanvas::mouseReleaseEvent(QMouseEvent *event) {
    if (m_dragging) {
        m_dragging = false;
        QString to = itemAt(unzoomed(event->pos()));
        // A device's box takes the wire anywhere on it.
        bool isEnd = false;
        for (const auto &box : m_layout.boxes)
            for (const auto &row : box.rows)
                isEnd = isEnd || row.end == to || (box.device && box.name == to);
        if (isEnd && to != m_dragFrom) {
            QString why;
            if (!m_view->document()->connectEnds(m_dragFrom, to, &why))
                m_view->refuse(why);
            else
                m_view->select(to);
        }
        update();
    }
    m_dragFrom.clear();
}

void NetworkCanvas::mouseDoubleClickEvent(QMouseEvent *event) {
    const QString item = itemAt(unzoomed(event->pos()));
    const QString station = item.section(QLatin1Char('/'), 0, 0);
    if (!item.startsWith(QLatin1String("wire:")) && m_view->document()->station(station))
        emit m_view->stationActivated(station);
}

void NetworkCanvas::contextMenuEvent(QContextMenuEvent *event) {
    m_view->contextMenuAt(unzoomed(event->pos()).toPoint(), event->globalPos());
}

} // namespace rung::app
