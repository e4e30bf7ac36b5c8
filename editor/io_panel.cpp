#include "io_panel.h"

#include "document.h"
#include "terminal_widgets.h"

#include "model/image/bcd.h"
#include "model/image/value_format.h"
#include "model/target/address.h"

#include <QComboBox>
#include <QContextMenuEvent>
#include <QCoreApplication>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QResizeEvent>
#include <QScrollArea>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace rung::editor {

namespace {

// How many further devices the program uses are shown beyond the strip (an expansion).
constexpr int kMaxExtra = 64;

int areaIndex(const model::Target &t, const QString &key) {
    for (int k = 0; k < static_cast<int>(t.areas.size()); ++k)
        if (t.area(k).key == key)
            return k;
    return -1;
}

std::int32_t toBcd(int value) { // four digits: the word of a CPM1 channel
    return static_cast<std::int32_t>(model::toBcd(value % 10000));
}

// Sections of the panel: bit inputs, bit outputs, word inputs, word outputs.
enum Section { Inputs, Outputs, AnalogInputs, AnalogOutputs, Sections };

} // namespace

IoPanel::IoPanel(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document) {
    setObjectName(QStringLiteral("ioPanel"));
    auto *outer = new QVBoxLayout(this);
    outer->setContentsMargins(4, 4, 4, 4);
    m_hint = new QLabel;
    m_hint->setWordWrap(true);
    m_mode = new QComboBox;
    m_mode->setObjectName(QStringLiteral("ioInputMode"));
    // As narrow as the terminals' grid: the panel is a column beside the ladder.
    m_mode->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_mode->setMinimumContentsLength(10);
    m_mode->addItems({QString(), QString()});
    outer->addWidget(m_mode);
    outer->addWidget(m_hint);
    auto *scroll = new QScrollArea;
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    m_content = new QWidget;
    m_layout = new QVBoxLayout(m_content);
    m_layout->setContentsMargins(0, 0, 0, 0);
    scroll->setWidget(m_content);
    outer->addWidget(scroll, 1);
    connect(m_mode, &QComboBox::activated, this,
            [this](int index) { setAllPushButtons(index == 1); });
    connect(document, &Document::programChanged, this, &IoPanel::rebuild);
    retranslate();
    rebuild();
}

void IoPanel::retranslate() {
    m_mode->setItemText(0, tr("Inputs are switches"));
    m_mode->setItemText(1, tr("Inputs are push buttons"));
    m_mode->setToolTip(tr("A switch stays where it is put; a push button is ON only while held "
                          "(mouse, or Space on the focused button). The right button sets one "
                          "input on its own"));
    m_hint->setText(m_source ? tr("Inputs take effect at the next scan")
                             : tr("Run the simulation (F10) to work the inputs"));
    m_shape.clear(); // group titles and section names are texts too
    rebuild();
}

void IoPanel::resizeEvent(QResizeEvent *event) {
    QWidget::resizeEvent(event);
    // A group of eight side by side wants about 8 terminals' width; a dock narrower than
    // that shows each group as two rows of four rather than cut it or scroll sideways.
    int terminal = 48;
    for (const Terminal &t : m_terminals)
        if (qobject_cast<TerminalFace *>(t.widget))
            terminal = std::max(terminal, t.widget->sizeHint().width());
    const int perRow = width() >= 8 * (terminal + 2) + 40 ? 8 : 4;
    if (perRow != m_perRow) {
        m_perRow = perRow;
        m_shape.clear();
        rebuild();
    }
}

void IoPanel::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

QString IoPanel::symbolOf(const model::Address &address) const {
    const model::Symbol *s = m_document->project().symbol(address);
    return s ? s->name : QString();
}

