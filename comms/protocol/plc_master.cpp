#include "comms/protocol/plc_master.h"

namespace rung::comms {

namespace {

using model::MasterRequest;
using model::MasterStatus;
using model::ProtocolSpace;

// A decoder's end as the engine reads it: a refusal by the slave, or bytes that are no reply.
template <typename Decoder> MasterStatus ended(const Decoder &d, QString *problem, int *code) {
    *problem = d.error().message;
    *code = d.error().code;
    return d.error().kind == ProtocolError::Kind::DeviceError ? MasterStatus::Refused
                                                              : MasterStatus::Garbled;
}

} // namespace

int VigorLinkMaster::maxUnits(ProtocolSpace, bool) const {
    return vigor::MaxBytes;
}

QByteArray VigorLinkMaster::request(const MasterRequest &r) {
    vigor::Request q;
    q.station = r.station;
    q.address = r.first;
    switch (r.kind) {
    case MasterRequest::Kind::Read:
        q.command = vigor::Command::Read;
        q.length = r.count;
        break;
    case MasterRequest::Kind::Write:
    case MasterRequest::Kind::WriteSingle:
        q.command = vigor::Command::Write;
        for (std::uint16_t v : r.values)
            q.data += char(v & 0xFF);
        q.length = int(q.data.size());
        break;
    case MasterRequest::Kind::SetBit:
    case MasterRequest::Kind::ResetBit:
        q.command =
            r.kind == MasterRequest::Kind::SetBit ? vigor::Command::BitOn : vigor::Command::BitOff;
        q.address = vigor::bitAddress(r.first, r.bit);
        break;
    }
    m_decoder.emplace(q);
    m_values.clear();
    m_problem.clear();
    m_code = 0;
    return vigor::encodeRequest(q);
}

MasterStatus VigorLinkMaster::feed(QByteArrayView bytes) {
    if (!m_decoder)
        return MasterStatus::Garbled;
    switch (m_decoder->feed(bytes)) {
    case FrameStatus::NeedMore:
        return MasterStatus::NeedMore;
    case FrameStatus::Complete:
        m_values.clear();
        for (char c : m_decoder->reply().data)
            m_values.push_back(static_cast<quint8>(c));
        return MasterStatus::Done;
    case FrameStatus::Failed:
        break;
    }
    return ended(*m_decoder, &m_problem, &m_code);
}

int ModbusMaster::maxUnits(ProtocolSpace space, bool write) const {
    const bool bits = space == ProtocolSpace::Coils || space == ProtocolSpace::DiscreteInputs;
    if (bits)
        return write ? modbus::MaxWriteBits : modbus::MaxReadBits;
    return write ? modbus::MaxWriteRegisters : modbus::MaxReadRegisters;
}

QByteArray ModbusMaster::request(const MasterRequest &r) {
    modbus::Request q;
    q.address = r.first;
    q.count = r.count;
    const bool bits = r.space == ProtocolSpace::Coils || r.space == ProtocolSpace::DiscreteInputs;
    switch (r.kind) {
    case MasterRequest::Kind::Read:
        q.function = r.space == ProtocolSpace::Coils            ? modbus::ReadCoils
                     : r.space == ProtocolSpace::DiscreteInputs ? modbus::ReadDiscreteInputs
                     : r.space == ProtocolSpace::InputRegisters ? modbus::ReadInputRegisters
                                                                : modbus::ReadHoldingRegisters;
        break;
    case MasterRequest::Kind::Write:
        q.function = bits ? modbus::WriteMultipleCoils : modbus::WriteMultipleRegisters;
        break;
    case MasterRequest::Kind::WriteSingle:
    case MasterRequest::Kind::SetBit:
    case MasterRequest::Kind::ResetBit:
        q.function = bits ? modbus::WriteSingleCoil : modbus::WriteSingleRegister;
        q.count = 1;
        break;
    }
    if (r.kind != MasterRequest::Kind::Read) {
        if (bits) {
            for (std::uint16_t v : r.values)
                q.bits.push_back(v != 0);
            if (r.kind == MasterRequest::Kind::SetBit || r.kind == MasterRequest::Kind::ResetBit)
                q.bits = {r.kind == MasterRequest::Kind::SetBit};
        } else {
            q.registers = r.values;
        }
        if (q.function == modbus::WriteSingleCoil || q.function == modbus::WriteSingleRegister) {
            q.bits.resize(bits ? 1 : 0);
            q.registers.resize(bits ? 0 : 1);
        }
    }
    m_expects = r.station != modbus::BroadcastUnit;
    m_decoder.emplace(m_framing, r.station, q);
    m_values.clear();
    m_problem.clear();
    m_code = 0;
    const QByteArray pdu = modbus::encodeRequestPdu(q);
    return m_framing == modbus::Framing::Ascii ? modbus::asciiFrame(r.station, pdu)
                                               : modbus::rtuFrame(r.station, pdu);
}

MasterStatus ModbusMaster::feed(QByteArrayView bytes) {
    if (!m_decoder)
        return MasterStatus::Garbled;
    switch (m_decoder->feed(bytes)) {
    case FrameStatus::NeedMore:
        return MasterStatus::NeedMore;
    case FrameStatus::Complete: {
        const modbus::Response &r = m_decoder->response();
        m_values.clear();
        if (!r.bits.empty())
            for (bool b : r.bits)
                m_values.push_back(b ? 1 : 0);
        else
            m_values.assign(r.registers.begin(), r.registers.end());
        return MasterStatus::Done;
    }
    case FrameStatus::Failed:
        break;
    }
    return ended(*m_decoder, &m_problem, &m_code);
}

} // namespace rung::comms
