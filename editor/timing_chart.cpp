#include "timing_chart.h"

#include "document.h"
#include "terminal_widgets.h"
#include "timing_canvas.h"

#include "model/target/address.h"
#include "model/target/target_lists.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPainter>
#include <QPushButton>
#include <QSaveFile>
#include <QScrollArea>
#include <QScrollBar>
#include <QSvgGenerator>
#include <QTextStream>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rung::editor {

namespace {

constexpr int kMaxChannels = 64;
constexpr double kMinMsPerPixel = 0.05;
constexpr double kMaxMsPerPixel = 3.6e5; // an hour across ten pixels

QString seconds(qint64 ms) {
    return QStringLiteral("%1 s").arg(static_cast<double>(ms) / 1000.0, 0, 'f', 3);
}

} // namespace

TimingChart::TimingChart(Document *document, QWidget *parent)
    : QWidget(parent)
    , m_document(document)
    , m_canvas(new TimingCanvas)
    , m_scroll(new QScrollBar(Qt::Horizontal))
    , m_add(new QLineEdit)
    , m_zoomIn(new QToolButton)
    , m_zoomOut(new QToolButton)
    , m_fit(new QToolButton)
    , m_followBox(new QCheckBox)
    , m_export(new QToolButton)
    , m_trigger(new QLineEdit)
    , m_triggerAction(new QComboBox)
    , m_arm(new QPushButton)
    , m_readout(new QLabel) {
    setObjectName(QStringLiteral("timingChart"));
    m_add->setObjectName(QStringLiteral("timingAdd"));
    m_trigger->setObjectName(QStringLiteral("timingTrigger"));
    m_arm->setObjectName(QStringLiteral("timingArm"));
    m_readout->setObjectName(QStringLiteral("timingReadout"));
    m_add->setClearButtonEnabled(true);
    m_trigger->setMinimumWidth(150);
    m_zoomIn->setText(QStringLiteral("+"));
    m_zoomOut->setText(QStringLiteral("−"));
    m_followBox->setChecked(true);
    m_arm->setCheckable(true);
    m_triggerAction->addItems({QString(), QString()});
    // Its width follows its texts: another language may be chosen while the window is open.
    m_triggerAction->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_export->setPopupMode(QToolButton::InstantPopup);
    auto *exportMenu = new QMenu(m_export);
    for (const char *format : {"csv", "png", "svg"})
        exportMenu->addAction(QString::fromLatin1(format).toUpper(), this, [this, format] {
            emit exportRequested(QString::fromLatin1(format));
        });
    m_export->setMenu(exportMenu);

    auto *bar = new QWidget;
    auto *tools = new FlowLayout(bar, 4);
    for (QWidget *w :
         std::initializer_list<QWidget *>{m_add, m_zoomOut, m_zoomIn, m_fit, m_followBox, m_trigger,
                                          m_triggerAction, m_arm, m_export})
        tools->addWidget(w);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(bar);
    // Rows scroll up and down; time scrolls with the bar below (the canvas draws the window).
    auto *rows = new QScrollArea;
    rows->setObjectName(QStringLiteral("timingRows"));
    rows->setWidget(m_canvas);
    rows->setWidgetResizable(true);
    rows->setFrameShape(QFrame::NoFrame);
    rows->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    layout->addWidget(rows, 1);
    layout->addWidget(m_scroll);
    layout->addWidget(m_readout);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_canvas->setChannels(&m_channels);

    connect(m_add, &QLineEdit::returnPressed, this, [this] {
        QStringList parts;
        for (const QString &p : m_add->text().split(QLatin1Char(',')))
            if (!p.trimmed().isEmpty())
                parts << p.trimmed();
        if (!parts.isEmpty() && addDevices(parts))
            m_add->clear();
    });
    connect(m_zoomIn, &QToolButton::clicked, this, [this] { zoom(0.5); });
    connect(m_zoomOut, &QToolButton::clicked, this, [this] { zoom(2.0); });
    connect(m_fit, &QToolButton::clicked, this, [this] {
        const qint64 span = std::max<qint64>(m_latestMs - m_earliestMs, 100);
        m_endMs = m_latestMs;
        setMsPerPixel(static_cast<double>(span) / (m_canvas->waveWidth() * 0.95));
    });
    connect(m_followBox, &QCheckBox::toggled, this, &TimingChart::setFollow);
    connect(m_arm, &QPushButton::toggled, this, [this](bool on) {
        if (!on) {
            disarmTrigger();
            return;
        }
        const auto action = m_triggerAction->currentIndex() == 0 ? model::Trigger::Action::Stop
                                                                 : model::Trigger::Action::Mark;
        if (!armTrigger(m_trigger->text(), action)) {
            const QSignalBlocker block(m_arm);
            m_arm->setChecked(false);
        }
    });
    connect(m_trigger, &QLineEdit::returnPressed, m_arm, [this] { m_arm->setChecked(true); });
    connect(m_scroll, &QScrollBar::valueChanged, this, [this](int value) {
        if (m_scrolling)
            return;
        setFollow(false);
        m_endMs = value;
        applyView();
    });
    connect(m_canvas, &TimingCanvas::cursorRequested, this, &TimingChart::placeCursor);
    connect(m_canvas, &TimingCanvas::zoomRequested, this,
            [this](double factor, qint64 anchor) { zoom(factor, anchor); });
    connect(m_canvas, &TimingCanvas::scrollRequested, this, [this](qint64 delta) {
        setFollow(false);
        m_endMs += delta;
        applyView();
    });
    connect(m_canvas, &TimingCanvas::rowMenuRequested, this, &TimingChart::rowMenu);
    connect(m_canvas, &TimingCanvas::devicesDropped, this,
            [this](const QStringList &devices) { addDevices(devices); });
    connect(m_canvas, &TimingCanvas::removeRequested, this, &TimingChart::removeChannel);
    connect(document, &Document::programChanged, this, [this] {
        if (&m_document->target() != m_hintsTarget)
            retranslate(); // another family: the hints' examples are its devices
        // Symbols renamed: the names column follows.
        for (model::TimingChannel &c : m_channels) {
            const model::Symbol *s = m_document->project().symbol(c.address);
            c.symbol = s ? s->name : QString();
        }
        m_canvas->update();
    });
    retranslate();
    applyView();
}

