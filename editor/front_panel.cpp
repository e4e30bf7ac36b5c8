#include "front_panel.h"

#include "terminal_widgets.h"

#include "model/target/address.h"

#include <QCoreApplication>
#include <QDial>
#include <QEvent>
#include <QFontDatabase>
#include <QGroupBox>
#include <QKeyEvent>
#include <QKeySequence>
#include <QLabel>
#include <QPainter>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace rung::editor {

namespace {

QString tableText(const char *text) {
    return text ? QCoreApplication::translate("rung::model::Target", text) : QString();
}

QColor lampColour(model::LampColour colour, bool lit) {
    QColor c;
    switch (colour) {
    case model::LampColour::Green:
        c = QColor(0x2e, 0xc4, 0x40);
        break;
    case model::LampColour::Red:
        c = QColor(0xe0, 0x30, 0x30);
        break;
    case model::LampColour::Yellow:
        c = QColor(0xf0, 0xd0, 0x20);
        break;
    case model::LampColour::Orange:
        c = QColor(0xf0, 0x90, 0x20);
        break;
    case model::LampColour::Unstated: // drawn plainly by PanelLamp::paintEvent
        break;
    }
    return lit ? c : c.darker(300);
}

// The SWAP / UP / DOWN / SET of a key's shortcut text as a Qt key.
int qtKeyOf(const QString &shortcut) {
    const QKeySequence sequence(shortcut);
    return sequence.isEmpty() ? 0 : sequence[0].key();
}

} // namespace

// ---- PanelLamp --------------------------------------------------------------------------

PanelLamp::PanelLamp(const QString &label, model::LampColour colour, QWidget *parent)
    : QWidget(parent)
    , m_label(label)
    , m_colour(colour) {
    setObjectName(QStringLiteral("panelLamp_") + label);
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void PanelLamp::setState(bool lit, int blinkMs) {
    if (lit == m_lit && blinkMs == m_blinkMs)
        return;
    m_lit = lit;
    m_blinkMs = blinkMs;
    update();
}

QSize PanelLamp::sizeHint() const {
    const QFontMetrics fm(font());
    const int disc = fm.height();
    return {disc + fm.horizontalAdvance(QLatin1Char(' ')) + fm.horizontalAdvance(m_label) + 4,
            disc + 4};
}

void PanelLamp::paintEvent(QPaintEvent *) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics fm(font());
    const int disc = fm.height();
    const QRectF circle(2, 2, disc - 2, disc - 2);
    p.setPen(QPen(palette().color(QPalette::WindowText), 1));
    // A lamp the manual gives no colour: filled when ON, empty when OFF, in the text's colours.
    if (m_colour == model::LampColour::Unstated)
        p.setBrush(palette().color(m_lit ? QPalette::WindowText : QPalette::Base));
    else
        p.setBrush(lampColour(m_colour, m_lit));
    p.drawEllipse(circle);
    p.setPen(palette().color(QPalette::WindowText));
    p.drawText(QRect(disc + fm.horizontalAdvance(QLatin1Char(' ')), 0, width(), height()),
               Qt::AlignLeft | Qt::AlignVCenter, m_label);
}

// ---- PanelDisplay -----------------------------------------------------------------------

PanelDisplay::PanelDisplay(QWidget *parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("panelDisplay"));
    setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
}

void PanelDisplay::setView(const model::PanelView *view) {
    m_view = view;
    updateGeometry();
    update();
}

QFont PanelDisplay::displayFont() const {
    QFont f = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    const qreal base = font().pointSizeF() > 0 ? font().pointSizeF() : 10.0;
    // The digits are the panel's main reading: large; the OLED's 21 columns and the LCD's 16
    // at the window's size.
    const bool digits = m_view && m_view->display == model::DisplayKind::Digits && m_view->fits;
    f.setPointSizeF(digits ? base * 2.6 : base);
    f.setBold(digits);
    return f;
}

QStringList PanelDisplay::rows() const {
    if (!m_view)
        return {};
    switch (m_view->display) {
    case model::DisplayKind::Digits:
        return {m_view->digitsText.isEmpty() ? QString(m_view->digits, QLatin1Char(' '))
                                             : m_view->digitsText};
    case model::DisplayKind::Text:
        return m_view->lines;
    case model::DisplayKind::IoLines: {
        QStringList out;
        for (qsizetype k = 0; k < m_view->lines.size(); ++k)
            out << m_view->lineLabels.value(k).leftJustified(4, QLatin1Char(' ')) +
                       m_view->lines[k];
        return out;
    }
    case model::DisplayKind::None:
        break;
    }
    return {};
}

