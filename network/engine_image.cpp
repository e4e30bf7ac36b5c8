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
        markWritten(c);
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

void EngineImage::markWritten(const model::DeviceCommand &c) {
    if (!m_written)
        return;
    const model::MemoryLayout &l = m_engine->layout();
    int word = -1;
    int count = 1;
    switch (c.kind) {
    case model::DeviceCommand::Kind::WriteBit:
        word = l.bit(c.address).word; // an input's stimulus: read by the next scan
        break;
    case model::DeviceCommand::Kind::WriteWord:
        word = l.word(c.address);
        count = 2; // a double word (PL110 VD) is two
        break;
    case model::DeviceCommand::Kind::WriteSetValue:
        word = l.setValueWord(c.address);
        break;
    case model::DeviceCommand::Kind::Force:
    case model::DeviceCommand::Kind::Release:
    case model::DeviceCommand::Kind::ReleaseAll:
        break;
    }
    if (word >= 0)
        m_written->mark(static_cast<std::size_t>(word), static_cast<std::size_t>(count));
    else // forced bits, or a device the engine refuses: the history looks at everything
        m_written->markAll(true);
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