void TimingChart::retranslate() {
    const model::Target &target = m_document->target();
    m_hintsTarget = &target;
    const QString bit = model::exampleDevice(target, true);
    m_add->setPlaceholderText(
        tr("Add: %1, %2, then Enter").arg(bit, model::exampleWordRange(target, 4)));
    m_canvas->setEmptyText(tr("Type devices above (%1, %2) or drag them here from the ladder "
                              "or the watch table")
                               .arg(bit, model::exampleWordRange(target, 4)));
    // Wide enough for the hint in every language (the clear button takes room too).
    m_add->setMinimumWidth(
        std::max(QFontMetrics(m_add->font()).horizontalAdvance(m_add->placeholderText()) + 36,
                 QFontMetrics(m_add->font()).averageCharWidth() * 30));
    m_add->setToolTip(tr("Devices and ranges to draw, with commas; they can also be dragged "
                         "here from the ladder or the watch table"));
    m_zoomIn->setToolTip(tr("Zoom in (+, Ctrl+wheel)"));
    m_zoomOut->setToolTip(tr("Zoom out (-, Ctrl+wheel)"));
    m_fit->setText(tr("Whole History"));
    m_fit->setToolTip(tr("Show everything recorded"));
    m_followBox->setText(tr("Follow"));
    m_followBox->setToolTip(tr("Keep the newest scan at the right edge"));
    m_trigger->setPlaceholderText(
        tr("Trigger: %1 rises, %2 > 100").arg(bit, model::exampleWord(target, 10)));
    m_trigger->setToolTip(tr("A condition checked after every scan: DEVICE rises, DEVICE falls, "
                             "or DEVICE = <> < <= > >= VALUE"));
    m_triggerAction->setItemText(0, tr("Stop the simulation"));
    m_triggerAction->setItemText(1, tr("Only mark"));
    m_arm->setText(tr("Arm"));
    m_arm->setToolTip(tr("Watch for the trigger (Enter in its field does the same)"));
    m_export->setText(tr("Export"));
    m_export->setToolTip(tr("Save the chart as CSV (every change), PNG or SVG"));
    m_canvas->setToolTip(tr("Click: cursor A; Shift+click or right click: cursor B; wheel: "
                            "scroll; Ctrl+wheel: zoom; right click on a name: its format"));
    updateReadout();
}

