#include "app/gui/network_chart.h"

#include "app/gui/network_watch_model.h"
#include "app/gui/simulation_controller.h"
#include "editor/timing_canvas.h"
#include "model/image/trigger.h"
#include "model/target/address.h"
#include "model/target/target_lists.h"
#include "network/network_session.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rung::app {

NetworkChart::NetworkChart(QWidget *parent)
    : QWidget(parent) {
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto *top = new QHBoxLayout;
    m_add = new QLineEdit(this);
    m_add->setObjectName(QStringLiteral("networkChartAdd"));
    connect(m_add, &QLineEdit::returnPressed, this, [this] {
        if (addDevice(m_add->text()))
            m_add->clear();
    });
    m_follow = new QCheckBox(this);
    m_follow->setChecked(true);
    connect(m_follow, &QCheckBox::toggled, this, [this] { refresh(); });
    m_trigger = new QLineEdit(this);
    m_trigger->setObjectName(QStringLiteral("networkChartTrigger"));
    m_triggerAction = new QComboBox(this);
    m_triggerAction->setObjectName(QStringLiteral("networkChartTriggerAction"));
    m_triggerAction->addItems({QString(), QString()}); // Stop, Mark (retranslate)
    // Its width follows its texts: another language may be chosen while the window is open.
    m_triggerAction->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_arm = new QPushButton(this);
    m_arm->setObjectName(QStringLiteral("networkChartArm"));
    m_arm->setCheckable(true);
    connect(m_arm, &QPushButton::toggled, this, [this](bool on) {
        if (!on) {
            emit disarmRequested();
            return;
        }
        // Unchecked again until the window says it is armed (showTrigger).
        {
            const QSignalBlocker block(m_arm);
            m_arm->setChecked(false);
        }
        emit armRequested(m_trigger->text(), m_triggerAction->currentIndex() == 0
                                                 ? model::Trigger::Action::Stop
                                                 : model::Trigger::Action::Mark);
    });
    connect(m_trigger, &QLineEdit::returnPressed, m_arm, [this] { m_arm->setChecked(true); });
    m_readout = new QLabel(this);
    m_readout->setObjectName(QStringLiteral("networkChartReadout"));
    top->addWidget(m_add, 1);
    top->addWidget(m_follow);
    top->addWidget(m_trigger, 1);
    top->addWidget(m_triggerAction);
    top->addWidget(m_arm);
    layout->addLayout(top);
    m_canvas = new editor::TimingCanvas(this);
    m_canvas->setObjectName(QStringLiteral("networkChartCanvas"));
    m_canvas->setChannels(&m_channels);
    layout->addWidget(m_canvas, 1);
    // Under the chart, as the single program's chart has it: a long trigger must not widen
    // the window.
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    layout->addWidget(m_readout);
    connect(m_canvas, &editor::TimingCanvas::zoomRequested, this, [this](double factor, qint64) {
        m_msPerPixel = std::clamp(m_msPerPixel * factor, 0.01, 100000.0);
        refresh();
    });
    connect(m_canvas, &editor::TimingCanvas::scrollRequested, this, [this](qint64 delta) {
        m_follow->setChecked(false);
        m_endMs = std::max<qint64>(0, m_endMs + delta);
        refresh();
    });
    connect(m_canvas, &editor::TimingCanvas::cursorRequested, this, [this](int which, qint64 ms) {
        m_canvas->setCursorTime(which, ms);
        refresh();
        if (which == 0)
            emit cursorMoved(ms);
    });
    connect(m_canvas, &editor::TimingCanvas::removeRequested, this, &NetworkChart::removeRow);
    connect(m_canvas, &editor::TimingCanvas::devicesDropped, this, [this](const QStringList &l) {
        for (const QString &d : l)
            addDevice(d);
    });
    retranslate();
}