QString PanelDisplay::text() const {
    return rows().join(QLatin1Char('\n'));
}

QSize PanelDisplay::sizeHint() const {
    const QStringList lines = rows();
    if (lines.isEmpty())
        return {0, 0};
    const QFontMetrics fm(displayFont());
    int width = 0;
    for (const QString &line : lines)
        width = std::max(width, fm.horizontalAdvance(line));
    const int margin = fm.height() / 2;
    return {width + 2 * margin, static_cast<int>(lines.size()) * fm.lineSpacing() + 2 * margin};
}

void PanelDisplay::paintEvent(QPaintEvent *) {
    const QStringList lines = rows();
    if (lines.isEmpty())
        return;
    QPainter p(this);
    const QFont f = displayFont();
    const QFontMetrics fm(f);
    const int margin = fm.height() / 2;
    // A dark screen with light characters: the manuals show no more of the look.
    p.fillRect(rect(), QColor(0x10, 0x14, 0x18));
    QColor ink = QColor(0xe8, 0xf0, 0xff);
    if (m_view->display == model::DisplayKind::Digits)
        ink = QColor(0xff, 0x60, 0x40);
    else if (m_view->display == model::DisplayKind::IoLines)
        ink = QColor(0xc8, 0xf0, 0xa0);
    // The standby dims the characters (PL110 SM100: 0 % is a dark screen).
    const QColor screen(0x10, 0x14, 0x18);
    const double light = std::clamp(m_view->brightness, 0, 100) / 100.0;
    const auto mix = [&](const QColor &c) {
        return QColor::fromRgbF(screen.redF() + (c.redF() - screen.redF()) * light,
                                screen.greenF() + (c.greenF() - screen.greenF()) * light,
                                screen.blueF() + (c.blueF() - screen.blueF()) * light);
    };
    ink = mix(ink);
    p.setFont(f);
    p.setPen(ink);
    for (qsizetype k = 0; k < lines.size(); ++k)
        p.drawText(margin, margin + static_cast<int>(k) * fm.lineSpacing() + fm.ascent(), lines[k]);
    if (m_view->display != model::DisplayKind::Text)
        return;
    // The field the keys edit "viene visualizzato in reverse" (PL110 manual 5.2); the digit UP
    // and DOWN change is underlined.
    for (const model::PanelFieldView &field : m_view->fields) {
        if (!field.editing || field.row >= lines.size() || lines[field.row].isEmpty())
            continue;
        // A character's width as the row was drawn (a fallback font's advance may differ
        // from its 'M').
        const QString &row = lines[field.row];
        const int left = fm.horizontalAdvance(row.left(field.column));
        const int width = fm.horizontalAdvance(row.mid(field.column, field.length));
        const QRect box(margin + left, margin + field.row * fm.lineSpacing(), width,
                        fm.lineSpacing());
        const int cell = field.length > 0 ? width / field.length : 0;
        p.fillRect(box, ink);
        p.setPen(screen);
        p.drawText(box.left(), box.top() + fm.ascent(),
                   lines[field.row].mid(field.column, field.length));
        if (field.cursor >= 0)
            p.fillRect(QRect(box.left() + field.cursor * cell, box.bottom() - 1, cell, 2), screen);
        p.setPen(ink);
    }
}

// ---- FrontPanel -------------------------------------------------------------------------

FrontPanel::FrontPanel(QWidget *parent)
    : QWidget(parent) {
    setObjectName(QStringLiteral("frontPanel"));
    setFocusPolicy(Qt::StrongFocus);
    m_clock.start();
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    m_hint = new QLabel;
    m_hint->setObjectName(QStringLiteral("frontPanelHint"));
    m_hint->setWordWrap(true);
    outer->addWidget(m_hint);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    // A click on the display or beside the keys gives the panel the focus, not the scroll
    // area: the arrow keys then press UP / DOWN instead of scrolling.
    scroll->setFocusPolicy(Qt::NoFocus);
    m_parts = new QWidget;
    auto *parts = new QVBoxLayout(m_parts);
    parts->setContentsMargins(0, 0, 0, 0);
    m_display = new PanelDisplay;
    m_display->setView(&m_view);
    parts->addWidget(m_display, 0, Qt::AlignLeft);
    m_caption = new QLabel;
    m_caption->setObjectName(QStringLiteral("frontPanelCaption"));
    m_caption->setWordWrap(true);
    parts->addWidget(m_caption);
    auto *lamps = new QWidget;
    m_lampRow = new FlowLayout(lamps, 6);
    parts->addWidget(lamps);
    auto *keys = new QWidget;
    m_keyRow = new FlowLayout(keys, 4);
    parts->addWidget(keys);
    auto *knobs = new QWidget;
    m_knobRow = new FlowLayout(knobs, 10);
    parts->addWidget(knobs);
    parts->addStretch(1);
    scroll->setWidget(m_parts);
    outer->addWidget(scroll, 1);
    m_blink.setInterval(50);
    connect(&m_blink, &QTimer::timeout, this, &FrontPanel::refresh);
    retranslate();
}

