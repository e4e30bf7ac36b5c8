#include "app/gui/network_view.h"

#include "app/gui/network_bridge_dialog.h"
#include "app/gui/network_document.h"
#include "app/gui/network_port_dialog.h"
#include "app/gui/network_station_dialog.h"

#include "model/comm/port_config.h"
#include "model/target/target.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <QWheelEvent>

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
    explicit NetworkCanvas(NetworkView *view)
        : QWidget(view)
        , m_view(view) {
        setMouseTracking(true);
        setFocusPolicy(Qt::NoFocus);
        setAttribute(Qt::WA_OpaquePaintEvent);
    }
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
    QPointF unzoomed(QPoint p) const { return QPointF(p) / m_view->zoom(); }
    NetworkView *m_view;
    NetworkLayout m_layout;
    QString m_dragFrom;
    QPointF m_dragTo;
    QPoint m_pressAt;
    bool m_dragging = false;
};

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
                const bool numbered = a.answersVigorLink || a.answersModbus || a.sharedLink == 1;
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
        // Wrapped to the boxes' width (at least 700), whole: the user wrote it.
        double boxesWidth = 0;
        for (const auto &box : l.boxes) {
            double width = kNetMinBoxWidth;
            for (const QString &h : box.head)
                width = std::max(width, fmBold.horizontalAdvance(h) + 2 * kNetPad);
            boxesWidth += width + kNetGap;
        }
        const double width = std::max(700.0, boxesWidth);
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

NetworkView::NetworkView(NetworkDocument *document, QWidget *parent)
    : QScrollArea(parent)
    , m_document(document)
    , m_canvas(new NetworkCanvas(this)) {
    setWidget(m_canvas);
    setWidgetResizable(false);
    setFocusPolicy(Qt::StrongFocus);
    setBackgroundRole(QPalette::Base);
    connect(document, &NetworkDocument::changed, this, [this] {
        // What was selected may be gone (undo of an add, a removed station).
        if (!m_selection.isEmpty() && !m_selection.startsWith(QLatin1String("wire:")) &&
            !m_document->station(m_selection.section(QLatin1Char('/'), 0, 0))) {
            bool device = false;
            for (const auto &v : m_document->description().devices)
                device = device || v.name == m_selection;
            if (!device)
                select({});
        }
        m_canvas->relayout();
    });
    connect(document, &NetworkDocument::filePathChanged, this, [this] { m_canvas->relayout(); });
    m_canvas->relayout();
}

QWidget *NetworkView::canvas() const {
    return m_canvas;
}

void NetworkView::setZoom(double zoom) {
    m_zoom = std::clamp(zoom, 0.5, 3.0);
    m_canvas->relayout();
}

void NetworkView::zoomIn() {
    setZoom(m_zoom * 1.25);
}
void NetworkView::zoomOut() {
    setZoom(m_zoom / 1.25);
}

void NetworkView::select(const QString &item) {
    if (item == m_selection)
        return;
    m_selection = item;
    m_canvas->update();
    emit selectionChanged(item);
    const QString station = selectedStation();
    if (!station.isEmpty() || item.isEmpty())
        emit stationSelected(station);
}

QString NetworkView::selectedStation() const {
    const QString name = m_selection.section(QLatin1Char('/'), 0, 0);
    return !m_selection.startsWith(QLatin1String("wire:")) && m_document->station(name) ? name
                                                                                        : QString();
}

QRect NetworkView::itemRect(const QString &item) const {
    for (const auto &box : m_canvas->layout().boxes)
        if (box.name == item)
            return QRectF(box.rect.topLeft() * m_zoom, box.rect.size() * m_zoom).toRect();
    return {};
}

QPoint NetworkView::endPoint(const QString &end) const {
    for (const auto &box : m_canvas->layout().boxes)
        for (const auto &row : box.rows)
            if (row.end == end)
                return (row.rect.center() * m_zoom).toPoint();
    return {-1, -1};
}

QString NetworkView::itemAt(const QPoint &canvasPoint) const {
    return m_canvas->itemAt(QPointF(canvasPoint) / m_zoom);
}

void NetworkView::refuse(const QString &why) {
    emit editRefused(why);
    if (!m_quiet)
        QMessageBox::warning(this, tr("Network"), why);
}

void NetworkView::removeSelected(bool confirm) {
    QString why;
    if (m_selection.startsWith(QLatin1String("wire:"))) {
        if (!m_document->removeWire(m_selection.mid(5), &why))
            refuse(why);
        return;
    }
    if (m_selection.contains(QLatin1Char('/'))) {
        if (!m_document->disconnectEnd(m_selection, &why))
            refuse(why);
        return;
    }
    if (!m_document->station(m_selection)) {
        if (!m_selection.isEmpty())
            refuse(tr("%1 is a simulated device: edit it in the network file").arg(m_selection));
        return;
    }
    const QStringList also = m_document->removalConsequences(m_selection);
    if (confirm && !also.isEmpty() &&
        QMessageBox::question(
            this, tr("Remove Station"),
            tr("Remove station %1? With it:\n%2\n(Edit > Undo brings it back.)")
                .arg(m_selection, QStringLiteral("- ") + also.join(QStringLiteral("\n- "))),
            QMessageBox::Yes | QMessageBox::Cancel) != QMessageBox::Yes)
        return;
    if (!m_document->removeStation(m_selection, &why))
        refuse(why);
}

