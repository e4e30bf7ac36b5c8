#include "engine.h"
#include "simulator/tr.h"

#include "model/target/address.h"

#include <QCoreApplication>

#include <algorithm>

// The communication instructions (docs/network.md): LINK and MBUS work through their table,
// RS sends and receives, after the user program (Vigor M/VB/VH communication manual, B-3-4: "nearly
// all" modes "do their communication work after the PLC completes the user program"). The bytes go
// through the station's ports (model/comm/plc_port.h) and the protocols through comms' codecs
// behind model::MasterProtocol; the engine knows neither the network nor comms.

namespace rung::simulator {

namespace {

using model::LinkStatus;
using model::MasterRequest;
using model::MasterStatus;
using model::ProtocolSpace;

// FX numbers a character received with a parity, overrun or framing error 6301 in D8063; the
// Vigor's M9063 / D9063 are the FX's M8063 / D8063 renumbered, and the Vigor M/VB/VH
// communication manual lists no codes.
constexpr std::int32_t kCharacterError = 6301;

} // namespace

void Engine::attachPorts(model::PlcPorts *ports) {
    m_ports = ports;
    m_commPorts.assign(m_program->comms.size(), nullptr);
    for (std::size_t k = 0; ports && k < m_program->comms.size(); ++k)
        m_commPorts[k] = ports->port(m_program->comms[k].port);
    for (std::size_t k = 0; k < m_program->comms.size(); ++k) {
        const CommStep &c = m_program->comms[k];
        if (c.kind == CommKind::ModuleRead || c.kind == CommKind::ModuleWrite)
            module(c.module).attached = m_commPorts[k] != nullptr;
    }
    m_portLinks.assign(m_program->ports.size(), nullptr);
    m_portAttached = false;
    for (std::size_t k = 0; ports && k < m_program->ports.size(); ++k) {
        m_portLinks[k] = ports->port(m_program->ports[k].port);
        m_portAttached = m_portAttached || m_portLinks[k];
        // Power-on: free-port is off (SM78 = 0), the port runs its protocol at its settings.
        if (model::PlcPort *p = m_portLinks[k]) {
            p->setProgramDriven(false);
            p->setLine(p->config().line);
        }
    }
}

qint64 Engine::commNowUs() const {
    // The communication work is done at the scan's END, the end of its period (timeMs counts
    // up after it): a network runs the scan at that instant of its clock.
    return (m_stats.timeMs + m_stats.periodMs) * 1000;
}

qint64 Engine::timeoutUs() const {
    // D9129 x 10 ms, 0 (the default): 100 ms (B-3-6 for MBUS, B-3-9 for RS; LINK, for which
    // the manual gives none, the same: docs/network.md).
    const std::int32_t w = m_program->commDevices.timeoutWord;
    const std::int32_t units = w >= 0 ? m_words[static_cast<std::size_t>(w)] : 0;
    return (units > 0 ? qint64(units) * 10 : 100) * 1000;
}

void Engine::communicate(const Step &s, std::size_t step, bool on) {
    CommTask &t = m_comm.tasks[static_cast<std::size_t>(s.count)];
    t.on = on;
    const CommStep &c = m_program->comms[static_cast<std::size_t>(s.count)];
    if (c.kind == CommKind::FreePortSend) {
        // SEND transmits when its coil is activated (engine_ports.cpp).
        if (on && !t.previous)
            freePortSend(c, step);
        t.previous = on;
        return;
    }
    if (!on)
        return;
    auto value = [&](const WordOperand &o) {
        return o.index >= 0 ? m_words[static_cast<std::size_t>(o.index)] : o.constant;
    };
    // FROM / TO reach the module's buffer memory at once, in the scan (engine_module.cpp).
    if (c.kind == CommKind::ModuleRead)
        moduleRead(c, s, step, value(c.m), value(c.n));
    else if (c.kind == CommKind::ModuleWrite)
        moduleWrite(c, s, step, value(c.m), value(c.n));
}

void Engine::serviceComms() {
    const CommDevices &d = m_program->commDevices;
    // M9199 is ON for the one scan after the END that completed a table.
    if (m_comm.cycleDone) {
        put(m_words.data(), d.cycleDone, false);
        m_comm.cycleDone = false;
    }
    for (std::size_t k = 0; k < m_comm.tasks.size(); ++k) {
        const CommKind kind = m_program->comms[k].kind;
        if (kind == CommKind::EasyLink || kind == CommKind::ModbusMaster)
            serviceMaster(k);
    }
    serviceSerial();
    if (!m_program->ports.empty())
        servicePorts(); // engine_ports.cpp
    for (std::size_t n = 0; n < m_comm.modules.size(); ++n)
        if (m_comm.modules[n].attached || !m_comm.modules[n].bfm.empty())
            serviceModule(static_cast<int>(n) + 1);
    // An instruction a jump skipped is not ON in the next scan unless it runs again.
    for (CommTask &t : m_comm.tasks)
        t.on = false;
}

// ----- LINK and MBUS -----

void Engine::endSet(std::size_t task, LinkStatus status) {
    CommTask &t = m_comm.tasks[task];
    const CommStep &c = m_program->comms[task];
    // S2: the status in the upper byte and the station in the lower (B-3-3); it shows the
    // latest error until a whole table has run without one.
    if (status != LinkStatus::Normal) {
        storeWord(static_cast<std::size_t>(c.second),
                  (static_cast<int>(status) << 8) | (t.station & 0xFF), 16);
        t.cycleClean = false;
    }
    t.running = false;
    t.waiting = false;
    t.frames.clear();
    t.frame = 0;
    ++t.set;
    const std::int32_t sets = m_words[static_cast<std::size_t>(c.first)];
    if (t.set >= sets) {
        t.set = 0;
        ++t.cycles;
        if (t.cycleClean)
            storeWord(static_cast<std::size_t>(c.second), 0, 16);
        t.cycleClean = true;
        storeWord(static_cast<std::size_t>(c.second) + 2, t.cycles, 16);
        put(m_words.data(), m_program->commDevices.cycleDone, true);
        m_comm.cycleDone = true;
    }
    storeWord(static_cast<std::size_t>(c.second) + 1, t.set + 1, 16);
}

bool Engine::planSet(std::size_t task) {
    CommTask &t = m_comm.tasks[task];
    const CommStep &c = m_program->comms[task];
    const model::Target &target = layout().target();
    const MemoryLayout &l = layout();
    const bool modbus = c.kind == CommKind::ModbusMaster;
    const std::int32_t *r =
        &m_words[static_cast<std::size_t>(c.first + 1 + model::kLinkSetRegisters * t.set)];
    const model::LinkSet set = model::readLinkSet(
        target, modbus ? model::LinkTableKind::Modbus : model::LinkTableKind::EasyLink, r);
    t.station = set.station;
    t.frames.clear();
    t.frame = 0;
    if (set.status != LinkStatus::Normal) {
        endSet(task, set.status);
        return false;
    }
    model::PlcPort *port = commPort(task);
    model::MasterProtocol *codec = port ? port->master() : nullptr;
    // The master's devices, in order.
    std::vector<std::int32_t> words;
    std::vector<BitRef> bits;
    for (int i = 0; i < set.length; ++i) {
        const model::Address a = model::linkDevice(target, set.master, i);
        if (set.bits)
            bits.push_back(l.bit(a));
        else
            words.push_back(l.word(a));
    }
    auto maxUnits = [&](ProtocolSpace space) {
        return codec ? codec->maxUnits(space, set.write) : model::VigorLinkMaxBytes;
    };
    auto bitOf = [&](std::size_t i) { return readBit(bits[i]) ? 1 : 0; };
    MasterRequest base;
    base.station = set.station;
    if (modbus) {
        base.space = set.space;
        MasterFrame f;
        f.request = base;
        f.request.first = set.unit;
        f.request.count = set.length;
        if (set.single) {
            f.request.kind = MasterRequest::Kind::WriteSingle;
            f.request.values = {static_cast<std::uint16_t>(
                set.bits ? bitOf(0) : m_words[static_cast<std::size_t>(words[0])])};
        } else if (set.write) {
            f.request.kind = MasterRequest::Kind::Write;
            for (std::size_t i = 0; i < std::size_t(set.length); ++i)
                f.request.values.push_back(static_cast<std::uint16_t>(
                    set.bits ? bitOf(i) : m_words[static_cast<std::size_t>(words[i])]));
        } else {
            f.request.kind = MasterRequest::Kind::Read;
            f.words = words;
            f.bits = bits;
        }
        t.frames.push_back(std::move(f));
        return true;
    }
    // Computer Link: where the slave's devices sit among its link bytes (the map is the
    // target's: the slave is a PLC of the same family).
    const model::ProtocolMap *map = model::findProtocolMap(target, model::ProtocolId::VigorLink);
    base.space = ProtocolSpace::LinkBytes;
    std::vector<int> positions; // bit address (unit << 3 | bit) or first unit of each device
    int unitsPerDevice = 1;
    for (int i = 0; map && i < set.length; ++i) {
        const model::Address a = model::linkDevice(target, set.slave, i);
        const auto pa = model::toProtocol(
            target, *map, a, set.bits ? model::DevicePart::Bit : model::DevicePart::Value);
        if (!pa || pa->space != ProtocolSpace::LinkBytes)
            break;
        positions.push_back(set.bits ? (pa->unit << 3 | std::max(0, pa->bit)) : pa->unit);
        unitsPerDevice = pa->units;
    }
    if (static_cast<int>(positions.size()) != set.length) {
        endSet(task, LinkStatus::BadDeviceNumber); // a device the link does not reach
        return false;
    }
    const int step = set.bits ? 1 : unitsPerDevice;
    const int most = maxUnits(ProtocolSpace::LinkBytes);
    // Runs of devices that sit one after another on the link.
    std::size_t i = 0;
    while (i < positions.size()) {
        std::size_t j = i + 1;
        while (j < positions.size() && positions[j] == positions[j - 1] + step)
            ++j;
        if (!set.bits) {
            // Values: a frame per run, at most `most` bytes.
            const std::size_t perFrame = std::max<std::size_t>(1, std::size_t(most / step));
            for (std::size_t k = i; k < j; k += perFrame) {
                const std::size_t n = std::min(perFrame, j - k);
                MasterFrame f;
                f.request = base;
                f.request.first = positions[k];
                f.request.count = int(n) * step;
                f.unitsPerWord = step;
                f.wordBits = set.masterValueBits;
                if (set.write) {
                    f.request.kind = MasterRequest::Kind::Write;
                    for (std::size_t w = k; w < k + n; ++w) {
                        const auto v =
                            static_cast<std::uint32_t>(m_words[static_cast<std::size_t>(words[w])]);
                        for (int b = 0; b < step; ++b) // low byte first (B-5)
                            f.request.values.push_back(std::uint16_t((v >> (8 * b)) & 0xFFu));
                    }
                } else {
                    f.request.kind = MasterRequest::Kind::Read;
                    f.words.assign(words.begin() + std::ptrdiff_t(k),
                                   words.begin() + std::ptrdiff_t(k + n));
                }
                t.frames.push_back(std::move(f));
            }
        } else if (!set.write) {
            // Bits read: the bytes that hold them (at most 9 for 64 bits).
            const int firstUnit = positions[i] >> 3;
            const int lastUnit = positions[j - 1] >> 3;
            MasterFrame f;
            f.request = base;
            f.request.kind = MasterRequest::Kind::Read;
            f.request.first = firstUnit;
            f.request.count = lastUnit - firstUnit + 1;
            f.firstBit = positions[i] & 7;
            f.bits.assign(bits.begin() + std::ptrdiff_t(i), bits.begin() + std::ptrdiff_t(j));
            t.frames.push_back(std::move(f));
        } else {
            // Bits written: whole bytes with 61h, the bits of a byte the set covers only in
            // part one by one with 70h / 71h, so that no other bit of the slave is touched.
            std::size_t k = i;
            while (k < j) {
                const int position = positions[k];
                if (position % 8 == 0 && j - k >= 8) {
                    std::size_t bytes = std::min<std::size_t>((j - k) / 8, std::size_t(most));
                    MasterFrame f;
                    f.request = base;
                    f.request.kind = MasterRequest::Kind::Write;
                    f.request.first = position >> 3;
                    f.request.count = int(bytes);
                    for (std::size_t b = 0; b < bytes; ++b) {
                        int v = 0;
                        for (int bit = 0; bit < 8; ++bit)
                            v |= bitOf(k + b * 8 + std::size_t(bit)) << bit;
                        f.request.values.push_back(std::uint16_t(v));
                    }
                    t.frames.push_back(std::move(f));
                    k += bytes * 8;
                } else {
                    MasterFrame f;
                    f.request = base;
                    f.request.kind =
                        bitOf(k) ? MasterRequest::Kind::SetBit : MasterRequest::Kind::ResetBit;
                    f.request.first = position >> 3;
                    f.request.bit = position & 7;
                    t.frames.push_back(std::move(f));
                    ++k;
                }
            }
        }
        i = j;
    }
    return true;
}

void Engine::sendFrame(std::size_t task) {
    CommTask &t = m_comm.tasks[task];
    model::PlcPort *port = commPort(task);
    model::MasterProtocol *codec = port ? port->master() : nullptr;
    const qint64 now = commNowUs();
    if (!codec) {
        // Connected to nothing: no answer comes, and the set ends in a time-out (status A).
        t.waiting = true;
        t.deadlineUs = now + timeoutUs();
        return;
    }
    port->receive(); // what came before the request is no answer to it
    const qint64 sent = port->send(codec->request(t.frames[t.frame].request));
    if (codec->expectsReply()) {
        t.waiting = true;
        t.deadlineUs = sent + timeoutUs();
    } else {
        ++t.frame; // a broadcast: nobody answers
    }
}

void Engine::applyReply(const MasterFrame &f, const std::vector<std::uint16_t> &values) {
    if (f.request.kind != MasterRequest::Kind::Read)
        return;
    const int unitBits = model::unitBits(f.request.space);
    for (std::size_t w = 0; w < f.words.size(); ++w) {
        std::uint32_t v = 0;
        for (int b = 0; b < f.unitsPerWord; ++b) {
            const std::size_t u = w * std::size_t(f.unitsPerWord) + std::size_t(b);
            if (u < values.size())
                v |= std::uint32_t(values[u]) << (unitBits * b);
        }
        storeWord(static_cast<std::size_t>(f.words[w]), static_cast<std::int32_t>(v), f.wordBits);
    }
    for (std::size_t b = 0; b < f.bits.size(); ++b) {
        const std::size_t position = std::size_t(f.firstBit) + b;
        const std::size_t u = position / std::size_t(unitBits);
        const bool on = u < values.size() && ((values[u] >> (position % unitBits)) & 1u);
        put(m_words.data(), f.bits[b], on);
    }
}

void Engine::serviceMaster(std::size_t task) {
    CommTask &t = m_comm.tasks[task];
    const CommStep &c = m_program->comms[task];
    model::PlcPort *port = commPort(task);
    if (!t.on) {
        // "When X20 is OFF, the instruction will be stopped and the data transmission /
        // receiving will be disabled immediately" (B-3-3): the next ON starts the table over.
        if (t.running || t.waiting || t.set != 0) {
            t.running = false;
            t.waiting = false;
            t.frames.clear();
            t.set = 0;
            t.cycleClean = true;
        }
        return;
    }
    const std::int32_t sets = m_words[static_cast<std::size_t>(c.first)];
    if (sets < 1 || sets > model::kLinkMaxSets ||
        1 + model::kLinkSetRegisters * sets > c.firstWords) {
        runtimeError(
            static_cast<std::size_t>(c.step),
            sets < 1 || sets > model::kLinkMaxSets
                ? EngineTr::tr("operation error: the communication table holds %1 sets; it "
                               "takes 1 to %2")
                      .arg(sets)
                      .arg(model::kLinkMaxSets)
                : EngineTr::tr("operation error: a table of %1 sets needs %2 registers, past "
                               "the end of its area")
                      .arg(sets)
                      .arg(1 + model::kLinkSetRegisters * sets));
        return;
    }
    if (t.set >= sets)
        t.set = 0;
    if (t.waiting) {
        model::MasterProtocol *codec = port ? port->master() : nullptr;
        const QByteArray bytes = port ? port->receive() : QByteArray();
        const MasterStatus status =
            codec && !bytes.isEmpty() ? codec->feed(bytes) : MasterStatus::NeedMore;
        if (status == MasterStatus::Done) {
            applyReply(t.frames[t.frame], codec->values());
            t.waiting = false;
            ++t.frame;
        } else if (status == MasterStatus::Refused || status == MasterStatus::Garbled) {
            endSet(task, LinkStatus::Abnormal);
        } else if (commNowUs() >= t.deadlineUs) {
            endSet(task, LinkStatus::NoResponse);
        } else {
            return;
        }
    }
    // Sets that cannot run end at once; at most one table's worth in one END.
    for (int guard = 0; guard <= sets; ++guard) {
        if (!t.running) {
            if (!planSet(task))
                continue;
            t.running = true;
        }
        if (t.frame < t.frames.size()) {
            sendFrame(task);
            if (t.waiting)
                return;
            continue;
        }
        endSet(task, LinkStatus::Normal);
    }
}

// ----- RS -----

void Engine::serviceSerial() {
    const CommDevices &d = m_program->commDevices;
    int active = -1;
    for (std::size_t k = 0; k < m_comm.tasks.size(); ++k) {
        if (m_program->comms[k].kind != CommKind::SerialData || !m_comm.tasks[k].on)
            continue;
        if (active >= 0) {
            // "More than one RS instruction can be programmed but only one may be active at
            // any one time" (B-3-9).
            runtimeError(
                static_cast<std::size_t>(m_program->comms[k].step),
                EngineTr::tr("operation error: another RS is active; only one may be active "
                             "at a time, this one does nothing"));
            continue;
        }
        active = static_cast<int>(k);
    }
    if (active < 0) {
        // Not ready to receive: what arrives is lost.
        if (m_comm.serial >= 0)
            if (model::PlcPort *p = commPort(std::size_t(m_comm.serial)))
                p->receive();
        m_comm.serial = -1;
        m_comm.received.clear();
        m_comm.started = false;
        return;
    }
    m_comm.serial = active;
    const CommStep &c = m_program->comms[std::size_t(active)];
    model::PlcPort *port = commPort(std::size_t(active));
    const bool bytes8 = readBit(d.byteMode);
    const qint64 now = commNowUs();
    auto value = [&](const WordOperand &o) {
        return o.index >= 0 ? m_words[static_cast<std::size_t>(o.index)] : o.constant;
    };
    // Send: M9122 set by the program sends m data from S; the PLC resets it when the last
    // byte has gone ("Do not use the RST instruction to reset the M9122").
    if (m_comm.sending && (!port || !port->sending())) {
        m_comm.sending = false;
        put(m_words.data(), d.sendRequest, false);
        if (d.sendLeft >= 0)
            storeWord(std::size_t(d.sendLeft), 0, 16);
    }
    if (!m_comm.sending && readBit(d.sendRequest)) {
        const std::int32_t m = value(c.m);
        const int words = bytes8 ? m : (m + 1) / 2;
        if (m < 0 || m > 256 || words > c.firstWords) {
            runtimeError(
                static_cast<std::size_t>(c.step),
                EngineTr::tr("operation error: %1 data to send from a block that ends after "
                             "%2 words; nothing is sent")
                    .arg(m)
                    .arg(c.firstWords));
            put(m_words.data(), d.sendRequest, false);
        } else {
            QByteArray frame;
            const model::PortConfig *config = port ? &port->config() : nullptr;
            if (config && config->startCode >= 0)
                frame += char(config->startCode);
            for (int k = 0; k < m; ++k) {
                const auto w = static_cast<std::uint32_t>(
                    m_words[static_cast<std::size_t>(c.first + (bytes8 ? k : k / 2))]);
                frame += char((bytes8 || k % 2 == 0 ? w : w >> 8) & 0xFFu);
            }
            if (config && config->endCode >= 0)
                frame += char(config->endCode);
            if (port) {
                port->send(frame);
                m_comm.sending = true;
                if (d.sendLeft >= 0)
                    storeWord(std::size_t(d.sendLeft), m, 16);
            } else {
                put(m_words.data(), d.sendRequest, false); // connected to nothing: gone at once
            }
        }
    }
    // Receive.
    const QByteArray in = port ? port->receive() : QByteArray();
    if (port && port->takeCharacterErrors() > 0) {
        put(m_words.data(), d.error, true);
        if (d.errorCode >= 0)
            storeWord(std::size_t(d.errorCode), kCharacterError, 16);
    }
    // M9123 ON: the program has not taken the last data yet; what arrives meanwhile is lost
    // (B-3-9: after the reset "PLC will be ready for the status of receiving immediately").
    if (readBit(d.receiveDone))
        return;
    const std::int32_t n = value(c.n);
    if (n <= 0)
        return; // n = K0: nothing is received
    const model::PortConfig *config = port ? &port->config() : nullptr;
    bool complete = false;
    for (char ch : in) {
        const int b = static_cast<quint8>(ch);
        if (config && config->startCode >= 0 && !m_comm.started) {
            m_comm.started = b == config->startCode; // bytes before the start code are noise
            continue;
        }
        m_comm.started = true;
        if (config && config->endCode >= 0 && b == config->endCode) {
            complete = true;
            break;
        }
        m_comm.received += ch;
        if (m_comm.received.size() >= n) {
            complete = true;
            break;
        }
    }
    if (d.received >= 0)
        storeWord(std::size_t(d.received), m_comm.received.size(), 16);
    // The time-out: reception stopped for D9129 x 10 ms after data began to arrive.
    bool timedOut = false;
    if (!complete && m_comm.started && port && port->lastReceivedUs() >= 0 &&
        now - port->lastReceivedUs() >= timeoutUs()) {
        complete = true;
        timedOut = true;
    }
    if (!complete)
        return;
    const qsizetype count = m_comm.received.size();
    const qsizetype words = bytes8 ? count : (count + 1) / 2;
    if (words > c.secondWords) {
        runtimeError(
            static_cast<std::size_t>(c.step),
            EngineTr::tr("operation error: %1 data received for a block that ends after %2 "
                         "words; they are not stored")
                .arg(count)
                .arg(c.secondWords));
    } else {
        for (qsizetype k = 0; k < count; ++k) {
            const auto b = static_cast<std::uint32_t>(static_cast<quint8>(m_comm.received[k]));
            const auto w = static_cast<std::size_t>(c.second + (bytes8 ? k : k / 2));
            if (bytes8)
                storeWord(w, b, 16);
            else if (k % 2 == 0)
                storeWord(w, b, 16);
            else
                storeWord(w, (static_cast<std::uint32_t>(m_words[w]) & 0xFFu) | (b << 8), 16);
        }
    }
    if (d.received >= 0)
        storeWord(std::size_t(d.received), count, 16);
    put(m_words.data(), d.receiveDone, true);
    if (timedOut)
        put(m_words.data(), d.timeout, true);
    m_comm.received.clear();
    m_comm.started = false;
}

} // namespace rung::simulator
