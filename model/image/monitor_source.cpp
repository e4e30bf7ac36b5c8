#include "model/image/monitor_source.h"

#include <algorithm>

namespace rung::model {

MonitorSource::MonitorSource(QObject *parent)
    : QObject(parent) {
    m_notifyTimer.setSingleShot(true);
    // A coarse timer may fire 5% late: the beat would slip under 30 a second.
    m_notifyTimer.setTimerType(Qt::PreciseTimer);
    m_clock.start();
    connect(&m_notifyTimer, &QTimer::timeout, this, &MonitorSource::scheduleNotify);
}

MonitorSource::~MonitorSource() = default;

std::shared_ptr<const Snapshot> MonitorSource::snapshot() const {
    std::lock_guard lock(m_mutex);
    return m_latest;
}

MonitorSource::CommandId MonitorSource::submit(const DeviceCommand &command) {
    const CommandId id = nextCommandId();
    startCommand(id, command);
    return id;
}

MonitorSource::CommandId MonitorSource::writeBit(const Address &address, bool on) {
    return submit({DeviceCommand::Kind::WriteBit, address, on ? 1 : 0});
}

MonitorSource::CommandId MonitorSource::writeWord(const Address &address, qint64 value) {
    return submit({DeviceCommand::Kind::WriteWord, address, value});
}

MonitorSource::CommandId MonitorSource::writeSetValue(const Address &address, qint64 value) {
    return submit({DeviceCommand::Kind::WriteSetValue, address, value});
}

MonitorSource::CommandId MonitorSource::force(const Address &address, bool on) {
    return submit({DeviceCommand::Kind::Force, address, on ? 1 : 0});
}

MonitorSource::CommandId MonitorSource::release(const Address &address) {
    return submit({DeviceCommand::Kind::Release, address, 0});
}

MonitorSource::CommandId MonitorSource::releaseAll() {
    return submit({DeviceCommand::Kind::ReleaseAll, {}, 0});
}

void MonitorSource::setWatched(QObject *reader, std::vector<Address> devices) {
    if (!m_watched.contains(reader))
        connect(reader, &QObject::destroyed, this, [this, reader] {
            if (m_watched.remove(reader))
                emit watchedChanged();
        });
    m_watched.insert(reader, std::move(devices));
    emit watchedChanged();
}

bool MonitorSource::switchSource(QPointer<MonitorSource> &current, MonitorSource *next,
                                 QObject *reader) {
    if (current == next)
        return false;
    if (current) {
        disconnect(current, nullptr, reader, nullptr);
        if (current->m_watched.remove(reader))
            emit current->watchedChanged();
    }
    current = next;
    return true;
}

std::vector<Address> MonitorSource::watched() const {
    std::vector<Address> all;
    for (const auto &devices : m_watched)
        all.insert(all.end(), devices.begin(), devices.end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

bool MonitorSource::watchHistory(const Address &) {
    return false;
}

void MonitorSource::readHistory(const std::function<void(const HistoryRecorder &)> &) const {}

bool MonitorSource::setTrigger(std::optional<Trigger>) {
    return false;
}

void MonitorSource::publishSnapshot(std::shared_ptr<const Snapshot> snapshot, bool answer) {
    {
        std::lock_guard lock(m_mutex);
        m_latest = std::move(snapshot);
    }
    // One notification in flight at a time; later snapshots replace the pointer it will read.
    // An answer asks again: the one in flight may be waiting for the beat.
    // By name, not by functor: the call event is then Qt's alone and carries no data.
    const bool wasPending = m_notifyPending.exchange(true, std::memory_order_acq_rel);
    const bool wasAnswer = answer && m_answerPending.exchange(true, std::memory_order_acq_rel);
    if (!wasPending || (answer && !wasAnswer))
        QMetaObject::invokeMethod(this, "scheduleNotify", Qt::QueuedConnection);
}

void MonitorSource::postToOwner(std::function<void()> function) {
    bool first = false;
    {
        std::lock_guard lock(m_mutex);
        first = m_posted.empty();
        m_posted.push_back(std::move(function));
    }
    if (first)
        QMetaObject::invokeMethod(this, "runPosted", Qt::QueuedConnection);
}

void MonitorSource::runPosted() {
    std::vector<std::function<void()>> posted;
    {
        std::lock_guard lock(m_mutex);
        posted.swap(m_posted);
    }
    for (const auto &function : posted)
        function();
}

void MonitorSource::scheduleNotify() {
    const qint64 due = m_beat.dueUs(m_notifyPending.load(std::memory_order_acquire),
                                    m_answerPending.load(std::memory_order_acquire));
    if (due == NotifyBeat::kNever)
        return;
    const qint64 now = m_clock.nsecsElapsed() / 1000;
    if (now >= due) {
        m_notifyTimer.stop();
        notify();
        return;
    }
    // Rounded up: early would find the beat not yet due and wait a whole beat more.
    const int ms = static_cast<int>((due - now + 999) / 1000);
    if (!m_notifyTimer.isActive() || m_notifyTimer.remainingTime() > ms)
        m_notifyTimer.start(ms);
}

void MonitorSource::notify() {
    m_notifyPending.store(false, std::memory_order_release);
    m_answerPending.store(false, std::memory_order_release);
    m_beat.notified(m_clock.nsecsElapsed() / 1000);
    emit snapshotChanged();
}

void MonitorSource::finishCommand(CommandId id, bool ok, const QString &error) {
    postToOwner([this, id, ok, error] { emit commandFinished(id, ok, error); });
}

void MonitorSource::setRunState(RunState state) {
    if (state == m_runState)
        return;
    m_runState = state;
    emit runStateChanged(state);
}

void MonitorSource::setErrorText(const QString &text) {
    if (text == m_errorText)
        return;
    m_errorText = text;
    emit errorTextChanged(text);
}

} // namespace rung::model
