#include "ladder_painter.h"

#include "model/ladder/ladder_text.h"

#include <QPainterPath>

#include <cmath>

namespace rung::editor {

namespace {
// Where a printed instruction's operands start (-1: none).
qsizetype space(const QString &printed) {
    return printed.indexOf(QLatin1Char(' '));
}
} // namespace

namespace {

// The letters on a box's inputs, as the manuals name them: SFT(10)'s data, shift and reset
// inputs (Omron W353: I, P, R), a counter's count and reset (CP, R), KEEP / LR set and reset,
// CNTR / MUP / MDOWN up, down and reset.
QStringList boxPins(const model::InstructionSpec &spec, std::size_t inputs) {
    if (spec.function == model::ApplyFunction::ShiftRegister)
        return {QStringLiteral("I"), QStringLiteral("P"), QStringLiteral("R")};
    if (spec.op == model::Op::Counter)
        return {QStringLiteral("CP"), QStringLiteral("R")};
    if (inputs == 2)
        return {QStringLiteral("S"), QStringLiteral("R")};
    return {QStringLiteral("U"), QStringLiteral("D"), QStringLiteral("R")};
}

const QColor kInk(0x20, 0x24, 0x2a);
const QColor kRail(0x3a, 0x5a, 0x8c);
const QColor kDim(0x6b, 0x72, 0x80);
const QColor kCursor(0x2f, 0x7d, 0xe1);
const QColor kError(0xd9, 0x3f, 0x3f);
const QColor kWarning(0xe0, 0x9b, 0x1a);
const QColor kBreakpoint(0xc6, 0x28, 0x28);
const QColor kStopped(0xe6, 0x8a, 0x00);

// How far a box stands in from the output column's left edge (its input stubs).
double boxInset(const LadderMetrics &m) {
    return m.rowHeight * 0.27;
}

} // namespace

double LadderMetrics::commentBlock(const model::Rung &rung) const {
    return rung.comment.isEmpty() ? 0.0
                                  : commentHeight * (rung.comment.count(QLatin1Char('\n')) + 1);
}

void LadderMetrics::zoomTo(double zoom) {
    cellWidth = std::floor(cellWidth * zoom);
    rowHeight = std::round(rowHeight * zoom);
    gutter = std::round(gutter * zoom);
    outputWidth = std::floor(outputWidth * zoom);
    commentHeight = std::round(commentHeight * zoom);
    rungGap = std::round(rungGap * zoom);
}

double LadderMetrics::rungHeight(const model::Rung &rung) const {
    const int lines = (blocks(rung) - 1) * blockStride(rung) + rung.rows;
    return commentBlock(rung) + lines * rowHeight + rungGap;
}

LadderMetrics::FontSizes LadderMetrics::fontSizes() const {
    return {std::max(1, static_cast<int>(rowHeight * 0.24)),
            std::max(1, static_cast<int>(rowHeight * 0.2)),
            std::max(1, static_cast<int>(rowHeight * 0.26))};
}

double LadderMetrics::minReadableZoom() {
    constexpr double full = LadderMetrics().rowHeight;
    LadderMetrics m;
    for (int row = 1; row < static_cast<int>(full); ++row) {
        m.rowHeight = row; // the view rounds the zoomed row to whole pixels
        const FontSizes f = m.fontSizes();
        if (f.label >= kMinReadableLabel && f.small >= kMinReadableSmall)
            return row / full;
    }
    return 1.0;
}

LadderPainter::LadderPainter(const model::Project &project, const LadderMetrics &metrics)
    : m_project(project)
    , m_m(metrics)
    , m_pen(std::max(1.0, std::round(1.6 * metrics.rowHeight / 52.0))) {
    m_font = QFont(QStringLiteral("DejaVu Sans"));
    const LadderMetrics::FontSizes sizes = metrics.fontSizes();
    m_font.setPixelSize(sizes.label);
    m_small = m_font;
    m_small.setPixelSize(sizes.small);
    m_mark = m_font;
    m_mark.setBold(true);
    m_mark.setPixelSize(sizes.mark);
}

double LadderPainter::snap(double v, double width) {
    // A line of odd width is centred on a pixel, one of even width on a pixel border.
    return std::round(v) + (static_cast<int>(std::round(width)) % 2 == 1 ? 0.5 : 0.0);
}

double LadderPainter::wireY(double rowTop) const {
    return snap(rowTop + m_m.rowHeight * 0.55, m_pen);
}

// Wires and symbols: square caps, so segments that meet at a cell border overlap and leave no
// light seam.
QPen LadderPainter::inkPen() const {
    return QPen(kInk, m_pen, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin);
}

QRectF LadderPainter::cellRect(const model::Rung &rung, int row, int column) const {
    const int shown = m_m.shownColumns();
    const int lastBlock = m_m.blocks(rung) - 1;
    const bool output = column >= m_m.gridColumns;
    const int block = output ? lastBlock : std::min(column / std::max(1, shown), lastBlock);
    const double top =
        m_m.commentBlock(rung) + (block * m_m.blockStride(rung) + row) * m_m.rowHeight;
    if (output) // the output column, aligned for every rung
        return QRectF(m_m.gutter + shown * m_m.cellWidth, top, m_m.outputWidth, m_m.rowHeight);
    return QRectF(m_m.gutter + (column - block * shown) * m_m.cellWidth, top, m_m.cellWidth,
                  m_m.rowHeight);
}

QRectF LadderPainter::outputRect(const model::Rung &rung, int row) const {
    return cellRect(rung, row, m_m.gridColumns);
}

QString LadderPainter::deviceLabel(const model::Operand &o) const {
    return model::formatOperand(*m_project.target, o);
}

QString LadderPainter::symbolLabel(const model::Operand &o) const {
    if (o.kind != model::Operand::Kind::Device)
        return {};
    const model::Symbol *s = m_project.symbol(o.address);
    return s ? s->name : QString();
}

QString LadderPainter::primaryLabel(const model::Operand &o) const {
    const QString name = m_namesFirst ? symbolLabel(o) : QString();
    return name.isEmpty() ? deviceLabel(o) : name;
}

QString LadderPainter::secondaryLabel(const model::Operand &o) const {
    const QString name = symbolLabel(o);
    return m_namesFirst && !name.isEmpty() ? deviceLabel(o) : name;
}

void LadderPainter::paintContact(QPainter &p, const QRectF &cell, const model::Contact &c,
                                 const QString &live) const {
    const double y = wireY(cell.top());
    const double cx = cell.center().x();
    const double half = snap(cx + m_m.cellWidth * 0.12, m_pen) - cx;
    const double h = m_m.rowHeight * 0.2;
    p.setPen(inkPen());
    if (c.invert) {
        p.drawLine(QPointF(cell.left(), y), QPointF(cx - half, y));
        p.drawLine(QPointF(cx + half, y), QPointF(cell.right(), y));
        p.drawLine(QPointF(cx - half, y + h), QPointF(cx + half, y - h));
        p.setFont(m_small);
        // PL110's P and N are power-flow elements too: the label tells them from NOT.
        const QString edge = model::invertText(c);
        const QString label = edge.isEmpty() ? QStringLiteral("INV") : edge;
        p.drawText(QRectF(cell.left(), cell.top(), cell.width(), y - h - cell.top()),
                   Qt::AlignCenter, label);
        return;
    }
    if (c.compare != model::CompareOp::None && c.operands.size() >= 2) {
        // A compare contact: the first operand above the box, where a contact has its device,
        // the comparison with the second operand in the box ("D100" over ">= K1000"); one line
        // would not fit a cell. What still does not fit is elided: the tooltip has it all.
        const QRectF box(cell.left() + 4, y - h, cell.width() - 8, 2 * h);
        p.drawLine(QPointF(cell.left(), y), QPointF(box.left(), y));
        p.drawLine(QPointF(box.right(), y), QPointF(cell.right(), y));
        p.drawRect(box);
        p.setFont(m_font);
        p.drawText(QRectF(cell.left(), cell.top() + 1, cell.width(), y - h - cell.top() - 1),
                   Qt::AlignHCenter | Qt::AlignBottom,
                   QFontMetricsF(m_font).elidedText(primaryLabel(c.operands[0]), Qt::ElideRight,
                                                    cell.width() - 2));
        p.setFont(m_small);
        QString text = QLatin1String(model::compareSymbol(c.compare)) + QLatin1Char(' ') +
                       primaryLabel(c.operands[1]);
        if (c.mode == model::ContactMode::Negated)
            text = QStringLiteral("NOT ") + text;
        p.drawText(box, Qt::AlignCenter,
                   QFontMetricsF(m_small).elidedText(text, Qt::ElideRight, box.width() - 2));
        // Under the box: the monitored values first (bold, in ink), then the name.
        const QString name = secondaryLabel(c.operands[0]);
        const QRectF under(cell.left(), y + h, cell.width(), cell.bottom() - y - h);
        if (!live.isEmpty()) {
            QFont bold = m_small;
            bold.setBold(true);
            p.setFont(bold);
            p.setPen(kInk);
            p.drawText(under, Qt::AlignHCenter | Qt::AlignTop,
                       QFontMetricsF(bold).elidedText(live, Qt::ElideRight, cell.width() - 4));
        } else if (!name.isEmpty()) {
            p.setPen(kDim);
            p.drawText(under, Qt::AlignHCenter | Qt::AlignTop,
                       QFontMetricsF(m_small).elidedText(name, Qt::ElideRight, cell.width() - 4));
        }
        return;
    }
    p.drawLine(QPointF(cell.left(), y), QPointF(cx - half, y));
    p.drawLine(QPointF(cx + half, y), QPointF(cell.right(), y));
    p.drawLine(QPointF(cx - half, y - h), QPointF(cx - half, y + h));
    p.drawLine(QPointF(cx + half, y - h), QPointF(cx + half, y + h));
    switch (c.mode) {
    case model::ContactMode::Normal:
        break;
    case model::ContactMode::Negated:
        p.drawLine(QPointF(cx - half - 3, y + h), QPointF(cx + half + 3, y - h));
        break;
    case model::ContactMode::Rising:
    case model::ContactMode::Falling:
        paintEdgeArrow(p, cx, y, h, c.mode == model::ContactMode::Rising);
        break;
    }
    if (!c.operands.empty()) {
        p.setFont(m_font);
        p.drawText(QRectF(cell.left(), cell.top() + 1, cell.width(), y - h - cell.top() - 1),
                   Qt::AlignHCenter | Qt::AlignBottom,
                   QFontMetricsF(m_font).elidedText(primaryLabel(c.operands[0]), Qt::ElideRight,
                                                    cell.width() - 2));
        const QString below = secondaryLabel(c.operands[0]);
        if (!below.isEmpty()) {
            p.setFont(m_small);
            p.setPen(kDim);
            const QFontMetricsF fm(m_small);
            p.drawText(QRectF(cell.left(), y + h, cell.width(), cell.bottom() - y - h),
                       Qt::AlignHCenter | Qt::AlignTop,
                       fm.elidedText(below, Qt::ElideRight, cell.width() - 4));
        }
    }
}

bool LadderPainter::isCoil(const model::Instruction &ins) const {
    const model::Op op = ins.op();
    return (op == model::Op::Out || op == model::Op::Set || op == model::Op::Reset ||
            op == model::Op::PulseRise || op == model::Op::PulseFall) &&
           ins.operands.size() == 1;
}

QStringList LadderPainter::valueLines(const QString &live, const QFontMetricsF &metrics,
                                      double width) {
    // "D0 = 12  D1 = 1234" as it is, else without the spaces around '=', else a device a line:
    // elided on one line, a MOV showed "D1 = 1…" and the value's last digits were lost.
    if (metrics.horizontalAdvance(live) <= width)
        return {live};
    QString compact = live;
    compact.replace(QStringLiteral(" = "), QStringLiteral("="));
    compact.replace(QStringLiteral("  "), QStringLiteral(" "));
    if (metrics.horizontalAdvance(compact) <= width)
        return {compact};
    QStringList lines = live.split(QStringLiteral("  "), Qt::SkipEmptyParts);
    for (QString &line : lines)
        if (metrics.horizontalAdvance(line) > width)
            line.replace(QStringLiteral(" = "), QStringLiteral("="));
    return lines;
}

QStringList LadderPainter::wrappedLines(const QString &text, const QFontMetricsF &metrics,
                                        double width, int maxLines) {
    QStringList lines;
    QString line;
    const QStringList words = text.split(QLatin1Char(' '), Qt::SkipEmptyParts);
    for (qsizetype i = 0; i < words.size(); ++i) {
        const QString longer = line.isEmpty() ? words[i] : line + QLatin1Char(' ') + words[i];
        if (line.isEmpty() || metrics.horizontalAdvance(longer) <= width) {
            line = longer;
            continue;
        }
        if (lines.size() + 1 == maxLines) { // the last line takes the rest, elided
            line =
                QStringList(words.mid(i - line.count(QLatin1Char(' ')) - 1)).join(QLatin1Char(' '));
            break;
        }
        lines << line;
        line = words[i];
    }
    if (!line.isEmpty())
        lines << metrics.elidedText(line, Qt::ElideRight, width);
    return lines;
}

QFont LadderPainter::liveFont() const {
    QFont bold = m_small;
    bold.setBold(true);
    return bold;
}

QRectF LadderPainter::boxTextRect(const QRectF &area) const {
    return boxRect(area).adjusted(3, 1, -3, -1); // a one-row box's, as paintOutput draws it
}

QRectF LadderPainter::boxRect(const QRectF &area) const {
    const double y = wireY(area.top());
    const double rowH = m_m.rowHeight;
    return QRectF(QPointF(snap(area.left() + boxInset(m_m), m_pen), snap(y - rowH * 0.3, m_pen)),
                  QPointF(snap(area.right() - 6 - boxInset(m_m) * 0.45, m_pen),
                          snap(area.bottom() - rowH * 0.15, m_pen)));
}

void LadderPainter::paintOutput(QPainter &p, const QRectF &area, const model::Instruction &ins,
                                const QString &live) const {
    const double y = wireY(area.top());
    const double h = m_m.rowHeight * 0.2;
    p.setPen(inkPen());
    const model::Op op = ins.op();
    if (isCoil(ins)) {
        const double cx = coilCenterX(area);
        const double r = h * 1.1;
        p.drawLine(QPointF(area.left(), y), QPointF(cx - r, y));
        p.drawLine(QPointF(cx + r, y), QPointF(area.right() - 6, y));
        p.drawArc(QRectF(cx - r, y - r, r * 1.2, 2 * r), 100 * 16, 160 * 16);
        p.drawArc(QRectF(cx - r * 0.2, y - r, r * 1.2, 2 * r), -80 * 16, 160 * 16);
        QString mark;
        if (op == model::Op::Set)
            mark = QStringLiteral("S");
        else if (op == model::Op::Reset)
            mark = QStringLiteral("R");
        else if (op == model::Op::PulseRise)
            mark = QStringLiteral("P");
        else if (op == model::Op::PulseFall)
            mark = QStringLiteral("F");
        else if (ins.spec && ins.spec->negated)
            mark = QStringLiteral("/");
        p.setFont(m_mark);
        p.drawText(QRectF(cx - r, y - r, 2 * r, 2 * r), Qt::AlignCenter, mark);
        p.setFont(m_font);
        p.drawText(QRectF(area.left(), area.top() + 1, area.width() * 0.8, y - r - area.top() - 1),
                   Qt::AlignHCenter | Qt::AlignBottom,
                   QFontMetricsF(m_font).elidedText(primaryLabel(ins.operands[0]), Qt::ElideRight,
                                                    area.width() * 0.8));
        const QString below = secondaryLabel(ins.operands[0]);
        if (!below.isEmpty()) {
            p.setFont(m_small);
            p.setPen(kDim);
            p.drawText(QRectF(area.left(), y + r, area.width() * 0.8, area.bottom() - y - r),
                       Qt::AlignHCenter | Qt::AlignTop, below);
        }
        return;
    }
    // A box: the instruction in a rectangle (timers, counters, moves, jumps, END). The wire runs
    // into the middle of a one-row box; a box with several inputs (S/R, U/D/R) spans their
    // rows, each input wired to its left edge.
    const double rowH = m_m.rowHeight;
    const bool tall = area.height() > rowH * 1.5;
    const QRectF box = boxRect(area);
    p.drawLine(QPointF(area.left(), y), QPointF(box.left(), y));
    p.drawLine(QPointF(box.right(), y), QPointF(area.right() - 6, y));
    p.setBrush(QColor(0xf4, 0xf6, 0xfa));
    p.drawRect(box);
    p.setBrush(Qt::NoBrush);
    const QString text = model::printInstruction(*m_project.target, ins);
    // Pin letters (U, D, R) sit inside the left edge of a tall box: its text keeps clear.
    const QRectF inner = box.adjusted(tall ? rowH * 0.3 : 3, 1, -3, -1);
    const QFontMetricsF fm(m_font);
    if (!live.isEmpty()) {
        // Monitored: the instruction on the first line, its values (bold) below it.
        QFont bold = m_small;
        bold.setBold(true);
        const QFontMetricsF fs(m_small);
        const QFontMetricsF fb(bold);
        const QStringList values = valueLines(live, fb, inner.width());
        // Values a line each: the operands are named beside their values, the mnemonic says
        // the rest (and keeps the three lines inside a one-row box).
        const QString first = values.size() > 1 && space(text) > 0 ? text.left(space(text)) : text;
        const double lines = fs.height() + fb.height() * values.size();
        const double top = tall ? inner.top() + 2 : inner.center().y() - lines / 2;
        p.setFont(m_small);
        p.drawText(QRectF(inner.left(), top, inner.width(), fs.height()), Qt::AlignCenter,
                   fs.elidedText(first, Qt::ElideRight, inner.width()));
        p.setFont(bold);
        for (qsizetype i = 0; i < values.size(); ++i)
            p.drawText(QRectF(inner.left(),
                              top + fs.height() + fb.height() * static_cast<double>(i),
                              inner.width(), fb.height()),
                       Qt::AlignCenter, fb.elidedText(values[i], Qt::ElideRight, inner.width()));
        return;
    }
    if (!tall && fm.horizontalAdvance(text) <= inner.width()) {
        p.setFont(m_font);
        p.drawText(inner, Qt::AlignCenter, text);
        return;
    }
    // The mnemonic as the box's title, its operands below in the small font.
    const qsizetype space = text.indexOf(QLatin1Char(' '));
    const QString title = space < 0 ? text : text.left(space);
    const QString operands = space < 0 ? QString() : text.mid(space + 1);
    QFont bold = m_font;
    bold.setBold(true);
    const QFontMetricsF fb(bold);
    const QFontMetricsF fs(m_small);
    // Operands that do not fit on one line (PL110 COM / EXP take seven) wrap onto the lines
    // the box has room for; when the title leaves room for only one, the mnemonic leads the
    // small lines instead of standing above them, so that every operand can still be read.
    const int roomWithTitle = std::max(1, int((inner.height() - fb.height()) / fs.height()));
    QStringList lines = wrappedLines(operands, fs, inner.width(), roomWithTitle);
    bool titled = true;
    if (!operands.isEmpty() && fs.horizontalAdvance(operands) > inner.width() &&
        roomWithTitle < 2) {
        const int room = std::max(1, int(inner.height() / fs.height()));
        lines = wrappedLines(text, fs, inner.width(), room);
        titled = false;
    }
    const double textHeight = (titled ? fb.height() : 0.0) +
                              (operands.isEmpty() && titled ? 0.0 : fs.height() * lines.size());
    const double top = tall ? inner.top() + 2 : inner.center().y() - textHeight / 2;
    double at = top;
    if (titled) {
        p.setFont(bold);
        p.drawText(QRectF(inner.left(), at, inner.width(), fb.height()), Qt::AlignCenter,
                   fb.elidedText(title, Qt::ElideRight, inner.width()));
        at += fb.height();
    }
    if (operands.isEmpty() && titled)
        return;
    p.setFont(m_small);
    for (const QString &line : lines) {
        p.drawText(QRectF(inner.left(), at, inner.width(), fs.height()), Qt::AlignCenter, line);
        at += fs.height();
    }
}

void LadderPainter::paintContinuation(QPainter &p, QPointF at, int mark, int row) const {
    // A small arrow with the fold and the row it joins ("1a": first fold, row a), drawn where
    // a row leaves one block and again where it comes in on the next.
    const double s = m_m.rowHeight * 0.12;
    p.save();
    p.setPen(QPen(kRail, 1.4));
    p.setBrush(kRail);
    const QPointF tri[3] = {at + QPointF(-s, -s), at + QPointF(s, 0), at + QPointF(-s, s)};
    p.drawPolygon(tri, 3);
    p.setFont(m_small);
    p.drawText(QRectF(at.x() - 3 * s - 4, at.y() - 4.4 * s, 6 * s + 8, 3 * s), Qt::AlignCenter,
               QStringLiteral("%1%2").arg(mark).arg(QChar(u'a' + row % 26)));
    p.restore();
}

void LadderPainter::paintEdgeArrow(QPainter &p, double cx, double y, double h, bool up) {
    // The arrow inside a rising (up) or falling edge contact.
    const double a = up ? y + h * 0.7 : y - h * 0.7;
    const double b = up ? y - h * 0.7 : y + h * 0.7;
    p.drawLine(QPointF(cx, a), QPointF(cx, b));
    p.drawLine(QPointF(cx, b), QPointF(cx - 3, b + (up ? 4 : -4)));
    p.drawLine(QPointF(cx, b), QPointF(cx + 3, b + (up ? 4 : -4)));
}

void LadderPainter::paintLinks(QPainter &p, const model::Rung &rung, int row, double commentH,
                               const model::RungOverlay *powered) const {
    // Vertical links between this row and the next; a link on a block boundary shows at the
    // end of one block and the start of the next.
    if (row + 1 >= rung.rows)
        return;
    const int shown = m_m.shownColumns();
    const int blocks = m_m.blocks(rung);
    const auto drawLink = [&](int block, double x) {
        const double y0 = wireY(commentH + (block * m_m.blockStride(rung) + row) * m_m.rowHeight);
        p.drawLine(QPointF(snap(x, m_pen), y0), QPointF(snap(x, m_pen), y0 + m_m.rowHeight));
    };
    for (int c = 0; c <= rung.columns; ++c) {
        if (!rung.link(row, c) || (powered && !powered->nodeOn(row, c)))
            continue;
        if (c == rung.columns) {
            drawLink(blocks - 1, m_m.gutter + shown * m_m.cellWidth);
            continue;
        }
        const int block = std::min(c / std::max(1, shown), blocks - 1);
        drawLink(block, m_m.gutter + (c - block * shown) * m_m.cellWidth);
        if (block > 0 && c == block * shown)
            drawLink(block - 1, m_m.gutter + shown * m_m.cellWidth);
    }
}

std::optional<QLineF> LadderPainter::outputWire(const model::Rung &rung, int row) const {
    // From the last contact column to the output column the row is a wire when it has an
    // output, so every output lines up at the right.
    const bool linkedAtEnd =
        rung.link(row, rung.columns) || (row > 0 && rung.link(row - 1, rung.columns));
    const bool wiredToEnd =
        rung.columns == 0 || rung.cell(row, rung.columns - 1).kind != model::CellKind::Empty;
    if (!(rung.outputs[static_cast<std::size_t>(row)] || rung.coveredByBox(row) || linkedAtEnd) ||
        !wiredToEnd)
        return std::nullopt;
    const QRectF outRect = outputRect(rung, row);
    const double y = wireY(outRect.top());
    const int endInBlock = rung.columns - (m_m.blocks(rung) - 1) * m_m.shownColumns();
    return QLineF(QPointF(m_m.gutter + endInBlock * m_m.cellWidth, y), QPointF(outRect.left(), y));
}

void LadderPainter::paintRung(QPainter &p, QPointF origin, int index,
                              const RungDecorations &d) const {
    const model::Rung &rung = m_project.program.rungs[static_cast<std::size_t>(index)];
    p.save();
    p.translate(origin);
    p.setRenderHint(QPainter::Antialiasing, true);
    const double commentH = m_m.commentBlock(rung);
    const double height = m_m.rungHeight(rung) - m_m.rungGap;
    const int shown = m_m.shownColumns();
    const int blocks = m_m.blocks(rung);
    const double rightRail = m_m.gutter + shown * m_m.cellWidth + m_m.outputWidth - 6;
    const double blockHeight = m_m.blockStride(rung) * m_m.rowHeight;

    if (!rung.comment.isEmpty()) {
        p.setFont(m_small);
        p.setPen(QColor(0x2e, 0x7d, 0x32));
        p.drawText(QRectF(m_m.gutter + 6, 0, m_m.width() - m_m.gutter, commentH),
                   Qt::AlignLeft | Qt::AlignVCenter, rung.comment);
    }
    // Gutter: rung number, step address, an error or warning bar.
    p.setFont(m_small);
    p.setPen(kDim);
    p.drawText(QRectF(0, commentH, m_m.gutter - 8, m_m.rowHeight * 0.5),
               Qt::AlignRight | Qt::AlignVCenter, QString::number(index + 1));
    if (d.firstStep >= 0)
        p.drawText(QRectF(0, commentH + m_m.rowHeight * 0.45, m_m.gutter - 8, m_m.rowHeight * 0.4),
                   Qt::AlignRight | Qt::AlignVCenter,
                   QStringLiteral("%1").arg(d.firstStep, 4, 10, QLatin1Char('0')));
    if (d.hasError || d.hasWarning)
        p.fillRect(QRectF(2, commentH + 4, 4, height - commentH - 8),
                   d.hasError ? kError : kWarning);

    // Rails: the left one beside the first block, the right one beside the last; the rows
    // of a folded rung run on from block to block through continuation marks.
    const double railWidth = m_pen + 1;
    const double leftX = snap(m_m.gutter, railWidth);
    const double rightX = snap(rightRail, railWidth);
    p.setPen(QPen(kRail, railWidth, Qt::SolidLine, Qt::FlatCap));
    p.drawLine(QPointF(leftX, commentH), QPointF(leftX, commentH + rung.rows * m_m.rowHeight));
    p.drawLine(QPointF(rightX, commentH + (blocks - 1) * blockHeight), QPointF(rightX, height));
    if (d.cursorRow >= 0 && blocks == 1) {
        // The rung being edited has a spare row below for a new branch: its rails, dashed.
        QPen spare(kRail, 1.5, Qt::DashLine);
        spare.setColor(QColor(0x3a, 0x5a, 0x8c, 110));
        p.setPen(spare);
        p.drawLine(QPointF(leftX, height), QPointF(leftX, height + m_m.rowHeight));
        p.drawLine(QPointF(rightX, height), QPointF(rightX, height + m_m.rowHeight));
    }
    for (int b = 0; b + 1 < blocks; ++b) {
        const int boundary = (b + 1) * shown; // the node between the two blocks
        for (int r = 0; r < rung.rows; ++r) {
            const bool before = rung.cell(r, boundary - 1).kind != model::CellKind::Empty;
            const bool after =
                boundary < rung.columns && rung.cell(r, boundary).kind != model::CellKind::Empty;
            if (!before && !after)
                continue;
            const double yOut = wireY(commentH + b * blockHeight + r * m_m.rowHeight);
            const double yIn = yOut + blockHeight;
            paintContinuation(p, QPointF(m_m.gutter + shown * m_m.cellWidth, yOut), b + 1, r);
            paintContinuation(p, QPointF(m_m.gutter, yIn), b + 1, r);
        }
    }

    // Marked cells and the cursor under the drawing.
    for (const auto &[row, col] : d.selected)
        p.fillRect(cellRect(rung, row, col), QColor(0xd6, 0xe6, 0xfa));
    for (const auto &[row, col] : d.marked)
        if (row >= 0 && row < rung.rows && col >= 0 && col < rung.columns)
            p.fillRect(cellRect(rung, row, col), QColor(0xfd, 0xe2, 0xe2));

    for (int r = 0; r < rung.rows; ++r) {
        for (int c = 0; c < rung.columns; ++c) {
            const model::Cell &cell = rung.cell(r, c);
            const QRectF rect = cellRect(rung, r, c);
            if (cell.kind == model::CellKind::Wire) {
                p.setPen(inkPen());
                const double y = wireY(rect.top());
                p.drawLine(QPointF(rect.left(), y), QPointF(rect.right(), y));
            } else if (cell.kind == model::CellKind::Contact) {
                paintContact(p, rect, cell.contact,
                             d.overlay ? d.overlay->valueAt(r, c) : QString());
            }
        }
        p.setPen(inkPen());
        paintLinks(p, rung, r, commentH, nullptr);
        const auto &out = rung.outputs[static_cast<std::size_t>(r)];
        const QRectF outRect = outputRect(rung, r);
        if (const std::optional<QLineF> wire = outputWire(rung, r)) {
            p.setPen(inkPen());
            p.drawLine(*wire);
        }
        if (out && out->spec) {
            QRectF area = outRect;
            const std::vector<int> inputs = rung.boxInputRows(r);
            if (inputs.size() > 1)
                area.setBottom(outputRect(rung, inputs.back()).bottom());
            const model::RungOverlay::Output *live = d.overlay ? d.overlay->output(r) : nullptr;
            paintOutput(p, area, *out, live ? live->value : QString());
            if (inputs.size() > 1) {
                p.setFont(m_small);
                p.setPen(kDim);
                const QStringList pins = boxPins(*out->spec, inputs.size());
                for (std::size_t k = 0;
                     k < inputs.size() && k < static_cast<std::size_t>(pins.size()); ++k) {
                    const QRectF pin = outputRect(rung, inputs[k]);
                    const double pinY = wireY(pin.top());
                    const double boxLeft = pin.left() + boxInset(m_m);
                    if (k > 0) { // the first input's stub comes with the box
                        p.setPen(inkPen());
                        p.drawLine(QPointF(pin.left(), pinY), QPointF(boxLeft, pinY));
                        p.setPen(kDim);
                    }
                    p.drawText(QRectF(boxLeft + 1, pinY - m_m.rowHeight * 0.16,
                                      m_m.rowHeight * 0.28, m_m.rowHeight * 0.32),
                               Qt::AlignCenter, pins[static_cast<int>(k)]);
                }
            }
        }
    }
    if (d.overlay && d.overlay->rows == rung.rows && d.overlay->columns == rung.columns)
        paintOverlay(p, rung, *d.overlay);
    if (d.cursorRow >= 0 && d.cursorRow <= rung.rows) { // rows: the spare row for a branch
        p.setPen(QPen(kCursor, 2));
        p.setBrush(Qt::NoBrush);
        p.drawRect(cellRect(rung, d.cursorRow, d.cursorColumn).adjusted(1, 1, -1, -1));
    }
    paintDebug(p, rung, d, commentH);
    p.restore();
}

// A breakpoint is a dot left of the rung number (a ring when conditional); a stopped scan an
// arrow there and a thick dashed frame round the element it stops before: shape, not colour
// alone, so it reads in print and for colour-blind users.
void LadderPainter::paintDebug(QPainter &p, const model::Rung &rung, const RungDecorations &d,
                               double commentH) const {
    const double r = std::max(3.0, m_m.rowHeight * 0.1);
    const QPointF dot(r + 8, commentH + m_m.rowHeight * 0.25); // clear of the error bar
    if (d.breakpoint != RungDecorations::Breakpoint::None) {
        p.setPen(QPen(kBreakpoint, 1.5));
        p.setBrush(d.breakpoint == RungDecorations::Breakpoint::Plain ? QBrush(kBreakpoint)
                                                                      : QBrush(Qt::white));
        p.drawEllipse(dot, r, r);
        if (d.breakpoint == RungDecorations::Breakpoint::Conditional)
            p.drawEllipse(dot, r * 0.35, r * 0.35);
    }
    if (!d.stopped)
        return;
    // Below the breakpoint's dot, left of the step address.
    const double y = commentH + m_m.rowHeight * 0.62;
    const QPointF tip(2 * r + 8, y);
    const QPointF arrow[3] = {tip + QPointF(-2 * r, -r), tip, tip + QPointF(-2 * r, r)};
    p.setPen(QPen(kStopped.darker(130), 1));
    p.setBrush(kStopped);
    p.drawPolygon(arrow, 3);
    QPen frame(kStopped.darker(120), 3, Qt::DashLine);
    p.setPen(frame);
    p.setBrush(Qt::NoBrush);
    if (d.stoppedAt.first >= 0)
        p.drawRect(cellRect(rung, d.stoppedAt.first, d.stoppedAt.second).adjusted(2, 2, -2, -2));
    else
        p.drawRect(QRectF(m_m.gutter, commentH,
                          m_m.width() - m_m.gutter - LadderMetrics::kRightMargin,
                          rung.rows * m_m.rowHeight)
                       .adjusted(2, 2, -2, -2));
}

} // namespace rung::editor
