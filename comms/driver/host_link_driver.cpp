#include "comms/driver/protocol_drivers.h"
#include "comms/protocol/ascii_hex.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::comms::detail {

namespace {

using model::ProtocolSpace;

int textOf(const QList<QByteArray> &parts) {
    int bytes = 0;
    for (const QByteArray &p : parts)
        bytes += int(p.size());
    return bytes;
}

} // namespace

QString HostLinkDriver::plcName() const {
    return QCoreApplication::translate("rung::comms::Driver", "%1 unit %2 on %3")
        .arg(m_target.displayName)
        .arg(m_station)
        .arg(m_link.transport().name());
}

int HostLinkDriver::maxReadUnits(ProtocolSpace) const {
    // A count has four digits; a long reply comes in parts of 30 / 31 words, which the cost
    // below counts (each part's FCS and CR, and the CR the host answers with).
    return hostlink::MaxWords;
}

int HostLinkDriver::readFrameBytes(ProtocolSpace space, int units) const {
    const auto key = std::pair{int(space), units};
    if (const auto it = m_costs.find(key); it != m_costs.end())
        return it->second;
    const hostlink::Frame command = hostlink::readCommand(m_station, space, 0, units);
    hostlink::Frame reply = command;
    reply.endCode = hostlink::Normal;
    reply.text = QByteArray(space == ProtocolSpace::HostLinkCompletion ? units : 4 * units, '0');
    const QList<QByteArray> parts = hostlink::encode(reply);
    const int bytes = textOf(hostlink::encode(command)) + textOf(parts) + int(parts.size()) - 1;
    m_costs.emplace(key, bytes);
    return bytes;
}

bool HostLinkDriver::bcdUnits(ProtocolSpace space) const {
    return space == ProtocolSpace::HostLinkTimerPv; // RC / WC carry BCD digits (W353)
}

DriverError HostLinkDriver::command(const hostlink::Frame &frame, hostlink::Reply *reply,
                                    const QString &what) {
    const QList<QByteArray> parts = hostlink::encode(frame);
    // The driver's commands fit one frame (writes are at most a few words); a longer one
    // would need the PLC's delimiter between its parts.
    Q_ASSERT(parts.size() == 1);
    DecoderSink<hostlink::ReplyDecoder> sink([&frame] { return hostlink::ReplyDecoder(frame); });
    DriverError e = m_link.exchange(parts.front(), sink, what);
    if (e.kind == DriverError::Kind::Refused &&
        (e.code == hostlink::NotInRun || e.code == hostlink::NotInMonitor ||
         e.code == hostlink::NotInProgram))
        m_mode = PlcMode::Unknown; // someone changed the mode: look again before the next write
    if (e.ok() && reply)
        *reply = sink.decoder().reply();
    return e;
}

DriverError HostLinkDriver::readUnits(ProtocolSpace space, int start, int count,
                                      std::vector<std::uint32_t> *units, const QString &what) {
    hostlink::Reply reply;
    if (DriverError e =
            command(hostlink::readCommand(m_station, space, start, count), &reply, what);
        !e.ok())
        return e;
    units->clear();
    if (space == ProtocolSpace::HostLinkCompletion)
        for (bool flag : reply.flags)
            units->push_back(flag ? 1 : 0);
    else
        units->assign(reply.words.begin(), reply.words.end());
    return {};
}

DriverError HostLinkDriver::writeUnits(ProtocolSpace space, int start,
                                       const std::vector<std::uint32_t> &units,
                                       const QString &what) {
    if (space == ProtocolSpace::HostLinkCompletion)
        return {DriverError::Kind::BadDevice, 0,
                QCoreApplication::translate("rung::comms::Driver",
                                            "%1: the completion flags of timers and counters "
                                            "are read-only over Host Link (RG)")
                    .arg(what)};
    // At most 29 words a command keeps every write in one frame (131 characters).
    constexpr std::size_t limit = 29;
    for (std::size_t at = 0; at < units.size(); at += limit) {
        std::vector<std::uint16_t> words;
        for (std::size_t i = at; i < std::min(units.size(), at + limit); ++i)
            words.push_back(std::uint16_t(units[i]));
        if (DriverError e = command(
                hostlink::writeCommand(m_station, space, start + int(at), words), nullptr, what);
            !e.ok())
            return e;
    }
    return {};
}

