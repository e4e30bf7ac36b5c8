#include "comms/slave/responder.h"

#include "comms/slave/host_link_responder.h"
#include "comms/slave/modbus_responder.h"
#include "comms/slave/vigor_responder.h"

namespace rung::comms::slave {

ImageChange Responder::apply(const MappedImage::Change &change) {
    const QDeadlineTimer deadline(m_writeTimeoutMs);
    if (!change.commands.empty()) {
        ImageChange done = m_image->apply(change.commands, deadline);
        if (!done.done())
            return done;
    }
    if (change.mode && *change.mode != m_image->mode())
        return m_image->setMode(*change.mode, deadline);
    return {};
}

std::unique_ptr<Responder> makeResponder(const model::Target &target, const model::ProtocolMap &map,
                                         int station, std::shared_ptr<DeviceImage> image,
                                         modbus::Framing framing, const SerialSettings &line,
                                         int writeTimeoutMs) {
    switch (map.protocol) {
    case model::ProtocolId::VigorLink:
        return std::make_unique<VigorResponder>(target, map, station, std::move(image),
                                                writeTimeoutMs);
    case model::ProtocolId::Modbus:
        return std::make_unique<ModbusResponder>(target, map, station, std::move(image), framing,
                                                 line, writeTimeoutMs);
    case model::ProtocolId::HostLink:
        return std::make_unique<HostLinkResponder>(target, map, station, std::move(image),
                                                   writeTimeoutMs);
    }
    return nullptr;
}

} // namespace rung::comms::slave