void IoPanel::rebuild() {
    const model::Target &t = m_document->target();
    const model::ModelVariant *variant = m_document->modelVariant();
    // The strip, then what the program uses beyond it.
    struct Block {
        QString title;
        std::vector<model::Address> devices;
        int lowest = 0, highest = 0;
        bool bcd = false;
    };
    std::vector<Block> blocks[Sections];
    std::set<model::Address> onStrip;
    for (const model::TerminalBlock &b : variant->terminals) {
        const int area = areaIndex(t, b.area);
        if (area < 0)
            continue;
        const bool channelBits = t.area(area).kind == model::AreaKind::Channel && !b.words();
        Block block{QString(), {}, b.lowest, b.highest, b.bcd};
        for (int k = 0; k < b.count; ++k)
            block.devices.push_back(channelBits ? model::Address{area, b.first, k}
                                                : model::Address{area, b.first + k, -1});
        onStrip.insert(block.devices.begin(), block.devices.end());
        block.title =
            b.label ? QCoreApplication::translate("rung::model::Target", b.label)
                    : QStringLiteral("%1–%2").arg(model::formatAddress(t, block.devices.front()),
                                                  model::formatAddress(t, block.devices.back()));
        const bool input = !t.area(area).writable;
        blocks[(b.words() ? AnalogInputs : Inputs) + (input ? 0 : 1)].push_back(block);
    }
    std::set<model::Address> extraIn, extraOut;
    for (const model::Instruction &ins : m_document->listing().list.instructions)
        for (const model::Operand &o : ins.operands) {
            if (o.kind != model::Operand::Kind::Device || !o.address.valid() ||
                onStrip.contains(o.address))
                continue;
            const model::Area &a = t.area(o.address.area);
            const bool bit = a.kind == model::AreaKind::Bit || o.address.bit >= 0;
            if (!a.physical || !bit)
                continue;
            (a.writable ? extraOut : extraIn).insert(o.address);
        }
    const auto extra = [&](const std::set<model::Address> &devices, const QString &title,
                           Section section) {
        if (devices.empty())
            return;
        Block block{title, {}, 0, 0, false};
        for (const model::Address &a : devices)
            if (static_cast<int>(block.devices.size()) < kMaxExtra)
                block.devices.push_back(a);
        blocks[section].push_back(block);
    };
    extra(extraIn, tr("Further inputs the program uses"), Inputs);
    extra(extraOut, tr("Further outputs the program uses"), Outputs);

    // Built again only when what it shows changed: a symbol renamed, a device added.
    QString shape = variant->name;
    for (const auto &section : blocks)
        for (const Block &b : section) {
            shape += QLatin1Char('|') + b.title;
            for (const model::Address &a : b.devices)
                shape +=
                    QLatin1Char(',') + model::formatAddress(t, a) + QLatin1Char(':') + symbolOf(a);
        }
    if (shape == m_shape)
        return;
    m_shape = shape;
    m_terminals.clear();
    while (QLayoutItem *item = m_layout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    const QString headings[Sections] = {tr("Inputs"), tr("Outputs"), tr("Analog inputs"),
                                        tr("Analog outputs")};
    for (int s = 0; s < Sections; ++s) {
        if (blocks[s].empty())
            continue;
        auto *heading = new QLabel(QStringLiteral("<b>%1</b>").arg(headings[s].toHtmlEscaped()));
        m_layout->addWidget(heading);
        auto *stripWidget = new QWidget;
        auto *strip = new FlowLayout(stripWidget);
        for (const Block &b : blocks[s])
            addBlock(strip, b.title, b.devices, s == Inputs || s == AnalogInputs, b.lowest,
                     b.highest, b.bcd);
        m_layout->addWidget(stripWidget);
    }
    if (m_terminals.empty())
        m_layout->addWidget(new QLabel(tr("This model has no terminals to show")));
    m_layout->addStretch(1);
    setMonitorSource(m_source); // enables, shows values, tells the source
    tellWatched();
    showValues();
}

void IoPanel::addBlock(QLayout *strip, const QString &title,
                       const std::vector<model::Address> &devices, bool input, int lowest,
                       int highest, bool bcd) {
    const model::Target &t = m_document->target();
    auto *box = new QGroupBox(title);
    const bool words = highest > lowest;
    if (words) {
        auto *column = new QVBoxLayout(box);
        for (const model::Address &a : devices) {
            const QString device = model::formatAddress(t, a);
            auto *w = new AnalogTerminal(device, symbolOf(a), lowest, highest, input);
            w->setMinimumWidth(220);
            column->addWidget(w);
            m_terminals.push_back({a, device, w, bcd});
            connect(w, &AnalogTerminal::requested, this, [this, a, bcd](int value) {
                if (m_source)
                    m_source->writeWord(a, bcd ? toBcd(value) : value);
            });
        }
        strip->addWidget(box);
        return;
    }
    // Terminals in rows of eight, as the strips print them (four in a narrow dock).
    auto *grid = new QGridLayout(box);
    grid->setHorizontalSpacing(2);
    grid->setVerticalSpacing(2);
    grid->setContentsMargins(4, 4, 4, 4);
    int k = 0;
    for (const model::Address &a : devices) {
        const QString device = model::formatAddress(t, a);
        QWidget *w = nullptr;
        if (input) {
            auto *button = new InputTerminal(device, symbolOf(a));
            button->setMode(m_pushButtons.value(device, m_mode->currentIndex() == 1)
                                ? InputTerminal::Mode::PushButton
                                : InputTerminal::Mode::Switch);
            connect(button, &InputTerminal::requested, this, [this, a](bool on) {
                if (m_source)
                    m_source->writeBit(a, on);
            });
            button->setContextMenuPolicy(Qt::CustomContextMenu);
            connect(button, &QWidget::customContextMenuRequested, this,
                    [this, button, a, device](const QPoint &at) {
                        QMenu menu;
                        QAction *sw = menu.addAction(tr("Switch"));
                        QAction *push = menu.addAction(tr("Push Button"));
                        sw->setCheckable(true);
                        push->setCheckable(true);
                        const bool isPush = button->mode() == InputTerminal::Mode::PushButton;
                        (isPush ? push : sw)->setChecked(true);
                        menu.addSeparator();
                        QAction *forceOn = menu.addAction(tr("Force ON"));
                        QAction *forceOff = menu.addAction(tr("Force OFF"));
                        QAction *release = menu.addAction(tr("Release"));
                        const QString noForce = m_source ? m_source->forceRefusal() : QString();
                        for (QAction *f : {forceOn, forceOff, release}) {
                            f->setEnabled(m_source != nullptr && noForce.isEmpty());
                            f->setToolTip(noForce);
                        }
                        menu.setToolTipsVisible(true);
                        QAction *chosen = menu.exec(button->mapToGlobal(at));
                        if (chosen == sw || chosen == push) {
                            m_pushButtons[device] = chosen == push;
                            button->setMode(chosen == push ? InputTerminal::Mode::PushButton
                                                           : InputTerminal::Mode::Switch);
                        } else if (m_source && chosen == forceOn) {
                            m_source->force(a, true);
                        } else if (m_source && chosen == forceOff) {
                            m_source->force(a, false);
                        } else if (m_source && chosen == release) {
                            m_source->release(a);
                        }
                    });
            w = button;
        } else {
            w = new Lamp(device, symbolOf(a));
        }
        grid->addWidget(w, k / m_perRow, k % m_perRow);
        m_terminals.push_back({a, device, w, false});
        ++k;
    }
    strip->addWidget(box);
}

void IoPanel::setAllPushButtons(bool pushButtons) {
    m_mode->setCurrentIndex(pushButtons ? 1 : 0);
    m_pushButtons.clear();
    for (const Terminal &t : m_terminals)
        if (auto *button = qobject_cast<InputTerminal *>(t.widget))
            button->setMode(pushButtons ? InputTerminal::Mode::PushButton
                                        : InputTerminal::Mode::Switch);
}

void IoPanel::setMonitorSource(model::MonitorSource *source) {
    if (model::MonitorSource::switchSource(m_source, source, this)) {
        if (source) {
            connect(source, &model::MonitorSource::snapshotChanged, this, &IoPanel::showValues);
            connect(source, &model::MonitorSource::commandFinished, this,
                    [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                        if (!ok)
                            emit message(error);
                    });
        }
        m_hint->setText(m_source ? tr("Inputs take effect at the next scan")
                                 : tr("Run the simulation (F10) to work the inputs"));
    }
    for (const Terminal &t : m_terminals)
        if (!qobject_cast<Lamp *>(t.widget))
            t.widget->setEnabled(m_source != nullptr);
    tellWatched();
    showValues();
}

void IoPanel::tellWatched() {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    for (const Terminal &t : m_terminals)
        devices.push_back(t.address);
    m_source->setWatched(this, std::move(devices));
}

void IoPanel::showValues() {
    const std::shared_ptr<const model::Snapshot> snapshot =
        m_source ? m_source->snapshot() : nullptr;
    const bool ours =
        snapshot && snapshot->layout && &snapshot->layout->target() == &m_document->target();
    for (const Terminal &t : m_terminals) {
        if (auto *face = qobject_cast<TerminalFace *>(t.widget)) {
            face->setState(ours && snapshot->bit(t.address), ours && snapshot->forced(t.address));
        } else if (auto *analog = qobject_cast<AnalogTerminal *>(t.widget)) {
            const std::int32_t word = ours ? snapshot->value(t.address) : 0;
            // A BCD channel holding a nibble above 9 shows the word as it is, not a number
            // made up from it (model/image/bcd.h: one rule).
            const std::optional<std::int64_t> number =
                t.bcd ? model::fromBcd(word & 0xFFFF) : std::optional<std::int64_t>(word);
            if (number)
                analog->setValue(static_cast<int>(*number));
            else
                analog->setUnreadable(model::formatValue(word, 16, model::ValueFormat::Bcd));
        }
    }
}

InputTerminal *IoPanel::input(const QString &device) const {
    for (const Terminal &t : m_terminals)
        if (t.device == device)
            return qobject_cast<InputTerminal *>(t.widget);
    return nullptr;
}

Lamp *IoPanel::lamp(const QString &device) const {
    for (const Terminal &t : m_terminals)
        if (t.device == device)
            return qobject_cast<Lamp *>(t.widget);
    return nullptr;
}

AnalogTerminal *IoPanel::analog(const QString &device) const {
    for (const Terminal &t : m_terminals)
        if (t.device == device)
            return qobject_cast<AnalogTerminal *>(t.widget);
    return nullptr;
}

} // namespace rung::editor
