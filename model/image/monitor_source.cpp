#include "model/image/monitor_source.h"

#include <algorithm>

namespace rung::model {

MonitorSource::MonitorSource(QObject *parent)
    : QObject(parent) {
    m_notifyTimer.setSingleShot(true);
    connect(&m_notifyTimer, &QTimer::timeout, this, &MonitorSource::notify);
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

void MonitorSource::publishSnapshot(std::shared_ptr<const Snapshot> snapshot) {
    {
        std::lock_guard lock(m_mutex);
        m_latest = std::move(snapshot);
    }
    // One notification in flight at a time; later snapshots replace the pointer it will read.
    // By name, not by functor: the call event is then Qt's alone and carries no data.
    if (!m_notifyPending.exchange(true, std::memory_order_acq_rel))
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
    const qint64 since = m_lastNotify.isValid() ? m_lastNotify.elapsed() : kMinSnapshotIntervalMs;
    if (since >= kMinSnapshotIntervalMs)
        notify();
    else if (!m_notifyTimer.isActive())
        m_notifyTimer.start(static_cast<int>(kMinSnapshotIntervalMs - since));
}

void MonitorSource::notify() {
    m_notifyPending.store(false, std::memory_order_release);
    m_lastNotify.restart();
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