void FrontPanel::setPlc(const model::Target *target, const QString &modelName) {
    if (target == m_target && modelName == m_modelName)
        return;
    m_target = target;
    m_modelName = modelName;
    rebuild();
}

void FrontPanel::setMonitorSource(model::MonitorSource *source) {
    if (model::MonitorSource::switchSource(m_source, source, this)) {
        m_watched.clear();
        m_terminal = {};
        if (!source) {
            refresh();
            return;
        }
        connect(source, &model::MonitorSource::snapshotChanged, this, &FrontPanel::refresh);
        connect(source, &model::MonitorSource::runStateChanged, this, &FrontPanel::refresh);
        connect(source, &model::MonitorSource::errorTextChanged, this, &FrontPanel::refresh);
        connect(source, &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                    if (!ok)
                        emit message(error);
                });
    }
    refresh();
}

void FrontPanel::setContext(std::optional<model::PanelContext> context) {
    m_context = std::move(context);
    refresh();
}

void FrontPanel::rebuild() {
    for (PanelLamp *l : m_lamps)
        delete l;
    for (QToolButton *k : m_keys)
        delete k;
    for (Knob &k : m_knobs)
        delete k.dial->parentWidget();
    m_lamps.clear();
    m_keys.clear();
    m_knobs.clear();
    m_terminal = {};
    if (m_target) {
        const model::ModelVariant *variant = m_target->model(m_modelName);
        const model::PanelView shape = model::panelView(*m_target, variant, {});
        for (const model::PanelLampView &l : shape.lamps) {
            auto *lamp = new PanelLamp(l.label, l.colour);
            m_lampRow->addWidget(lamp);
            m_lamps.push_back(lamp);
        }
        for (std::size_t k = 0; k < shape.keys.size(); ++k) {
            auto *button = new QToolButton;
            button->setText(shape.keys[k].label);
            button->setObjectName(QStringLiteral("panelKey_") + shape.keys[k].label);
            button->setAutoRepeat(false);
            button->setToolButtonStyle(Qt::ToolButtonTextOnly);
            // The keys as the terminal has them, side by side: a tool button is as wide as its
            // word (a push button's style minimum put SET and DOWN on a second row).
            button->setFocusPolicy(Qt::StrongFocus);
            connect(button, &QToolButton::pressed, this, [this, k] { pressKey(k, true); });
            // Released, the panel takes the focus from the button: the arrow keys then press
            // UP and DOWN, as the shortcuts say, instead of moving between the buttons.
            connect(button, &QToolButton::released, this, [this, k] {
                pressKey(k, false);
                setFocus(Qt::MouseFocusReason);
            });
            m_keyRow->addWidget(button);
            m_keys.push_back(button);
        }
        for (std::size_t k = 0; k < shape.knobs.size(); ++k) {
            const model::PanelKnobView &kv = shape.knobs[k];
            auto *box = new QWidget;
            auto *column = new QVBoxLayout(box);
            column->setContentsMargins(0, 0, 0, 0);
            column->setSpacing(2);
            auto *name = new QLabel(kv.label);
            name->setAlignment(Qt::AlignHCenter);
            auto *dial = new QDial;
            dial->setObjectName(QStringLiteral("panelKnob_") + kv.label);
            dial->setRange(kv.lowest, kv.highest);
            dial->setNotchesVisible(true);
            const int side = QFontMetrics(font()).height() * 3;
            dial->setFixedSize(side, side);
            auto *number = new QSpinBox;
            number->setObjectName(QStringLiteral("panelKnobNumber_") + kv.label);
            number->setRange(kv.lowest, kv.highest);
            number->setKeyboardTracking(false);
            column->addWidget(name);
            column->addWidget(dial, 0, Qt::AlignHCenter);
            column->addWidget(number, 0, Qt::AlignHCenter);
            connect(dial, &QDial::valueChanged, this, [this, k](int v) { writeKnob(k, v); });
            connect(number, &QSpinBox::valueChanged, this, [this, k](int v) { writeKnob(k, v); });
            m_knobRow->addWidget(box);
            m_knobs.push_back({kv.label, dial, number});
        }
    }
    retranslate();
    refresh();
}

