#include "terminal_widgets.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QProgressBar>
#include <QSlider>
#include <QSpinBox>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>

namespace rung::editor {

// ---- FlowLayout -------------------------------------------------------------------------

FlowLayout::FlowLayout(QWidget *parent, int spacing)
    : QLayout(parent)
    , m_spacing(spacing) {
    setContentsMargins(0, 0, 0, 0);
}

FlowLayout::~FlowLayout() {
    while (QLayoutItem *item = takeAt(0))
        delete item;
}

void FlowLayout::addItem(QLayoutItem *item) {
    m_items.append(item);
}

QLayoutItem *FlowLayout::itemAt(int index) const {
    return index >= 0 && index < m_items.size() ? m_items[index] : nullptr;
}

QLayoutItem *FlowLayout::takeAt(int index) {
    return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

int FlowLayout::heightForWidth(int width) const {
    return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::minimumSize() const {
    QSize size;
    for (const QLayoutItem *item : m_items)
        size = size.expandedTo(item->minimumSize());
    const QMargins m = contentsMargins();
    return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

QSize FlowLayout::sizeHint() const {
    // As wide as everything in one line; the dock gives the width, heightForWidth the rest.
    int width = 0;
    int height = 0;
    for (const QLayoutItem *item : m_items) {
        width += item->sizeHint().width() + m_spacing;
        height = std::max(height, item->sizeHint().height());
    }
    return {std::max(0, width - m_spacing), height};
}

void FlowLayout::setGeometry(const QRect &rect) {
    QLayout::setGeometry(rect);
    arrange(rect, true);
}

int FlowLayout::arrange(const QRect &rect, bool apply) const {
    const QRect area = rect.marginsRemoved(contentsMargins());
    int x = area.x();
    int y = area.y();
    int line = 0;
    for (QLayoutItem *item : m_items) {
        const QSize hint = item->sizeHint();
        if (x > area.x() && x + hint.width() > area.right() + 1) {
            x = area.x();
            y += line + m_spacing;
            line = 0;
        }
        if (apply)
            item->setGeometry(QRect(QPoint(x, y), hint));
        x += hint.width() + m_spacing;
        line = std::max(line, hint.height());
    }
    return y + line - rect.y() + contentsMargins().bottom();
}

// ---- TerminalFace -----------------------------------------------------------------------

namespace {

constexpr int kStateSize = 18; // the switch's, button's and lamp's drawing

QFont smaller(QFont font) {
    font.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.8));
    return font;
}

} // namespace

TerminalFace::TerminalFace(const QString &device, const QString &symbol, QWidget *parent)
    : QAbstractButton(parent)
    , m_device(device)
    , m_symbol(symbol) {
    setText(device);
    setToolTip(symbol.isEmpty() ? device : QStringLiteral("%1  %2").arg(device, symbol));
    setAccessibleName(toolTip());
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

QSize TerminalFace::sizeHint() const {
    const QFontMetrics fm(font());
    const QFontMetrics small(smaller(font()));
    // Narrow enough that a group of eight fits a dock of about 330 pixels.
    const int width = std::max({fm.horizontalAdvance(m_device) + 8, kStateSize + 14, 34});
    const int height = fm.height() + kStateSize + 8 + (small.height() + 1);
    return {width, height};
}

QRect TerminalFace::stateRect() const {
    const QFontMetrics fm(font());
    return QRect((width() - kStateSize) / 2, fm.height() + 3, kStateSize, kStateSize);
}

void TerminalFace::setState(bool on, bool forced) {
    if (on == m_on && forced == m_forced)
        return;
    m_on = on;
    m_forced = forced;
    update();
}

void TerminalFace::paintLabels(QPainter &p) const {
    const QFontMetrics fm(font());
    QFont bold = font();
    bold.setBold(m_on);
    p.setFont(bold);
    p.setPen(
        palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText));
    p.drawText(QRect(0, 0, width(), fm.height()), Qt::AlignCenter, m_device);
    if (!m_symbol.isEmpty()) {
        const QFont small = smaller(font());
        p.setFont(small);
        const QFontMetrics sm(small);
        const QRect r(1, stateRect().bottom() + 4, width() - 2, sm.height());
        p.drawText(r, Qt::AlignCenter, sm.elidedText(m_symbol, Qt::ElideRight, r.width()));
    }
    if (hasFocus()) {
        p.setPen(QPen(palette().color(QPalette::Highlight), 1, Qt::DotLine));
        p.setBrush(Qt::NoBrush);
        p.drawRect(rect().adjusted(0, 0, -1, -1));
    }
}

void TerminalFace::paintForced(QPainter &p) const {
    if (!m_forced)
        return;
    // "F" in a box at the top right, as the ladder marks a forced device.
    QFont f = smaller(font());
    f.setBold(true);
    p.setFont(f);
    const QFontMetrics fm(f);
    const QRect box(width() - fm.horizontalAdvance(QLatin1Char('F')) - 5, 0,
                    fm.horizontalAdvance(QLatin1Char('F')) + 4, fm.height());
    p.setPen(palette().color(QPalette::WindowText));
    p.setBrush(palette().color(QPalette::Base));
    p.drawRect(box);
    p.drawText(box, Qt::AlignCenter, QStringLiteral("F"));
}

// ---- InputTerminal ----------------------------------------------------------------------

InputTerminal::InputTerminal(const QString &device, const QString &symbol, QWidget *parent)
    : TerminalFace(device, symbol, parent) {
    setFocusPolicy(Qt::StrongFocus);
    setCursor(Qt::PointingHandCursor);
    // QAbstractButton: a press of the mouse or of Space emits pressed(), its release
    // released() and clicked(); auto-repeated keys do not press again.
    connect(this, &QAbstractButton::pressed, this, [this] {
        if (m_mode == Mode::PushButton)
            emit requested(true);
    });
    connect(this, &QAbstractButton::released, this, [this] {
        if (m_mode == Mode::PushButton)
            emit requested(false);
    });
    connect(this, &QAbstractButton::clicked, this, [this] {
        if (m_mode == Mode::Switch)
            emit requested(!m_on);
    });
}

void InputTerminal::setMode(Mode mode) {
    m_mode = mode;
    update();
}

void InputTerminal::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor ink =
        palette().color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText);
    const QColor fill = QColor(0x2e, 0x7d, 0x32); // green, and filled: ON reads without it
    const QRect r = stateRect();
    if (m_mode == Mode::Switch) {
        // A slide switch: the knob right and the track filled when ON.
        const QRectF track(r.center().x() - 13.0, r.center().y() - 6.0, 26.0, 12.0);
        p.setPen(QPen(ink, m_on ? 2 : 1));
        p.setBrush(m_on ? fill : palette().color(QPalette::Base));
        p.drawRoundedRect(track, track.height() / 2, track.height() / 2);
        const double d = track.height() - 4;
        const QRectF knob(m_on ? track.right() - d - 2 : track.left() + 2, track.top() + 2, d, d);
        p.setBrush(palette().color(QPalette::Button));
        p.setPen(QPen(ink, 1));
        p.drawEllipse(knob);
    } else {
        // A round push button, pressed in (filled, heavy ring) while ON.
        p.setPen(QPen(ink, m_on ? 3 : 1));
        p.setBrush(m_on ? fill : palette().color(QPalette::Button));
        p.drawEllipse(QRectF(r).adjusted(2, 2, -2, -2));
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(ink, 1));
        p.drawEllipse(QRectF(r).adjusted(5, 5, -5, -5));
    }
    paintLabels(p);
    paintForced(p);
}