void NetworkView::editPort(const QString &end) {
    const QString station = end.section(QLatin1Char('/'), 0, 0);
    const QString port = end.section(QLatin1Char('/'), 1);
    const auto *s = m_document->station(station);
    if (!s)
        return;
    const NetworkStationInfo info = m_document->stationInfo(station);
    const auto edited =
        editPortSettings(this, *info.target, info.model, port, s->ports.value(port).toObject(),
                         info.projectPorts.value(port).toObject(), end);
    QString why;
    if (edited && !m_document->setPortSettings(station, port, *edited, &why))
        refuse(why);
}

void NetworkView::addStationFromProgram() {
    const QString file = QFileDialog::getOpenFileName(
        this, tr("Add Station from Program"), QFileInfo(m_document->filePath()).absolutePath(),
        tr("Programs (*.rung *.il *.ladder);;All files (*)"));
    if (file.isEmpty())
        return;
    QString why;
    const QString name = m_document->freeName(QFileInfo(file).completeBaseName());
    if (!m_document->addExistingProgram(name, file, QString(), QString(), &why))
        refuse(why);
    else
        select(name);
}

void NetworkView::addNewProjectStation() {
    NetworkStationDialog dialog(m_document, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    QString why;
    if (!m_document->addNewProject(dialog.name(), dialog.file(), dialog.target(), dialog.model(),
                                   &why))
        refuse(why);
    else
        select(dialog.name());
}

void NetworkView::editPeriod() {
    bool ok = false;
    const int ms = QInputDialog::getInt(
        this, tr("Network Period"), tr("Scan period of the stations that give none (ms):"),
        int(m_document->description().periodMs), 1, 1000000, 1, &ok);
    QString why;
    if (ok && !m_document->setPeriod(ms, &why))
        refuse(why);
}

QString NetworkView::bridgeText(const QString &end) const {
    const network::BridgeDescription *b = m_document->bridgeOf(end);
    if (!b)
        return {};
    using K = network::BridgeDescription::Kind;
    const auto live = m_live.find(end);
    const QString reached = live == m_live.end() ? QString() : live->second.reached;
    if (live != m_live.end() && !live->second.error.isEmpty())
        //: a bridge whose line did not open; the tooltip says why
        return tr("bridge: failed (%1)").arg(b->kind == K::Pty ? tr("pseudo-terminal") : b->where);
    switch (b->kind) {
    case K::Pty:
        //: %1 the pseudo-terminal's path while the network runs
        return reached.isEmpty() ? tr("bridge: pseudo-terminal")
                                 : tr("bridge: pseudo-terminal %1").arg(reached);
    case K::Serial:
        return tr("bridge: serial %1").arg(b->where);
    case K::Tcp:
        return tr("bridge: TCP to %1").arg(b->where);
    case K::Listen:
        return tr("bridge: listens on %1").arg(reached.isEmpty() ? b->where : reached);
    }
    return {};
}

void NetworkView::setLiveBridges(std::map<QString, LiveBridge> live) {
    if (live.size() == m_live.size() &&
        std::equal(live.begin(), live.end(), m_live.begin(), [](const auto &a, const auto &b) {
            return a.first == b.first && a.second.reached == b.second.reached &&
                   a.second.error == b.second.error;
        }))
        return;
    m_live = std::move(live);
    m_canvas->relayout();
}

void NetworkView::editBridge(const QString &end,
                             std::optional<network::BridgeDescription::Kind> kind) {
    const QString station = end.section(QLatin1Char('/'), 0, 0);
    const QString port = end.section(QLatin1Char('/'), 1);
    const auto *s = m_document->station(station);
    if (!s)
        return;
    const NetworkStationInfo info = m_document->stationInfo(station);
    model::PortConfig config;
    QString why;
    if (!model::readPortConfig(*info.target, info.target->model(info.model), port,
                               {{m_document->effectivePortSettings(station, port), end}}, &config,
                               &why)) {
        refuse(why);
        return;
    }
    network::BridgeDescription bridge;
    bridge.end = end;
    if (const network::BridgeDescription *b = m_document->bridgeOf(end))
        bridge = *b;
    NetworkBridgeDialog dialog(bridge, *config.application, config.line,
                               s->ports.value(port).toObject(), this);
    if (kind)
        dialog.setKind(*kind);
    if (dialog.exec() != QDialog::Accepted)
        return;
    if (!m_document->setBridge(dialog.bridge(), dialog.portSettings(), &why))
        refuse(why);
}

void NetworkView::removeBridge(const QString &end) {
    QString why;
    if (!m_document->removeBridge(end, &why))
        refuse(why);
}

void NetworkView::addBridgeMenu(QMenu *menu, const QString &end) {
    using K = network::BridgeDescription::Kind;
    QMenu *bridges = menu->addMenu(tr("&Bridge To"));
    bridges->setObjectName(QStringLiteral("networkBridgeTo"));
    // A pseudo-terminal needs nothing more; the others ask where (network_bridge_dialog.h).
    bridges->addAction(tr("&Pseudo-terminal"), this, [this, end] {
        network::BridgeDescription b;
        b.end = end;
        QString why;
        if (!m_document->addBridge(b, &why))
            refuse(why);
    });
    bridges->addAction(tr("&Serial Port..."), this, [this, end] { editBridge(end, K::Serial); });
    bridges->addAction(tr("&TCP Device Server..."), this, [this, end] { editBridge(end, K::Tcp); });
    bridges->addAction(tr("TCP &Listen..."), this, [this, end] { editBridge(end, K::Listen); });
}

void NetworkView::contextMenuAt(const QPoint &canvasPoint, const QPoint &global) {
    const QString item = m_canvas->itemAt(canvasPoint);
    select(item);
    QMenu menu(this);
    const QString station = selectedStation();
    QString why;
    if (item.contains(QLatin1Char('/'))) {
        menu.addAction(tr("Port &Settings..."), this, [this, item] { editPort(item); });
        if (m_document->wireOf(item))
            menu.addAction(tr("&Disconnect"), this, [this, item] {
                QString why;
                if (!m_document->disconnectEnd(item, &why))
                    refuse(why);
            });
        bool bridged = false;
        for (const auto &b : m_document->description().bridges)
            bridged = bridged || b.end == item;
        if (bridged) {
            menu.addAction(tr("Edit &Bridge..."), this, [this, item] { editBridge(item); });
            if (const auto live = m_live.find(item);
                live != m_live.end() && !live->second.reached.isEmpty())
                menu.addAction(tr("&Copy %1").arg(live->second.reached), this,
                               [reached = live->second.reached] {
                                   QApplication::clipboard()->setText(reached);
                               });
            menu.addAction(tr("Remove Brid&ge"), this, [this, item] { removeBridge(item); });
        } else {
            addBridgeMenu(&menu, item);
        }
        menu.addSeparator();
    }
    if (item.startsWith(QLatin1String("wire:")))
        menu.addAction(tr("Remove &Wire"), this, [this] { removeSelected(); });
    if (!station.isEmpty()) {
        menu.addAction(tr("&Open Program"), this,
                       [this, station] { emit stationActivated(station); });
        menu.addAction(tr("&Remove Station %1...").arg(station), this, [this, station] {
            select(station);
            removeSelected();
        });
        menu.addSeparator();
    }
    menu.addAction(tr("Add Station from &Program..."), this, &NetworkView::addStationFromProgram);
    menu.addAction(tr("Add New Pro&ject Station..."), this, &NetworkView::addNewProjectStation);
    menu.addAction(tr("&Network Period..."), this, &NetworkView::editPeriod);
    menu.addSeparator();
    menu.addAction(tr("Zoom &In"), this, &NetworkView::zoomIn);
    menu.addAction(tr("Zoom O&ut"), this, &NetworkView::zoomOut);
    menu.exec(global);
}

void NetworkView::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        m_canvas->relayout();
    QScrollArea::changeEvent(event);
}

