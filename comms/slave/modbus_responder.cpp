#include "comms/slave/modbus_responder.h"

namespace rung::comms::slave {

namespace {

using model::ProtocolSpace;
using namespace modbus;

bool isWrite(int function) {
    return function == WriteSingleCoil || function == WriteSingleRegister ||
           function == WriteMultipleCoils || function == WriteMultipleRegisters;
}

} // namespace

ModbusResponder::ModbusResponder(const model::Target &target, const model::ProtocolMap &map,
                                 int station, std::shared_ptr<DeviceImage> image, Framing framing,
                                 const SerialSettings &line, int writeTimeoutMs)
    : Responder(target, map, station, std::move(image), writeTimeoutMs)
    , m_framing(framing)
    , m_line(line)
    , m_decoder(framing) {}

int ModbusResponder::silenceMicroseconds() const {
    return m_framing == Framing::Rtu ? m_line.rtuGapMicroseconds() : 0;
}

QByteArray ModbusResponder::breakChecksum(QByteArray frame) const {
    if (m_framing == Framing::Rtu && !frame.isEmpty())
        frame[frame.size() - 1] = char(frame.back() ^ 0x5A); // the CRC's high byte
    else if (m_framing == Framing::Ascii && frame.size() > 4)
        frame[frame.size() - 3] = frame[frame.size() - 3] == '0' ? '1' : '0'; // the LRC
    return frame;
}

QByteArrayList ModbusResponder::feed(QByteArrayView bytes) {
    m_decoder.feed(bytes);
    return take();
}

QByteArrayList ModbusResponder::silence() {
    m_decoder.silence();
    return take();
}

QByteArrayList ModbusResponder::take() {
    QByteArrayList out;
    while (true) {
        if (m_decoder.droppedFrames() != m_dropped) {
            m_statistics.dropped += quint64(m_decoder.droppedFrames() - m_dropped);
            m_dropped = m_decoder.droppedFrames();
            if (!m_decoder.discarded().ok())
                m_lastProblem = m_decoder.discarded().message;
        }
        if (m_decoder.status() != FrameStatus::Complete)
            return out;
        const int unit = m_decoder.unit();
        const bool own = unit == m_station || unit == m_mapped.map().anyStationUnit ||
                         (m_framing == Framing::Tcp && (unit == 0 || unit == 0xFF));
        const bool broadcast = m_framing != Framing::Tcp && unit == BroadcastUnit;
        if (!own && !broadcast) {
            ++m_statistics.ignored;
        } else {
            const QByteArray pdu = respond(m_decoder.parsed(), broadcast);
            if (broadcast || pdu.isEmpty())
                ++m_statistics.ignored;
            else if (m_framing == Framing::Rtu)
                out << rtuFrame(unit == m_station ? m_replyStation : unit, pdu);
            else if (m_framing == Framing::Ascii)
                out << asciiFrame(unit == m_station ? m_replyStation : unit, pdu);
            else
                out << tcpFrame(m_decoder.transaction(), unit == m_station ? m_replyStation : unit,
                                pdu);
        }
        m_decoder.next();
    }
}

QByteArray ModbusResponder::exception(std::uint8_t function, int code) {
    ++m_statistics.refused;
    Response r;
    r.function = function;
    r.exception = code;
    return encodeResponsePdu(r);
}

QByteArray ModbusResponder::respond(const ParsedRequest &parsed, bool broadcast) {
    const Request &q = parsed.request;
    const model::ProtocolMap &map = m_mapped.map();
    const int illegalValue = map.illegalValueException;
    if (parsed.exception)
        return broadcast
                   ? QByteArray()
                   : exception(q.function, parsed.exception == IllegalDataValue ? illegalValue
                                                                                : parsed.exception);
    // A broadcast read has nobody to answer to (serial line 2.1): nothing is done.
    if (broadcast && !isWrite(q.function))
        return {};
    ProtocolSpace space = ProtocolSpace::Coils;
    bool words = false;
    switch (q.function) {
    case ReadCoils:
    case WriteSingleCoil:
    case WriteMultipleCoils:
        break;
    case ReadDiscreteInputs:
        space = map.inputsShareSpaces ? ProtocolSpace::Coils : ProtocolSpace::DiscreteInputs;
        break;
    case ReadInputRegisters:
        if (!map.inputsShareSpaces) // no input registers in this map (Vigor CP2: none)
            return exception(q.function, IllegalDataAddress);
        [[fallthrough]];
    default:
        space = ProtocolSpace::HoldingRegisters;
        words = true;
        break;
    }
    const int limit = isWrite(q.function) ? map.maxWriteUnits : map.maxReadUnits;
    if (words && limit > 0 && q.count > limit)
        return broadcast ? QByteArray() : exception(q.function, illegalValue);
    if (q.address + q.count > 0x10000)
        return broadcast ? QByteArray() : exception(q.function, IllegalDataAddress);

    const auto snapshot = m_image->snapshot();
    if (!isWrite(q.function)) {
        const MappedImage::Units units =
            m_mapped.read(*snapshot, m_image->mode(), space, q.address, q.count);
        if (units.refusal != MappedImage::Refusal::None)
            return exception(q.function, IllegalDataAddress);
        Response r;
        r.function = q.function;
        if (words)
            r.registers = units.values;
        else
            for (const std::uint16_t v : units.values)
                r.bits.push_back(v != 0);
        ++m_statistics.answered;
        return encodeResponsePdu(r);
    }
    std::vector<std::uint16_t> values = q.registers;
    if (!words)
        for (const bool b : q.bits)
            values.push_back(b ? 1 : 0);
    const MappedImage::Change change = m_mapped.write(*snapshot, space, q.address, values);
    if (change.refusal != MappedImage::Refusal::None)
        return broadcast ? QByteArray() : exception(q.function, IllegalDataAddress);
    const ImageChange done = apply(change);
    if (!done.done()) {
        m_lastProblem = done.message;
        return broadcast ? QByteArray()
                         : exception(q.function, done.status == ImageChange::Status::Refused
                                                     ? ServerDeviceFailure
                                                     : ServerDeviceBusy);
    }
    ++m_statistics.writes;
    if (broadcast)
        return {};
    ++m_statistics.answered;
    Response r;
    r.function = q.function;
    r.address = q.address;
    switch (q.function) {
    case WriteSingleCoil:
        r.count = values.front() ? 0xFF00 : 0x0000;
        break;
    case WriteSingleRegister:
        r.count = values.front();
        break;
    default:
        r.count = q.count;
        break;
    }
    return encodeResponsePdu(r);
}

} // namespace rung::comms::slave