void TimingChart::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void TimingChart::setMonitorSource(model::MonitorSource *source) {
    if (!model::MonitorSource::switchSource(m_source, source, this))
        return;
    m_latestMs = 0;
    m_latestScan = 0;
    m_earliestMs = 0;
    if (source) {
        connect(source, &model::MonitorSource::snapshotChanged, this, &TimingChart::refresh);
        connect(source, &model::MonitorSource::triggered, this, &TimingChart::triggered);
        watchChannels();
        if (m_armed && !source->setTrigger(m_armed))
            emit message(tr("The trigger could not be armed on this source"));
    }
    m_canvas->setPastMarks({});
    refresh();
}

void TimingChart::watchChannels() {
    if (!m_source)
        return;
    std::vector<model::Address> devices;
    bool kept = true;
    for (const model::TimingChannel &c : m_channels) {
        kept = m_source->watchHistory(c.address) && kept;
        devices.push_back(c.address);
    }
    m_source->setWatched(this, devices);
    if (!kept)
        emit message(tr("This source keeps no history of some devices: the chart cannot draw "
                        "them"));
}

bool TimingChart::addDevices(const QStringList &texts) {
    const model::Target &t = m_document->target();
    std::vector<model::Address> found;
    for (const QString &text : texts) {
        const auto parsed = model::parseAddressRange(t, text, m_document->modelVariant());
        if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
            emit message(tr("Not added to the timing chart: %1").arg(e->message));
            return false;
        }
        const auto &list = std::get<std::vector<model::Address>>(parsed);
        found.insert(found.end(), list.begin(), list.end());
    }
    for (const model::Address &a : found) {
        if (std::any_of(m_channels.begin(), m_channels.end(),
                        [&a](const model::TimingChannel &c) { return c.address == a; }))
            continue;
        if (static_cast<int>(m_channels.size()) >= kMaxChannels) {
            emit message(tr("The timing chart draws at most %1 devices").arg(kMaxChannels));
            break;
        }
        model::TimingChannel c;
        c.address = a;
        c.device = model::formatAddress(t, a);
        const model::Symbol *s = m_document->project().symbol(a);
        c.symbol = s ? s->name : QString();
        c.bit = a.bit >= 0 || t.area(a.area).kind == model::AreaKind::Bit;
        c.bits = t.area(a.area).wordBits;
        m_channels.push_back(c);
    }
    m_canvas->setChannels(&m_channels);
    watchChannels();
    refresh();
    return true;
}

void TimingChart::removeChannel(int index) {
    if (index < 0 || index >= static_cast<int>(m_channels.size()))
        return;
    m_channels.erase(m_channels.begin() + index);
    m_canvas->setSelectedRow(-1);
    m_canvas->setChannels(&m_channels);
    watchChannels();
    refresh();
}

void TimingChart::rowMenu(int row, const QPoint &at) {
    QMenu menu;
    model::TimingChannel &c = m_channels[static_cast<std::size_t>(row)];
    if (!c.bit) {
        QMenu *show = menu.addMenu(tr("Show As"));
        for (const model::ValueFormat f : model::kValueFormats) {
            QAction *a = show->addAction(model::valueFormatName(f));
            a->setCheckable(true);
            a->setChecked(f == c.format);
            connect(a, &QAction::triggered, this, [this, row, f] {
                m_channels[static_cast<std::size_t>(row)].format = f;
                m_canvas->update();
            });
        }
    }
    menu.addAction(tr("Remove"), this, [this, row] { removeChannel(row); });
    menu.exec(at);
}

void TimingChart::setFollow(bool follow) {
    if (m_follow == follow)
        return;
    m_follow = follow;
    const QSignalBlocker block(m_followBox);
    m_followBox->setChecked(follow);
    if (follow)
        refresh();
}

void TimingChart::setMsPerPixel(double msPerPixel) {
    m_msPerPixel = std::clamp(msPerPixel, kMinMsPerPixel, kMaxMsPerPixel);
    applyView();
}

void TimingChart::zoom(double factor, std::optional<qint64> anchorMs) {
    const double before = m_msPerPixel;
    const double after = std::clamp(before * factor, kMinMsPerPixel, kMaxMsPerPixel);
    if (anchorMs && !m_follow) {
        // The time under the mouse stays under it.
        const double right = static_cast<double>(m_endMs - *anchorMs) / before;
        m_endMs = *anchorMs + static_cast<qint64>(std::llround(right * after));
    }
    m_msPerPixel = after;
    applyView();
}

void TimingChart::centreOn(qint64 timeMs) {
    setFollow(false);
    refresh();
    m_endMs = timeMs + static_cast<qint64>(std::llround(m_canvas->waveWidth() * m_msPerPixel / 2));
    applyView();
}

