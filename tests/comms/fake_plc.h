#pragma once

// PLCs in a test: answer the requests a FakeTransport passes them from an image of registers
// and coils (Modbus RTU) or channels, DM and a mode (Host Link), with the protocol codecs'
// slave side. For the online session's unit tests; the real peers are other programs.

#include "comms/protocol/host_link_slave.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_slave.h"
#include "tests/comms/fake_transport.h"

#include <map>
#include <mutex>
#include <set>

namespace rung::comms::test {

class FakeModbusPlc {
public:
    explicit FakeModbusPlc(int unit = 1)
        : m_unit(unit) {}

    void setRegister(int address, std::uint16_t value) {
        std::lock_guard lock(m_mutex);
        m_registers[address] = value;
    }
    std::uint16_t reg(int address) const {
        std::lock_guard lock(m_mutex);
        const auto it = m_registers.find(address);
        return it == m_registers.end() ? 0 : it->second;
    }
    void setCoil(int address, bool on) {
        std::lock_guard lock(m_mutex);
        m_coils[address] = on;
    }
    bool coil(int address) const {
        std::lock_guard lock(m_mutex);
        const auto it = m_coils.find(address);
        return it != m_coils.end() && it->second;
    }
    void setSilent(bool silent) {
        std::lock_guard lock(m_mutex);
        m_silent = silent;
    }
    // Writes to this register or coil are refused with exception 02.
    void refuseWritesAt(int address) {
        std::lock_guard lock(m_mutex);
        m_refused.insert(address);
    }
    // The requests answered, as (function, address, count).
    std::vector<std::tuple<int, int, int>> requests() const {
        std::lock_guard lock(m_mutex);
        return m_requests;
    }
    void clearRequests() {
        std::lock_guard lock(m_mutex);
        m_requests.clear();
    }

    FakeTransport::Responder responder() {
        return [this](const QByteArray &bytes) { return respond(bytes); };
    }

private:
    QList<QByteArray> respond(const QByteArray &bytes) {
        std::lock_guard lock(m_mutex);
        if (m_silent)
            return {};
        modbus::RequestDecoder decoder(modbus::Framing::Rtu);
        if (decoder.feed(bytes) != FrameStatus::Complete || decoder.unit() != m_unit)
            return {};
        const modbus::Request &r = decoder.parsed().request;
        m_requests.emplace_back(r.function, r.address, r.count);
        modbus::Response out;
        out.function = r.function;
        out.address = r.address;
        out.count = r.count;
        switch (r.function) {
        case modbus::ReadCoils:
        case modbus::ReadDiscreteInputs:
            for (int i = 0; i < r.count; ++i)
                out.bits.push_back(m_coils[r.address + i]);
            break;
        case modbus::ReadHoldingRegisters:
        case modbus::ReadInputRegisters:
            for (int i = 0; i < r.count; ++i)
                out.registers.push_back(m_registers[r.address + i]);
            break;
        case modbus::WriteSingleCoil:
        case modbus::WriteMultipleCoils:
            for (int i = 0; i < int(r.bits.size()); ++i) {
                if (m_refused.count(r.address + i)) {
                    out.exception = modbus::IllegalDataAddress;
                    break;
                }
                m_coils[r.address + i] = r.bits[std::size_t(i)];
            }
            if (r.function == modbus::WriteSingleCoil)
                out.count = r.bits.front() ? 0xFF00 : 0;
            break;
        default:
            for (int i = 0; i < int(r.registers.size()); ++i) {
                if (m_refused.count(r.address + i)) {
                    out.exception = modbus::IllegalDataAddress;
                    break;
                }
                m_registers[r.address + i] = r.registers[std::size_t(i)];
            }
            if (r.function == modbus::WriteSingleRegister)
                out.count = r.registers.front();
            break;
        }
        return {modbus::rtuFrame(m_unit, modbus::encodeResponsePdu(out))};
    }