void FrontPanel::retranslate() {
    if (m_target) {
        const model::PanelView shape =
            model::panelView(*m_target, m_target->model(m_modelName), {});
        for (std::size_t k = 0; k < m_lamps.size() && k < shape.lamps.size(); ++k)
            m_lamps[k]->setToolTip(tableText(shape.lamps[k].meaning));
        for (std::size_t k = 0; k < m_keys.size() && k < shape.keys.size(); ++k)
            m_keys[k]->setToolTip(
                tr("%1: %2 (key %3; held down, %4 is 1)")
                    .arg(shape.keys[k].label, tableText(shape.keys[k].meaning),
                         QKeySequence(shape.keys[k].shortcut).toString(QKeySequence::NativeText),
                         model::formatAddress(*m_target, shape.keys[k].address)));
        for (std::size_t k = 0; k < m_knobs.size() && k < shape.knobs.size(); ++k) {
            const QString tip = tr("%1: %2 (writes %3)")
                                    .arg(shape.knobs[k].label, tableText(shape.knobs[k].meaning),
                                         model::formatAddress(*m_target, shape.knobs[k].address));
            m_knobs[k].dial->setToolTip(tip);
            m_knobs[k].number->setToolTip(tip);
        }
    }
    refresh();
}

void FrontPanel::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString FrontPanel::hint() const {
    return m_hint->isVisible() ? m_hint->text() : QString();
}

void FrontPanel::refresh() {
    const bool hasPanel = m_target && model::hasFrontPanel(*m_target, m_target->model(m_modelName));
    std::shared_ptr<const model::Snapshot> snapshot = m_source ? m_source->snapshot() : nullptr;
    // A source of another PLC than the panel's (a moment between two switches) shows nothing.
    if (snapshot && (!snapshot->layout || &snapshot->layout->target() != m_target))
        snapshot.reset();
    model::PanelInput input;
    input.snapshot = snapshot.get();
    input.runState = m_source ? m_source->runState() : model::MonitorSource::RunState::Offline;
    input.fault = m_source && !m_source->errorText().isEmpty();
    input.nowMs = m_clock.elapsed();
    input.context = m_context ? &*m_context : nullptr;
    if (snapshot && hasPanel) {
        model::terminalTick(*m_target, *snapshot, m_terminal, input.nowMs);
        input.terminal = &m_terminal;
    } else {
        m_terminal = {};
    }
    m_view = hasPanel ? model::panelView(*m_target, m_target->model(m_modelName), input)
                      : model::PanelView{};
    // An online PLC is polled for what the panel shows (the page's characters, the register the
    // display names: they change with the PLC's words).
    std::vector<model::Address> devices = m_view.devices;
    std::sort(devices.begin(), devices.end());
    devices.erase(std::unique(devices.begin(), devices.end()), devices.end());
    if (m_source && devices != m_watched) {
        m_watched = devices;
        m_source->setWatched(this, std::move(devices));
    }
    QString hint;
    if (!hasPanel)
        hint = tr("This PLC has no front panel that its manual describes");
    else if (!snapshot)
        hint = tr("Run the simulation (F10) to see the PLC's front panel");
    m_hint->setText(hint);
    m_hint->setVisible(!hint.isEmpty());
    m_parts->setVisible(hasPanel);
    bool blinking = false;
    for (std::size_t k = 0; k < m_lamps.size() && k < m_view.lamps.size(); ++k) {
        m_lamps[k]->setState(m_view.lamps[k].lit, m_view.lamps[k].blinkMs);
        blinking = blinking || m_view.lamps[k].blinkMs > 0;
    }
    // SET held: the password page opens after its hold without waiting for a snapshot.
    blinking = blinking || m_terminal.setDownMs >= 0;
    if (blinking && !m_blink.isActive())
        m_blink.start();
    else if (!blinking)
        m_blink.stop();
    for (std::size_t k = 0; k < m_knobs.size() && k < m_view.knobs.size(); ++k) {
        Knob &knob = m_knobs[k];
        knob.dial->setEnabled(snapshot != nullptr);
        knob.number->setEnabled(snapshot != nullptr);
        // Not under the user's hand: the value the PLC holds.
        if (!knob.dial->isSliderDown() && !knob.number->hasFocus()) {
            const QSignalBlocker a(knob.dial), b(knob.number);
            knob.dial->setValue(m_view.knobs[k].value);
            knob.number->setValue(m_view.knobs[k].value);
        }
    }
    for (QToolButton *key : m_keys)
        key->setEnabled(snapshot != nullptr);
    QString caption;
    const model::PanelDisplay &d = m_target ? m_target->panel.display : model::PanelDisplay{};
    if (snapshot && m_view.display == model::DisplayKind::Digits)
        caption = tr("Display mode %1 (%2)").arg(m_view.mode).arg(d.modeDevice);
    else if (snapshot && m_view.display == model::DisplayKind::Text && m_view.page > 0)
        caption = tr("Page %1 (%2)").arg(m_view.page).arg(d.pageShownDevice);
    // The note says the mode or that no page is shown in place of the caption; on a page shown
    // it says what the page's values are (a system page's), below the page's number.
    if (!m_view.note.isEmpty())
        caption = m_view.page > 0 && !caption.isEmpty() ? caption + QLatin1Char('\n') + m_view.note
                                                        : m_view.note;
    m_caption->setText(caption);
    m_caption->setVisible(!caption.isEmpty());
    m_display->setVisible(m_view.display != model::DisplayKind::None);
    m_display->setView(&m_view);
    m_display->setAccessibleDescription(m_display->text());
}

