#include "engine.h"
#include "simulator/tr.h"

#include <QCoreApplication>

#include <algorithm>

// The PL110's serial ports as its program drives them (PL110 manual, Italian; docs/network.md):
// free-port and SEND (4.2.19 with the special markers of 2.1.2: SM78 / SM88 / SM98 switch it,
// SM79 / SM89 / SM99 count what came, SM0.6..SM0.8 show a transmission; the byte buffers of
// 2.1.14, 2.1.15), and the COM / EXP master (4.2.21, with SM70..SM77 / SM80..SM87). Everything
// the target's table names (model::PortMarkers, resolved in Program::ports). The work is done
// at the scan's END, as the Vigor's (the PL110 manual does not say when); SEND starts its
// transmission when its coil is activated.

namespace rung::simulator {

namespace {

using model::MasterRequest;
using model::MasterStatus;
using model::ProtocolSpace;

constexpr std::int32_t kFreePortOn = 0x100; // SM78 bit 8

// The line SM78's codes give (bits 0-3 baud, 4-7 format); false for a code outside the lists.
bool freePortLine(const model::PortMarkers &m, std::int32_t control, model::SerialSettings *line) {
    const auto baud = static_cast<std::size_t>(control & 0xF);
    const auto format = static_cast<std::size_t>((control >> 4) & 0xF);
    if (baud >= m.bauds.size() || format >= m.formats.size())
        return false;
    if (!model::parseFrameFormat(QString::fromLatin1(m.formats[format]), line))
        return false;
    line->baud = m.bauds[baud];
    return true;
}

} // namespace

void Engine::freePortSend(const CommStep &c, std::size_t step) {
    if (c.portIndex < 0)
        return;
    const auto k = static_cast<std::size_t>(c.portIndex);
    m_comm.ports.resize(m_program->ports.size());
    PortState &p = m_comm.ports[k];
    const PortDevices &d = m_program->ports[k];
    applyFreePort(k);
    // "Chiamate alla funzione SEND prima della fine della trasmissione precedente o con
    // modalita free-port disabilitata verranno ignorate" (4.2.19).
    if (!p.freePort || p.sendingUntilUs >= 0)
        return;
    const std::int32_t n =
        c.n.index >= 0 ? m_words[static_cast<std::size_t>(c.n.index)] : c.n.constant;
    if (n < 1 || n > d.transmitSize) {
        runtimeError(step, EngineTr::tr("operation error: SEND of %1 characters; the transmit "
                                        "buffer holds 1 to %2, nothing is sent")
                               .arg(n)
                               .arg(d.transmitSize));
        return;
    }
    QByteArray bytes;
    bytes.reserve(n);
    for (std::int32_t i = 0; i < n; ++i)
        bytes += char(m_words[static_cast<std::size_t>(d.transmit + i)] & 0xFF);
    model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
    const qint64 now = commNowUs();
    if (port) {
        p.sendingUntilUs = port->send(bytes);
    } else {
        // Connected to nothing: the characters still take their time on the line.
        model::SerialSettings line;
        freePortLine(*d.markers, p.control, &line);
        p.sendingUntilUs = now + qint64(n) * line.characterMicroseconds();
    }
    put(m_words.data(), d.sending, true);
}

// SM78's bit 8 switches the port to free-port at its codes' line, and back to the protocol of
// its settings; a code outside the lists of 2.1.2 leaves the port in its protocol.
void Engine::applyFreePort(std::size_t k) {
    PortState &p = m_comm.ports[k];
    const PortDevices &d = m_program->ports[k];
    const std::int32_t control = portWord(d.freePort);
    if (control == p.control)
        return;
    p.control = control;
    model::SerialSettings line;
    const bool on = (control & kFreePortOn) && freePortLine(*d.markers, control, &line);
    model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
    if (port) {
        if (on && !p.freePort)
            port->receive(); // what came before belongs to the protocol
        port->setLine(on ? line : port->config().line);
        port->setProgramDriven(on);
    }
    if (on != p.freePort) {
        p.waiting = false; // a query in flight is abandoned with the protocol
        p.writeAt = -1;
    }
    p.freePort = on;
}

// Without a port attached, an instruction or free-port, the END's port work changes nothing
// (servicePorts: no frame to receive, no slave to supervise, no query to send); it cost a PL110
// program with no communication instruction about 100 instructions a scan (callgrind, issue 35).
bool Engine::portsBusy() const {
    if (m_portAttached)
        return true;
    for (std::size_t k = 0; k < m_program->ports.size(); ++k) {
        if (portWord(m_program->ports[k].freePort) & kFreePortOn)
            return true;
        if (k < m_comm.ports.size()) {
            const PortState &p = m_comm.ports[k];
            if (p.freePort || p.sendingUntilUs >= 0 || p.waiting)
                return true;
        }
    }
    return false;
}

void Engine::servicePorts() {
    m_comm.ports.resize(m_program->ports.size());
    const qint64 now = commNowUs();
    for (std::size_t k = 0; k < m_program->ports.size(); ++k) {
        PortState &p = m_comm.ports[k];
        const PortDevices &d = m_program->ports[k];
        model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
        applyFreePort(k);
        // SM0.6: "verra portato a 0 ad indicare la fine della trasmissione".
        if (p.sendingUntilUs >= 0 && now >= p.sendingUntilUs) {
            p.sendingUntilUs = -1;
            put(m_words.data(), d.sending, false);
        }
        if (p.freePort) {
            // SM79: "qualsiasi scrittura ... equivale allo svuotamento del buffer": a value
            // other than the PLC's own count is the program's write.
            if (d.received >= 0 && m_words[static_cast<std::size_t>(d.received)] != p.count)
                p.count = 0;
            const QByteArray in = port ? port->receive() : QByteArray();
            // Beyond the buffer's end characters are lost, as the manual gives no size.
            for (char ch : in) {
                if (p.count >= d.receiveSize)
                    break;
                storeWord(static_cast<std::size_t>(d.receive + p.count), static_cast<quint8>(ch),
                          16);
                ++p.count;
            }
            if (port && port->takeCharacterErrors() > 0 && d.errors >= 0)
                storeWord(static_cast<std::size_t>(d.errors), portWord(d.errors) + 1, 16);
            if (d.received >= 0)
                storeWord(static_cast<std::size_t>(d.received), p.count, 16);
            continue;
        }
        if (port && !port->config().application->master)
            superviseSlave(k);
        else
            serviceQueries(k);
    }
}

// A slave port's status word (PL110 manual 2.1.2, SM70 / SM80 / SM90: "tutti i bit a 1" when
// no correct packet with the PLC's address came for the time SM75 / SM85 / SM95 sets, in
// seconds; 0 again with the next one). An answered request is a correct packet for it.
void Engine::superviseSlave(std::size_t k) {
    PortState &p = m_comm.ports[k];
    const PortDevices &d = m_program->ports[k];
    const model::PlcPort *port = m_portLinks[k];
    if (d.status < 0 || d.errorLimit < 0)
        return;
    const qint64 now = commNowUs();
    if (p.supervisedFromUs < 0) {
        p.supervisedFromUs = now;
        p.requestErrorsBase = port->requestErrors();
    }
    // SM77: requests for the station that came wrong (a wrong CRC, a wrong length).
    if (d.errors >= 0)
        storeWord(static_cast<std::size_t>(d.errors),
                  std::int32_t((port->requestErrors() - p.requestErrorsBase) & 0xFFFF), 16);
    const qint64 since = std::max(p.supervisedFromUs, port->lastAnsweredRequestUs());
    const qint64 limitUs = qint64(portWord(d.errorLimit)) * 1'000'000;
    const bool lost = limitUs > 0 && now - since >= limitUs;
    storeWord(static_cast<std::size_t>(d.status), lost ? 0xFFFF : 0, 16);
}

// ----- COM / EXP -----

void Engine::serviceQueries(std::size_t k) {
    PortState &p = m_comm.ports[k];
    const PortDevices &d = m_program->ports[k];
    model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
    model::MasterProtocol *codec = port ? port->master() : nullptr;
    const qint64 now = commNowUs();
    if (p.waiting) {
        const QByteArray bytes = port ? port->receive() : QByteArray();
        const MasterStatus status =
            codec && !bytes.isEmpty() ? codec->feed(bytes) : MasterStatus::NeedMore;
        // SM73: "l'attesa massima tra l'inizio della trasmissione dei dati dell'interrogazione
        // ... alla ricezione completa dei dati della risposta".
        const qint64 deadline = p.startUs + qint64(portWord(d.replyTimeout)) * 1000;
        const qint64 last = port ? port->lastReceivedUs() : -1;
        if (status == MasterStatus::Done && last <= deadline) {
            endQuery(k, MasterStatus::Done);
            p.readyUs = last + qint64(portWord(d.requestGap)) * 1000;
        } else if (status == MasterStatus::Refused || status == MasterStatus::Garbled) {
            endQuery(k, MasterStatus::Garbled);
            p.readyUs = std::max(now, last) + qint64(portWord(d.requestGap)) * 1000;
        } else if (now >= deadline) {
            endQuery(k, MasterStatus::NeedMore);
            p.readyUs = now + qint64(portWord(d.requestGap)) * 1000;
        } else {
            return;
        }
    } else if (port) {
        port->receive(); // nothing is awaited: what comes is no reply
        port->takeCharacterErrors();
    }
    if (now < p.readyUs)
        return;
    // The next query whose coil is ON, after the last one served, by index (COM_1 first).
    int best = -1;
    int bestAfter = -1;
    const int lastIndex = p.query >= 0 ? m_program->comms[std::size_t(p.query)].index : 0;
    for (std::size_t t = 0; t < m_program->comms.size(); ++t) {
        const CommStep &c = m_program->comms[t];
        if (c.kind != CommKind::MasterQuery || c.portIndex != static_cast<std::int32_t>(k) ||
            !m_comm.tasks[t].on)
            continue;
        auto lower = [&](int current) {
            return current < 0 || c.index < m_program->comms[std::size_t(current)].index;
        };
        if (lower(best))
            best = static_cast<int>(t);
        if (c.index > lastIndex && lower(bestAfter))
            bestAfter = static_cast<int>(t);
    }
    const int next = bestAfter >= 0 ? bestAfter : best;
    if (next >= 0)
        sendQuery(k, static_cast<std::size_t>(next));
}

void Engine::sendQuery(std::size_t k, std::size_t task) {
    PortState &p = m_comm.ports[k];
    const PortDevices &d = m_program->ports[k];
    const CommStep &c = m_program->comms[task];
    CommTask &t = m_comm.tasks[task];
    model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
    model::MasterProtocol *codec = port ? port->master() : nullptr;
    const std::size_t n = static_cast<std::size_t>(c.count);
    auto datum = [&](std::size_t i) -> std::int32_t {
        return c.bitData ? (readBit(c.bits[i]) ? 1 : 0) : m_words[std::size_t(c.words[i])];
    };
    MasterRequest r;
    r.station = c.slave;
    r.space = c.bitData ? ProtocolSpace::Coils : ProtocolSpace::HoldingRegisters;
    r.first = c.number;
    r.count = c.count;
    p.writeAt = -1;
    if (c.operation == 1) {
        r.kind = MasterRequest::Kind::Write;
        for (std::size_t i = 0; i < n; ++i)
            r.values.push_back(static_cast<std::uint16_t>(datum(i)));
    } else {
        r.kind = MasterRequest::Kind::Read;
        // Read-write: a datum the program changed since it was read goes to the slave, one
        // at a time ("questa istruzione puo operare su di un solo dato alla volta").
        for (std::size_t i = 0; c.operation == 2 && i < t.shadow.size(); ++i)
            if (datum(i) != t.shadow[i]) {
                p.writeAt = static_cast<int>(i);
                p.writeValue = datum(i);
                r.kind = MasterRequest::Kind::WriteSingle;
                r.first = c.number + static_cast<int>(i);
                r.count = 1;
                r.values = {static_cast<std::uint16_t>(p.writeValue)};
                break;
            }
    }
    p.query = static_cast<int>(task);
    p.startUs = commNowUs();
    p.waiting = true;
    if (!codec)
        return; // connected to nothing, or a protocol without frames: the query times out
    port->receive();
    const qint64 sent = port->send(codec->request(r));
    if (!codec->expectsReply()) {
        // Slave 0, MODBUS's broadcast: nobody answers; the next request after SM74.
        p.waiting = false;
        p.readyUs = sent + qint64(portWord(d.requestGap)) * 1000;
        if (r.kind != MasterRequest::Kind::Read)
            endQuery(k, MasterStatus::Done);
    }
}

// A query's end: the data read stored, the status bit and the counters (2.1.2: SM70 "ciascun
// bit ... segnala una condizione di mancata comunicazione (fuori linea) o errore", SM75 errors
// in a row before it, SM76 time-outs, SM77 errors). NeedMore stands for a time-out.
void Engine::endQuery(std::size_t k, MasterStatus outcome) {
    PortState &p = m_comm.ports[k];
    p.waiting = false;
    const PortDevices &d = m_program->ports[k];
    const auto task = static_cast<std::size_t>(p.query);
    const CommStep &c = m_program->comms[task];
    CommTask &t = m_comm.tasks[task];
    model::PlcPort *port = m_portLinks.empty() ? nullptr : m_portLinks[k];
    model::MasterProtocol *codec = port ? port->master() : nullptr;
    const std::uint32_t bit = 1u << ((c.index - 1) & 15);
    if (outcome != MasterStatus::Done) {
        const std::int32_t counter = outcome == MasterStatus::NeedMore ? d.timeouts : d.errors;
        if (counter >= 0)
            storeWord(static_cast<std::size_t>(counter), portWord(counter) + 1, 16);
        ++t.failures;
        if (t.failures >= std::max(1, portWord(d.errorLimit)) && d.status >= 0)
            storeWord(static_cast<std::size_t>(d.status),
                      static_cast<std::uint32_t>(portWord(d.status)) | bit, 16);
        p.writeAt = -1;
        return;
    }
    t.failures = 0;
    if (d.status >= 0)
        storeWord(static_cast<std::size_t>(d.status),
                  static_cast<std::uint32_t>(portWord(d.status)) & ~bit, 16);
    const std::size_t n = static_cast<std::size_t>(c.count);
    if (p.writeAt >= 0) {
        if (t.shadow.size() == n)
            t.shadow[static_cast<std::size_t>(p.writeAt)] = p.writeValue;
        p.writeAt = -1;
        return;
    }
    if (c.operation == 1 || !codec)
        return;
    const std::vector<std::uint16_t> &values = codec->values();
    const bool first = t.shadow.size() != n;
    if (first)
        t.shadow.assign(n, 0);
    for (std::size_t i = 0; i < n && i < values.size(); ++i) {
        const std::int32_t now =
            c.bitData ? (readBit(c.bits[i]) ? 1 : 0) : m_words[std::size_t(c.words[i])];
        // Read-write: a datum the program changed while the read was out is written next,
        // not overwritten.
        if (c.operation == 2 && !first && now != t.shadow[i])
            continue;
        const std::int32_t v =
            c.bitData ? (values[i] ? 1 : 0) : static_cast<std::int16_t>(values[i]);
        if (c.bitData)
            put(m_words.data(), c.bits[i], v != 0);
        else
            storeWord(static_cast<std::size_t>(c.words[i]), v, 16);
        t.shadow[i] = v;
    }
}

} // namespace rung::simulator
