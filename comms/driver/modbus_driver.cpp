#include "comms/driver/protocol_drivers.h"
#include "model/target/target.h"

#include <QCoreApplication>

namespace rung::comms::detail {

namespace {

using model::ProtocolSpace;

// Request: RTU unit(1) PDU(5) CRC(2); TCP MBAP(7) PDU(5). Reply to a read: function(1)
// count(1) data, in the same frame (Application Protocol 6.1-6.4).
constexpr int RtuOverhead = 1 + 2;
constexpr int TcpOverhead = 7;

bool isBitSpace(ProtocolSpace space) {
    return space == ProtocolSpace::Coils || space == ProtocolSpace::DiscreteInputs;
}

} // namespace

ModbusDriver::ModbusDriver(Link &link, const model::Target &target, const model::ProtocolMap &map,
                           int station, bool tcp)
    : ProtocolDriver(link, target, map, station)
    , m_tcp(tcp) {}

QString ModbusDriver::plcName() const {
    return QCoreApplication::translate("rung::comms::Driver", "%1 unit %2 on %3")
        .arg(m_target.displayName)
        .arg(m_station)
        .arg(m_link.transport().name());
}

int ModbusDriver::maxReadUnits(ProtocolSpace space) const {
    // The PL110 manual (3.1) limits the word functions (03, 04, 10) to 30 words and says
    // nothing of a limit on bits: the map's limit is a register limit.
    if (isBitSpace(space))
        return modbus::MaxReadBits;
    return m_map.maxReadUnits > 0 ? std::min(m_map.maxReadUnits, modbus::MaxReadRegisters)
                                  : modbus::MaxReadRegisters;
}

int ModbusDriver::readFrameBytes(ProtocolSpace space, int units) const {
    const int overhead = m_tcp ? TcpOverhead : RtuOverhead;
    const int data = isBitSpace(space) ? (units + 7) / 8 : 2 * units;
    return (overhead + 5) + (overhead + 2 + data);
}

DriverError ModbusDriver::transact(const modbus::Request &request, modbus::Response *response,
                                   const QString &what) {
    const QByteArray pdu = modbus::encodeRequestPdu(request);
    const int transaction = m_transaction = (m_transaction + 1) & 0xFFFF;
    const auto framing = m_tcp ? modbus::Framing::Tcp : modbus::Framing::Rtu;
    const QByteArray frame =
        m_tcp ? modbus::tcpFrame(transaction, m_station, pdu) : modbus::rtuFrame(m_station, pdu);
    DecoderSink<modbus::ReplyDecoder> sink(
        [&] { return modbus::ReplyDecoder(framing, m_station, request, transaction); });
    DriverError e = m_link.exchange(frame, sink, what);
    if (e.ok() && response)
        *response = sink.decoder().response();
    return e;
}

DriverError ModbusDriver::readUnits(ProtocolSpace space, int start, int count,
                                    std::vector<std::uint32_t> *units, const QString &what) {
    modbus::Request request;
    request.function = space == ProtocolSpace::Coils            ? modbus::ReadCoils
                       : space == ProtocolSpace::DiscreteInputs ? modbus::ReadDiscreteInputs
                                                                : modbus::ReadHoldingRegisters;
    request.address = start;
    request.count = count;
    modbus::Response response;
    if (DriverError e = transact(request, &response, what); !e.ok())
        return e;
    units->clear();
    if (isBitSpace(space))
        for (int i = 0; i < count; ++i)
            units->push_back(response.bits[std::size_t(i)] ? 1 : 0);
    else
        units->assign(response.registers.begin(), response.registers.end());
    return {};
}

DriverError ModbusDriver::writeUnits(ProtocolSpace space, int start,
                                     const std::vector<std::uint32_t> &units, const QString &what) {
    if (space == ProtocolSpace::DiscreteInputs)
        return {DriverError::Kind::BadDevice, 0,
                QCoreApplication::translate("rung::comms::Driver",
                                            "%1: Modbus has no function that writes discrete "
                                            "inputs")
                    .arg(what)};
    const bool bits = space == ProtocolSpace::Coils;
    const int mapLimit = m_map.maxWriteUnits > 0 ? m_map.maxWriteUnits : modbus::MaxWriteRegisters;
    const int limit = bits ? modbus::MaxWriteBits : std::min(mapLimit, modbus::MaxWriteRegisters);
    for (std::size_t at = 0; at < units.size(); at += std::size_t(limit)) {
        const std::size_t end = std::min(units.size(), at + std::size_t(limit));
        modbus::Request request;
        request.address = start + int(at);
        request.count = int(end - at);
        for (std::size_t i = at; i < end; ++i) {
            if (bits)
                request.bits.push_back(units[i] != 0);
            else
                request.registers.push_back(std::uint16_t(units[i]));
        }
        // One unit: the single-write functions, which every slave has.
        request.function =
            bits ? (request.count == 1 ? modbus::WriteSingleCoil : modbus::WriteMultipleCoils)
                 : (request.count == 1 ? modbus::WriteSingleRegister
                                       : modbus::WriteMultipleRegisters);
        if (DriverError e = transact(request, nullptr, what); !e.ok())
            return e;
    }
    return {};
}

DriverError ModbusDriver::writeBit(const model::ProtocolAddress &address, bool on,
                                   const QString &what) {
    if (address.bit < 0)
        return writeUnits(address.space, address.unit, {on ? 1u : 0u}, what);
    return writeBitOfWord(address, on, what); // a bit inside a register
}

bool ModbusDriver::identifies() const {
    return m_map.modelRegister >= 0;
}

DriverError ModbusDriver::identify(PlcIdentity *identity) {
    *identity = {};
    if (m_map.modelRegister < 0)
        return {};
    const QString what =
        QCoreApplication::translate("rung::comms::Driver", "reading the model of %1")
            .arg(plcName());
    std::vector<std::uint32_t> words;
    const bool adjacent = m_map.versionRegister == m_map.modelRegister + 1;
    if (DriverError e = readUnits(ProtocolSpace::HoldingRegisters, m_map.modelRegister,
                                  adjacent ? 2 : 1, &words, what);
        !e.ok())
        return e;
    identity->model =
        QCoreApplication::translate("rung::comms::Driver", "device type %1").arg(words[0]);
    if (m_map.versionRegister >= 0) {
        if (!adjacent) {
            std::vector<std::uint32_t> version;
            if (DriverError e = readUnits(ProtocolSpace::HoldingRegisters, m_map.versionRegister, 1,
                                          &version, what);
                !e.ok())
                return e;
            words.push_back(version[0]);
        }
        // Word 1, "Versione software programma PL110" (PL110 manual 3.2): a number, which
        // the panel introduces as the version.
        identity->version = QString::number(words[1]);
    }
    return {};
}

} // namespace rung::comms::detail
