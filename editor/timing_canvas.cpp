#include "timing_canvas.h"

#include "device_mime.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rung::editor {

namespace {

constexpr int kAxisHeight = 20;
constexpr int kBitRow = 24;
constexpr int kWordRow = 26;

const QColor kHigh(0x2e, 0x7d, 0x32);   // a bit's ON (also filled: not colour alone)
const QColor kMark(0x8e, 0x24, 0xaa);   // trigger marks
const QColor kCursor(0x15, 0x65, 0xc0); // cursors A and B

// A tick step of 1, 2 or 5 times a power of ten milliseconds, at least minMs apart.
qint64 niceStep(double minMs) {
    qint64 step = 1;
    for (;;) {
        for (const qint64 k : {1, 2, 5})
            if (static_cast<double>(step * k) >= minMs)
                return step * k;
        step *= 10;
    }
}

QString timeText(qint64 ms, qint64 step) {
    if (step >= 1000 && ms % 1000 == 0)
        return QStringLiteral("%1 s").arg(ms / 1000);
    const int decimals = step >= 100 ? 1 : step >= 10 ? 2 : 3;
    return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', decimals);
}

} // namespace

TimingCanvas::TimingCanvas(QWidget *parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("timingCanvas"));
    setAcceptDrops(true);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(false);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void TimingCanvas::setChannels(const std::vector<model::TimingChannel> *channels) {
    m_channels = channels;
    // Every row drawn: the chart's scroll area scrolls them when the dock is low.
    setMinimumHeight(std::max(60, contentHeight()));
    updateGeometry();
    update();
}

void TimingCanvas::setWindow(model::TimingWindow window) {
    m_window = std::move(window);
    update();
}

void TimingCanvas::setView(qint64 endMs, double msPerPixel) {
    m_endMs = endMs;
    m_msPerPixel = msPerPixel;
    update();
}

void TimingCanvas::setPastMarks(std::vector<model::HistoryRecorder::Mark> marks) {
    m_pastMarks = std::move(marks);
    update();
}

void TimingCanvas::setCursorTime(int which, std::optional<qint64> timeMs) {
    m_cursor[which] = timeMs;
    update();
}

void TimingCanvas::setSelectedRow(int row) {
    m_selected = row;
    update();
}

int TimingCanvas::nameWidth() const {
    const QFontMetrics fm(font());
    int width = fm.horizontalAdvance(QStringLiteral("MMMMMM"));
    if (m_channels)
        for (const model::TimingChannel &c : *m_channels)
            width = std::max(
                width, fm.horizontalAdvance(c.symbol.isEmpty()
                                                ? c.device
                                                : c.device + QStringLiteral("  ") + c.symbol));
    return std::min(width + 12, 200);
}

int TimingCanvas::waveWidth() const {
    return std::max(1, width() - nameWidth());
}

qint64 TimingCanvas::fromMs() const {
    return m_endMs - static_cast<qint64>(std::llround(waveWidth() * m_msPerPixel));
}

int TimingCanvas::rowHeight(int row) const {
    return m_channels && (*m_channels)[static_cast<std::size_t>(row)].bit ? kBitRow : kWordRow;
}

int TimingCanvas::rowTop(int row) const {
    int y = kAxisHeight;
    for (int k = 0; k < row; ++k)
        y += rowHeight(k);
    return y;
}

int TimingCanvas::rowAt(int y) const {
    if (!m_channels || y < kAxisHeight)
        return -1;
    for (int k = 0; k < static_cast<int>(m_channels->size()); ++k)
        if (y < rowTop(k) + rowHeight(k))
            return k;
    return -1;
}

int TimingCanvas::contentHeight() const {
    return m_channels ? rowTop(static_cast<int>(m_channels->size())) + 4 : kAxisHeight;
}

double TimingCanvas::xAt(qint64 timeMs, int left, int width, qint64 from) const {
    Q_UNUSED(width);
    return left + static_cast<double>(timeMs - from) / m_msPerPixel;
}

