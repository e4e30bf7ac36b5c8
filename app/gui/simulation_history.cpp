#include "simulation_controller.h"

#include "simulator/history_source.h"
#include "simulator/session.h"

// History: the views show a past scan, rebuilt from the session's record (ScanHistory), in
// place of the live session until Return to Live. The session goes on meanwhile (pause it to
// look at the past at leisure); the history is read-only.

namespace rung::app {

namespace {

QString duration(qint64 ms) {
    const qint64 s = ms / 1000;
    return QStringLiteral("%1:%2:%3")
        .arg(s / 3600)
        .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
        .arg(s % 60, 2, 10, QLatin1Char('0'));
}

} // namespace

void SimulationController::showHistoryScan(quint64 scan) {
    if (!m_session)
        return;
    if (!m_historySource) {
        m_historySource = std::make_unique<simulator::HistorySource>(m_session->scanHistory());
        connect(m_historySource.get(), &simulator::HistorySource::shown, this,
                &SimulationController::statusChanged);
        connect(m_historySource.get(), &simulator::HistorySource::unavailable, this,
                &SimulationController::message);
        connect(m_historySource.get(), &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &error) {
                    if (!ok)
                        emit message(error);
                });
        emit monitorSourceChanged(m_historySource.get());
    }
    m_historySource->showScan(scan);
    emit statusChanged();
}

void SimulationController::showHistoryAt(qint64 timeMs) {
    if (!m_session)
        return;
    if (const auto scan = m_session->scanHistory()->scanAt(timeMs))
        showHistoryScan(*scan);
}

void SimulationController::returnToLive() {
    if (!m_historySource)
        return;
    // Live before anyone is told: the window names the origin by historyShown(), and the
    // views let go of the history while it still lives (it goes at the end of this scope).
    const std::unique_ptr<simulator::HistorySource> shown = std::move(m_historySource);
    emit monitorSourceChanged(m_session.get());
    emit statusChanged();
}

QString SimulationController::historyText() const {
    if (!m_historySource)
        return {};
    const auto s = m_historySource->snapshot();
    if (!s)
        return tr("History: rebuilding...");
    return simulator::HistorySource::label(s->statistics.scans, s->statistics.timeMs);
}

QString SimulationController::historyWindowText() const {
    if (!m_session)
        return tr("No history: the simulation is off");
    const simulator::ScanHistory::Window w = m_session->scanHistory()->window();
    if (w.lastScan <= w.firstScan)
        return tr("No history yet: run the simulation");
    //: %1 h:mm:ss of simulated time, %2 %3 first and last scan, %4 memory in MB
    // The record keeps at least the last hour and drops the oldest scans only a checkpoint at
    // a time (simulator/scan_history.h): it may hold more than an hour, never less.
    return tr("Recorded: the last %1 of simulated time (scans %2..%3, %4 MB); at least the last "
              "hour is kept")
        .arg(duration(w.lastMs - w.firstMs))
        .arg(w.firstScan)
        .arg(w.lastScan)
        .arg(QString::number(static_cast<double>(w.bytes) / (1024.0 * 1024.0), 'f', 1));
}

} // namespace rung::app
