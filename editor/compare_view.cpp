#include "compare_view.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPagedPaintDevice>
#include <QPainter>
#include <QScrollBar>

#include <cmath>

namespace rung::editor {

namespace {

using model::RungStatus;

constexpr double kMargin = 8;

} // namespace

CompareView::CompareView(QWidget *parent)
    : QAbstractScrollArea(parent) {
    setFocusPolicy(Qt::StrongFocus);
    viewport()->setBackgroundRole(QPalette::Base);
    viewport()->setAutoFillBackground(true);
}

QString CompareView::statusMark(RungStatus status) {
    switch (status) {
    case RungStatus::Same:
        return QStringLiteral("=");
    case RungStatus::Moved:
        return QStringLiteral("\u2195");
    case RungStatus::Changed:
        return QStringLiteral("~");
    case RungStatus::MovedChanged:
        return QStringLiteral("\u2195 ~");
    case RungStatus::Inserted:
        return QStringLiteral("+");
    case RungStatus::Deleted:
        return QStringLiteral("-");
    }
    return {};
}

QString CompareView::statusText(RungStatus status) {
    switch (status) {
    case RungStatus::Same:
        return tr("the same");
    case RungStatus::Moved:
        return tr("moved");
    case RungStatus::Changed:
        return tr("changed");
    case RungStatus::MovedChanged:
        return tr("moved and changed");
    case RungStatus::Inserted:
        return tr("inserted");
    case RungStatus::Deleted:
        return tr("deleted");
    }
    return {};
}

Qt::BrushStyle CompareView::statusPattern(RungStatus status) {
    switch (status) {
    case RungStatus::Same:
        return Qt::NoBrush;
    case RungStatus::Moved:
        return Qt::Dense6Pattern;
    case RungStatus::Changed:
    case RungStatus::MovedChanged:
        return Qt::BDiagPattern;
    case RungStatus::Inserted:
        return Qt::CrossPattern;
    case RungStatus::Deleted:
        return Qt::HorPattern;
    }
    return Qt::NoBrush;
}

QColor CompareView::statusColor(RungStatus status) {
    // Okabe and Ito's palette: distinct for deuteranopes, protanopes and tritanopes alike.
    switch (status) {
    case RungStatus::Same:
        return QColor(0x60, 0x60, 0x60);
    case RungStatus::Moved:
        return QColor(0xCC, 0x79, 0xA7); // reddish purple
    case RungStatus::Changed:
    case RungStatus::MovedChanged:
        return QColor(0xE6, 0x9F, 0x00); // orange
    case RungStatus::Inserted:
        return QColor(0x00, 0x72, 0xB2); // blue
    case RungStatus::Deleted:
        return QColor(0xD5, 0x5E, 0x00); // vermillion
    }
    return Qt::black;
}

void CompareView::setComparison(const model::Project &a, const model::Project &b,
                                const model::Comparison &comparison) {
    m_a = a;
    m_b = b;
    m_comparison = comparison;
    m_current = -1;
    relayout();
    nextChange(false);
    viewport()->update();
}

int CompareView::changeCount() const {
    return static_cast<int>(
        std::count_if(m_comparison.rungs.begin(), m_comparison.rungs.end(),
                      [](const model::RungDifference &d) { return d.status != RungStatus::Same; }));
}

void CompareView::setCurrent(int difference) {
    if (difference < -1 || difference >= static_cast<int>(m_comparison.rungs.size()))
        return;
    m_current = difference;
    if (difference >= 0 && static_cast<std::size_t>(difference) + 1 < m_top.size()) {
        // The row in view, its top a little below the view's top when it has to move.
        const int top = static_cast<int>(m_top[static_cast<std::size_t>(difference)]);
        const int bottom = static_cast<int>(m_top[static_cast<std::size_t>(difference) + 1]);
        QScrollBar *bar = verticalScrollBar();
        if (top < bar->value() || bottom > bar->value() + viewport()->height())
            bar->setValue(std::max(0, top - static_cast<int>(kMargin)));
    }
    viewport()->update();
    emit currentChanged(difference);
}

bool CompareView::nextChange(bool backwards) {
    const int n = static_cast<int>(m_comparison.rungs.size());
    for (int k = m_current + (backwards ? -1 : 1); k >= 0 && k < n; k += backwards ? -1 : 1)
        if (m_comparison.rungs[static_cast<std::size_t>(k)].status != RungStatus::Same) {
            setCurrent(k);
            return true;
        }
    return false;
}

LadderMetrics CompareView::metricsFor(double zoom) const {
    LadderMetrics m;
    int widest = 1;
    for (const model::Project *p : {&m_a, &m_b})
        for (const model::Rung &r : p->program.rungs)
            widest = std::max(widest, r.columns);
    m.gridColumns = widest;
    if (m_a.target)
        m.foldColumns = std::max(0, m_a.target->limits.contactsPerRow);
    m.zoomTo(zoom);
    return m;
}

double CompareView::rowHeight(std::size_t d, const LadderMetrics &m) const {
    const model::RungDifference &r = m_comparison.rungs[d];
    double h = m.rowHeight;
    if (r.a >= 0 && static_cast<std::size_t>(r.a) < m_a.program.rungs.size())
        h = std::max(h, m.rungHeight(m_a.program.rungs[static_cast<std::size_t>(r.a)]));
    if (r.b >= 0 && static_cast<std::size_t>(r.b) < m_b.program.rungs.size())
        h = std::max(h, m.rungHeight(m_b.program.rungs[static_cast<std::size_t>(r.b)]));
    return std::round(kHeader * m_zoom) + h + kMargin;
}

void CompareView::relayout() {
    // Both sides and the band in the width, zoomed no further down than stays readable.
    const LadderMetrics full = metricsFor(1.0);
    const double needed = 2 * full.width() + kBand + 2 * kMargin;
    m_zoom = std::clamp(viewport()->width() / needed, LadderMetrics::minReadableZoom(), 1.0);
    const LadderMetrics m = metricsFor(m_zoom);
    m_top.assign(m_comparison.rungs.size() + 1, 0.0);
    double y = kMargin;
    for (std::size_t d = 0; d < m_comparison.rungs.size(); ++d) {
        m_top[d] = y;
        y += rowHeight(d, m);
    }
    m_top.back() = y;
    const double width = 2 * m.width() + kBand * m_zoom + 2 * kMargin;
    verticalScrollBar()->setRange(0, std::max(0, static_cast<int>(y) - viewport()->height()));
    verticalScrollBar()->setPageStep(viewport()->height());
    verticalScrollBar()->setSingleStep(static_cast<int>(m.rowHeight));
    horizontalScrollBar()->setRange(0, std::max(0, static_cast<int>(width) - viewport()->width()));
    horizontalScrollBar()->setPageStep(viewport()->width());
}

void CompareView::resizeEvent(QResizeEvent *event) {
    QAbstractScrollArea::resizeEvent(event);
    relayout();
}

void CompareView::changeEvent(QEvent *event) {
    QAbstractScrollArea::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        viewport()->update();
}

void CompareView::mousePressEvent(QMouseEvent *event) {
    const double y = event->position().y() + verticalScrollBar()->value();
    for (std::size_t d = 0; d + 1 < m_top.size(); ++d)
        if (y >= m_top[d] && y < m_top[d + 1]) {
            setCurrent(static_cast<int>(d));
            return;
        }
}

void CompareView::paintEvent(QPaintEvent *) {
    QPainter p(viewport());
    p.setRenderHint(QPainter::Antialiasing);
    const LadderMetrics m = metricsFor(m_zoom);
    p.translate(-horizontalScrollBar()->value(), -verticalScrollBar()->value());
    const double top = verticalScrollBar()->value();
    const double bottom = top + viewport()->height();
    for (std::size_t d = 0; d + 1 < m_top.size(); ++d) {
        if (m_top[d + 1] < top || m_top[d] > bottom)
            continue;
        paintRow(p, d, m_top[d], m_top[d + 1] - m_top[d], m, static_cast<int>(d) == m_current);
    }
    if (m_comparison.rungs.empty()) {
        p.resetTransform();
        p.drawText(viewport()->rect(), Qt::AlignCenter, tr("Both programs are empty."));
    }
}

void CompareView::print(QPagedPaintDevice *device) const {
    // Drawn at 100 % and scaled to the page: the marks are patterns, dashes and signs, so they
    // read on a black and white printer too.
    auto *self = const_cast<CompareView *>(this);
    const double saved = m_zoom;
    self->m_zoom = 1.0;
    const LadderMetrics m = metricsFor(1.0);
    const double width = 2 * m.width() + kBand + 2 * kMargin;
    QPainter p(device);
    const QRect page = p.viewport();
    const double scale = page.width() / width;
    p.scale(scale, scale);
    const double pageHeight = page.height() / scale;
    double y = 0;
    for (std::size_t d = 0; d < m_comparison.rungs.size(); ++d) {
        const double h = rowHeight(d, m);
        if (y > 0 && y + h > pageHeight) {
            device->newPage();
            y = 0;
        }
        paintRow(p, d, y, h, m, false);
        y += h;
    }
    self->m_zoom = saved;
}

void CompareView::paintRow(QPainter &p, std::size_t d, double top, double height,
                           const LadderMetrics &m, bool current) const {
    const model::RungDifference &r = m_comparison.rungs[d];
    const double sideWidth = m.width();
    const double band = kBand * m_zoom;
    const double header = std::round(kHeader * m_zoom);
    const QColor color = statusColor(r.status);
    QFont small = font();
    small.setPixelSize(std::max(9, static_cast<int>(13 * m_zoom)));
    p.setFont(small);
    // The rung numbers above each side, in the ink of the text.
    p.setPen(palette().color(QPalette::Text));
    const double leftX = kMargin;
    const double bandX = leftX + sideWidth;
    const double rightX = bandX + band;
    if (r.a >= 0)
        p.drawText(QRectF(leftX, top, sideWidth, header), Qt::AlignLeft | Qt::AlignVCenter,
                   tr("A: rung %1").arg(r.a + 1));
    if (r.b >= 0)
        p.drawText(QRectF(rightX, top, sideWidth, header), Qt::AlignLeft | Qt::AlignVCenter,
                   tr("B: rung %1").arg(r.b + 1));
    // The band: the status's pattern in its colour, and its sign and words in black on white.
    const QRectF bandRect(bandX + 4, top + 2, band - 8, height - kMargin - 4);
    if (r.status != RungStatus::Same) {
        p.fillRect(bandRect, QBrush(color, statusPattern(r.status)));
        p.setPen(QPen(color, 2));
        p.drawRect(bandRect);
        const QRectF label = bandRect.adjusted(6, 6, -6, -6);
        QFont bold = small;
        bold.setBold(true);
        p.setFont(bold);
        const QRectF text =
            p.boundingRect(label, Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap,
                           statusMark(r.status) + QLatin1Char('\n') + statusText(r.status));
        p.fillRect(text.adjusted(-4, -2, 4, 2), Qt::white);
        p.setPen(Qt::black);
        p.drawText(label, Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap,
                   statusMark(r.status) + QLatin1Char('\n') + statusText(r.status));
        p.setFont(small);
    } else {
        p.setPen(QPen(palette().color(QPalette::Mid), 1));
        p.drawText(bandRect, Qt::AlignCenter, statusMark(r.status));
    }
    const double drawTop = top + header;
    const double drawHeight = height - header - kMargin;
    paintSide(p, m_a, r.a, QPointF(leftX, drawTop), sideWidth, drawHeight, m, r, true);
    paintSide(p, m_b, r.b, QPointF(rightX, drawTop), sideWidth, drawHeight, m, r, false);
    if (current) {
        p.setPen(QPen(palette().color(QPalette::Highlight), 3));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(1.5, top + 1.5, 2 * sideWidth + band + 2 * kMargin - 3, height - 3));
    }
    // Divider between rows.
    p.setPen(QPen(palette().color(QPalette::Midlight), 1));
    p.drawLine(QPointF(0, top + height - 0.5),
               QPointF(2 * sideWidth + band + 2 * kMargin, top + height - 0.5));
}

