#include "app/gui/network_debug_controller.h"

#include "model/image/trigger.h"
#include "network/network_session.h"

// Stop When (network_debug_controller.h): a condition on one station's device, armed as that
// station's trigger with the Stop action (network_session.h: the whole network pauses right
// after the scan in which it fires).

namespace rung::app {

bool NetworkDebugController::setStopCondition(const QString &text, QString *error) {
    const QString before = m_stopCondition;
    m_stopCondition = text.trimmed();
    if (armStopCondition(error)) {
        emit message(m_stopCondition.isEmpty()
                         ? tr("No stop condition")
                         : tr("The network stops when %1 becomes true").arg(m_stopCondition));
        return true;
    }
    m_stopCondition = before;
    armStopCondition(nullptr);
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
    trigger.action = model::Trigger::Action::Stop;
    if (!source->setTrigger(trigger)) {
        if (error)
            *error = tr("%1 cannot be watched in %2").arg(m_stopCondition, s->parts.name);
        return false;
    }
    m_stopSource = source;
    const QString name = s->parts.name;
    connect(source, &model::MonitorSource::triggered, this,
            [this, name](quint64 scan, qint64 timeMs) {
                emit stationWanted(name);
                //: %1 the condition ("s2/D10 > 100"), %2 scan number, %3 virtual time
                emit message(tr("%1 became true after scan %2 (%3): the network stopped there")
                                 .arg(m_stopCondition)
                                 .arg(scan)
                                 .arg(SimulationController::clockText(timeMs)));
            });
    return true;
}

} // namespace rung::app
