#include "eliding_label.h"

#include <QFontMetrics>

namespace rung::app {

ElidingLabel::ElidingLabel(QWidget *parent)
    : QLabel(parent) {}

void ElidingLabel::setFullText(const QString &text) {
    m_full = text;
    setToolTip(text);
    elide();
    updateGeometry();
}

QSize ElidingLabel::sizeHint() const {
    // What the whole text needs, whatever part of it is shown now.
    const QSize hint = QLabel::sizeHint();
    const QFontMetrics metrics(font());
    return {hint.width() - metrics.horizontalAdvance(text()) + metrics.horizontalAdvance(m_full),
            hint.height()};
}

QSize ElidingLabel::minimumSizeHint() const {
    // Room for a few characters and the ellipsis; the rest is the layout's to give.
    const QFontMetrics metrics(font());
    const QSize hint = QLabel::minimumSizeHint();
    return {std::min(hint.width(), metrics.horizontalAdvance(QLatin1Char('x')) * 12),
            hint.height()};
}

void ElidingLabel::resizeEvent(QResizeEvent *event) {
    QLabel::resizeEvent(event);
    elide();
}

void ElidingLabel::elide() {
    const int room = contentsRect().width();
    const QString shown = fontMetrics().elidedText(m_full, Qt::ElideRight, room);
    if (shown != text())
        QLabel::setText(shown);
}

} // namespace rung::app
