#pragma once

// History across the network in the network window: while the network is paused, cursor A of
// the timing chart (or a frame chosen in the Traffic view, which puts cursor A there) shows
// every station as it was at that instant: each station's ladder, inputs and outputs, front
// panel and its rows of the network watch read the station's past (network::StationPastSource,
// rebuilt from the session's NetworkHistory) in place of the live station, until Return to
// Live, Run, Single Scan or Stop. The past is read-only, and marked as the single program's
// window marks it: an amber "History: ..." beside the run state.
//
// The controller knows the widgets it works on, never the window: the window hands it a
// function that points one station's views at a source (live or past).

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QLabel;

namespace rung::model {
class MonitorSource;
}
namespace rung::network {
class NetworkSession;
class StationPastSource;
class StationSource;
} // namespace rung::network

namespace rung::app {

class NetworkChart;
class NetworkTrafficView;
class NetworkWatchModel;

class NetworkHistoryController : public QObject {
    Q_OBJECT

public:
    // Points the views of one station (its ladder, its inputs and outputs, the front panel when
    // it is the station selected) at `source`: the live station or its past.
    using ShowSource =
        std::function<void(network::StationSource *station, model::MonitorSource *source)>;

    NetworkHistoryController(NetworkChart *chart, NetworkTrafficView *traffic,
                             NetworkWatchModel *watch, ShowSource show, QObject *parent);
    ~NetworkHistoryController() override;

    // The session whose past is shown (null: none); the views return to live first.
    void setSession(network::NetworkSession *session);

    // Every station at virtual time `us` (the last instant recorded at or before it), while
    // the network is paused; false with why in message() (running, stopped, not recorded).
    bool showAt(qint64 us);
    void returnToLive();
    bool historyShown() const { return m_shownUs.has_value(); }
    // The instant shown (virtual time, µs).
    std::optional<qint64> shownUs() const { return m_shownUs; }
    // What the views of `station` show: its past while the history is shown, else itself.
    model::MonitorSource *shownSource(network::StationSource *station) const;

    // "History: 0:00:12.34, every station (read-only)"; empty while live.
    QString historyText() const;
    // The amber mark for the status bar (hidden while live). Return to Live (Ctrl+Shift+L) is
    // the Simulation menu's debugging entry (network_debug_controller.h).
    QLabel *label() const { return m_label; }

signals:
    // Translated, for the status bar.
    void message(const QString &text);
    // The history was shown, moved or left.
    void historyChanged();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    void retranslate();
    void update();
    void showSources(bool past);

    QPointer<network::NetworkSession> m_session;
    QPointer<NetworkWatchModel> m_watch;
    ShowSource m_show;
    std::vector<std::unique_ptr<network::StationPastSource>> m_past; // per station, in order
    std::optional<qint64> m_shownUs;
    QLabel *m_label;
};

} // namespace rung::app