void NetworkChart::retranslate() {
    const QString example = exampleStationDevice(m_session);
    m_add->setPlaceholderText(tr("Add station/device, e.g. %1").arg(example));
    m_follow->setText(tr("Follow"));
    m_canvas->setEmptyText(tr("Type a station's device above (%1) to draw it").arg(example));
    // The example in the first station's own devices: a bit rises, a word compares.
    QString word = QStringLiteral("STATION/WORD");
    if (m_session && !m_session->stations().empty()) {
        const network::StationSource *first = m_session->stations().front();
        word = first->stationName() + QLatin1Char('/') + model::exampleWord(first->target(), 10);
    }
    m_trigger->setPlaceholderText(tr("Trigger: %1 rises, %2 > 100").arg(example, word));
    m_trigger->setToolTip(tr("A condition on one station's device, checked after each of its "
                             "scans: STATION/DEVICE rises, falls, or = <> < <= > >= VALUE (the "
                             "same as Simulation > Stop When...)"));
    m_triggerAction->setItemText(0, tr("Stop the network"));
    m_triggerAction->setItemText(1, tr("Only mark"));
    m_triggerAction->setToolTip(tr("Stop the network: every station pauses at the end of its "
                                   "scan when the condition becomes true"));
    m_arm->setText(tr("Arm"));
    m_arm->setToolTip(tr("Watch for the trigger (Enter in its field does the same)"));
    showTrigger(m_armed, m_triggerAction->currentIndex() == 0 ? model::Trigger::Action::Stop
                                                              : model::Trigger::Action::Mark);
}

void NetworkChart::showTrigger(const QString &condition, model::Trigger::Action action) {
    const bool stop = action == model::Trigger::Action::Stop;
    const bool changed = condition != m_armed || stop != m_armedStops;
    m_armed = condition;
    m_armedStops = stop;
    if (changed)
        readPastMarks();
    {
        const QSignalBlocker block(m_arm);
        m_arm->setChecked(!condition.isEmpty());
    }
    if (!condition.isEmpty()) {
        m_trigger->setText(condition);
        m_triggerAction->setCurrentIndex(stop ? 0 : 1);
    }
    m_triggerStatus = condition.isEmpty() ? QString()
                      : stop              ? tr("Armed: stops the network when %1").arg(condition)
                                          : tr("Armed: marks when %1").arg(condition);
    refresh();
}

void NetworkChart::showTriggerFired(quint64 scan, qint64 timeMs, bool stopped) {
    //: %1 the condition, %2 the virtual time, %3 the scan of its station
    m_triggerStatus =
        tr("%1 at %2 (scan %3)").arg(m_armed, SimulationController::clockText(timeMs)).arg(scan);
    if (stopped)
        placeCursor(timeMs); // the moment in view; the network shows it live
    else
        refresh();
}

QString NetworkChart::readoutText() const {
    return m_readout->text();
}