void FrontPanel::writeKnob(std::size_t index, int value) {
    if (!m_source || index >= m_view.knobs.size())
        return;
    const model::PanelKnobView &knob = m_view.knobs[index];
    {
        const QSignalBlocker a(m_knobs[index].dial), b(m_knobs[index].number);
        m_knobs[index].dial->setValue(value);
        m_knobs[index].number->setValue(value);
    }
    m_source->writeWord(knob.address, model::panelKnobWord(knob, value));
}

void FrontPanel::pressKey(std::size_t index, bool down) {
    if (!m_source || !m_target || index >= m_view.keys.size())
        return;
    const model::PanelKeyView &key = m_view.keys[index];
    std::shared_ptr<const model::Snapshot> snapshot = m_source->snapshot();
    if (snapshot && (!snapshot->layout || &snapshot->layout->target() != m_target))
        snapshot.reset();
    const model::PanelKeyAction action = model::panelKeyAction(
        *m_target, snapshot.get(), m_terminal, key.role, down, m_clock.elapsed());
    if (action.writeBit)
        m_source->writeBit(key.address, down);
    for (const model::TerminalWrite &w : action.words)
        m_source->writeWord(w.device, w.value);
    if (key.role != model::PanelKeyRole::Other && snapshot)
        refresh();
}

int FrontPanel::keyIndexFor(int qtKey) const {
    for (std::size_t k = 0; k < m_view.keys.size(); ++k)
        if (qtKeyOf(m_view.keys[k].shortcut) == qtKey)
            return static_cast<int>(k);
    return -1;
}

void FrontPanel::keyPressEvent(QKeyEvent *event) {
    const int k = keyIndexFor(event->key());
    if (k < 0 || static_cast<std::size_t>(k) >= m_keys.size() || !m_keys[k]->isEnabled()) {
        QWidget::keyPressEvent(event);
        return;
    }
    if (!event->isAutoRepeat()) {
        m_keys[k]->setDown(true);
        pressKey(static_cast<std::size_t>(k), true);
    }
    event->accept();
}

void FrontPanel::keyReleaseEvent(QKeyEvent *event) {
    const int k = keyIndexFor(event->key());
    if (k < 0 || static_cast<std::size_t>(k) >= m_keys.size() || !m_keys[k]->isEnabled()) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    if (!event->isAutoRepeat()) {
        m_keys[k]->setDown(false);
        pressKey(static_cast<std::size_t>(k), false);
    }
    event->accept();
}

QDial *FrontPanel::knob(const QString &label) const {
    for (const Knob &k : m_knobs)
        if (k.label == label)
            return k.dial;
    return nullptr;
}

QSpinBox *FrontPanel::knobNumber(const QString &label) const {
    for (const Knob &k : m_knobs)
        if (k.label == label)
            return k.number;
    return nullptr;
}

QToolButton *FrontPanel::key(const QString &label) const {
    for (QToolButton *k : m_keys)
        if (k->text() == label)
            return k;
    return nullptr;
}

PanelLamp *FrontPanel::lamp(const QString &label) const {
    for (PanelLamp *l : m_lamps)
        if (l->objectName() == QStringLiteral("panelLamp_") + label)
            return l;
    return nullptr;
}

} // namespace rung::editor
