#include "network/devices.h"
#include "network/tr.h"

#include <QCoreApplication>
#include <QJsonArray>

#include <limits>

namespace rung::network {

namespace {

using namespace comms::modbus;

bool readLine(const QJsonObject &o, const QString &where, const char *defaultFrame,
              model::SerialSettings *line, QString *error) {
    line->baud = o.value(QLatin1String("baud")).toInt(19200);
    if (line->baud < 50 || line->baud > 1000000) {
        *error = DevicesTr::tr("%1.baud: needs a rate from 50 to 1000000").arg(where);
        return false;
    }
    const QString frame = o.value(QLatin1String("frame")).toString(QLatin1String(defaultFrame));
    if (!model::parseFrameFormat(frame, line)) {
        *error = DevicesTr::tr("%1.frame: \"%2\" is no character format (8N1, 7E1, ...)")
                     .arg(where, frame);
        return false;
    }
    const double delay = o.value(QLatin1String("delay")).toDouble(2);
    if (delay < 0 || delay > 60000) {
        *error = DevicesTr::tr("%1.delay: needs milliseconds from 0 to 60000").arg(where);
        return false;
    }
    return true;
}

} // namespace

bool hexBytes(const QString &text, QByteArray *bytes) {
    bytes->clear();
    for (const QString &part : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        bool ok = false;
        const uint v = part.toUInt(&ok, 16);
        if (!ok || part.size() > 2 || v > 0xFF)
            return false;
        *bytes += char(v);
    }
    return !bytes->isEmpty();
}

QByteArray escapedBytes(const QString &text) {
    QByteArray out;
    const QByteArray in = text.toLatin1();
    for (qsizetype i = 0; i < in.size(); ++i) {
        if (in[i] != '\\' || i + 1 >= in.size()) {
            out += in[i];
            continue;
        }
        const char c = in[++i];
        if (c == 'x' && i + 2 < in.size() + 1) {
            bool ok = false;
            const int v = in.mid(i + 1, 2).toInt(&ok, 16);
            if (ok) {
                out += char(v);
                i += 2;
                continue;
            }
        }
        out += c == 'r' ? '\r' : c == 'n' ? '\n' : c == 't' ? '\t' : c;
    }
    return out;
}

std::unique_ptr<Endpoint> makeDevice(Network *network, const DeviceDescription &d, QString *error) {
    if (d.kind == QLatin1String("modbus-slave")) {
        auto device = std::make_unique<ModbusSlaveDevice>(network, d.name);
        if (!device->read(d, error))
            return nullptr;
        return device;
    }
    auto device = std::make_unique<LineDevice>(network, d.name);
    if (!device->read(d, error))
        return nullptr;
    return device;
}

// ----- MODBUS slave -----

bool ModbusSlaveDevice::read(const DeviceDescription &d, QString *error) {
    const QJsonObject &o = d.json;
    if (!onlyJsonKeys(o,
                      {QStringLiteral("name"), QStringLiteral("kind"), QStringLiteral("station"),
                       QStringLiteral("baud"), QStringLiteral("frame"), QStringLiteral("mode"),
                       QStringLiteral("delay"), QStringLiteral("registers"),
                       QStringLiteral("inputRegisters"), QStringLiteral("coils"),
                       QStringLiteral("inputs"), QStringLiteral("comment")},
                      d.where, error) ||
        !readLine(o, d.where, "8N1", &m_line, error))
        return false;
    m_delayUs = qint64(o.value(QLatin1String("delay")).toDouble(2) * 1000);
    station = o.value(QLatin1String("station")).toInt(1);
    if (station < 1 || station > 247) {
        *error = DevicesTr::tr("%1.station: needs a MODBUS station from 1 to 247").arg(d.where);
        return false;
    }
    const QString mode = o.value(QLatin1String("mode")).toString(QStringLiteral("rtu"));
    if (mode != QLatin1String("rtu") && mode != QLatin1String("ascii")) {
        *error = DevicesTr::tr("%1.mode: needs \"rtu\" or \"ascii\"").arg(d.where);
        return false;
    }
    m_framing = mode == QLatin1String("ascii") ? Framing::Ascii : Framing::Rtu;
    m_decoder = std::make_unique<RequestDecoder>(m_framing);
    auto table = [&](const char *key, auto &into, bool bits) {
        const QJsonObject t = o.value(QLatin1String(key)).toObject();
        for (auto it = t.begin(); it != t.end(); ++it) {
            bool ok = false;
            const int address = it.key().toInt(&ok);
            const double v = it.value().toDouble(-1e300);
            if (!ok || address < 0 || address > 65535 || v != double(qint64(v)) ||
                v < (bits ? 0 : -32768) || v > (bits ? 1 : 65535)) {
                *error =
                    DevicesTr::tr("%1.%2.%3: needs an address 0..65535 and a value %4")
                        .arg(d.where, QLatin1String(key), it.key(),
                             bits ? QStringLiteral("0 or 1") : QStringLiteral("-32768..65535"));
                return false;
            }
            into[address] = static_cast<std::remove_reference_t<decltype(into[0])>>(
                bits ? (v != 0) : std::uint16_t(qint64(v) & 0xFFFF));
        }
        return true;
    };
    return table("registers", holding, false) && table("inputRegisters", input, false) &&
           table("coils", coils, true) && table("inputs", discrete, true);
}

void ModbusSlaveDevice::deliver(const QByteArray &bytes, int, qint64 atUs) {
    m_lastUs = atUs;
    m_decoder->feed(bytes);
    while (m_decoder->status() == comms::FrameStatus::Complete) {
        const int unit = m_decoder->unit();
        if (unit == station || unit == BroadcastUnit) {
            const QByteArray pdu = respond(m_decoder->parsed());
            if (unit == station && !pdu.isEmpty())
                m_replies.push_back({atUs + m_delayUs + m_line.rtuGapMicroseconds(),
                                     m_framing == Framing::Ascii ? asciiFrame(station, pdu)
                                                                 : rtuFrame(station, pdu)});
        }
        m_decoder->next();
    }
    if (m_decoder->buffered() > kMaxReceivedKept)
        m_decoder = std::make_unique<RequestDecoder>(m_framing);
}

QByteArray ModbusSlaveDevice::respond(const ParsedRequest &parsed) {
    const Request &q = parsed.request;
    Response r;
    r.function = q.function;
    auto refuse = [&](int code) {
        r.exception = code;
        return encodeResponsePdu(r);
    };
    if (parsed.exception)
        return refuse(parsed.exception);
    auto has = [&](const auto &table) {
        for (int a = q.address; a < q.address + q.count; ++a)
            if (!table.count(a))
                return false;
        return true;
    };
    switch (q.function) {
    case ReadCoils:
    case ReadDiscreteInputs: {
        const auto &t = q.function == ReadCoils ? coils : discrete;
        if (!has(t))
            return refuse(IllegalDataAddress);
        for (int a = q.address; a < q.address + q.count; ++a)
            r.bits.push_back(t.at(a));
        break;
    }
    case ReadHoldingRegisters:
    case ReadInputRegisters: {
        const auto &t = q.function == ReadHoldingRegisters ? holding : input;
        if (!has(t))
            return refuse(IllegalDataAddress);
        for (int a = q.address; a < q.address + q.count; ++a)
            r.registers.push_back(t.at(a));
        break;
    }
    case WriteSingleCoil:
    case WriteMultipleCoils:
        if (!has(coils))
            return refuse(IllegalDataAddress);
        for (int k = 0; k < q.count && std::size_t(k) < q.bits.size(); ++k)
            coils[q.address + k] = q.bits[std::size_t(k)];
        r.address = q.address;
        r.count = q.function == WriteSingleCoil ? (q.bits.front() ? 0xFF00 : 0) : q.count;
        break;
    case WriteSingleRegister:
    case WriteMultipleRegisters:
        if (!has(holding))
            return refuse(IllegalDataAddress);
        for (int k = 0; k < q.count && std::size_t(k) < q.registers.size(); ++k)
            holding[q.address + k] = q.registers[std::size_t(k)];
        r.address = q.address;
        r.count = q.function == WriteSingleRegister ? q.registers.front() : q.count;
        break;
    default:
        return refuse(IllegalFunction);
    }
    return encodeResponsePdu(r);
}

qint64 ModbusSlaveDevice::nextUs() const {
    qint64 next = std::numeric_limits<qint64>::max();
    for (const auto &[due, frame] : m_replies)
        next = std::min(next, due);
    // An RTU frame of unknown length ends at 3.5 characters of silence.
    if (m_framing == Framing::Rtu && m_decoder->buffered() > 0 && m_lastUs >= 0)
        next = std::min(next, m_lastUs + m_line.rtuGapMicroseconds());
    return next;
}

void ModbusSlaveDevice::run(qint64 nowUs) {
    if (m_framing == Framing::Rtu && m_decoder->buffered() > 0 && m_lastUs >= 0 &&
        nowUs >= m_lastUs + m_line.rtuGapMicroseconds()) {
        m_decoder->silence();
        deliver({}, 0, m_lastUs);
        if (m_decoder->buffered() > 0)
            m_decoder = std::make_unique<RequestDecoder>(m_framing);
    }
    std::vector<std::pair<qint64, QByteArray>> later;
    for (auto &[due, frame] : m_replies) {
        if (due <= nowUs)
            m_network->transmit(this, frame);
        else
            later.push_back({due, frame});
    }
    m_replies = std::move(later);
}

// ----- line device -----

bool LineDevice::read(const DeviceDescription &d, QString *error) {
    const QJsonObject &o = d.json;
    if (!onlyJsonKeys(o,
                      {QStringLiteral("name"), QStringLiteral("kind"), QStringLiteral("baud"),
                       QStringLiteral("frame"), QStringLiteral("delay"), QStringLiteral("answers"),
                       QStringLiteral("comment")},
                      d.where, error) ||
        !readLine(o, d.where, "8N1", &m_line, error))
        return false;
    m_delayUs = qint64(o.value(QLatin1String("delay")).toDouble(2) * 1000);
    const QJsonArray answers = o.value(QLatin1String("answers")).toArray();
    for (qsizetype i = 0; i < answers.size(); ++i) {
        const QString where = QStringLiteral("%1.answers[%2]").arg(d.where).arg(i);
        const QJsonObject a = answers[i].toObject();
        Answer answer;
        auto bytes = [&](const char *hexKey, const char *textKey, QByteArray *into) {
            if (a.contains(QLatin1String(textKey))) {
                *into = escapedBytes(a.value(QLatin1String(textKey)).toString());
                return !into->isEmpty();
            }
            return hexBytes(a.value(QLatin1String(hexKey)).toString(), into);
        };
        if (!bytes("expect", "expectText", &answer.expect) ||
            !bytes("reply", "replyText", &answer.reply)) {
            *error =
                DevicesTr::tr("%1: needs \"expect\" and \"reply\" as hex bytes (\"02 30 31\"), or "
                              "\"expectText\" and \"replyText\" as text (\"\\x02"
                              "01\")")
                    .arg(where);
            return false;
        }
        m_answers.push_back(answer);
    }
    return true;
}

void LineDevice::deliver(const QByteArray &bytes, int, qint64 atUs) {
    m_all += bytes;
    trimReceived(m_all);
    m_buffer += bytes;
    // The first answer whose expected bytes have come is sent; what came up to them is used.
    for (bool matched = true; matched;) {
        matched = false;
        qsizetype best = -1;
        const Answer *which = nullptr;
        for (const Answer &a : m_answers) {
            const qsizetype at = m_buffer.indexOf(a.expect);
            if (at >= 0 && (best < 0 || at < best)) {
                best = at;
                which = &a;
            }
        }
        if (which) {
            m_replies.push_back({atUs + m_delayUs, which->reply});
            m_buffer.remove(0, best + which->expect.size());
            matched = true;
        }
    }
    trimReceived(m_buffer);
}

qint64 LineDevice::nextUs() const {
    qint64 next = std::numeric_limits<qint64>::max();
    for (const auto &[due, frame] : m_replies)
        next = std::min(next, due);
    return next;
}

void LineDevice::run(qint64 nowUs) {
    std::vector<std::pair<qint64, QByteArray>> later;
    for (auto &[due, frame] : m_replies) {
        if (due <= nowUs)
            m_network->transmit(this, frame);
        else
            later.push_back({due, frame});
    }
    m_replies = std::move(later);
}

} // namespace rung::network
