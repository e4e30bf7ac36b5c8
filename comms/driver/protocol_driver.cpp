#include "comms/driver/protocol_driver.h"

#include "comms/driver/protocol_drivers.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::comms {

model::ProtocolId protocolIdOf(ProtocolKind kind) {
    switch (kind) {
    case ProtocolKind::VigorLink:
        return model::ProtocolId::VigorLink;
    case ProtocolKind::HostLink:
        return model::ProtocolId::HostLink;
    default:
        return model::ProtocolId::Modbus;
    }
}

std::vector<ProtocolKind> protocolsOf(const model::Target &target) {
    std::vector<ProtocolKind> kinds;
    for (const ProtocolKind kind : {ProtocolKind::VigorLink, ProtocolKind::ModbusRtu,
                                    ProtocolKind::ModbusTcp, ProtocolKind::HostLink})
        for (const model::ProtocolMap &map : target.protocolMaps)
            if (map.protocol == protocolIdOf(kind)) {
                kinds.push_back(kind);
                break;
            }
    return kinds;
}

QString protocolName(ProtocolKind kind) {
    switch (kind) {
    case ProtocolKind::VigorLink:
        return QCoreApplication::translate("rung::comms::Driver", "Vigor Computer Link");
    case ProtocolKind::ModbusRtu:
        return QCoreApplication::translate("rung::comms::Driver", "Modbus RTU");
    case ProtocolKind::ModbusTcp:
        return QCoreApplication::translate("rung::comms::Driver", "Modbus TCP");
    case ProtocolKind::HostLink:
        return QCoreApplication::translate("rung::comms::Driver", "Host Link");
    }
    return {};
}

QString modeName(PlcMode mode) {
    switch (mode) {
    case PlcMode::Stop:
        return QCoreApplication::translate("rung::comms::Driver", "STOP");
    case PlcMode::Program:
        return QCoreApplication::translate("rung::comms::Driver", "PROGRAM");
    case PlcMode::Monitor:
        return QCoreApplication::translate("rung::comms::Driver", "MONITOR");
    case PlcMode::Run:
        return QCoreApplication::translate("rung::comms::Driver", "RUN");
    case PlcMode::Unknown:
        break;
    }
    return QCoreApplication::translate("rung::comms::Driver", "unknown mode");
}

ProtocolDriver::ProtocolDriver(Link &link, const model::Target &target,
                               const model::ProtocolMap &map, int station)
    : m_link(link)
    , m_target(target)
    , m_map(map)
    , m_station(station) {}

ProtocolDriver::~ProtocolDriver() = default;

DriverError ProtocolDriver::unsupported(const QString &what, const QString &why) const {
    return {DriverError::Kind::Unsupported, 0,
            QCoreApplication::translate("rung::comms::Driver", "%1: %2").arg(what, why)};
}

DriverError ProtocolDriver::writeBitOfWord(const model::ProtocolAddress &address, bool on,
                                           const QString &what) {
    std::vector<std::uint32_t> word;
    if (DriverError e = readUnits(address.space, address.unit, 1, &word, what); !e.ok())
        return e;
    const std::uint32_t mask = 1u << address.bit;
    return writeUnits(address.space, address.unit, {on ? word[0] | mask : word[0] & ~mask}, what);
}

DriverError ProtocolDriver::forceBit(const model::ProtocolAddress &, bool, const QString &what) {
    return unsupported(
        what,
        QCoreApplication::translate("rung::comms::Driver", "cannot force over %1: the protocol "
                                                           "has no force command; write the "
                                                           "bit instead (the program may "
                                                           "overwrite it)")
            .arg(QCoreApplication::translate("rung::model::Target", m_map.description)));
}

DriverError ProtocolDriver::releaseAllForces(const QString &what) {
    return forceBit({}, false, what);
}

DriverError ProtocolDriver::readMode(PlcMode *mode) {
    *mode = PlcMode::Unknown;
    return {};
}

DriverError ProtocolDriver::setMode(PlcMode) {
    return unsupported(
        plcName(),
        QCoreApplication::translate("rung::comms::Driver", "%1 has no command to change RUN / STOP")
            .arg(QCoreApplication::translate("rung::model::Target", m_map.description)));
}

DriverError ProtocolDriver::prepareWrite(QString *) {
    return {};
}

DriverError ProtocolDriver::identify(PlcIdentity *identity) {
    *identity = {};
    return {};
}

std::unique_ptr<ProtocolDriver> makeProtocolDriver(ProtocolKind kind, Link &link,
                                                   const model::Target &target, int station,
                                                   QString *error) {
    const model::ProtocolMap *map = model::findProtocolMap(target, protocolIdOf(kind));
    if (!map) {
        if (error)
            *error = QCoreApplication::translate("rung::comms::Driver", "%1 does not speak %2")
                         .arg(target.displayName, protocolName(kind));
        return nullptr;
    }
    switch (kind) {
    case ProtocolKind::VigorLink:
        return std::make_unique<detail::VigorLinkDriver>(link, target, *map, station);
    case ProtocolKind::ModbusRtu:
    case ProtocolKind::ModbusTcp:
        return std::make_unique<detail::ModbusDriver>(link, target, *map, station,
                                                      kind == ProtocolKind::ModbusTcp);
    case ProtocolKind::HostLink:
        return std::make_unique<detail::HostLinkDriver>(link, target, *map, station);
    }
    return nullptr;
}

} // namespace rung::comms
