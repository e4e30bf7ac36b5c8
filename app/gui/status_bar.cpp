#include "status_bar.h"

#include <QHelpEvent>
#include <QPainter>
#include <QSizeGrip>
#include <QStyle>
#include <QStyleOption>
#include <QToolTip>

namespace rung::app {

namespace {
constexpr int kMargin = 6; // Qt's own left margin of a message
constexpr int kGap = 16;   // between the message and the first field
} // namespace

StatusBar::StatusBar(QWidget *parent)
    : QStatusBar(parent) {
    connect(this, &QStatusBar::messageChanged, this, [this] { update(); });
}

QRect StatusBar::messageArea() const {
    // While a message shows, the fields that stay are the permanent ones.
    int right = width() - kMargin;
    for (const QWidget *w : findChildren<QWidget *>(Qt::FindDirectChildrenOnly))
        if (w->isVisible() && !qobject_cast<const QSizeGrip *>(w))
            right = std::min(right, w->x() - kGap);
    return QRect(kMargin, 0, std::max(0, right - kMargin), height());
}

QString StatusBar::shownMessage() const {
    return fontMetrics().elidedText(currentMessage(), Qt::ElideRight, messageArea().width());
}

void StatusBar::paintEvent(QPaintEvent *event) {
    if (currentMessage().isEmpty()) {
        QStatusBar::paintEvent(event);
        return;
    }
    // As QStatusBar paints: the panel, the frames of the fields shown; then the message.
    QPainter p(this);
    QStyleOption panel;
    panel.initFrom(this);
    style()->drawPrimitive(QStyle::PE_PanelStatusBar, &panel, &p, this);
    for (QWidget *w : findChildren<QWidget *>(Qt::FindDirectChildrenOnly)) {
        if (!w->isVisible() || qobject_cast<QSizeGrip *>(w))
            continue;
        QStyleOption frame(0);
        frame.rect = w->geometry().adjusted(-2, -1, 2, 1);
        frame.palette = palette();
        frame.state = QStyle::State_None;
        style()->drawPrimitive(QStyle::PE_FrameStatusBarItem, &frame, &p, w);
    }
    p.setPen(palette().windowText().color());
    p.drawText(messageArea(), Qt::AlignLeading | Qt::AlignVCenter | Qt::TextSingleLine,
               shownMessage());
}

bool StatusBar::event(QEvent *event) {
    if (event->type() == QEvent::ToolTip && !currentMessage().isEmpty()) {
        const auto *help = static_cast<QHelpEvent *>(event);
        if (messageArea().contains(help->pos()) && shownMessage() != currentMessage()) {
            QToolTip::showText(help->globalPos(), currentMessage(), this);
            return true;
        }
    }
    return QStatusBar::event(event);
}

} // namespace rung::app