    mutable std::mutex m_mutex;
    int m_unit;
    bool m_silent = false;
    std::map<int, std::uint16_t> m_registers;
    std::map<int, bool> m_coils;
    std::set<int> m_refused;
    std::vector<std::tuple<int, int, int>> m_requests;
};

// A Vigor on the Computer Link: a byte image, 51h / 61h / 70h / 71h.
class FakeVigorPlc {
public:
    void setByte(int address, std::uint8_t value) {
        std::lock_guard lock(m_mutex);
        m_bytes[address] = value;
    }
    std::uint8_t byte(int address) const {
        std::lock_guard lock(m_mutex);
        const auto it = m_bytes.find(address);
        return it == m_bytes.end() ? 0 : it->second;
    }
    FakeTransport::Responder responder() {
        return [this](const QByteArray &bytes) { return respond(bytes); };
    }

private:
    QList<QByteArray> respond(const QByteArray &bytes) {
        std::lock_guard lock(m_mutex);
        vigor::RequestDecoder decoder;
        if (decoder.feed(bytes) != FrameStatus::Complete)
            return {};
        const vigor::Request &r = decoder.request();
        vigor::Reply reply{r.station, r.command, decoder.errorCode(), {}};
        if (reply.error == 0) {
            switch (r.command) {
            case vigor::Command::Read:
                for (int i = 0; i < r.length; ++i)
                    reply.data += char(m_bytes[r.address + i]);
                break;
            case vigor::Command::Write:
                for (int i = 0; i < int(r.data.size()); ++i)
                    m_bytes[r.address + i] = std::uint8_t(r.data[i]);
                break;
            case vigor::Command::BitOn:
            case vigor::Command::BitOff: {
                std::uint8_t &b = m_bytes[r.address >> 3];
                const std::uint8_t mask = std::uint8_t(1u << (r.address & 7));
                b = r.command == vigor::Command::BitOn ? std::uint8_t(b | mask)
                                                       : std::uint8_t(b & ~mask);
                break;
            }
            }
        }
        return {vigor::encodeReply(reply)};
    }

    mutable std::mutex m_mutex;
    std::map<int, std::uint8_t> m_bytes;
};

// A CPM1 on Host Link: IR and DM words, the mode (MS / SC), forcing (KS / KR / KC), MM;
// writes in RUN answer end code 01, as the PLC does.
class FakeHostLinkPlc {
public:
    void setMode(hostlink::Mode mode) {
        std::lock_guard lock(m_mutex);
        m_mode = mode;
    }
    hostlink::Mode mode() const {
        std::lock_guard lock(m_mutex);
        return m_mode;
    }
    void setWord(model::ProtocolSpace space, int address, std::uint16_t value) {
        std::lock_guard lock(m_mutex);
        m_words[{int(space), address}] = value;
    }
    std::uint16_t word(model::ProtocolSpace space, int address) const {
        std::lock_guard lock(m_mutex);
        const auto it = m_words.find({int(space), address});
        return it == m_words.end() ? 0 : it->second;
    }
    std::set<std::pair<int, int>> forced() const {
        std::lock_guard lock(m_mutex);
        return m_forced;
    }
    FakeTransport::Responder responder() {
        return [this](const QByteArray &bytes) { return respond(bytes); };
    }

private:
    QList<QByteArray> respond(const QByteArray &bytes) {
        std::lock_guard lock(m_mutex);
        hostlink::CommandDecoder decoder;
        if (decoder.feed(bytes) != FrameStatus::Complete)
            return {};
        const hostlink::Frame &c = decoder.command();
        hostlink::Frame reply{c.unit, c.header, hostlink::Normal, {}};
        model::ProtocolSpace space;
        bool write = false;
        if (hostlink::spaceOfHeader(c.header, space, write)) {
            if (write) {
                const auto w = hostlink::parseWrite(c.text);
                if (m_mode == hostlink::Mode::Run)
                    reply.endCode = hostlink::NotInRun;
                else
                    for (std::size_t i = 0; i < w.words.size(); ++i)
                        m_words[{int(space), w.begin + int(i)}] = w.words[i];
            } else {
                const auto r = hostlink::parseRead(c.text);
                for (int i = 0; i < r.count; ++i) {
                    const std::uint16_t w = m_words[{int(space), r.begin + i}];
                    reply.text += space == model::ProtocolSpace::HostLinkCompletion
                                      ? QByteArray(w ? "1" : "0")
                                      : QByteArray::number(w, 16).toUpper().rightJustified(4, '0');
                }
            }
        } else if (c.header == "MS") {
            const int bits = m_mode == hostlink::Mode::Run       ? 2
                             : m_mode == hostlink::Mode::Monitor ? 3
                                                                 : 0;
            reply.text = QByteArray::number(bits << 8, 16).rightJustified(4, '0');
        } else if (c.header == "SC") {
            m_mode = hostlink::Mode(c.text.toInt(nullptr, 16));
        } else if (c.header == "KS" || c.header == "KR") {
            const auto f = hostlink::parseForce(c.text);
            if (m_mode == hostlink::Mode::Run)
                reply.endCode = hostlink::NotInRun;
            else
                m_forced.insert({f.begin, f.bit});
        } else if (c.header == "KC") {
            m_forced.clear();
        } else if (c.header == "MM") {
            reply.text = "12";
        } else {
            reply.endCode = hostlink::NotSupported;
        }
        return hostlink::encode(reply);
    }

    mutable std::mutex m_mutex;
    hostlink::Mode m_mode = hostlink::Mode::Run;
    std::map<std::pair<int, int>, std::uint16_t> m_words;
    std::set<std::pair<int, int>> m_forced;
};

} // namespace rung::comms::test
