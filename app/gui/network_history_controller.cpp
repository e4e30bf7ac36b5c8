#include "app/gui/network_history_controller.h"

#include "app/gui/network_chart.h"
#include "app/gui/network_traffic_view.h"
#include "app/gui/network_watch_model.h"
#include "app/gui/simulation_controller.h"
#include "network/network_session.h"
#include "network/station_past_source.h"

#include <QEvent>
#include <QLabel>

namespace rung::app {

using RunState = model::MonitorSource::RunState;

NetworkHistoryController::NetworkHistoryController(NetworkChart *chart, NetworkTrafficView *traffic,
                                                   NetworkWatchModel *watch, ShowSource show,
                                                   QObject *parent)
    : QObject(parent)
    , m_watch(watch)
    , m_show(std::move(show))
    , m_label(new QLabel) {
    m_label->setObjectName(QStringLiteral("networkHistoryStatus"));
    // A past instant is never taken for the live network: bold on amber, as the single
    // program's window marks its history (simulation_menu.cpp).
    m_label->setStyleSheet(QStringLiteral(
        "QLabel { background: #ffd54f; color: #3e2700; font-weight: bold; padding: 0 6px; }"));
    m_label->hide();
    m_label->installEventFilter(this);
    // Cursor A (cursor B only measures) and a frame chosen in the Traffic view.
    connect(chart, &NetworkChart::cursorMoved, this,
            [this](qint64 timeMs) { showAt(timeMs * 1000); });
    connect(traffic, &NetworkTrafficView::frameChosen, this,
            [this](qint64 startUs) { showAt(startUs); });
    retranslate();
}

NetworkHistoryController::~NetworkHistoryController() {
    // The views are the window's and may be gone already: no call back into them now.
    if (m_watch)
        for (const auto &p : m_past)
            m_watch->setShownSource(p->live(), nullptr);
    if (m_label && !m_label->parent())
        delete m_label;
}

void NetworkHistoryController::retranslate() {
    update();
}

bool NetworkHistoryController::eventFilter(QObject *watched, QEvent *event) {
    if (watched == m_label && event->type() == QEvent::LanguageChange)
        retranslate();
    return QObject::eventFilter(watched, event);
}

void NetworkHistoryController::setSession(network::NetworkSession *session) {
    returnToLive();
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_past.clear();
    m_session = session;
    if (!session)
        return;
    for (std::size_t i = 0; i < session->stations().size(); ++i) {
        network::StationSource *live = session->stations()[i];
        auto past = std::make_unique<network::StationPastSource>(session->history(), i, live);
        // A write, force or release in the past is refused: say why where the user looks.
        connect(past.get(), &model::MonitorSource::commandFinished, this,
                [this](model::MonitorSource::CommandId, bool ok, const QString &why) {
                    if (!ok)
                        emit message(why);
                });
        m_past.push_back(std::move(past));
    }
    // Run, Single Scan and Stop go on from the present (or start it again): the past is left.
    connect(session, &network::NetworkSession::runStateChanged, this, [this](RunState state) {
        if (state != RunState::Paused)
            returnToLive();
    });
}

bool NetworkHistoryController::showAt(qint64 us) {
    if (!m_session)
        return false;
    const RunState state = m_session->runState();
    if (state != RunState::Paused) {
        emit message(state == RunState::Stopped || state == RunState::Offline
                         ? tr("The network is stopped: run it, then pause it to see any instant "
                              "of its past")
                         : tr("Pause the network to see every station at the cursor's time"));
        return false;
    }
    const auto instant = m_session->history()->instantAt(std::max<qint64>(0, us));
    if (!instant) {
        //: %1 the oldest virtual time still recorded, h:mm:ss.hh
        emit message(tr("That instant is no longer recorded: the history starts at %1")
                         .arg(SimulationController::clockText(
                             m_session->history()->window().firstUs / 1000)));
        return false;
    }
    for (const auto &p : m_past)
        p->show(*instant);
    const bool entering = !m_shownUs;
    m_shownUs = *instant;
    if (entering)
        showSources(true);
    update();
    emit historyChanged();
    return true;
}

void NetworkHistoryController::returnToLive() {
    if (!m_shownUs)
        return;
    m_shownUs.reset();
    showSources(false);
    update();
    emit historyChanged();
}

void NetworkHistoryController::showSources(bool past) {
    for (const auto &p : m_past) {
        network::StationSource *live = p->live();
        if (!live)
            continue;
        model::MonitorSource *source = past ? static_cast<model::MonitorSource *>(p.get()) : live;
        if (m_show)
            m_show(live, source);
        if (m_watch)
            m_watch->setShownSource(live, past ? p.get() : nullptr);
    }
}

model::MonitorSource *NetworkHistoryController::shownSource(network::StationSource *station) const {
    if (m_shownUs)
        for (const auto &p : m_past)
            if (p->live() == station)
                return p.get();
    return station;
}

QString NetworkHistoryController::historyText() const {
    if (!m_shownUs)
        return {};
    //: %1 the virtual time shown, h:mm:ss.hh; every station of the network shows that instant
    return tr("History: %1, every station (read-only)")
        .arg(SimulationController::clockText(*m_shownUs / 1000));
}

void NetworkHistoryController::update() {
    if (!m_label)
        return;
    m_label->setVisible(m_shownUs.has_value());
    m_label->setText(historyText());
    m_label->setToolTip(
        m_shownUs ? tr("Every station's ladder, inputs and outputs, front panel and watched values "
                       "show this instant. Run, Single Scan, Stop or Return to Live (Ctrl+Shift+L) "
                       "go back to the present")
                  : QString());
}

} // namespace rung::app