// ---- Lamp -------------------------------------------------------------------------------

Lamp::Lamp(const QString &device, const QString &symbol, QWidget *parent)
    : TerminalFace(device, symbol, parent) {
    setFocusPolicy(Qt::NoFocus);
    setEnabled(true);
}

void Lamp::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QColor ink = palette().color(QPalette::WindowText);
    const QRectF r = QRectF(stateRect()).adjusted(1, 1, -1, -1);
    if (m_on) {
        // Lit: filled amber with a heavy ring and rays, as a panel lamp glows.
        p.setPen(QPen(ink, 3));
        p.setBrush(QColor(0xff, 0xb3, 0x00));
        p.drawEllipse(r);
    } else {
        p.setPen(QPen(ink, 1));
        p.setBrush(palette().color(QPalette::Base));
        p.drawEllipse(r);
        // A cross through an unlit lamp, as a lamp is drawn in a wiring diagram.
        p.setPen(QPen(palette().color(QPalette::Mid), 1));
        const QPointF c = r.center();
        const double k = r.width() * 0.35;
        p.drawLine(c + QPointF(-k, -k), c + QPointF(k, k));
        p.drawLine(c + QPointF(-k, k), c + QPointF(k, -k));
    }
    paintLabels(p);
    paintForced(p);
}

