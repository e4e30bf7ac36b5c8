#pragma once

// What the editor draws from: the latest memory image of a PLC, its run state, an error to
// show, and commands that write, force and release devices. A simulator session and an
// online session implement it; nothing above it knows which one feeds it.
//
// Threads: a source lives in the thread that made it (its owner, the UI thread in the IDE)
// and emits every signal there. Snapshots may be published from any thread; readers share
// one immutable copy (no copy per reader) and are told on a beat of kMaxSnapshotsPerSecond
// (NotifyBeat), sooner when a snapshot answers the user.
// Commands are asynchronous: submit() returns an id at once, commandFinished() reports it
// later (online: when the PLC acknowledged the write).

#include "model/image/device_command.h"
#include "model/image/history.h"
#include "model/image/notify_beat.h"
#include "model/image/snapshot.h"
#include "model/image/trigger.h"

#include <QElapsedTimer>
#include <QHash>
#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace rung::model {

class MonitorSource : public QObject {
    Q_OBJECT

public:
    enum class RunState {
        // No program loaded / not connected. A source that goes Offline keeping its last
        // snapshot (an online PLC that stopped answering) shows the last values known:
        // readers draw them as stale until the source is back.
        Offline,
        Stopped,  // at power-on state, not scanning
        Paused,   // image kept, not scanning
        Running,  // scanning
        Stepping, // scanning a counted number of scans, then Paused
    };
    Q_ENUM(RunState)

    using CommandId = quint64;
    static constexpr int kMaxSnapshotsPerSecond = NotifyBeat::kPerSecond;
    // The beat's length in whole milliseconds (33).
    static constexpr int kMinSnapshotIntervalMs = 1000 / kMaxSnapshotsPerSecond;

    explicit MonitorSource(QObject *parent = nullptr);
    ~MonitorSource() override;

    // Any thread. Null until the first snapshot.
    std::shared_ptr<const Snapshot> snapshot() const;
    RunState runState() const { return m_runState; }
    // Translated, empty when there is nothing wrong.
    QString errorText() const { return m_errorText; }

    // Owner thread. Returns the id commandFinished() will carry.
    CommandId submit(const DeviceCommand &command);
    CommandId writeBit(const Address &address, bool on);
    CommandId writeWord(const Address &address, qint64 value);
    CommandId writeSetValue(const Address &address, qint64 value);
    CommandId force(const Address &address, bool on);
    CommandId release(const Address &address);
    CommandId releaseAll();

    // Why this source cannot force bits (translated: an online PLC whose protocol has no force
    // command), or empty when it can. Views grey their force entries out and say why, rather
    // than offer what the PLC would refuse. Owner thread.
    virtual QString forceRefusal() const { return {}; }

    // Readers say which devices they show (an online source polls only those); a reader's
    // set is dropped when it is destroyed. watched() is the union, sorted, without repeats.
    void setWatched(QObject *reader, std::vector<Address> devices);
    std::vector<Address> watched() const;
    // A reader moving from `current` to `next` (either may be null): leaves the old source
    // (its signals to the reader and what the reader watched there) and points `current` at
    // `next`. False, and nothing done, when `next` is the reader's source already.
    static bool switchSource(QPointer<MonitorSource> &current, MonitorSource *next,
                             QObject *reader);

    // History, for the timing chart: the source records chosen devices scan by scan (or poll
    // by poll) in a HistoryRecorder. A source that keeps none answers false and never calls
    // read. Owner thread.
    // Records the device from the next scan on; false for a device not in the image.
    virtual bool watchHistory(const Address &address);
    // Calls read with the history under the lock its recording takes after every scan: read
    // must be quick (copy out what it draws; no dialog, no waiting).
    virtual void readHistory(const std::function<void(const HistoryRecorder &)> &read) const;
    // A condition evaluated on the recorded values of every scan (HistoryRecorder::setTrigger):
    // each time it becomes true the moment is marked and triggered() follows; with
    // Trigger::Action::Stop a simulation also pauses at that scan. Empty: none. False when the
    // source keeps no history or has no such device.
    virtual bool setTrigger(std::optional<Trigger> trigger);

signals:
    void snapshotChanged();
    void runStateChanged(rung::model::MonitorSource::RunState state);
    void errorTextChanged(const QString &text);
    void commandFinished(rung::model::MonitorSource::CommandId id, bool ok, const QString &error);
    void watchedChanged();
    // The trigger fired after this scan, at this virtual time (owner thread).
    void triggered(quint64 scan, qint64 timeMs);

protected:
    // Starts a command; the source calls finishCommand(id, ...) once it is done.
    virtual void startCommand(CommandId id, const DeviceCommand &command) = 0;

    CommandId nextCommandId() { return m_nextId++; } // owner thread
    // Any thread: makes the snapshot the latest and tells readers, on the beat. An answer (the
    // first snapshot after a command of the user took effect) is told at once, so an input
    // toggled shows on the coil within a scan and a repaint.
    void publishSnapshot(std::shared_ptr<const Snapshot> snapshot, bool answer = false);
    // Any thread: delivered to the owner thread as commandFinished().
    void finishCommand(CommandId id, bool ok, const QString &error);
    // Any thread: runs the function on the owner thread, in posting order. Everything the
    // function needs travels through a mutex-guarded queue, so a ThreadSanitizer build sees
    // the hand-over (Qt's own event queue is not instrumented).
    void postToOwner(std::function<void()> function);
    // Owner thread.
    void setRunState(RunState state);
    void setErrorText(const QString &text);

private:
    Q_INVOKABLE void scheduleNotify();
    Q_INVOKABLE void runPosted();
    void notify();

    mutable std::mutex m_mutex;
    std::shared_ptr<const Snapshot> m_latest;
    std::atomic<bool> m_notifyPending{false};
    std::atomic<bool> m_answerPending{false};
    QElapsedTimer m_clock;
    NotifyBeat m_beat; // owner thread
    QTimer m_notifyTimer;
    RunState m_runState = RunState::Offline;
    QString m_errorText;
    CommandId m_nextId = 1;
    QHash<QObject *, std::vector<Address>> m_watched;
    std::vector<std::function<void()>> m_posted; // under m_mutex
};

} // namespace rung::model