void TimingCanvas::paintEvent(QPaintEvent *) {
    QPainter p(this);
    render(p, size());
}

void TimingCanvas::render(QPainter &p, QSize size) const {
    p.setRenderHint(QPainter::Antialiasing, false);
    p.fillRect(QRect(QPoint(0, 0), size), palette().color(QPalette::Base));
    const int left = nameWidth();
    const int width = std::max(1, size.width() - left);
    const qint64 from = m_endMs - static_cast<qint64>(std::llround(width * m_msPerPixel));
    p.fillRect(QRect(0, 0, left, size.height()), palette().color(QPalette::Window));
    paintAxis(p, left, width, from, size);
    const QColor ink = palette().color(QPalette::Text);
    if (!m_channels || m_channels->empty()) {
        p.setPen(palette().color(QPalette::PlaceholderText));
        p.drawText(QRect(left, kAxisHeight, width, size.height() - kAxisHeight), Qt::AlignCenter,
                   m_emptyText);
    }
    if (m_channels) {
        const QFontMetrics fm(p.font());
        for (int k = 0; k < static_cast<int>(m_channels->size()); ++k) {
            const model::TimingChannel &c = (*m_channels)[static_cast<std::size_t>(k)];
            const QRect row(0, rowTop(k), size.width(), rowHeight(k));
            if (k == m_selected)
                p.fillRect(row, palette().color(QPalette::Highlight).lighter(170));
            p.setPen(palette().color(QPalette::Mid));
            p.drawLine(0, row.bottom(), size.width(), row.bottom());
            p.setPen(ink);
            const QString name =
                c.symbol.isEmpty() ? c.device : c.device + QStringLiteral("  ") + c.symbol;
            p.drawText(QRect(4, row.top(), left - 8, row.height()),
                       Qt::AlignVCenter | Qt::AlignLeft,
                       fm.elidedText(name, Qt::ElideRight, left - 8));
            const QRect wave(left, row.top() + 4, width, row.height() - 8);
            p.save();
            p.setClipRect(QRect(left, row.top(), width, row.height()));
            if (c.bit)
                paintBit(p, wave, static_cast<std::size_t>(k), from);
            else
                paintWord(p, wave, static_cast<std::size_t>(k), from);
            p.restore();
        }
    }
    // Marks where the trigger fired: dashed, with a flag on the axis.
    p.save();
    p.setClipRect(QRect(left, 0, width, size.height()));
    const auto drawMark = [&](const model::HistoryRecorder::Mark &m) {
        const double x = xAt(m.timeMs, left, width, from);
        p.setPen(QPen(kMark, 1, Qt::DashLine));
        p.drawLine(QPointF(x, kAxisHeight), QPointF(x, size.height()));
        p.setPen(Qt::NoPen);
        p.setBrush(kMark);
        p.drawPolygon(QPolygonF{
            {x, double(kAxisHeight)}, {x - 5, kAxisHeight - 8.0}, {x + 5, kAxisHeight - 8.0}});
    };
    for (const auto &m : m_window.marks)
        drawMark(m);
    for (const auto &m : m_pastMarks)
        if (m.timeMs >= from && m.timeMs <= m_endMs)
            drawMark(m);
    for (int which = 0; which < 2; ++which) {
        if (!m_cursor[which])
            continue;
        const double x = xAt(*m_cursor[which], left, width, from);
        p.setPen(QPen(kCursor, which == 0 ? 2 : 1.5, which == 0 ? Qt::SolidLine : Qt::DashLine));
        p.drawLine(QPointF(x, 0), QPointF(x, size.height()));
        // The letter white on the cursor's colour, in the ruler: never over a number.
        QFont bold = p.font();
        bold.setBold(true);
        p.setFont(bold);
        const QFontMetricsF fm(bold);
        const QString letter = which == 0 ? QStringLiteral("A") : QStringLiteral("B");
        const QRectF tag(x + 1, 1, fm.horizontalAdvance(letter) + 6, fm.height());
        p.fillRect(tag, kCursor);
        p.setPen(Qt::white);
        p.drawText(tag, Qt::AlignCenter, letter);
        p.setFont(font());
    }
    p.restore();
    p.setPen(palette().color(QPalette::Mid));
    p.drawLine(left, 0, left, size.height());
}