qint64 TimingChart::snapToScan(qint64 timeMs) const {
    // Scans end every period from the newest one back: a cursor sits on a scan's end.
    const qint64 period = std::max<qint64>(1, m_periodMs);
    const qint64 back = (m_latestMs - timeMs + period / 2) / period;
    return std::clamp<qint64>(m_latestMs - std::max<qint64>(0, back) * period, 0, m_latestMs);
}

void TimingChart::placeCursor(int which, qint64 timeMs) {
    const qint64 t = snapToScan(timeMs);
    m_canvas->setCursorTime(which, t);
    const quint64 back = static_cast<quint64>((m_latestMs - t) / std::max<qint64>(1, m_periodMs));
    const quint64 scan = back <= m_latestScan ? m_latestScan - back : 0;
    if (m_source && m_source->runState() == model::MonitorSource::RunState::Running)
        setFollow(false); // a measurement holds the view still
    updateReadout();
    emit cursorMoved(which, scan, t);
}

void TimingChart::refresh() {
    const auto snapshot = m_source ? m_source->snapshot() : nullptr;
    if (snapshot) {
        m_latestMs = snapshot->statistics.timeMs;
        m_latestScan = snapshot->statistics.scans;
        m_periodMs = snapshot->statistics.periodMs;
    }
    qint64 earliest = m_latestMs;
    if (m_source)
        m_source->readHistory([&](const model::HistoryRecorder &h) {
            for (const model::TimingChannel &c : m_channels)
                if (const auto first = h.oldest(c.address))
                    earliest = std::min(earliest, first->timeMs);
        });
    m_earliestMs = earliest;
    if (m_follow)
        m_endMs = std::max<qint64>(
            m_latestMs, static_cast<qint64>(std::llround(m_canvas->waveWidth() * m_msPerPixel)));
    applyView();
}

void TimingChart::applyView() {
    m_canvas->setView(m_endMs, m_msPerPixel);
    if (m_source) {
        const qint64 from = m_canvas->fromMs();
        m_canvas->setWindow(
            model::readWindow(*m_source, m_channels, from, std::min(m_endMs, m_latestMs)));
    } else {
        m_canvas->setWindow({});
    }
    updateScrollBar();
    updateReadout();
}

void TimingChart::updateScrollBar() {
    const qint64 visible = static_cast<qint64>(m_canvas->waveWidth() * m_msPerPixel);
    const qint64 lowest = std::min(m_earliestMs + visible, m_latestMs);
    const qint64 highest = std::max(m_latestMs, lowest);
    constexpr qint64 limit = std::numeric_limits<int>::max();
    m_scrolling = true;
    m_scroll->setRange(static_cast<int>(std::min(lowest, limit)),
                       static_cast<int>(std::min(highest, limit)));
    m_scroll->setPageStep(static_cast<int>(std::clamp<qint64>(visible, 1, limit)));
    m_scroll->setSingleStep(static_cast<int>(std::clamp<qint64>(visible / 10, 1, limit)));
    m_scroll->setValue(static_cast<int>(std::clamp<qint64>(m_endMs, 0, limit)));
    m_scrolling = false;
}

void TimingChart::updateReadout() {
    const auto a = m_canvas->cursorTime(0);
    const auto b = m_canvas->cursorTime(1);
    const qint64 period = std::max<qint64>(1, m_periodMs);
    QStringList parts;
    if (a)
        parts << tr("A: %1").arg(seconds(*a));
    if (b)
        parts << tr("B: %1").arg(seconds(*b));
    if (a && b)
        //: the time between the cursors, and how many scans that is
        parts << tr("B − A: %1 (%n scan(s))", nullptr, static_cast<int>((*b - *a) / period))
                     .arg(seconds(*b - *a));
    if (parts.isEmpty())
        parts << tr("Click the chart for cursor A, Shift+click for cursor B");
    if (!m_triggerStatus.isEmpty())
        parts << m_triggerStatus;
    m_readout->setText(parts.join(QStringLiteral("    ")));
}

