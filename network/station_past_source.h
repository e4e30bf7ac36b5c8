#pragma once

// A station of a network as it was at a past instant (network_history.h), as the views see a
// PLC: the ladder, the inputs and outputs, the front panel and the network watch show it in
// place of the live station while the network window shows the past. It is read-only: every
// command is refused with a translated "history is read-only". The timing chart's rows read
// the live station's recorder through it (readHistory), so they stay whole.
//
// show() rebuilds on the owner thread: a key and at most NetworkHistory::Limits::keyEvery
// instants of changes, under 0.01 ms of CPU a Vigor station (BM_NetworkHistoryMinute), so a
// dragged cursor is followed without a thread of its own.

#include "network/network_history.h"

#include "model/image/monitor_source.h"

#include <QPointer>

#include <memory>

namespace rung::network {

class StationSource;

class StationPastSource final : public model::MonitorSource {
    Q_OBJECT

public:
    // `index`: the station's place in the network (NetworkSession::stations()).
    StationPastSource(std::shared_ptr<const NetworkHistory> history, std::size_t index,
                      StationSource *live, QObject *parent = nullptr);
    ~StationPastSource() override;

    StationSource *live() const { return m_live; }
    // Owner thread: publishes the station as it was at virtual time `us` (the last instant
    // recorded at or before it); false, and nothing published, when the history does not
    // reach back so far.
    bool show(qint64 us);

    bool watchHistory(const model::Address &address) override;
    void
    readHistory(const std::function<void(const model::HistoryRecorder &)> &read) const override;
    QString forceRefusal() const override;

protected:
    void startCommand(CommandId id, const model::DeviceCommand &command) override;

private:
    std::shared_ptr<const NetworkHistory> m_history;
    std::size_t m_index;
    QPointer<StationSource> m_live;
};

} // namespace rung::network