std::vector<QRectF> TimingCanvas::cursorTags(QSize size) const {
    std::vector<QRectF> tags;
    const int left = nameWidth();
    const int width = std::max(1, size.width() - left);
    const qint64 from = m_endMs - static_cast<qint64>(std::llround(width * m_msPerPixel));
    QFont bold = font();
    bold.setBold(true);
    const QFontMetricsF fm(bold);
    for (int which = 0; which < 2; ++which) {
        if (!m_cursor[which])
            continue;
        const double x = xAt(*m_cursor[which], left, width, from);
        const QString letter = which == 0 ? QStringLiteral("A") : QStringLiteral("B");
        // The line's whole crossing of the ruler, and the letter's tag beside it.
        tags.emplace_back(x - 2, 0, fm.horizontalAdvance(letter) + 9, kAxisHeight);
    }
    return tags;
}

std::vector<QRectF> TimingCanvas::rulerLabels(QSize size) const {
    const int left = nameWidth();
    const int width = std::max(1, size.width() - left);
    const qint64 from = m_endMs - static_cast<qint64>(std::llround(width * m_msPerPixel));
    const QFontMetricsF fm(font());
    const qint64 step = niceStep(
        static_cast<double>(fm.horizontalAdvance(QStringLiteral("0000.00 s")) + 16) * m_msPerPixel);
    const std::vector<QRectF> tags = cursorTags(size);
    std::vector<QRectF> labels;
    const qint64 first = (std::max<qint64>(from, 0) + step - 1) / step * step;
    for (qint64 t = first; t <= m_endMs; t += step) {
        const double x = xAt(t, left, width, from);
        const QRectF label(x + 2, kAxisHeight - 6 - fm.ascent(),
                           fm.horizontalAdvance(timeText(t, step)), fm.height());
        // A number a cursor's line and letter would cross is left out: the cursor's own time
        // is in the chart's readout, and the two drawn over each other read as neither.
        if (std::none_of(tags.begin(), tags.end(),
                         [&label](const QRectF &tag) { return tag.intersects(label); }))
            labels.push_back(label);
    }
    return labels;
}

void TimingCanvas::paintAxis(QPainter &p, int left, int width, qint64 from, QSize size) const {
    const QFontMetrics fm(p.font());
    const std::vector<QRectF> labels = rulerLabels(size);
    const qint64 step = niceStep(
        static_cast<double>(fm.horizontalAdvance(QStringLiteral("0000.00 s")) + 16) * m_msPerPixel);
    p.setPen(palette().color(QPalette::Text));
    p.drawLine(left, kAxisHeight - 1, left + width, kAxisHeight - 1);
    const qint64 first = (std::max<qint64>(from, 0) + step - 1) / step * step;
    for (qint64 t = first; t <= m_endMs; t += step) {
        const double x = xAt(t, left, width, from);
        p.setPen(palette().color(QPalette::Text));
        p.drawLine(QPointF(x, kAxisHeight - 5), QPointF(x, kAxisHeight - 1));
        if (std::any_of(labels.begin(), labels.end(),
                        [x](const QRectF &label) { return qAbs(label.left() - (x + 2)) < 0.5; }))
            p.drawText(QPointF(x + 2, kAxisHeight - 6), timeText(t, step));
        p.setPen(QPen(palette().color(QPalette::Midlight), 1, Qt::DotLine));
        p.drawLine(QPointF(x, kAxisHeight),
                   QPointF(x, rowTop(m_channels ? int(m_channels->size()) : 0)));
    }
}

