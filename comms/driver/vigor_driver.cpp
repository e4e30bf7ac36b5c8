#include "comms/driver/protocol_drivers.h"
#include "comms/protocol/vigor_link_master.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::comms::detail {

namespace {

// 51h: STX station(2) 51 address(4) length(2) ETX sum(2); the reply ACK station(2) 51
// error(2) data(2 a byte) ETX sum(2) (Vigor M/VB/VH communication manual, B-5-3).
constexpr int ReadRequestBytes = 14;
constexpr int ReadReplyOverhead = 10;

} // namespace

QString VigorLinkDriver::plcName() const {
    return QCoreApplication::translate("rung::comms::Driver", "%1 station %2 on %3")
        .arg(m_target.displayName)
        .arg(m_station)
        .arg(m_link.transport().name());
}

int VigorLinkDriver::maxReadUnits(model::ProtocolSpace) const {
    return m_map.maxReadUnits > 0 ? m_map.maxReadUnits : vigor::MaxBytes;
}

int VigorLinkDriver::readFrameBytes(model::ProtocolSpace, int units) const {
    return ReadRequestBytes + ReadReplyOverhead + 2 * units;
}

DriverError VigorLinkDriver::readUnits(model::ProtocolSpace, int start, int count,
                                       std::vector<std::uint32_t> *units, const QString &what) {
    const vigor::Request request{m_station, vigor::Command::Read, start, count, {}};
    DecoderSink<vigor::ReplyDecoder> sink([&request] { return vigor::ReplyDecoder(request); });
    DriverError e = m_link.exchange(vigor::encodeRequest(request), sink, what);
    if (!e.ok())
        return e;
    units->clear();
    for (char byte : sink.decoder().reply().data)
        units->push_back(static_cast<quint8>(byte));
    return {};
}

DriverError VigorLinkDriver::writeUnits(model::ProtocolSpace, int start,
                                        const std::vector<std::uint32_t> &units,
                                        const QString &what) {
    const int limit = m_map.maxWriteUnits > 0 ? m_map.maxWriteUnits : vigor::MaxBytes;
    for (std::size_t at = 0; at < units.size(); at += std::size_t(limit)) {
        vigor::Request request{m_station, vigor::Command::Write, start + int(at), 0, {}};
        for (std::size_t i = at; i < std::min(units.size(), at + std::size_t(limit)); ++i)
            request.data += char(units[i] & 0xFF);
        request.length = int(request.data.size());
        DecoderSink<vigor::ReplyDecoder> sink([&request] { return vigor::ReplyDecoder(request); });
        if (DriverError e = m_link.exchange(vigor::encodeRequest(request), sink, what); !e.ok())
            return e;
    }
    return {};
}

DriverError VigorLinkDriver::writeBit(const model::ProtocolAddress &address, bool on,
                                      const QString &what) {
    // 70h / 71h set one bit of X, Y, M, S (and the contacts of T and C) without touching the
    // other seven of its byte.
    const vigor::Request request{m_station,
                                 on ? vigor::Command::BitOn : vigor::Command::BitOff,
                                 vigor::bitAddress(address.unit, std::max(0, address.bit)),
                                 0,
                                 {}};
    DecoderSink<vigor::ReplyDecoder> sink([&request] { return vigor::ReplyDecoder(request); });
    return m_link.exchange(vigor::encodeRequest(request), sink, what);
}

} // namespace rung::comms::detail
