// The live overlay over a painted rung. It has to read without colour (colour-blind users, a
// grey printout), so every state has a shape of its own besides its blue:
//   power flows      wires, links and stubs drawn twice as heavy
//   contact conducts the gap between its plates filled (an NC contact conducts when OFF)
//   coil ON          the coil filled, its letter cut out of the fill
//   box active       a heavy border and a filled corner (a timer or counter: its done bit)
//   forced device    a dashed outline round the element and an "F" badge at its corner
//   stale values     (an online PLC that stopped answering) dashed lines, hatched fills, grey
// The shapes sit exactly on the plain drawing's, which stays underneath.

#include "ladder_painter.h"

#include "model/ladder/ladder_text.h"

#include <cmath>

namespace rung::editor {

namespace {

const QColor kPaper(Qt::white);

// How far a box stands in from the output column's left edge (as ladder_painter.cpp).
double inset(const LadderMetrics &m) {
    return m.rowHeight * 0.27;
}

} // namespace

QColor LadderPainter::energisedColor() {
    return QColor(0x15, 0x65, 0xc0); // a blue: apart from red and green for every colour vision
}

QColor LadderPainter::forcedColor() {
    return QColor(0xc4, 0x4d, 0x00);
}

QColor LadderPainter::staleColor() {
    return QColor(0x8a, 0x8f, 0x98);
}

QPen LadderPainter::livePen(bool stale) const {
    const double width = std::max(3.0, std::round(m_pen * 2));
    QPen pen(stale ? staleColor() : energisedColor(), width, stale ? Qt::DashLine : Qt::SolidLine,
             stale ? Qt::FlatCap : Qt::SquareCap, Qt::MiterJoin);
    return pen;
}

double LadderPainter::forceBadgeSize() const {
    return std::max(9.0, std::round(m_m.rowHeight * 0.27));
}

void LadderPainter::paintForced(QPainter &p, const QRectF &element, const QRectF &badge,
                                bool stale) const {
    p.save();
    const QColor color = stale ? staleColor() : forcedColor();
    QPen outline(color, std::max(1.5, m_pen * 0.8), Qt::DashLine);
    p.setPen(outline);
    p.setBrush(Qt::NoBrush);
    p.drawRect(element);
    // The badge: an "F" cut out of a filled square, where it covers no text.
    p.fillRect(badge, color);
    QFont font = m_small;
    font.setBold(true);
    font.setPixelSize(std::max(7, static_cast<int>(badge.height() * 0.8)));
    p.setFont(font);
    p.setPen(kPaper);
    p.drawText(badge, Qt::AlignCenter, QStringLiteral("F"));
    p.restore();
}

QRectF LadderPainter::contactForceBadge(const QRectF &cell) const {
    const double cx = cell.center().x();
    return forceBadgeBeside(cell, snap(cx + m_m.cellWidth * 0.12, m_pen));
}

QRectF LadderPainter::forceBadgeBeside(const QRectF &cell, double symbolRight) const {
    // Right of the contact's or coil's symbol, on its wire: the device's label above and the
    // name or value below stay whole ("X1", "000.00" lost their last character under a badge
    // in the corner).
    const double size = forceBadgeSize();
    const double y = wireY(cell.top());
    const double left = std::min(symbolRight + std::max(2.0, m_pen), cell.right() - 3 - size);
    return QRectF(left, y - size / 2, size, size);
}

void LadderPainter::paintContactState(QPainter &p, const QRectF &cell, const model::Contact &c,
                                      const model::RungOverlay &o, int row, int column) const {
    const bool stale = o.stale;
    const double y = wireY(cell.top());
    const double cx = cell.center().x();
    const double half = snap(cx + m_m.cellWidth * 0.12, m_pen) - cx;
    const double h = m_m.rowHeight * 0.2;
    const bool arrives = o.nodeOn(row, column);
    const bool passes = o.passes(row, column);
    const bool closed = o.conducts(row, column);
    const QPen live = livePen(stale);
    const QBrush fill(stale ? staleColor() : energisedColor(),
                      stale ? Qt::BDiagPattern : Qt::SolidPattern);
    p.setPen(live);
    if (c.compare != model::CompareOp::None && !c.invert) {
        const QRectF box(cell.left() + 4, y - h, cell.width() - 8, 2 * h);
        if (arrives)
            p.drawLine(QPointF(cell.left(), y), QPointF(box.left(), y));
        if (passes)
            p.drawLine(QPointF(box.right(), y), QPointF(cell.right(), y));
        if (closed) {
            // The comparison holds: a heavy frame and a bar under the text.
            p.setBrush(Qt::NoBrush);
            p.drawRect(box);
            p.fillRect(QRectF(box.left(), box.bottom() - h * 0.35, box.width(), h * 0.35), fill);
        }
    } else {
        if (arrives)
            p.drawLine(QPointF(cell.left(), y), QPointF(cx - half, y));
        if (passes)
            p.drawLine(QPointF(cx + half, y), QPointF(cell.right(), y));
        if (c.invert) {
            if (closed) // NOT / P / N passes power: its slash heavy
                p.drawLine(QPointF(cx - half, y + h), QPointF(cx + half, y - h));
        } else if (closed) {
            const QRectF gap(cx - half, y - h, 2 * half, 2 * h);
            p.fillRect(gap, fill);
            p.drawLine(QPointF(cx - half, y - h), QPointF(cx - half, y + h));
            p.drawLine(QPointF(cx + half, y - h), QPointF(cx + half, y + h));
            // The contact's own mark (NC slash, edge arrow) stays readable on the fill.
            QPen mark(kPaper, std::max(1.0, m_pen * 0.75));
            p.setPen(mark);
            if (c.mode == model::ContactMode::Negated) {
                p.drawLine(QPointF(cx - half + 1, y + h - 1), QPointF(cx + half - 1, y - h + 1));
            } else if (c.mode == model::ContactMode::Rising ||
                       c.mode == model::ContactMode::Falling) {
                paintEdgeArrow(p, cx, y, h, c.mode == model::ContactMode::Rising);
            }
        }
    }
    if (o.isForced(row, column))
        paintForced(p, cell.adjusted(2, 2, -2, -2),
                    c.compare != model::CompareOp::None && !c.invert
                        ? forceBadgeBeside(cell, cell.right() - 4 - forceBadgeSize())
                        : forceBadgeBeside(cell, cx + half),
                    stale);
}

void LadderPainter::paintOutputState(QPainter &p, const QRectF &area, const model::Instruction &ins,
                                     const model::RungOverlay::Output &out, bool stale) const {
    const double y = wireY(area.top());
    const double h = m_m.rowHeight * 0.2;
    const QPen live = livePen(stale);
    const QBrush fill(stale ? staleColor() : energisedColor(),
                      stale ? Qt::BDiagPattern : Qt::SolidPattern);
    p.setPen(live);
    if (isCoil(ins)) {
        const double cx = coilCenterX(area);
        const double r = h * 1.1;
        if (out.powered) {
            p.drawLine(QPointF(area.left(), y), QPointF(cx - r, y));
            p.drawLine(QPointF(cx + r, y), QPointF(area.right() - 6, y));
        }
        if (out.on) {
            p.setBrush(fill);
            p.setPen(Qt::NoPen);
            p.drawEllipse(QRectF(cx - r * 0.72, y - r * 0.92, r * 1.44, r * 1.84));
            p.setBrush(Qt::NoBrush);
            p.setPen(live);
            p.drawArc(QRectF(cx - r, y - r, r * 1.2, 2 * r), 100 * 16, 160 * 16);
            p.drawArc(QRectF(cx - r * 0.2, y - r, r * 1.2, 2 * r), -80 * 16, 160 * 16);
            QString mark;
            switch (ins.op()) {
            case model::Op::Set:
                mark = QStringLiteral("S");
                break;
            case model::Op::Reset:
                mark = QStringLiteral("R");
                break;
            case model::Op::PulseRise:
                mark = QStringLiteral("P");
                break;
            case model::Op::PulseFall:
                mark = QStringLiteral("F");
                break;
            default:
                if (ins.spec && ins.spec->negated)
                    mark = QStringLiteral("/");
                break;
            }
            if (!mark.isEmpty()) {
                p.setFont(m_mark);
                p.setPen(kPaper);
                p.drawText(QRectF(cx - r, y - r, 2 * r, 2 * r), Qt::AlignCenter, mark);
            }
        }
        if (out.forced)
            paintForced(p, QRectF(cx - r * 1.5, y - r * 1.45, r * 3, r * 2.9),
                        forceBadgeBeside(area, cx + r * 1.5), stale);
        return;
    }
    const QRectF box = boxRect(area);
    if (out.powered)
        p.drawLine(QPointF(area.left(), y), QPointF(box.left(), y));
    // A timer or counter is active when its done bit is ON, an STL while its step is; another
    // box while it runs.
    const bool active = out.hasBit ? out.on : out.powered;
    if (active) {
        p.drawLine(QPointF(box.right(), y), QPointF(area.right() - 6, y));
        p.setBrush(Qt::NoBrush);
        p.drawRect(box);
        const double corner = std::max(6.0, m_m.rowHeight * 0.2);
        const QPointF tri[3] = {box.topRight(), box.topRight() + QPointF(-corner, 0),
                                box.topRight() + QPointF(0, corner)};
        p.setPen(Qt::NoPen);
        p.setBrush(fill);
        p.drawPolygon(tri, 3);
        p.setBrush(Qt::NoBrush);
    }
    if (out.forced) {
        const QRectF element = box.adjusted(-3, -3, 3, 3);
        const double size = forceBadgeSize();
        paintForced(p, element, QRectF(element.right() - size, element.top(), size, size), stale);
    }
}

void LadderPainter::paintOverlay(QPainter &p, const model::Rung &rung,
                                 const model::RungOverlay &o) const {
    p.save();
    const double commentH = m_m.commentBlock(rung);
    const QPen live = livePen(o.stale);
    if (o.rail) {
        // The left rail beside the first block, heavier than the plain rail underneath.
        QPen rail = live;
        rail.setWidthF(live.widthF() + 1);
        rail.setCapStyle(Qt::FlatCap);
        p.setPen(rail);
        const double x = snap(m_m.gutter, m_pen + 1);
        p.drawLine(QPointF(x, commentH), QPointF(x, commentH + rung.rows * m_m.rowHeight));
    }
    for (int r = 0; r < rung.rows; ++r) {
        for (int c = 0; c < rung.columns; ++c) {
            const model::Cell &cell = rung.cell(r, c);
            const QRectF rect = cellRect(rung, r, c);
            if (cell.kind == model::CellKind::Wire && o.passes(r, c)) {
                p.setPen(live);
                const double y = wireY(rect.top());
                p.drawLine(QPointF(rect.left(), y), QPointF(rect.right(), y));
            } else if (cell.kind == model::CellKind::Contact) {
                paintContactState(p, rect, cell.contact, o, r, c);
            }
        }
        // Vertical links carry the power of the node they join.
        p.setPen(live);
        paintLinks(p, rung, r, commentH, &o);
        // The wire from the last contact column to the output column.
        const auto &out = rung.outputs[static_cast<std::size_t>(r)];
        const QRectF outRect = outputRect(rung, r);
        if (const std::optional<QLineF> wire = outputWire(rung, r);
            wire && o.nodeOn(r, rung.columns)) {
            p.setPen(live);
            p.drawLine(*wire);
        }
        const model::RungOverlay::Output *state = o.output(r);
        if (out && out->spec && state) {
            QRectF area = outRect;
            const std::vector<int> inputs = rung.boxInputRows(r);
            if (inputs.size() > 1)
                area.setBottom(outputRect(rung, inputs.back()).bottom());
            paintOutputState(p, area, *out, *state, o.stale);
            // The further inputs of a box (S/R, U/D/R): their stubs carry their rows' power.
            p.setPen(live);
            for (std::size_t k = 1; k < inputs.size(); ++k) {
                if (!o.nodeOn(inputs[k], rung.columns))
                    continue;
                const QRectF pin = outputRect(rung, inputs[k]);
                const double pinY = wireY(pin.top());
                p.drawLine(QPointF(pin.left(), pinY), QPointF(pin.left() + inset(m_m), pinY));
            }
        }
    }
    p.restore();
}

} // namespace rung::editor