void TimingCanvas::paintBit(QPainter &p, const QRect &r, std::size_t k, qint64 from) const {
    if (k >= m_window.changes.size())
        return;
    const auto &changes = m_window.changes[k];
    const double right = r.right() + 1;
    const qint64 known = m_window.knownFromMs[k];
    // Before the first recorded value: unknown, hatched.
    const double knownX =
        known < 0 ? right
                  : std::clamp(xAt(known, r.left(), r.width(), from), double(r.left()), right);
    if (knownX > r.left())
        p.fillRect(QRectF(r.left(), r.top(), knownX - r.left(), r.height()),
                   QBrush(palette().color(QPalette::Mid), Qt::BDiagPattern));
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const double x0 =
            std::max(double(r.left()), xAt(changes[i].timeMs, r.left(), r.width(), from));
        const double x1 = i + 1 < changes.size()
                              ? xAt(changes[i + 1].timeMs, r.left(), r.width(), from)
                              : std::min(right, xAt(m_window.toMs, r.left(), r.width(), from));
        if (x1 < x0)
            continue;
        const bool on = changes[i].value != 0;
        if (on) {
            QColor fill = kHigh;
            fill.setAlpha(60);
            p.fillRect(QRectF(x0, r.top(), std::max(1.0, x1 - x0), r.height()), fill);
            p.setPen(QPen(kHigh, 2));
            p.drawLine(QPointF(x0, r.top()), QPointF(x1, r.top()));
        } else {
            p.setPen(QPen(palette().color(QPalette::Text), 1));
            p.drawLine(QPointF(x0, r.bottom()), QPointF(x1, r.bottom()));
        }
        // The edge: a value changes at an instant.
        if (i > 0 || changes[i].timeMs > from) {
            p.setPen(QPen(palette().color(QPalette::Text), 1));
            p.drawLine(QPointF(x0, r.top()), QPointF(x0, r.bottom()));
        }
    }
}

void TimingCanvas::paintWord(QPainter &p, const QRect &r, std::size_t k, qint64 from) const {
    if (k >= m_window.changes.size())
        return;
    const model::TimingChannel &c = (*m_channels)[k];
    const auto &changes = m_window.changes[k];
    const double right = r.right() + 1;
    const qint64 known = m_window.knownFromMs[k];
    const double knownX =
        known < 0 ? right
                  : std::clamp(xAt(known, r.left(), r.width(), from), double(r.left()), right);
    if (knownX > r.left())
        p.fillRect(QRectF(r.left(), r.top(), knownX - r.left(), r.height()),
                   QBrush(palette().color(QPalette::Mid), Qt::BDiagPattern));
    const QFontMetrics fm(p.font());
    const double mid = r.center().y() + 0.5;
    const double slant = 3;
    p.setPen(QPen(palette().color(QPalette::Text), 1));
    p.setRenderHint(QPainter::Antialiasing, true);
    for (std::size_t i = 0; i < changes.size(); ++i) {
        const double x0 = xAt(changes[i].timeMs, r.left(), r.width(), from);
        const double x1 = i + 1 < changes.size()
                              ? xAt(changes[i + 1].timeMs, r.left(), r.width(), from)
                              : std::min(right, xAt(m_window.toMs, r.left(), r.width(), from));
        if (x1 < x0)
            continue;
        // A bus segment: two lines that cross where the value changes.
        const bool edge = i > 0 || changes[i].timeMs > from;
        const double a =
            edge ? std::min(x0 + slant, (x0 + x1) / 2) : std::max(x0, double(r.left()));
        QPolygonF shape{{edge ? x0 : a, mid}, {a, double(r.top())}, {x1, double(r.top())}};
        p.drawPolyline(shape);
        p.drawPolyline(
            QPolygonF{{edge ? x0 : a, mid}, {a, double(r.bottom())}, {x1, double(r.bottom())}});
        const QString text = model::formatValue(changes[i].value, c.bits, c.format);
        const double room = std::min(x1, right) - std::max(a, double(r.left())) - 4;
        if (room > fm.horizontalAdvance(QStringLiteral("0")))
            p.drawText(QRectF(std::max(a, double(r.left())) + 2, r.top(), room, r.height()),
                       Qt::AlignVCenter | Qt::AlignLeft,
                       fm.elidedText(text, Qt::ElideRight, int(room)));
    }
    p.setRenderHint(QPainter::Antialiasing, false);
}