void NetworkChart::changeEvent(QEvent *event) {
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void NetworkChart::setSession(network::NetworkSession *session) {
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    m_channels.clear();
    m_stations.clear();
    m_past.clear();
    m_canvas->setChannels(&m_channels);
    if (session)
        connect(session, &network::NetworkSession::clockChanged, this, &NetworkChart::refresh);
    retranslate();
    refresh();
}

void NetworkChart::setFollow(bool follow) {
    m_follow->setChecked(follow);
}

void NetworkChart::placeCursor(qint64 timeMs) {
    m_follow->setChecked(false);
    m_endMs = timeMs + std::llround(m_canvas->waveWidth() * m_msPerPixel / 2);
    m_canvas->setCursorTime(0, timeMs);
    refresh();
}

bool NetworkChart::addDevice(const QString &text) {
    if (!m_session)
        return false;
    const QString trimmed = text.trimmed();
    const qsizetype slash = trimmed.indexOf(QLatin1Char('/'));
    network::StationSource *station =
        slash > 0 ? m_session->station(trimmed.left(slash).trimmed()) : nullptr;
    if (!station) {
        QStringList names;
        for (network::StationSource *s : m_session->stations())
            names << s->stationName();
        emit message(
            tr("%1: write STATION/DEVICE, e.g. %2 (stations: %3)")
                .arg(trimmed, exampleStationDevice(m_session), names.join(QStringLiteral(", "))));
        return false;
    }
    const auto parsed =
        model::parseAddress(station->target(), trimmed.mid(slash + 1).trimmed(), station->model());
    if (const auto *e = std::get_if<model::AddressError>(&parsed)) {
        emit message(tr("Not added to the timing chart: %1").arg(e->message));
        return false;
    }
    const model::Address a = std::get<model::Address>(parsed);
    model::TimingChannel c;
    c.address = a;
    c.device =
        station->stationName() + QLatin1Char('/') + model::formatAddress(station->target(), a);
    for (const model::TimingChannel &o : m_channels)
        if (o.device == c.device)
            return true;
    const model::Area &area = station->target().area(a.area);
    c.bit = a.bit >= 0 || area.kind == model::AreaKind::Bit;
    c.bits = area.wordBits;
    if (!station->watchHistory(a)) {
        emit message(tr("%1 keeps no history of %2").arg(station->stationName(), c.device));
        return false;
    }
    m_channels.push_back(c);
    m_stations.emplace_back(station);
    m_past.emplace_back();
    m_canvas->setChannels(&m_channels);
    refresh();
    return true;
}

void NetworkChart::removeRow(int row) {
    if (row < 0 || row >= int(m_channels.size()))
        return;
    m_channels.erase(m_channels.begin() + row);
    m_stations.erase(m_stations.begin() + row);
    m_past.erase(m_past.begin() + row);
    m_canvas->setSelectedRow(-1);
    m_canvas->setChannels(&m_channels);
    refresh();
}

QStringList NetworkChart::devices() const {
    QStringList out;
    for (const model::TimingChannel &c : m_channels)
        out << c.device;
    return out;
}

void NetworkChart::readPast(std::size_t row, qint64 recorderFromMs) {
    Past &past = m_past[row];
    network::StationSource *station = m_stations[row];
    const std::shared_ptr<const network::NetworkHistory> history =
        m_session ? m_session->history() : nullptr;
    if (!station || !history)
        return;
    const std::uint64_t generation = history->generation();
    if (past.generation != generation)
        past = Past{generation}; // Stop: the network started again
    // Read on until the recorder's first value (new instants only, each refresh).
    if (recorderFromMs >= 0 && past.throughMs >= recorderFromMs)
        return;
    const auto &all = m_session->stations();
    const auto index =
        static_cast<std::size_t>(std::find(all.begin(), all.end(), station) - all.begin());
    const model::Address address = m_channels[row].address;
    int word = -1;
    station->readHistory([&](const model::HistoryRecorder &h) { word = h.wordOf(address); });
    if (word < 0 || index >= all.size())
        return;
    network::NetworkHistory::WordValue newest;
    const auto values =
        history->wordValues(index, static_cast<std::size_t>(word), past.throughUs, &newest);
    if (values.empty())
        return;
    station->readHistory([&](const model::HistoryRecorder &h) {
        for (const network::NetworkHistory::WordValue &v : values) {
            const model::HistoryRecorder::Change c{v.scans, v.timeMs, h.valueIn(address, v.value)};
            if (past.changes.empty() || past.changes.back().value != c.value)
                past.changes.push_back(c);
        }
    });
    past.throughUs = newest.us;
    past.throughMs = newest.timeMs;
}

void NetworkChart::readPastMarks() {
    m_pastMarks.clear();
    if (m_armedStops)
        return; // only a marking trigger marks the past, as one program's chart does
    const qsizetype slash = m_armed.indexOf(QLatin1Char('/'));
    network::StationSource *station =
        m_session && slash > 0 ? m_session->station(m_armed.left(slash).trimmed()) : nullptr;
    const std::shared_ptr<const network::NetworkHistory> history =
        m_session ? m_session->history() : nullptr;
    if (!station || !history)
        return;
    m_pastMarksGeneration = history->generation();
    const auto parsed =
        model::parseTrigger(station->target(), m_armed.mid(slash + 1).trimmed(), station->model());
    const auto *trigger = std::get_if<model::Trigger>(&parsed);
    const auto &all = m_session->stations();
    const auto index =
        static_cast<std::size_t>(std::find(all.begin(), all.end(), station) - all.begin());
    if (!trigger || index >= all.size())
        return;
    station->readHistory([&](const model::HistoryRecorder &h) {
        const int word = h.wordOf(trigger->device);
        if (word < 0)
            return;
        const auto values = history->wordValues(index, static_cast<std::size_t>(word), -1);
        for (std::size_t k = 1; k < values.size(); ++k)
            if (trigger->fires(h.valueIn(trigger->device, values[k - 1].value),
                               h.valueIn(trigger->device, values[k].value)))
                m_pastMarks.push_back({values[k].scans, values[k].timeMs});
    });
}

void NetworkChart::refresh() {
    const qint64 now = m_session ? m_session->nowUs() / 1000 : 0;
    if (m_follow->isChecked())
        m_endMs = std::max<qint64>(now, std::llround(m_canvas->waveWidth() * m_msPerPixel));
    m_canvas->setView(m_endMs, m_msPerPixel);
    using Change = model::HistoryRecorder::Change;
    // One window over every row: each row read from its own station's history.
    model::TimingWindow window;
    window.fromMs = m_canvas->fromMs();
    window.toMs = std::min(m_endMs, now);
    for (std::size_t k = 0; k < m_channels.size(); ++k) {
        model::TimingWindow one;
        if (m_stations[k])
            one = model::readWindow(*m_stations[k], {m_channels[k]}, window.fromMs, window.toMs);
        std::vector<Change> changes =
            one.changes.empty() ? std::vector<Change>{} : std::move(one.changes.front());
        qint64 knownFromMs = one.knownFromMs.empty() ? -1 : one.knownFromMs.front();
        // Before the recorder's first value: the network's history.
        readPast(k, knownFromMs);
        const std::vector<Change> &past = m_past[k].changes;
        if (!past.empty() && (knownFromMs < 0 || knownFromMs > window.fromMs)) {
            std::vector<Change> merged;
            for (const Change &c : past) {
                if ((knownFromMs >= 0 && c.timeMs >= knownFromMs) || c.timeMs > window.toMs)
                    break;
                if (c.timeMs <= window.fromMs)
                    merged.assign(1, c); // the value the window starts with
                else
                    merged.push_back(c);
            }
            for (const Change &c : changes)
                if (merged.empty() || merged.back().value != c.value)
                    merged.push_back(c);
            changes = std::move(merged);
            knownFromMs = past.front().timeMs;
        }
        window.changes.push_back(std::move(changes));
        window.knownFromMs.push_back(knownFromMs);
    }
    // The moments the trigger became true: before it was armed from the network's history,
    // since from its station's recorder.
    const qsizetype slash = m_armed.indexOf(QLatin1Char('/'));
    const std::shared_ptr<const network::NetworkHistory> history =
        m_session ? m_session->history() : nullptr;
    if (history && history->generation() != m_pastMarksGeneration)
        m_pastMarks.clear(); // the network started again
    for (const auto &m : m_pastMarks)
        if (m.timeMs >= window.fromMs && m.timeMs <= window.toMs)
            window.marks.push_back(m);
    if (network::StationSource *station =
            m_session && slash > 0 ? m_session->station(m_armed.left(slash).trimmed()) : nullptr)
        station->readHistory([&](const model::HistoryRecorder &h) {
            for (const auto &m : h.marks())
                if (m.timeMs >= window.fromMs && m.timeMs <= window.toMs &&
                    (m_pastMarks.empty() || m.timeMs > m_pastMarks.back().timeMs))
                    window.marks.push_back(m);
        });
    m_window = window;
    m_canvas->setWindow(window);
    const auto a = m_canvas->cursorTime(0);
    QStringList readout;
    if (a)
        readout << tr("A: %1").arg(SimulationController::clockText(*a));
    if (!m_triggerStatus.isEmpty())
        readout << m_triggerStatus;
    m_readout->setText(readout.join(QStringLiteral("    ")));
}

} // namespace rung::app