bool TimingChart::armTrigger(const QString &text, model::Trigger::Action action) {
    auto parsed = model::parseTrigger(m_document->target(), text, m_document->modelVariant());
    if (const auto *error = std::get_if<QString>(&parsed)) {
        emit message(tr("Trigger not armed: %1").arg(*error));
        return false;
    }
    model::Trigger trigger = std::get<model::Trigger>(parsed);
    trigger.action = action;
    if (m_source && !m_source->setTrigger(trigger)) {
        emit message(tr("Trigger not armed: this source cannot watch %1")
                         .arg(model::formatAddress(m_document->target(), trigger.device)));
        return false;
    }
    m_armed = trigger;
    m_triggerAction->setCurrentIndex(action == model::Trigger::Action::Stop ? 0 : 1);
    const QString shown = model::formatTrigger(m_document->target(), trigger);
    if (m_trigger->text().trimmed().isEmpty())
        m_trigger->setText(shown);
    {
        const QSignalBlocker block(m_arm);
        m_arm->setChecked(true);
    }
    // The moments already recorded where it became true, marked too.
    std::vector<model::HistoryRecorder::Mark> past;
    if (m_source)
        m_source->readHistory([&](const model::HistoryRecorder &h) {
            past = model::triggerMoments(h.changes(trigger.device,
                                                   std::numeric_limits<qint64>::min() / 2,
                                                   std::numeric_limits<qint64>::max() / 2),
                                         trigger);
        });
    m_canvas->setPastMarks(past);
    m_triggerStatus = action == model::Trigger::Action::Stop
                          ? tr("Armed: stops when %1").arg(shown)
                          : tr("Armed: marks when %1").arg(shown);
    updateReadout();
    return true;
}

void TimingChart::disarmTrigger() {
    m_armed.reset();
    if (m_source)
        m_source->setTrigger(std::nullopt);
    const QSignalBlocker block(m_arm);
    m_arm->setChecked(false);
    m_triggerStatus.clear();
    m_canvas->setPastMarks({});
    updateReadout();
}

void TimingChart::triggered(quint64 scan, qint64 timeMs) {
    if (!m_armed)
        return;
    const QString shown = model::formatTrigger(m_document->target(), *m_armed);
    m_triggerStatus = tr("%1 at %2 (scan %3)").arg(shown, seconds(timeMs)).arg(scan);
    if (m_armed->action == model::Trigger::Action::Stop) {
        // The moment in view, cursor A on it: the state of that scan is what the window shows.
        m_latestMs = std::max(m_latestMs, timeMs);
        m_latestScan = std::max(m_latestScan, scan);
        setFollow(false);
        m_endMs = timeMs + static_cast<qint64>(m_canvas->waveWidth() * m_msPerPixel / 4);
        placeCursor(0, timeMs);
        emit message(tr("Trigger: %1 at %2 (scan %3); the simulation is paused there")
                         .arg(shown, seconds(timeMs))
                         .arg(scan));
    }
    applyView();
}

bool TimingChart::exportTo(const QString &path, const QString &format, QString *error) const {
    const QString f = format.toLower();
    if (f == QLatin1String("csv")) {
        QSaveFile file(path);
        if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
            *error = tr("Cannot write %1: %2").arg(path, file.errorString());
            return false;
        }
        QTextStream out(&file);
        if (m_source)
            model::writeCsv(*m_source, m_channels, out);
        out.flush();
        if (!file.commit()) {
            *error = tr("Cannot write %1: %2").arg(path, file.errorString());
            return false;
        }
        return true;
    }
    // Every row, at least as wide as the chart on screen.
    const QSize size(std::max(m_canvas->width(), 900), std::max(m_canvas->contentHeight(), 60));
    if (f == QLatin1String("png")) {
        QImage image(size, QImage::Format_ARGB32);
        image.fill(Qt::white);
        QPainter painter(&image);
        painter.setFont(m_canvas->font());
        m_canvas->render(painter, size);
        painter.end();
        if (!image.save(path, "PNG")) {
            *error = tr("Cannot write %1").arg(path);
            return false;
        }
        return true;
    }
    if (f == QLatin1String("svg")) {
        QSvgGenerator svg;
        svg.setFileName(path);
        svg.setSize(size);
        svg.setViewBox(QRect(QPoint(0, 0), size));
        svg.setTitle(tr("Timing chart"));
        QPainter painter;
        if (!painter.begin(&svg)) {
            *error = tr("Cannot write %1").arg(path);
            return false;
        }
        painter.setFont(m_canvas->font());
        m_canvas->render(painter, size);
        painter.end();
        if (!QFileInfo::exists(path)) {
            *error = tr("Cannot write %1").arg(path);
            return false;
        }
        return true;
    }
    *error = tr("%1 is no export format (CSV, PNG, SVG)").arg(format);
    return false;
}

} // namespace rung::editor