void NetworkView::keyPressEvent(QKeyEvent *event) {
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        removeSelected();
    } else if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) &&
               !selectedStation().isEmpty()) {
        emit stationActivated(selectedStation());
    } else if (ctrl && (event->key() == Qt::Key_Plus || event->key() == Qt::Key_Equal)) {
        zoomIn();
    } else if (ctrl && event->key() == Qt::Key_Minus) {
        zoomOut();
    } else if (ctrl && event->key() == Qt::Key_0) {
        setZoom(1.0);
    } else {
        QScrollArea::keyPressEvent(event);
        return;
    }
    event->accept();
}

void NetworkView::wheelEvent(QWheelEvent *event) {
    if (event->modifiers() & Qt::ControlModifier) {
        if (event->angleDelta().y() > 0)
            zoomIn();
        else if (event->angleDelta().y() < 0)
            zoomOut();
        event->accept();
        return;
    }
    QScrollArea::wheelEvent(event);
}

bool saveNetwork(QWidget *parent, NetworkDocument *document, const QString &file) {
    const QString to = file.isEmpty() ? document->filePath() : file;
    QStringList notKept;
    QString why;
    if (file.isEmpty() ? document->save(&notKept, &why) : document->saveAs(to, &notKept, &why))
        return true;
    if (!notKept.isEmpty()) {
        // Never write less than the user has without saying so and letting them choose.
        const auto answer = QMessageBox::warning(
            parent, NetworkView::tr("Save Network"),
            NetworkView::tr("%1 cannot hold everything in this network:\n%2\n\nSave anyway, "
                            "leaving this out of the file?")
                .arg(to, QStringLiteral("- ") + notKept.join(QStringLiteral("\n- "))),
            QMessageBox::Save | QMessageBox::Cancel, QMessageBox::Cancel);
        if (answer != QMessageBox::Save)
            return false;
        if (document->saveAs(to, &notKept, &why, true))
            return true;
    }
    QMessageBox::critical(parent, NetworkView::tr("Save Network"), why);
    return false;
}

} // namespace rung::app