void TimingCanvas::mousePressEvent(QMouseEvent *event) {
    setFocus();
    const int left = nameWidth();
    const QPoint pos = event->position().toPoint();
    const int row = rowAt(pos.y());
    if (pos.x() < left) {
        setSelectedRow(row);
        if (event->button() == Qt::RightButton && row >= 0)
            emit rowMenuRequested(row, event->globalPosition().toPoint());
        return;
    }
    const qint64 t = fromMs() + static_cast<qint64>(std::llround((pos.x() - left) * m_msPerPixel));
    const bool second =
        event->button() == Qt::RightButton || (event->modifiers() & Qt::ShiftModifier);
    if (event->button() == Qt::LeftButton || event->button() == Qt::RightButton) {
        m_dragging = second ? 1 : 0;
        emit cursorRequested(m_dragging, t);
    }
}

void TimingCanvas::mouseMoveEvent(QMouseEvent *event) {
    if (m_dragging < 0 || !(event->buttons() & (Qt::LeftButton | Qt::RightButton)))
        return;
    const double x = event->position().x() - nameWidth();
    emit cursorRequested(m_dragging,
                         fromMs() + static_cast<qint64>(std::llround(x * m_msPerPixel)));
}

void TimingCanvas::wheelEvent(QWheelEvent *event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (event->modifiers() & Qt::ControlModifier) {
        const double x = event->position().x() - nameWidth();
        emit zoomRequested(std::pow(1.25, -steps),
                           fromMs() + static_cast<qint64>(std::llround(x * m_msPerPixel)));
    } else {
        // A wheel step scrolls a tenth of the window.
        emit scrollRequested(static_cast<qint64>(-steps * waveWidth() * m_msPerPixel / 10));
    }
    event->accept();
}

void TimingCanvas::keyPressEvent(QKeyEvent *event) {
    if ((event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && m_selected >= 0) {
        emit removeRequested(m_selected);
        return;
    }
    if (event->key() == Qt::Key_Plus || event->key() == Qt::Key_Equal) {
        emit zoomRequested(0.5, m_endMs - static_cast<qint64>(waveWidth() * m_msPerPixel / 2));
        return;
    }
    if (event->key() == Qt::Key_Minus) {
        emit zoomRequested(2.0, m_endMs - static_cast<qint64>(waveWidth() * m_msPerPixel / 2));
        return;
    }
    if (event->key() == Qt::Key_Left || event->key() == Qt::Key_Right) {
        const double step = waveWidth() * m_msPerPixel / 10;
        emit scrollRequested(static_cast<qint64>(event->key() == Qt::Key_Left ? -step : step));
        return;
    }
    QWidget::keyPressEvent(event);
}

void TimingCanvas::dragEnterEvent(QDragEnterEvent *event) {
    if (devicesFromMime(event->mimeData()).isEmpty())
        return event->ignore();
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

void TimingCanvas::dragMoveEvent(QDragMoveEvent *event) {
    event->setDropAction(Qt::CopyAction);
    event->accept();
}

void TimingCanvas::dropEvent(QDropEvent *event) {
    const QStringList devices = devicesFromMime(event->mimeData());
    if (devices.isEmpty())
        return event->ignore();
    event->setDropAction(Qt::CopyAction);
    event->accept();
    emit devicesDropped(devices);
}

} // namespace rung::editor