void CompareView::paintSide(QPainter &p, const model::Project &project, int rung, QPointF origin,
                            double width, double height, const LadderMetrics &m,
                            const model::RungDifference &d, bool sideA) const {
    if (rung < 0 || static_cast<std::size_t>(rung) >= project.program.rungs.size()) {
        // Nothing on this side: a hatched place that says which program lacks the rung.
        const QRectF empty(origin, QSizeF(width, height));
        p.fillRect(empty, QBrush(palette().color(QPalette::Mid), Qt::FDiagPattern));
        p.setPen(palette().color(QPalette::Text));
        const QString text = sideA ? tr("(not in A)") : tr("(not in B)");
        const QRectF box = p.boundingRect(empty, Qt::AlignCenter, text).adjusted(-6, -3, 6, 3);
        p.fillRect(box, palette().color(QPalette::Base));
        p.drawText(empty, Qt::AlignCenter, text);
        return;
    }
    const model::Rung &r = project.program.rungs[static_cast<std::size_t>(rung)];
    LadderPainter painter(project, m);
    p.save();
    painter.paintRung(p, origin, rung, RungDecorations());
    p.restore();
    // The elements that differ, framed with a dashed line and their sign.
    const QColor color = statusColor(RungStatus::Changed);
    for (const model::ElementChange &e : d.elements) {
        if (e.element == model::ElementChange::Element::Branches)
            continue;
        const model::CellOrigin &cell = sideA ? e.cellA : e.cellB;
        if (cell.row < 0)
            continue; // an element of the other side only
        const bool output = cell.column < 0 || cell.column >= r.columns;
        QRectF rect =
            output ? painter.outputRect(r, cell.row) : painter.cellRect(r, cell.row, cell.column);
        rect.translate(origin);
        const QString sign = e.kind == model::ElementChange::Kind::Added     ? QStringLiteral("+")
                             : e.kind == model::ElementChange::Kind::Removed ? QStringLiteral("-")
                                                                             : QStringLiteral("~");
        const QColor frame =
            e.kind == model::ElementChange::Kind::Added     ? statusColor(RungStatus::Inserted)
            : e.kind == model::ElementChange::Kind::Removed ? statusColor(RungStatus::Deleted)
                                                            : color;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(frame, 3, Qt::DashLine));
        p.drawRect(rect.adjusted(2, 2, -2, -2));
        QFont bold = p.font();
        bold.setBold(true);
        p.setFont(bold);
        const QRectF tag(rect.left() + 2, rect.top() + 2, p.fontMetrics().height() + 4,
                         p.fontMetrics().height() + 2);
        p.fillRect(tag, Qt::white);
        p.setPen(QPen(Qt::black, 1));
        p.drawRect(tag);
        p.drawText(tag, Qt::AlignCenter, sign);
    }
    if (d.commentChanged) {
        // The comment line framed like an element.
        p.setPen(QPen(color, 2, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(origin.x() + 2, origin.y() + 1, width - 4, m.commentBlock(r) - 2));
    }
}

} // namespace rung::editor
