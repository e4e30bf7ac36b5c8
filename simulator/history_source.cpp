#include "history_source.h"
#include "simulator/tr.h"

#include <QCoreApplication>

namespace rung::simulator {

namespace {

QString clock(qint64 ms) {
    const qint64 hundredths = ms / 10;
    return QStringLiteral("%1:%2:%3.%4")
        .arg(hundredths / 360000)
        .arg(hundredths / 6000 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths / 100 % 60, 2, 10, QLatin1Char('0'))
        .arg(hundredths % 100, 2, 10, QLatin1Char('0'));
}

} // namespace

HistorySource::HistorySource(std::shared_ptr<const ScanHistory> history, QObject *parent)
    : MonitorSource(parent)
    , m_history(std::move(history)) {
    // Not scanning: the image is held, as a paused session's.
    setRunState(RunState::Paused);
    m_worker = std::thread([this] { workerLoop(); });
}

HistorySource::~HistorySource() {
    {
        std::lock_guard lock(m_mutex);
        m_quit = true;
    }
    m_wake.notify_all();
    m_worker.join();
}

QString HistorySource::label(quint64 scan, qint64 timeMs) {
    //: the window's mark while it shows a past scan; %1 the scan, %2 its time h:mm:ss.cc
    return HistorySourceTr::tr("History: scan %1 (%2)").arg(scan).arg(clock(timeMs));
}

void HistorySource::showScan(quint64 scan) {
    {
        std::lock_guard lock(m_mutex);
        m_request = scan;
    }
    m_wake.notify_all();
}

void HistorySource::showTime(qint64 timeMs) {
    if (const auto scan = m_history->scanAt(timeMs))
        showScan(*scan);
    else
        emit unavailable(HistorySourceTr::tr("nothing is recorded yet: run the simulation first"));
}

std::optional<quint64> HistorySource::shownScan() const {
    std::lock_guard lock(m_mutex);
    return m_shown;
}

void HistorySource::startCommand(CommandId id, const model::DeviceCommand &) {
    finishCommand(
        id, false,
        HistorySourceTr::tr("history is read-only: return to live to write, force or release"));
}

void HistorySource::workerLoop() {
    for (;;) {
        quint64 scan = 0;
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [this] { return m_quit || m_request.has_value(); });
            if (m_quit)
                return;
            scan = *m_request;
            m_request.reset();
        }
        const ScanHistory::Window w = m_history->window();
        if (w.empty()) {
            postToOwner([this] {
                emit unavailable(
                    HistorySourceTr::tr("nothing is recorded yet: run the simulation first"));
            });
            continue;
        }
        const quint64 clamped = std::clamp(scan, w.firstScan, w.lastScan);
        std::optional<model::Snapshot> rebuilt = m_history->rebuild(clamped);
        if (!rebuilt) { // the window moved on meanwhile
            postToOwner([this] {
                emit unavailable(HistorySourceTr::tr("that scan is no longer recorded"));
            });
            continue;
        }
        const qint64 timeMs = rebuilt->statistics.timeMs;
        // The snapshot first: whoever sees shownScan() change finds that scan's snapshot.
        publishSnapshot(std::make_shared<const model::Snapshot>(std::move(*rebuilt)));
        {
            std::lock_guard lock(m_mutex);
            m_shown = clamped;
        }
        postToOwner([this, clamped, timeMs] { emit shown(clamped, timeMs); });
    }
}

} // namespace rung::simulator
