#include "app/gui/network_debug_controller.h"

#include "model/image/trigger.h"
#include "network/network_session.h"

// The network's trigger (network_debug_controller.h): a condition on one station's device,
// armed as that station's trigger (model/image/trigger.h). Stop When... and the timing chart's
// trigger both set it: with the Stop action the whole network pauses right after the scan in
// which it fires, every other station at its scan boundary (network_session.h); with Mark the
// moment is only noted.

namespace rung::app {

bool NetworkDebugController::setStopCondition(const QString &text, QString *error) {
    return setTrigger(text, model::Trigger::Action::Stop, error);
}

bool NetworkDebugController::setTrigger(const QString &text, model::Trigger::Action action,
                                        QString *error) {
    const QString before = m_stopCondition;
    const model::Trigger::Action actionBefore = m_triggerAction;
    m_stopCondition = text.trimmed();
    m_triggerAction = action;
    if (armStopCondition(error)) {
        emit message(m_stopCondition.isEmpty() ? tr("No stop condition")
                     : action == model::Trigger::Action::Stop
                         ? tr("The network stops when %1 becomes true").arg(m_stopCondition)
                         //: %1 the condition ("s2/D10 > 100")
                         : tr("The timing chart marks when %1 becomes true").arg(m_stopCondition));
        emit triggerChanged();
        return true;
    }
    m_stopCondition = before;
    m_triggerAction = actionBefore;
    armStopCondition(nullptr);
    emit triggerChanged();
    return false;
}

bool NetworkDebugController::armStopCondition(QString *error) {
    if (m_stopSource) {
        disconnect(m_stopSource, &model::MonitorSource::triggered, this, nullptr);
        m_stopSource->setTrigger(std::nullopt);
        m_stopSource = nullptr;
    }
    if (m_stopCondition.isEmpty())
        return true;
    const qsizetype slash = m_stopCondition.indexOf(QLatin1Char('/'));
    const Station *s = slash > 0 ? find(m_stopCondition.left(slash).trimmed()) : nullptr;
    if (!s) {
        if (error) {
            QStringList names;
            for (const Station &st : m_stations)
                names << st.parts.name;
            //: %1 what was typed, %2 the stations' names
            *error = tr("%1: write STATION/CONDITION with a station of the network (%2)")
                         .arg(m_stopCondition, names.join(QStringLiteral(", ")));
        }
        return false;
    }
    network::StationSource *source = s->parts.source;
    const auto parsed =
        model::parseTrigger(source->target(), m_stopCondition.mid(slash + 1), source->model());
    if (const QString *why = std::get_if<QString>(&parsed)) {
        if (error)
            *error = *why;
        return false;
    }
    model::Trigger trigger = std::get<model::Trigger>(parsed);
    trigger.action = m_triggerAction;
    if (!source->setTrigger(trigger)) {
        if (error)
            *error = tr("%1 cannot be watched in %2").arg(m_stopCondition, s->parts.name);
        return false;
    }
    m_stopSource = source;
    const QString name = s->parts.name;
    connect(source, &model::MonitorSource::triggered, this,
            [this, name](quint64 scan, qint64 timeMs) {
                const bool stopped = m_triggerAction == model::Trigger::Action::Stop;
                if (stopped) {
                    // Shown as a breakpoint's stop is: the station, and what stopped it.
                    m_triggerStop = m_stopCondition;
                    emit stationWanted(name);
                    //: %1 the condition ("s2/D10 > 100"), %2 scan number, %3 virtual time
                    emit message(tr("%1 became true after scan %2 (%3): the network stopped there")
                                     .arg(m_stopCondition)
                                     .arg(scan)
                                     .arg(SimulationController::clockText(timeMs)));
                    updateHeld();
                }
                emit triggerFired(scan, timeMs, stopped);
            });
    return true;
}

} // namespace rung::app
