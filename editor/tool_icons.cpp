#include "tool_icons.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace rung::editor {

namespace {

const QColor kInk(0x20, 0x24, 0x2a);
const QColor kAccent(0x2f, 0x7d, 0xe1);
const QColor kPaper(0xfb, 0xfc, 0xfe);

// Draws on a 32 x 32 canvas; the pixmap is painted at the requested size.
void draw(QPainter &p, ToolIcon icon) {
    QPen ink(kInk, 2.2, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin);
    p.setPen(ink);
    switch (icon) {
    case ToolIcon::OpenContact:
    case ToolIcon::ClosedContact:
        p.drawLine(QPointF(2, 16), QPointF(11, 16));
        p.drawLine(QPointF(21, 16), QPointF(30, 16));
        p.drawLine(QPointF(11, 7), QPointF(11, 25));
        p.drawLine(QPointF(21, 7), QPointF(21, 25));
        if (icon == ToolIcon::ClosedContact)
            p.drawLine(QPointF(8, 25), QPointF(24, 7));
        break;
    case ToolIcon::ParallelContact:
        // A contact on a branch below, joined to the line above at both ends.
        p.drawLine(QPointF(2, 8), QPointF(30, 8));
        p.drawLine(QPointF(5, 8), QPointF(5, 23));
        p.drawLine(QPointF(27, 8), QPointF(27, 23));
        p.drawLine(QPointF(5, 23), QPointF(12, 23));
        p.drawLine(QPointF(20, 23), QPointF(27, 23));
        p.drawLine(QPointF(12, 16), QPointF(12, 30));
        p.drawLine(QPointF(20, 16), QPointF(20, 30));
        break;
    case ToolIcon::RisingContact:
    case ToolIcon::FallingContact: {
        p.drawLine(QPointF(2, 16), QPointF(9, 16));
        p.drawLine(QPointF(23, 16), QPointF(30, 16));
        p.drawLine(QPointF(9, 6), QPointF(9, 26));
        p.drawLine(QPointF(23, 6), QPointF(23, 26));
        const bool up = icon == ToolIcon::RisingContact;
        const double tip = up ? 9 : 23;
        const double tail = up ? 23 : 9;
        p.setPen(QPen(kAccent, 2.2, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawLine(QPointF(16, tail), QPointF(16, tip));
        p.drawLine(QPointF(12.5, tip + (up ? 4 : -4)), QPointF(16, tip));
        p.drawLine(QPointF(19.5, tip + (up ? 4 : -4)), QPointF(16, tip));
        break;
    }
    case ToolIcon::Coil:
        p.drawLine(QPointF(2, 16), QPointF(9, 16));
        p.drawLine(QPointF(23, 16), QPointF(30, 16));
        p.drawArc(QRectF(8, 7, 10, 18), 100 * 16, 160 * 16);
        p.drawArc(QRectF(14, 7, 10, 18), -80 * 16, 160 * 16);
        break;
    case ToolIcon::Instruction:
        p.drawLine(QPointF(2, 16), QPointF(7, 16));
        p.drawLine(QPointF(25, 16), QPointF(30, 16));
        p.setBrush(kPaper);
        p.drawRect(QRectF(7, 8, 18, 16));
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(kAccent, 2));
        p.drawLine(QPointF(11, 13), QPointF(21, 13));
        p.drawLine(QPointF(11, 19), QPointF(18, 19));
        break;
    case ToolIcon::HorizontalWire:
        p.drawLine(QPointF(3, 16), QPointF(29, 16));
        p.setPen(QPen(kAccent, 1.5));
        p.drawLine(QPointF(3, 10), QPointF(3, 22));
        p.drawLine(QPointF(29, 10), QPointF(29, 22));
        break;
    case ToolIcon::VerticalLink:
        p.drawLine(QPointF(4, 8), QPointF(16, 8));
        p.drawLine(QPointF(16, 8), QPointF(16, 24));
        p.drawLine(QPointF(16, 24), QPointF(28, 24));
        p.drawLine(QPointF(16, 8), QPointF(28, 8));
        break;
    case ToolIcon::NewFile: {
        // A sheet with a small rung on it and a plus.
        QPainterPath sheet;
        sheet.moveTo(7, 3);
        sheet.lineTo(20, 3);
        sheet.lineTo(26, 9);
        sheet.lineTo(26, 29);
        sheet.lineTo(7, 29);
        sheet.closeSubpath();
        p.setPen(QPen(kInk, 1.8));
        p.setBrush(kPaper);
        p.drawPath(sheet);
        p.drawLine(QPointF(20, 3), QPointF(20, 9));
        p.drawLine(QPointF(20, 9), QPointF(26, 9));
        p.setPen(QPen(kInk, 1.4));
        p.drawLine(QPointF(10, 12), QPointF(10, 24));
        p.drawLine(QPointF(10, 18), QPointF(19, 18));
        p.setPen(QPen(kAccent, 3, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(QPointF(24, 19), QPointF(24, 29));
        p.drawLine(QPointF(19, 24), QPointF(29, 24));
        break;
    }
    case ToolIcon::OpenFile: {
        // A folder, its front flap open.
        QPainterPath back;
        back.moveTo(3, 26);
        back.lineTo(3, 7);
        back.lineTo(11, 7);
        back.lineTo(14, 10);
        back.lineTo(26, 10);
        back.lineTo(26, 14);
        p.setPen(QPen(kInk, 1.8, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
        p.drawPath(back);
        QPainterPath front;
        front.moveTo(3, 26);
        front.lineTo(8, 14);
        front.lineTo(30, 14);
        front.lineTo(25, 26);
        front.closeSubpath();
        p.setBrush(QColor(0xd6, 0xe6, 0xfa));
        p.drawPath(front);
        break;
    }
    case ToolIcon::SaveFile: {
        // A diskette: body, shutter and label.
        QPainterPath body;
        body.moveTo(4, 4);
        body.lineTo(24, 4);
        body.lineTo(28, 8);
        body.lineTo(28, 28);
        body.lineTo(4, 28);
        body.closeSubpath();
        p.setPen(QPen(kInk, 1.8, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin));
        p.setBrush(QColor(0xd6, 0xe6, 0xfa));
        p.drawPath(body);
        p.setBrush(kPaper);
        p.drawRect(QRectF(9, 4, 13, 8));
        p.drawRect(QRectF(8, 17, 16, 11));
        p.setPen(QPen(kAccent, 2));
        p.drawLine(QPointF(18, 6), QPointF(18, 10));
        break;
    }
    case ToolIcon::Undo:
    case ToolIcon::Redo: {
        p.save();
        if (icon == ToolIcon::Redo) {
            p.translate(32, 0);
            p.scale(-1, 1);
        }
        p.setPen(QPen(kInk, 2.6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        QPainterPath curve;
        curve.moveTo(8, 13);
        curve.lineTo(20, 13);
        curve.cubicTo(30, 13, 30, 27, 20, 27);
        curve.lineTo(12, 27);
        p.drawPath(curve);
        p.drawLine(QPointF(8, 13), QPointF(13, 8));
        p.drawLine(QPointF(8, 13), QPointF(13, 18));
        p.restore();
        break;
    }
    case ToolIcon::Pointer: {
        QPainterPath arrow;
        arrow.moveTo(9, 4);
        arrow.lineTo(9, 25);
        arrow.lineTo(14, 20);
        arrow.lineTo(18, 29);
        arrow.lineTo(21.5, 27.5);
        arrow.lineTo(17.5, 18.5);
        arrow.lineTo(24, 18.5);
        arrow.closeSubpath();
        p.setPen(QPen(kInk, 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(kPaper);
        p.drawPath(arrow);
        break;
    }
    }
}

} // namespace

QIcon toolIcon(ToolIcon icon) {
    QIcon result;
    for (const int size : {16, 24, 32, 48}) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter p(&pixmap);
        p.setRenderHint(QPainter::Antialiasing, true);
        p.scale(size / 32.0, size / 32.0);
        draw(p, icon);
        p.end();
        result.addPixmap(pixmap);
    }
    // Disabled (Undo with nothing to undo): QIcon derives a greyed form from these pixmaps.
    return result;
}

} // namespace rung::editor