// ---- AnalogTerminal ---------------------------------------------------------------------

AnalogTerminal::AnalogTerminal(const QString &device, const QString &symbol, int lowest,
                               int highest, bool input, QWidget *parent)
    : QWidget(parent)
    , m_device(device) {
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto *name =
        new QLabel(symbol.isEmpty() ? device : QStringLiteral("%1 %2").arg(device, symbol));
    name->setToolTip(name->text());
    name->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(device) + 4);
    name->setMaximumWidth(QFontMetrics(font()).averageCharWidth() * 16);
    layout->addWidget(name);
    if (input) {
        m_slider = new QSlider(Qt::Horizontal);
        m_slider->setRange(lowest, highest);
        m_slider->setMinimumWidth(80);
        m_slider->setAccessibleName(device);
        m_spin = new QSpinBox;
        m_spin->setRange(lowest, highest);
        m_spin->setAccessibleName(device);
        m_spin->setKeyboardTracking(false); // typed digits go out on Enter or leaving the box
        layout->addWidget(m_slider, 1);
        layout->addWidget(m_spin);
        connect(m_slider, &QSlider::valueChanged, this, [this](int v) {
            if (m_updating)
                return;
            m_updating = true;
            m_spin->setValue(v);
            m_updating = false;
            emit requested(v);
        });
        connect(m_spin, &QSpinBox::valueChanged, this, [this](int v) {
            if (m_updating)
                return;
            m_updating = true;
            m_slider->setValue(v);
            m_updating = false;
            emit requested(v);
        });
    } else {
        auto *bar = new QProgressBar;
        bar->setRange(lowest, highest);
        bar->setTextVisible(false);
        bar->setMinimumWidth(80);
        bar->setMaximumHeight(QFontMetrics(font()).height());
        m_shown = new QLabel(QStringLiteral("0"));
        m_shown->setMinimumWidth(QFontMetrics(font()).horizontalAdvance(QString::number(lowest)) +
                                 6);
        m_shown->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        layout->addWidget(bar, 1);
        layout->addWidget(m_shown);
        bar->setObjectName(QStringLiteral("bar"));
    }
    m_unreadable = new QLabel;
    m_unreadable->hide();
    layout->addWidget(m_unreadable);
}

void AnalogTerminal::setUnreadable(const QString &text) {
    m_unreadable->setText(text);
    m_unreadable->show();
    if (m_shown) { // an output shows nothing it cannot read
        m_shown->clear();
        if (auto *bar = findChild<QProgressBar *>(QStringLiteral("bar")))
            bar->setValue(bar->minimum());
    }
}

QString AnalogTerminal::unreadable() const {
    return m_unreadable->isHidden() ? QString() : m_unreadable->text();
}

void AnalogTerminal::setValue(int value) {
    m_unreadable->hide();
    if (m_slider) {
        // The slider the user holds stays where it is held; the box being typed in too.
        if (m_slider->isSliderDown() || m_spin->hasFocus())
            return;
        m_updating = true;
        m_slider->setValue(value);
        m_spin->setValue(value);
        m_updating = false;
        return;
    }
    if (auto *bar = findChild<QProgressBar *>(QStringLiteral("bar")))
        bar->setValue(std::clamp(value, bar->minimum(), bar->maximum()));
    m_shown->setText(QString::number(value));
}

int AnalogTerminal::value() const {
    return m_spin ? m_spin->value() : m_shown->text().toInt();
}

} // namespace rung::editor
