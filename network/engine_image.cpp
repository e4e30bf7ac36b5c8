#include "network/engine_image.h"
#include "network/tr.h"

#include "simulator/command_inbox.h"

#include <QCoreApplication>

namespace rung::network {

std::shared_ptr<const model::Snapshot> EngineImage::snapshot() const {
    if (!m_snapshot || m_scans != m_engine->statistics().scans) {
        m_snapshot = std::make_shared<const model::Snapshot>(m_engine->snapshot());
        m_scans = m_engine->statistics().scans;
    }
    return m_snapshot;
}

comms::slave::ImageChange EngineImage::apply(const std::vector<model::DeviceCommand> &commands,
                                             QDeadlineTimer) {
    comms::slave::ImageChange change;
    for (const model::DeviceCommand &c : commands) {
        QString error;
        if (!simulator::applyCommand(*m_engine, simulator::EngineCommand{0, c}, &error)) {
            change.status = comms::slave::ImageChange::Status::Refused;
            change.message = error;
            break;
        }
    }
    m_snapshot.reset(); // the next read sees the write
    return change;
}

comms::slave::ImageChange EngineImage::setMode(comms::slave::OperatingMode mode, QDeadlineTimer) {
    comms::slave::ImageChange change;
    if (mode != comms::slave::OperatingMode::Run && mode != comms::slave::OperatingMode::Monitor) {
        change.status = comms::slave::ImageChange::Status::Refused;
        change.message =
            EngineImageTr::tr("a station of a network keeps running: it is not stopped from "
                              "its port");
        return change;
    }
    m_mode = mode;
    return change;
}

} // namespace rung::network