DriverError HostLinkDriver::writeBit(const model::ProtocolAddress &address, bool on,
                                     const QString &what) {
    if (address.space == ProtocolSpace::HostLinkCompletion || address.bit < 0)
        return writeUnits(address.space, address.unit, {on ? 1u : 0u}, what);
    return writeBitOfWord(address, on, what); // C-mode has no command that writes one bit
}

DriverError HostLinkDriver::forceBit(const model::ProtocolAddress &address, bool on,
                                     const QString &what) {
    if (address.space != ProtocolSpace::HostLinkIr || address.bit < 0)
        return unsupported(what, QCoreApplication::translate(
                                     "rung::comms::Driver",
                                     "Host Link forces bits of the IR / SR channels (CIO) only"));
    return command(hostlink::forceCommand(m_station, on, address.unit, address.bit), nullptr, what);
}

DriverError HostLinkDriver::releaseAllForces(const QString &what) {
    return command(hostlink::cancelForceCommand(m_station), nullptr, what);
}

DriverError HostLinkDriver::readMode(PlcMode *mode) {
    hostlink::Reply reply;
    const QString what =
        QCoreApplication::translate("rung::comms::Driver", "reading the mode of %1").arg(plcName());
    if (DriverError e = command(hostlink::statusCommand(m_station), &reply, what); !e.ok())
        return e;
    switch (hostlink::modeOfStatus(reply.status)) {
    case hostlink::Mode::Program:
        m_mode = PlcMode::Program;
        break;
    case hostlink::Mode::Monitor:
        m_mode = PlcMode::Monitor;
        break;
    case hostlink::Mode::Run:
        m_mode = PlcMode::Run;
        break;
    }
    *mode = m_mode;
    return {};
}

DriverError HostLinkDriver::setMode(PlcMode mode) {
    const hostlink::Mode wire = mode == PlcMode::Run       ? hostlink::Mode::Run
                                : mode == PlcMode::Monitor ? hostlink::Mode::Monitor
                                                           : hostlink::Mode::Program;
    const QString what = QCoreApplication::translate("rung::comms::Driver", "switching %1 to %2")
                             .arg(plcName(), modeName(mode));
    DriverError e = command(hostlink::modeCommand(m_station, wire), nullptr, what);
    m_mode = e.ok() ? mode : PlcMode::Unknown;
    return e;
}

DriverError HostLinkDriver::prepareWrite(QString *notice) {
    if (m_mode == PlcMode::Unknown) {
        PlcMode mode;
        if (DriverError e = readMode(&mode); !e.ok())
            return e;
    }
    if (m_mode != PlcMode::Run)
        return {};
    if (DriverError e = setMode(PlcMode::Monitor); !e.ok())
        return e;
    if (notice)
        *notice = QCoreApplication::translate("rung::comms::Driver",
                                              "%1 was in RUN mode: switched to MONITOR, "
                                              "where Host Link writes are accepted (the "
                                              "program goes on running)")
                      .arg(plcName());
    return {};
}

DriverError HostLinkDriver::identify(PlcIdentity *identity) {
    *identity = {};
    hostlink::Reply reply;
    const QString what =
        QCoreApplication::translate("rung::comms::Driver", "reading the model of %1")
            .arg(plcName());
    if (DriverError e = command(hostlink::modelCommand(m_station), &reply, what); !e.ok())
        return e;
    identity->model = QCoreApplication::translate("rung::comms::Driver", "model code %1h")
                          .arg(detail::hex2(reply.model));
    return {};
}

} // namespace rung::comms::detail
