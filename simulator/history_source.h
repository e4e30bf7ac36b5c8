#pragma once

// A past scan of a simulation as a MonitorSource: the views show it in place of the live
// session (clearly marked "History: scan N (time)") and go back to the live one after. It is
// read-only: every command is refused with a translated "history is read-only".
//
// showScan / showTime return at once; a thread of the source rebuilds the scan from the
// session's ScanHistory (the nearest checkpoint and the record after it) and publishes it.
// Requests that come while one is rebuilt collapse to the newest (a dragged slider asks for
// many), so the picture always ends on the last one asked for.

#include "scan_history.h"

#include "model/image/monitor_source.h"

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace rung::simulator {

class HistorySource : public model::MonitorSource {
    Q_OBJECT

public:
    explicit HistorySource(std::shared_ptr<const ScanHistory> history, QObject *parent = nullptr);
    ~HistorySource() override; // waits for a rebuild under way

    const ScanHistory &history() const { return *m_history; }

    // Owner thread: the state after that scan (clamped to the window) / at that virtual time.
    void showScan(quint64 scan);
    void showTime(qint64 timeMs);
    // The scan of the latest snapshot published; empty before the first.
    std::optional<quint64> shownScan() const;

    // The text the window marks the history with: "History: scan 1234 (0:00:12.34)".
    static QString label(quint64 scan, qint64 timeMs);

signals:
    // Owner thread, once the rebuilt snapshot of `scan` is the latest.
    void shown(quint64 scan, qint64 timeMs);
    // The scan asked for is no longer (or not yet) recorded.
    void unavailable(const QString &reason);

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    void workerLoop();

    std::shared_ptr<const ScanHistory> m_history;
    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::optional<quint64> m_request; // under m_mutex
    std::optional<quint64> m_shown;   // under m_mutex
    bool m_quit = false;
    std::thread m_worker; // last: starts after everything it reads exists
};

} // namespace rung::simulator
