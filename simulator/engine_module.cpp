#include "engine.h"
#include "simulator/tr.h"

#include <QCoreApplication>

// The VB-1COM serial module (Vigor M/VB/VH communication manual, B-4): its buffer memory (BFM) as
// FROM / TO reach it, and what the module does with its port when the program sets the command bits
// of BFM #1. The module is the station's port MODULEn in a network (docs/network.md); without one
// FROM / TO name a module that is not there.

namespace rung::simulator {

namespace {

// B-4-4's buffer memory: #0 .. #30, #1000 .. #1256 (send), #2000 .. #2256 (receive).
constexpr int kModelId = 7030; // BFM #30: "K7030"
enum : int {
    Format = 0,
    Command = 1,
    ReceiveLimit = 2,
    ReceiveTimeout = 3,
    SendStart = 4,
    SendEnd = 6,
    ReceiveStart = 8,
    ReceiveEnd = 10,
    SendLeft = 13,
    ReceivedBytes = 14,
    SendSum = 15,
    ReceiveSum = 16,
    Status = 28,
    Error = 29,
    ModelId = 30,
    SendCount = 1000,
    ReceiveCount = 2000,
};
// BFM #28 (status) and #1 (command) bits.
enum : std::int32_t {
    SendDone = 1,
    ReceiveDone = 2,
    ReceiveTimedOut = 4,
    ErrorBit = 8,
    Sending = 64,
    Receiving = 128,
    Enable = 1,
    StartSend = 2,
    ClearReceive = 4,
    ClearError = 8,
};
// BFM #29
constexpr std::int32_t kParityError = 1, kNotAscii = 3, kSumError = 4, kBaudError = 6;

bool writable(int bfm) {
    return (bfm >= 0 && bfm <= 11) || (bfm >= SendCount && bfm <= SendCount + 256);
}

bool readable(int bfm) {
    return (bfm >= 0 && bfm <= 30) || (bfm >= SendCount && bfm <= SendCount + 256) ||
           (bfm >= ReceiveCount && bfm <= ReceiveCount + 256);
}

int slot(int bfm) {
    return bfm < SendCount ? bfm : bfm < ReceiveCount ? 31 + bfm - SendCount : 288 + bfm - 2000;
}

// A code of up to four bytes in two BFM words, "this byte will not be sent" when 0; sent
// "4th, 3rd, 2nd, 1st": #4 = 0002H is STX alone.
QByteArray code(const std::vector<std::int32_t> &bfm, int first) {
    const auto lo = static_cast<std::uint32_t>(bfm[std::size_t(slot(first))]);
    const auto hi = static_cast<std::uint32_t>(bfm[std::size_t(slot(first + 1))]);
    const std::uint32_t bytes[4] = {lo & 0xFF, (lo >> 8) & 0xFF, hi & 0xFF, (hi >> 8) & 0xFF};
    QByteArray out;
    for (int k = 3; k >= 0; --k)
        if (bytes[k])
            out += char(bytes[k]);
    return out;
}

QByteArray hex2(std::uint32_t byte) {
    return QByteArray::number(byte & 0xFF, 16).toUpper().rightJustified(2, '0');
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

} // namespace

ModuleState &Engine::module(int number) {
    const auto n = static_cast<std::size_t>(std::max(1, number));
    if (m_comm.modules.size() < n)
        m_comm.modules.resize(n);
    ModuleState &m = m_comm.modules[n - 1];
    if (m.bfm.empty()) {
        m.bfm.assign(std::size_t(slot(ReceiveCount + 256)) + 1, 0);
        m.bfm[Format] = 0x0087; // B-4-4: initial 0087H
        m.bfm[ModelId] = kModelId;
    }
    return m;
}

void Engine::moduleRead(const CommStep &c, const Step &s, std::size_t step, int bfm, int words) {
    ModuleState &m = module(c.module);
    if (!m.attached) {
        runtimeError(step, EngineTr::tr("operation error: no special module %1 is connected (in a "
                                        "network a VB-1COM is the station's port MODULE%1)")
                               .arg(c.module));
        return;
    }
    if (words < 1 || words > c.firstWords || !readable(bfm) || !readable(bfm + words - 1)) {
        runtimeError(step,
                     EngineTr::tr("operation error: buffer memory #%1..#%2 of module %3 does not "
                                  "exist or the block runs past its area; nothing is read")
                         .arg(bfm)
                         .arg(bfm + words - 1)
                         .arg(c.module));
        return;
    }
    if (c.first < 0) { // a digit group: one word, written back to its bits after the step
        storeWord(static_cast<std::size_t>(s.dest), m.bfm[std::size_t(slot(bfm))], s.width);
        return;
    }
    for (int k = 0; k < words; ++k)
        storeWord(static_cast<std::size_t>(c.first + k), m.bfm[std::size_t(slot(bfm + k))], 16);
}

void Engine::moduleWrite(const CommStep &c, const Step &s, std::size_t step, int bfm, int words) {
    ModuleState &m = module(c.module);
    if (!m.attached) {
        runtimeError(step, EngineTr::tr("operation error: no special module %1 is connected (in a "
                                        "network a VB-1COM is the station's port MODULE%1)")
                               .arg(c.module));
        return;
    }
    if (words < 1 || words > c.firstWords || !writable(bfm) || !writable(bfm + words - 1)) {
        runtimeError(
            step,
            EngineTr::tr(
                "operation error: buffer memory #%1..#%2 of module %3 cannot "
                "be written (the module's table marks it read-only, or it does not exist); nothing "
                "is written")
                .arg(bfm)
                .arg(bfm + words - 1)
                .arg(c.module));
        return;
    }
    for (int k = 0; k < words; ++k)
        m.bfm[std::size_t(slot(bfm + k))] =
            c.first < 0 ? readWord(m_words.data(), s.x) // a digit group: one word
                        : m_words[static_cast<std::size_t>(c.first + k)];
    if (bfm > Command || bfm + words - 1 < Command)
        return;
    // The command bits act on their rising edge (B-4-4, BFM #1).
    std::int32_t &status = m.bfm[Status];
    const std::int32_t now = m.bfm[Command];
    const std::int32_t rose = now & ~m.command;
    m.command = now;
    model::PlcPort *port = nullptr;
    for (std::size_t k = 0; k < m_program->comms.size(); ++k)
        if (m_program->comms[k].module == c.module && m_commPorts.size() > k && m_commPorts[k])
            port = m_commPorts[k];
    if (rose & Enable) {
        // Takes #0 (and the codes) over and clears the error.
        const auto f = static_cast<std::uint32_t>(m.bfm[Format]);
        static const int bauds[16] = {0,    0,     0,     300,   600,   1200,  2400,  4800,
                                      9600, 19200, 38400, 76800, 14400, 28800, 57600, 0};
        status &= ~ErrorBit;
        m.bfm[Error] = 0;
        const int baud = bauds[(f >> 4) & 0xF];
        if (baud == 0) {
            status |= ErrorBit;
            m.bfm[Error] = kBaudError;
        } else if (port) {
            model::SerialSettings line = port->line();
            line.baud = baud;
            line.dataBits = (f & 1) ? 8 : 7;
            const std::uint32_t parity = (f >> 1) & 3;
            line.parity = parity == 1   ? model::SerialSettings::Parity::Odd
                          : parity == 3 ? model::SerialSettings::Parity::Even
                                        : model::SerialSettings::Parity::None;
            line.stopBits = (f & 8) ? 2 : 1;
            port->setLine(line);
        }
    }
    if (rose & ClearError) {
        status &= ~ErrorBit;
        m.bfm[Error] = 0;
    }
    if (rose & ClearReceive) {
        status &= ~(ReceiveDone | ReceiveTimedOut | Receiving);
        m.bfm[std::size_t(slot(ReceiveCount))] = 0;
        m.bfm[ReceivedBytes] = 0;
        m.received.clear();
        m.started = false;
    }
    if ((rose & StartSend) && (now & Enable) && !m.sending) {
        const auto f = static_cast<std::uint32_t>(m.bfm[Format]);
        const bool bytes8 = f & 0x4000;
        const bool convert = f & 0x1000;
        const bool withSum = f & 0x2000;
        const int count =
            std::clamp<int>(m.bfm[std::size_t(slot(SendCount))], 0, bytes8 ? 256 : 512);
        QByteArray data;
        for (int k = 0; k < count; ++k) {
            const auto w = static_cast<std::uint32_t>(
                m.bfm[std::size_t(slot(SendCount + 1 + (bytes8 ? k : k / 2)))]);
            const std::uint32_t b = (bytes8 || k % 2 == 0 ? w : w >> 8) & 0xFF;
            data += convert ? hex2(b) : QByteArray(1, char(b));
        }
        const QByteArray end = code(m.bfm, SendEnd);
        QByteArray frame = code(m.bfm, SendStart) + data + end;
        std::uint32_t sum = 0;
        for (char ch : data + end)
            sum += static_cast<quint8>(ch);
        m.bfm[SendSum] = std::int32_t(sum & 0xFFFF);
        if (withSum)
            frame += hex2(sum);
        const std::uint32_t crlf = (f >> 10) & 3;
        if (crlf == 1 || crlf == 3)
            frame += '\r';
        if (crlf == 3)
            frame += '\n';
        status &= ~SendDone;
        if (port) {
            port->send(frame);
            m.sending = true;
            status |= Sending;
            m.bfm[SendLeft] = count;
        } else {
            status |= SendDone;
        }
    }
}

void Engine::serviceModule(int number) {
    ModuleState &m = module(number);
    model::PlcPort *port = nullptr;
    for (std::size_t k = 0; k < m_program->comms.size(); ++k)
        if (m_program->comms[k].module == number && m_commPorts.size() > k && m_commPorts[k])
            port = m_commPorts[k];
    if (!port)
        return;
    std::int32_t &status = m.bfm[Status];
    if (m.sending && !port->sending()) {
        m.sending = false;
        status = (status & ~Sending) | SendDone;
        m.bfm[SendLeft] = 0;
    }
    const QByteArray in = port->receive();
    if (port->takeCharacterErrors() > 0) {
        status |= ErrorBit;
        m.bfm[Error] = kParityError;
    }
    if (!(m.command & Enable) || (status & ReceiveDone))
        return; // disabled, or the last reception not cleared: what comes is lost
    const auto f = static_cast<std::uint32_t>(m.bfm[Format]);
    const bool bytes8 = f & 0x4000;
    const bool convert = f & 0x1000;
    const bool withSum = f & 0x2000;
    const QByteArray start = code(m.bfm, ReceiveStart);
    const QByteArray end = code(m.bfm, ReceiveEnd);
    const int limit = m.bfm[ReceiveLimit] > 0 ? m.bfm[ReceiveLimit] : (bytes8 ? 256 : 512);
    const std::uint32_t crlf = (f >> 10) & 3;
    const int trailer = (withSum ? 2 : 0) + (crlf == 1 ? 1 : crlf == 3 ? 2 : 0);
    bool complete = false;
    for (char ch : in) {
        if (!m.started) {
            // Before the start code (when one is set) the line's bytes are not the frame.
            m.received += ch;
            if (!start.isEmpty()) {
                if (!start.startsWith(
                        m.received.right(std::min<qsizetype>(m.received.size(), start.size())))) {
                    m.received.clear();
                    continue;
                }
                if (!m.received.endsWith(start))
                    continue;
                m.received.clear();
            }
            m.started = true;
            status |= Receiving;
            if (start.isEmpty())
                m.received = QByteArray(1, ch);
            else
                continue;
        } else {
            m.received += ch;
        }
        const qsizetype endAt = end.isEmpty() ? -1 : m.received.indexOf(end);
        if (endAt >= 0 && m.received.size() >= endAt + end.size() + trailer) {
            complete = true;
            break;
        }
        if (end.isEmpty() && m.received.size() >= (convert ? 2 * limit : limit) + trailer) {
            complete = true;
            break;
        }
    }
    bool timedOut = false;
    if (!complete && m.started && m.bfm[ReceiveTimeout] > 0 && port->lastReceivedUs() >= 0 &&
        commNowUs() - port->lastReceivedUs() >= qint64(m.bfm[ReceiveTimeout]) * 10000) {
        complete = true;
        timedOut = true;
    }
    if (!complete)
        return;
    // Split the frame: data, end code, sum, CR / LF.
    QByteArray data = m.received;
    QByteArray sumText;
    const qsizetype endAt = end.isEmpty() ? -1 : data.indexOf(end);
    std::uint32_t sum = 0;
    if (endAt >= 0) {
        for (char ch : data.left(endAt + end.size()))
            sum += static_cast<quint8>(ch);
        if (withSum)
            sumText = data.mid(endAt + end.size(), 2);
        data.truncate(endAt);
    } else {
        if (trailer > 0 && data.size() > trailer) {
            if (withSum)
                sumText = data.mid(data.size() - trailer, 2);
            data.chop(trailer);
        }
        for (char ch : data)
            sum += static_cast<quint8>(ch);
    }
    m.bfm[ReceiveSum] = std::int32_t(sum & 0xFFFF);
    if (withSum && sumText != hex2(sum)) {
        status |= ErrorBit;
        m.bfm[Error] = kSumError;
    }
    QByteArray bytes;
    if (convert) {
        for (qsizetype k = 0; k + 1 < data.size(); k += 2) {
            const int hi = hexDigit(data[k]);
            const int lo = hexDigit(data[k + 1]);
            if (hi < 0 || lo < 0) {
                status |= ErrorBit;
                m.bfm[Error] = kNotAscii;
                break;
            }
            bytes += char(hi << 4 | lo);
        }
    } else {
        bytes = data;
    }
    bytes.truncate(limit);
    for (qsizetype k = 0; k < bytes.size(); ++k) {
        const auto b = static_cast<std::int32_t>(static_cast<quint8>(bytes[k]));
        std::int32_t &w = m.bfm[std::size_t(slot(ReceiveCount + 1 + int(bytes8 ? k : k / 2)))];
        w = bytes8 || k % 2 == 0 ? b : ((w & 0xFF) | (b << 8));
    }
    m.bfm[std::size_t(slot(ReceiveCount))] = std::int32_t(bytes.size());
    m.bfm[ReceivedBytes] = std::int32_t(bytes.size());
    status = (status & ~Receiving) | ReceiveDone | (timedOut ? ReceiveTimedOut : 0);
    m.received.clear();
    m.started = false;
}

} // namespace rung::simulator
