#include "network/traffic_decode.h"

#include "network/bridge.h"
#include "network/devices.h"
#include "network/station.h"
#include "network/tr.h"
#include "network/traffic_decode_detail.h"

#include "comms/driver/protocol_driver.h"
#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"
#include "comms/protocol/modbus_master.h"
#include "comms/protocol/modbus_slave.h"
#include "comms/protocol/vigor_link_master.h"
#include "comms/protocol/vigor_link_slave.h"
#include "model/target/address.h"

namespace rung::network {

namespace decode_detail {

using comms::detail::hex2;

QString hex4(int value) {
    return QString::number(value, 16).toUpper().rightJustified(4, u'0');
}

// The device at a unit of a space as the target writes it; empty when the map has none.
QString deviceAt(const model::Target *target, model::ProtocolId protocol,
                 model::ProtocolSpace space, int unit, int bit) {
    if (!target)
        return {};
    const model::ProtocolMap *map = model::findProtocolMap(*target, protocol);
    if (!map)
        return {};
    std::optional<model::MappedDevice> d = model::fromProtocol(*target, *map, space, unit, bit);
    // A link byte of bit devices names its first device; a byte of a word names the word.
    if (!d && bit == 0 && model::unitBits(space) > 1)
        d = model::fromProtocol(*target, *map, space, unit, -1);
    if (!d)
        return {};
    const model::Address a{d->area, d->index, d->part == model::DevicePart::Value ? -1 : d->bit};
    return model::formatAddress(*target, a);
}

QString withDevice(const QString &device, const QString &raw) {
    return device.isEmpty() ? raw : TrafficDecodeTr::tr("%1 (%2)").arg(device, raw);
}

QString bitsText(const std::vector<bool> &bits, int count) {
    QString out;
    for (int i = 0; i < count && i < int(bits.size()); ++i)
        out += bits[std::size_t(i)] ? u'1' : u'0';
    return out;
}

// A frame of no protocol as a reader would quote it: printable characters as they are, the
// others as C escapes.
QString quoted(QByteArrayView bytes) {
    QString out;
    for (char c : bytes) {
        const auto u = static_cast<quint8>(c);
        if (u == '\r')
            out += QStringLiteral("\\r");
        else if (u == '\n')
            out += QStringLiteral("\\n");
        else if (u == '\\')
            out += QStringLiteral("\\\\");
        else if (u >= 0x20 && u < 0x7F)
            out += QLatin1Char(c);
        else
            out += QStringLiteral("\\x") + hex2(u);
    }
    return out;
}

QString truncatedText(qsizetype size) {
    return TrafficDecodeTr::tr("the frame stops after %n byte(s): cut short or not a frame", "",
                               int(size));
}

QString extraText(qsizetype size) {
    return TrafficDecodeTr::tr("%n byte(s) after the end of the frame", "", int(size));
}

} // namespace decode_detail

namespace {

using Speaks = TrafficDecoder::End::Speaks;
namespace mb = comms::modbus;
namespace vg = comms::vigor;
namespace hl = comms::hostlink;
using comms::detail::hex2;

QString modbusFunctionName(int function) {
    switch (function) {
    case mb::ReadCoils:
        return TrafficDecodeTr::tr("read coils");
    case mb::ReadDiscreteInputs:
        return TrafficDecodeTr::tr("read discrete inputs");
    case mb::ReadHoldingRegisters:
        return TrafficDecodeTr::tr("read holding registers");
    case mb::ReadInputRegisters:
        return TrafficDecodeTr::tr("read input registers");
    case mb::WriteSingleCoil:
        return TrafficDecodeTr::tr("write single coil");
    case mb::WriteSingleRegister:
        return TrafficDecodeTr::tr("write single register");
    case mb::WriteMultipleCoils:
        return TrafficDecodeTr::tr("write multiple coils");
    case mb::WriteMultipleRegisters:
        return TrafficDecodeTr::tr("write multiple registers");
    default:
        return TrafficDecodeTr::tr("unknown function");
    }
}

QString vigorCommandName(int command) {
    switch (vg::Command(command)) {
    case vg::Command::Read:
        return TrafficDecodeTr::tr("read");
    case vg::Command::Write:
        return TrafficDecodeTr::tr("write");
    case vg::Command::BitOn:
        return TrafficDecodeTr::tr("bit ON");
    case vg::Command::BitOff:
        return TrafficDecodeTr::tr("bit OFF");
    }
    return TrafficDecodeTr::tr("unknown command");
}

// The space a MODBUS function reaches in a map (PL110: 02 and 04 read the tables of 01 and 03).
model::ProtocolSpace modbusSpace(int function, const model::ProtocolMap &map) {
    switch (function) {
    case mb::ReadDiscreteInputs:
        return map.inputsShareSpaces ? model::ProtocolSpace::Coils
                                     : model::ProtocolSpace::DiscreteInputs;
    case mb::ReadInputRegisters:
        return map.inputsShareSpaces ? model::ProtocolSpace::HoldingRegisters
                                     : model::ProtocolSpace::InputRegisters;
    case mb::ReadHoldingRegisters:
    case mb::WriteSingleRegister:
    case mb::WriteMultipleRegisters:
        return model::ProtocolSpace::HoldingRegisters;
    default:
        return model::ProtocolSpace::Coils;
    }
}

QString hexText(QByteArrayView bytes) {
    return QString::fromLatin1(bytes.toByteArray().toHex(' ').toUpper());
}

QString registersText(const std::vector<std::uint16_t> &registers) {
    QStringList out;
    for (auto v : registers)
        out << QString::number(v);
    return out.join(u' ');
}

} // namespace

TrafficDecoder::TrafficDecoder(const Network &network) {
    for (const auto &wire : network.wires()) {
        QStringList names;
        for (const Endpoint *e : wire->ends)
            names << learn(network, *e, wire->name);
        m_wires[wire->name] = names;
    }
    // A bridge's real line joins its port's wire when the bridge opens, after the decoder
    // learnt the wiring (NetworkSession::startBridges): it is learnt now from the description,
    // with its port, on the wire the port will be on (its own, named as the bridge's end, when
    // the file puts the port on none: Network::attach).
    for (const BridgeDescription &b : network.description().bridges) {
        const Endpoint *port = network.endpoint(b.end);
        if (!port || dynamic_cast<const StationPort *>(port) == nullptr)
            continue;
        const QString bridge = bridgeEndName(b.end);
        const QString wire = port->wire ? port->wire->name : bridge;
        QStringList &names = m_wires[wire];
        if (!port->wire)
            names << learn(network, *port, wire);
        End line;
        line.name = bridge;
        line.owner = bridge;
        line.wire = wire;
        line.programDriven = true;
        line.application = TrafficDecodeTr::tr("real line");
        names << bridge;
        m_ends[bridge] = line;
    }
}

QString TrafficDecoder::learn(const Network &network, const Endpoint &endpoint,
                              const QString &wire) {
    const Endpoint *e = &endpoint;
    End end;
    end.name = e->name;
    end.owner = e->owner;
    end.wire = wire;
    if (const auto *port = dynamic_cast<const StationPort *>(e)) {
        const model::PortConfig &config = port->config();
        const model::PortApplication &app = *config.application;
        const Station *station = network.station(e->owner);
        end.target = station ? &station->target() : nullptr;
        end.application = QCoreApplication::translate("rung::model::Target", app.name);
        end.station = config.station;
        end.modbusAscii = config.modbusAscii;
        end.sharedLink = app.sharedLink != 0;
        end.programDriven = app.programDriven;
        if (app.answers == model::ProtocolId::HostLink) {
            // A CPM1's peripheral port: the PLC's side of Host Link; the host is a
            // bridge's real line or a device on the wire.
            end.speaks = Speaks::HostLink;
            end.answers = true;
        } else if (app.answers == model::ProtocolId::VigorLink) {
            end.speaks = Speaks::VigorLink;
            end.answers = true;
            // LINK drives the port: its program is the master (Easy Link, B-3-3).
            end.master = port->usedByProgram();
        } else if (app.answers == model::ProtocolId::Modbus || (app.master && app.published)) {
            end.speaks = Speaks::Modbus;
            // Station 0 of the Vigor's MODBUS is MBUS's master (B-3-6).
            end.master = app.master || config.station == 0;
            end.answers = model::answersAt(app, config.station);
            // A PL110 port its program may switch to free-port (SEND; PL110 manual
            // 4.2.19) sends bytes of no protocol then.
            const model::PortSpec *spec = end.target->port(config.port);
            end.programDriven =
                !app.master && spec && spec->markers.freePort && port->usedByProgram();
            if (const auto *map = model::findProtocolMap(*end.target, model::ProtocolId::Modbus))
                end.anyStation = map->anyStationUnit;
        }
    } else if (const auto *slave = dynamic_cast<const ModbusSlaveDevice *>(e)) {
        end.speaks = Speaks::Modbus;
        end.answers = true;
        end.station = slave->station;
        end.application = TrafficDecodeTr::tr("MODBUS slave device");
        for (const DeviceDescription &d : network.description().devices)
            if (d.name == e->name)
                end.modbusAscii =
                    d.json.value(QStringLiteral("mode")).toString() == QStringLiteral("ascii");
    } else {
        end.programDriven = true;
        end.application = dynamic_cast<const LineDevice *>(e) ? TrafficDecodeTr::tr("line device")
                                                              : TrafficDecodeTr::tr("real line");
    }
    m_ends[end.name] = end;
    return end.name;
}

TrafficDecoder::~TrafficDecoder() = default;

void TrafficDecoder::reset() {
    m_pending.clear();
}

QString TrafficDecoder::noReplyText() {
    return TrafficDecodeTr::tr("no reply came before the next request (a time-out)");
}

bool TrafficDecoder::takeUnanswered(const QString &wire) {
    const auto it = m_pending.find(wire);
    if (it == m_pending.end())
        return false;
    const bool waiting = it->second->slave != nullptr;
    m_pending.erase(it);
    return waiting;
}

const TrafficDecoder::End *TrafficDecoder::end(const QString &name) const {
    const auto it = m_ends.find(name);
    return it == m_ends.end() ? nullptr : &it->second;
}

QString TrafficDecoder::ownerOf(const QString &name) const {
    const End *e = end(name);
    return e ? e->owner : name.section(u'/', 0, 0);
}

const TrafficDecoder::End *TrafficDecoder::slaveOn(const QString &wire, Speaks speaks,
                                                   int station) const {
    const auto it = m_wires.find(wire);
    if (it == m_wires.end())
        return nullptr;
    for (const QString &name : it->second) {
        const End *e = end(name);
        if (e && e->speaks == speaks && e->answers && !e->master &&
            (e->station == station || (e->anyStation >= 0 && e->anyStation == station)))
            return e;
    }
    return nullptr;
}

QString TrafficDecoder::receiversOf(const QString &wire, const QString &sender) const {
    const auto it = m_wires.find(wire);
    if (it == m_wires.end())
        return {};
    QStringList others = it->second;
    others.removeAll(sender);
    return others.join(QStringLiteral(", "));
}

DecodedFrame TrafficDecoder::raw(const End *from, const QByteArray &bytes,
                                 const QString &wire) const {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Raw;
    // A port of a protocol sends bytes of none in free-port (PL110 manual 4.2.19).
    f.protocol = !from                             ? TrafficDecodeTr::tr("bytes")
                 : from->speaks != Speaks::Nothing ? TrafficDecodeTr::tr("free-port")
                                                   : from->application;
    f.receiver = receiversOf(wire, from ? from->name : QString());
    f.count = int(bytes.size());
    f.data = quoted(bytes);
    return f;
}

DecodedFrame TrafficDecoder::decode(const TrafficRecord &record) {
    const End *from = end(record.sender);
    const QString &wire = record.wire;
    if (record.bytes.isEmpty()) {
        DecodedFrame f;
        f.kind = DecodedFrame::Kind::Exchange;
        f.protocol = from ? from->application : QString();
        f.receiver = receiversOf(wire, record.sender);
        return f;
    }
    if (!from)
        return raw(nullptr, record.bytes, wire);
    const QByteArray &bytes = record.bytes;
    const auto pending = m_pending.find(wire);
    const bool askedHere = pending != m_pending.end() && pending->second->slave == from;
    // A frame a fault kept off the wire answered nobody: the request before it still waits.
    std::unique_ptr<Pending> waiting;
    if (!record.delivered && pending != m_pending.end())
        waiting = std::make_unique<Pending>(*pending->second);
    const auto restore = [&](DecodedFrame f) {
        if (waiting && f.kind == DecodedFrame::Kind::Reply)
            m_pending[wire] = std::move(waiting);
        return f;
    };
    if (from->speaks == Speaks::VigorLink && !from->programDriven) {
        if (bytes.front() == vg::Stx || (bytes.front() != vg::Ack && from->master))
            return decodeVigorRequest(*from, bytes, wire);
        return restore(decodeVigorReply(*from, bytes, wire));
    }
    if (from->speaks == Speaks::HostLink)
        return restore(decodeHostLinkReply(*from, bytes, wire));
    if (from->speaks == Speaks::Modbus && (!from->programDriven || askedHere)) {
        if (from->master)
            return decodeModbusRequest(*from, bytes, from->modbusAscii, wire);
        return restore(decodeModbusReply(*from, bytes, from->modbusAscii, wire));
    }
    // A program that builds a protocol's request itself (RS, a VB-1COM: Vigor M/VB/VH
    // communication manual, B-3-9 and B-4-5 speak Computer Link so) is read as one when a
    // slave on the wire answers that protocol and the frame reads; else as bytes.
    if (from->programDriven && !from->answers) {
        // Host Link's frames start with "@" (its later parts and CRs follow a frame in parts).
        if (continuesHostLink(*from, bytes, wire))
            return decodeHostLinkRequest(*from, bytes, wire);
        // A Computer Link frame (STX .. ETX sum) for a station on the wire is shown as one even
        // when it is wrong (a wrong sum); MODBUS has no start character to tell it from text.
        const auto keep = [&](Speaks speaks, auto decodeRequest) -> std::optional<DecodedFrame> {
            const auto ends = m_wires.find(wire);
            if (ends == m_wires.end())
                return std::nullopt;
            for (const QString &name : ends->second) {
                const End *e = end(name);
                if (!e || e == from || e->speaks != speaks || !e->answers)
                    continue;
                DecodedFrame f = decodeRequest(*e);
                if (!f.receiver.isEmpty() && (f.problem.isEmpty() || speaks == Speaks::VigorLink))
                    return f;
                m_pending.erase(wire);
                return std::nullopt;
            }
            return std::nullopt;
        };
        if (bytes.front() == vg::Stx)
            if (auto f = keep(Speaks::VigorLink,
                              [&](const End &) { return decodeVigorRequest(*from, bytes, wire); }))
                return *f;
        if (auto f = keep(Speaks::Modbus, [&](const End &slave) {
                return decodeModbusRequest(*from, bytes, slave.modbusAscii, wire);
            }))
            return *f;
    }
    return raw(from, bytes, wire);
}

DecodedFrame TrafficDecoder::decodeVigorRequest(const End &from, const QByteArray &bytes,
                                                const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Request;
    f.protocol = TrafficDecodeTr::tr("Computer Link");
    vg::RequestDecoder decoder;
    decoder.feed(bytes);
    f.previousUnanswered = takeUnanswered(wire);
    if (decoder.status() != comms::FrameStatus::Complete) {
        f.problem = !decoder.discarded().ok() ? decoder.discarded().message
                    : bytes.front() != vg::Stx
                        ? TrafficDecodeTr::tr(
                              "not a Computer Link request: it does not start with STX (02h)")
                        : truncatedText(bytes.size());
        return f;
    }
    const vg::Request r = decoder.request(); // next() below starts the decoder over
    f.station = r.station;
    f.command = int(r.command);
    f.commandText = QStringLiteral("%1h %2").arg(hex2(f.command), vigorCommandName(f.command));
    const End *slave = slaveOn(wire, Speaks::VigorLink, r.station);
    if (slave)
        f.receiver = slave->name;
    const int code = decoder.errorCode();
    if (code == int(vg::ErrorCode::SumCheck)) {
        const qsizetype etx = bytes.indexOf(vg::Etx);
        f.problem =
            TrafficDecodeTr::tr("wrong sum (received %1, computed %2): the slave answers error 11h")
                .arg(QString::fromLatin1(bytes.mid(etx + 1, 2)),
                     QString::fromLatin1(vg::sum(QByteArrayView(bytes).sliced(1, etx))));
        return f;
    }
    if (code != 0) {
        f.problem = TrafficDecodeTr::tr("the slave refuses it: %1").arg(vg::errorText(code));
        return f;
    }
    const bool bitCommand = r.command == vg::Command::BitOn || r.command == vg::Command::BitOff;
    const model::Target *target = slave ? slave->target : nullptr;
    f.rawAddress = r.address;
    f.address = withDevice(bitCommand ? deviceAt(target, model::ProtocolId::VigorLink,
                                                 model::ProtocolSpace::LinkBytes, r.address >> 3,
                                                 r.address & 7)
                                      : deviceAt(target, model::ProtocolId::VigorLink,
                                                 model::ProtocolSpace::LinkBytes, r.address, 0),
                           hex4(r.address) + u'h');
    if (!bitCommand)
        f.count = r.length;
    if (r.command == vg::Command::Write)
        f.data = hexText(r.data);
    decoder.next();
    if (decoder.buffered() > 0)
        f.problem = extraText(decoder.buffered());
    auto p = std::make_unique<Pending>();
    p->speaks = Speaks::VigorLink;
    p->sender = from.name;
    p->slave = slave;
    p->station = r.station;
    p->vigor = r;
    m_pending[wire] = std::move(p);
    return f;
}

DecodedFrame TrafficDecoder::decodeVigorReply(const End &from, const QByteArray &bytes,
                                              const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Reply;
    f.protocol = TrafficDecodeTr::tr("Computer Link");
    vg::Request request;
    const auto it = m_pending.find(wire);
    const bool known = it != m_pending.end() && it->second->speaks == Speaks::VigorLink;
    if (known) {
        request = it->second->vigor;
        f.receiver = it->second->sender;
    } else {
        // No request was seen: the reply is read against what it says of itself.
        request.station = comms::detail::hexValue(bytes, 1, 2).value_or(from.station);
        request.command = vg::Command(comms::detail::hexValue(bytes, 3, 2).value_or(0x51));
        request.length = std::max<int>(0, int(bytes.indexOf(vg::Etx)) - 7) / 2;
    }
    m_pending.erase(wire);
    f.station = request.station;
    f.command = int(request.command);
    f.commandText = QStringLiteral("%1h %2").arg(hex2(f.command), vigorCommandName(f.command));
    if (known) {
        const bool bitCommand =
            request.command == vg::Command::BitOn || request.command == vg::Command::BitOff;
        f.rawAddress = request.address;
        f.address = withDevice(deviceAt(from.target, model::ProtocolId::VigorLink,
                                        model::ProtocolSpace::LinkBytes,
                                        bitCommand ? request.address >> 3 : request.address,
                                        bitCommand ? request.address & 7 : 0),
                               hex4(request.address) + u'h');
        if (!bitCommand)
            f.count = request.length;
    }
    vg::ReplyDecoder decoder(request);
    decoder.feed(bytes);
    if (verdict(decoder, bytes.size(), &vg::errorText, f) && request.command == vg::Command::Read)
        f.data = hexText(decoder.reply().data);
    return f;
}

DecodedFrame TrafficDecoder::decodeModbusRequest(const End &from, const QByteArray &bytes,
                                                 bool ascii, const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Request;
    f.protocol = ascii ? TrafficDecodeTr::tr("MODBUS ASCII") : TrafficDecodeTr::tr("MODBUS RTU");
    f.previousUnanswered = takeUnanswered(wire);
    mb::RequestDecoder decoder(ascii ? mb::Framing::Ascii : mb::Framing::Rtu);
    decoder.feed(bytes);
    if (decoder.status() == comms::FrameStatus::NeedMore && !ascii)
        decoder.silence(); // a transmission ends at the line's silence
    if (decoder.status() != comms::FrameStatus::Complete) {
        if (!decoder.discarded().ok())
            f.problem = decoder.discarded().message;
        else if (!ascii && bytes.size() >= 4) {
            const QByteArrayView frame(bytes);
            const int received = quint8(frame[frame.size() - 2]) | quint8(frame[frame.size() - 1])
                                                                       << 8;
            f.problem = TrafficDecodeTr::tr(
                            "wrong CRC (received %1, computed %2): the slave answers nothing")
                            .arg(hex4(received), hex4(mb::crc16(frame.first(frame.size() - 2))));
        } else {
            f.problem = truncatedText(bytes.size());
        }
        // The unit is the first byte: whom the frame was for, though it does not read.
        if (!ascii && !bytes.isEmpty()) {
            f.station = quint8(bytes[0]);
            if (const End *slave = slaveOn(wire, Speaks::Modbus, f.station))
                f.receiver = slave->name;
        }
        return f;
    }
    const mb::ParsedRequest parsed = decoder.parsed(); // next() below starts the decoder over
    const mb::Request &r = parsed.request;
    f.station = decoder.unit();
    f.command = r.function;
    f.commandText = QStringLiteral("%1h %2").arg(hex2(r.function), modbusFunctionName(r.function));
    const End *slave =
        f.station == mb::BroadcastUnit ? nullptr : slaveOn(wire, Speaks::Modbus, f.station);
    f.receiver = f.station == mb::BroadcastUnit ? TrafficDecodeTr::tr("every slave (broadcast)")
                 : slave                        ? slave->name
                                                : QString();
    if (parsed.exception) {
        f.problem = TrafficDecodeTr::tr("not a request a slave can carry out: it answers %1")
                        .arg(mb::exceptionText(parsed.exception));
        return f;
    }
    f.rawAddress = r.address;
    QString device;
    if (slave && slave->target)
        if (const auto *map = model::findProtocolMap(*slave->target, model::ProtocolId::Modbus))
            device = deviceAt(slave->target, model::ProtocolId::Modbus,
                              modbusSpace(r.function, *map), r.address, -1);
    f.address = withDevice(device, QString::number(r.address));
    f.count = r.count;
    if (!r.registers.empty())
        f.data = registersText(r.registers);
    else if (!r.bits.empty())
        f.data = bitsText(r.bits, r.count);
    decoder.next();
    if (decoder.buffered() > 0)
        f.problem = extraText(decoder.buffered());
    if (f.station == mb::BroadcastUnit)
        return f; // nobody answers a broadcast
    auto p = std::make_unique<Pending>();
    p->speaks = Speaks::Modbus;
    p->sender = from.name;
    p->slave = slave;
    p->station = f.station;
    p->ascii = ascii;
    p->modbus = r;
    m_pending[wire] = std::move(p);
    return f;
}

DecodedFrame TrafficDecoder::decodeModbusReply(const End &from, const QByteArray &bytes, bool ascii,
                                               const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Reply;
    f.protocol = ascii ? TrafficDecodeTr::tr("MODBUS ASCII") : TrafficDecodeTr::tr("MODBUS RTU");
    mb::Request request;
    int unit = from.station;
    const auto it = m_pending.find(wire);
    const bool known = it != m_pending.end() && it->second->speaks == Speaks::Modbus;
    if (known) {
        request = it->second->modbus;
        unit = it->second->station;
        f.receiver = it->second->sender;
    } else {
        // No request was seen: the reply is read against what it says of itself (RTU: unit,
        // function, byte count or the echoed address and value).
        QByteArray body = bytes;
        if (ascii) {
            QString why;
            const qsizetype end = bytes.indexOf("\r\n");
            body = bytes.size() > 1 && end > 1
                       ? mb::detail::asciiBody(QByteArrayView(bytes).sliced(1, end - 1), &why)
                             .value_or(QByteArray())
                       : QByteArray();
        }
        if (body.size() >= 3) {
            unit = quint8(body[0]);
            request.function = quint8(body[1]) & 0x7F;
            const int counted = quint8(body[2]);
            if (request.function <= mb::ReadInputRegisters)
                request.count =
                    request.function <= mb::ReadDiscreteInputs ? counted * 8 : counted / 2;
            else if (body.size() >= 6) {
                request.address = quint8(body[2]) << 8 | quint8(body[3]);
                const int value = quint8(body[4]) << 8 | quint8(body[5]);
                request.count = value;
                if (request.function == mb::WriteSingleRegister)
                    request.registers = {std::uint16_t(value)};
                else if (request.function == mb::WriteSingleCoil)
                    request.bits = {value == 0xFF00};
                else if (request.function == mb::WriteMultipleRegisters)
                    request.registers.resize(std::size_t(value));
                else
                    request.bits.resize(std::size_t(value));
            }
        }
    }
    m_pending.erase(wire);
    f.station = unit;
    f.command = request.function;
    f.commandText =
        QStringLiteral("%1h %2").arg(hex2(request.function), modbusFunctionName(request.function));
    if (known) {
        f.rawAddress = request.address;
        QString device;
        if (from.target)
            if (const auto *map = model::findProtocolMap(*from.target, model::ProtocolId::Modbus))
                device = deviceAt(from.target, model::ProtocolId::Modbus,
                                  modbusSpace(request.function, *map), request.address, -1);
        f.address = withDevice(device, QString::number(request.address));
        f.count = request.count;
    }
    mb::ReplyDecoder decoder(ascii ? mb::Framing::Ascii : mb::Framing::Rtu, unit, request);
    decoder.feed(bytes);
    if (verdict(decoder, bytes.size(), &mb::exceptionText, f)) {
        const mb::Response &r = decoder.response();
        if (!r.registers.empty())
            f.data = registersText(r.registers);
        else if (!r.bits.empty())
            f.data = bitsText(r.bits, request.count);
    }
    return f;
}

} // namespace rung::network
