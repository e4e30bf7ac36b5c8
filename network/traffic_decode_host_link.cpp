// The Traffic view's reading of Host Link (Omron CPM1/SRM1 programming manual W353, Host Link
// commands): a command and its reply, in parts with their delimiters, against the last
// command on the wire (traffic_decode.h).

#include "network/traffic_decode.h"

#include "network/tr.h"
#include "network/traffic_decode_detail.h"

#include "comms/driver/protocol_driver.h"
#include "comms/protocol/ascii_hex.h"
#include "comms/protocol/host_link_master.h"
#include "comms/protocol/host_link_slave.h"

namespace rung::network {

namespace {

using Speaks = TrafficDecoder::End::Speaks;
namespace hl = comms::hostlink;
using comms::detail::hex2;

// Omron CPM1/SRM1 programming manual W353, Host Link commands (C-mode): the headers of the
// CPM1 (what the product's codec and the virtual PLC know, and those the PLC has that the
// virtual PLC answers "not supported").
QString hostLinkHeaderName(QByteArrayView header) {
    static const struct {
        const char *header;
        const char *name;
    } names[] = {
        {"RR", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read IR/SR words")},
        {"RH", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read HR words")},
        {"RD", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read DM words")},
        {"RC", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read timer/counter PVs")},
        {"RG", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read completion flags")},
        {"RL", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read LR words")},
        {"RJ", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read AR words")},
        {"WR", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write IR/SR words")},
        {"WH", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write HR words")},
        {"WD", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write DM words")},
        {"WC", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write timer/counter PVs")},
        {"WL", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write LR words")},
        {"WJ", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "write AR words")},
        {"MS", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read status")},
        {"SC", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "change mode")},
        {"MF", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read errors")},
        {"MM", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "read model")},
        {"KS", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "force set")},
        {"KR", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "force reset")},
        {"KC", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "cancel all forcing")},
        {"TS", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "test")},
        {"IC", QT_TRANSLATE_NOOP("rung::network::TrafficDecode", "command not recognised")},
    };
    for (const auto &n : names)
        if (header == QByteArrayView(n.header))
            return TrafficDecodeTr::tr(n.name);
    return TrafficDecodeTr::tr("unknown command");
}

// The header as a number (DecodedFrame::command) and with its name.
int hostLinkCode(const QByteArray &header) {
    return header.size() == 2 ? quint8(header[0]) << 8 | quint8(header[1]) : -1;
}
QString hostLinkCommandText(const QByteArray &header) {
    return QStringLiteral("%1 %2").arg(QString::fromLatin1(header), hostLinkHeaderName(header));
}

// SC's mode and MS's status in the words the IDE's Connection dock uses.
QString hostLinkModeText(hl::Mode mode) {
    switch (mode) {
    case hl::Mode::Program:
        return comms::modeName(comms::PlcMode::Program);
    case hl::Mode::Monitor:
        return comms::modeName(comms::PlcMode::Monitor);
    case hl::Mode::Run:
        return comms::modeName(comms::PlcMode::Run);
    }
    return comms::modeName(comms::PlcMode::Unknown);
}

QString wordsText(const std::vector<std::uint16_t> &words) {
    QStringList out;
    for (auto w : words)
        out << hex4(w);
    return out.join(u' ');
}

QString partText(int part) {
    return TrafficDecodeTr::tr("part %1 of a frame in parts: the other side answers CR for the "
                               "next")
        .arg(part);
}

QString delimiterText() {
    return TrafficDecodeTr::tr("CR: the next part, please");
}

QString refusedText(const QString &why) {
    return TrafficDecodeTr::tr("the slave refuses it: %1").arg(why);
}

} // namespace

bool TrafficDecoder::continuesHostLink(const End &from, const QByteArray &bytes,
                                       const QString &wire) const {
    const auto ends = m_wires.find(wire);
    if (ends == m_wires.end())
        return false;
    bool plcOnWire = false;
    for (const QString &name : ends->second)
        if (const End *e = end(name); e && e->speaks == Speaks::HostLink)
            plcOnWire = true;
    if (!plcOnWire)
        return false;
    if (bytes.front() == '@')
        return true;
    const auto it = m_pending.find(wire);
    if (it == m_pending.end() || it->second->speaks != Speaks::HostLink ||
        it->second->sender != from.name)
        return false;
    return it->second->hostLinkCommand ||
           (it->second->hostLinkReply && bytes == QByteArray(1, hl::Cr));
}

DecodedFrame TrafficDecoder::decodeHostLinkRequest(const End &from, const QByteArray &bytes,
                                                   const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Request;
    f.protocol = TrafficDecodeTr::tr("Host Link");
    const auto it = m_pending.find(wire);
    Pending *asked = it != m_pending.end() && it->second->speaks == Speaks::HostLink &&
                             it->second->sender == from.name
                         ? it->second.get()
                         : nullptr;
    const auto describe = [&f](const Pending &p) {
        f.receiver = p.slave ? p.slave->name : QString();
        f.station = p.hostLink.unit;
        f.command = hostLinkCode(p.hostLink.header);
        f.commandText = hostLinkCommandText(p.hostLink.header);
        f.rawAddress = p.rawAddress;
        f.address = p.address;
        f.count = p.count;
    };
    // The host's CR after a part of a reply in parts (W353: the delimiter): the next part.
    if (asked && asked->hostLinkReply && bytes.front() != '@') {
        describe(*asked);
        f.data = delimiterText();
        if (bytes != QByteArray(1, hl::Cr))
            f.problem = extraText(bytes.size() - 1);
        return f;
    }
    // A later part of a command in parts goes on with the parts before it; "@" starts anew.
    hl::CommandDecoder decoder;
    int part = 1;
    if (asked && asked->hostLinkCommand && bytes.front() != '@') {
        decoder = *asked->hostLinkCommand;
        part = asked->parts + 1;
    } else {
        f.previousUnanswered = takeUnanswered(wire);
    }
    decoder.feed(bytes);
    const bool more = decoder.takeDelimiterRequest();
    const hl::Frame command = decoder.command();
    const End *slave = nullptr;
    if (decoder.status() == comms::FrameStatus::Complete || more) {
        slave = slaveOn(wire, Speaks::HostLink, command.unit);
        f.receiver = slave ? slave->name : QString();
        f.station = command.unit;
        f.command = hostLinkCode(command.header);
        f.commandText = hostLinkCommandText(command.header);
    }
    auto p = std::make_unique<Pending>();
    p->speaks = Speaks::HostLink;
    p->sender = from.name;
    p->slave = slave;
    p->station = command.unit;
    p->hostLink = command;
    p->parts = part;
    if (decoder.status() != comms::FrameStatus::Complete) {
        if (more) {
            f.data = partText(part);
            p->hostLinkCommand = decoder;
            m_pending[wire] = std::move(p);
            return f;
        }
        // No "*" CR: cut short, or bytes that are no command.
        m_pending.erase(wire);
        f.problem =
            !decoder.discarded().ok() ? decoder.discarded().message : truncatedText(bytes.size());
        // The unit is the frame's first two digits: whom it was for, though it does not read.
        if (const auto unit = comms::detail::decimalValue(bytes, 1, 2);
            unit && bytes.front() == '@') {
            f.station = *unit;
            if (const End *to = slaveOn(wire, Speaks::HostLink, f.station))
                f.receiver = to->name;
        }
        return f;
    }
    const int code = decoder.endCode();
    if (code == hl::FcsError) {
        f.problem =
            TrafficDecodeTr::tr("wrong FCS (received %1, computed %2): the PLC answers end code 13")
                .arg(QString::fromLatin1(decoder.receivedFcs()),
                     QString::fromLatin1(decoder.computedFcs()));
    } else if (code != hl::Normal) {
        f.problem = refusedText(hl::endCodeText(code));
    } else {
        const QByteArray &h = command.header;
        const model::Target *target = slave ? slave->target : nullptr;
        const auto at = [&](model::ProtocolSpace space, int unit, int bit, const QString &onWire) {
            f.rawAddress = unit;
            f.address =
                withDevice(deviceAt(target, model::ProtocolId::HostLink, space, unit, bit), onWire);
        };
        model::ProtocolSpace space;
        bool write = false;
        if (hl::spaceOfHeader(h, space, write)) {
            const hl::Operands o =
                write ? hl::parseWrite(command.text) : hl::parseRead(command.text);
            if (!o.valid) {
                f.problem = refusedText(hl::endCodeText(hl::FormatError));
            } else {
                at(space, o.begin, -1, QString::fromLatin1(command.text.first(4)));
                f.count = o.count;
                if (write)
                    f.data = wordsText(o.words);
            }
        } else if (h == "KS" || h == "KR") {
            const hl::Operands o = hl::parseForce(command.text);
            if (!o.valid)
                f.problem = refusedText(hl::endCodeText(hl::FormatError));
            else
                at(model::ProtocolSpace::HostLinkIr, o.begin, o.bit,
                   QString::fromLatin1(command.text));
        } else if (h == "SC") {
            const auto mode = comms::detail::hexValue(command.text, 0, 2);
            f.data = mode && command.text.size() == 2
                         ? QStringLiteral("%1 %2").arg(QString::fromLatin1(command.text),
                                                       hostLinkModeText(hl::Mode(*mode)))
                         : quoted(command.text);
        } else if (!command.text.isEmpty()) {
            f.data = quoted(command.text);
        }
    }
    p->rawAddress = f.rawAddress;
    p->address = f.address;
    p->count = f.count;
    decoder.next();
    if (decoder.buffered() > 0)
        f.problem = extraText(decoder.buffered());
    m_pending[wire] = std::move(p);
    return f;
}

DecodedFrame TrafficDecoder::decodeHostLinkReply(const End &from, const QByteArray &bytes,
                                                 const QString &wire) {
    DecodedFrame f;
    f.kind = DecodedFrame::Kind::Reply;
    f.protocol = TrafficDecodeTr::tr("Host Link");
    const auto it = m_pending.find(wire);
    Pending *asked = it != m_pending.end() && it->second->speaks == Speaks::HostLink
                         ? it->second.get()
                         : nullptr;
    hl::Frame command;
    if (asked) {
        command = asked->hostLink;
        f.receiver = asked->sender;
        f.rawAddress = asked->rawAddress;
        f.address = asked->address;
        f.count = asked->count;
        // The PLC's CR after a part of a command in parts (W353: the delimiter).
        if (asked->hostLinkCommand) {
            f.station = command.unit;
            f.command = hostLinkCode(command.header);
            f.commandText = hostLinkCommandText(command.header);
            f.data = delimiterText();
            if (bytes != QByteArray(1, hl::Cr))
                f.problem = TrafficDecodeTr::tr("not the CR that asks for the next part");
            return f;
        }
    } else {
        // No command was seen: the reply is read against what it says of itself (unit,
        // header, and for a read as many words or flags as its text holds).
        command.unit = comms::detail::decimalValue(bytes, 1, 2).value_or(from.station);
        command.header = bytes.mid(3, 2);
        model::ProtocolSpace space;
        bool write = false;
        if (hl::spaceOfHeader(command.header, space, write) && !write) {
            const int characters = std::max<int>(0, int(bytes.indexOf('*')) - 9);
            const int count =
                space == model::ProtocolSpace::HostLinkCompletion ? characters : characters / 4;
            command = hl::readCommand(command.unit, space, 0, count);
        } else if (command.header == "TS") {
            // TEST returns what was sent: the reply's own characters (before FCS "*").
            const qsizetype end = bytes.indexOf('*') - 2;
            if (end > 5)
                command.text = bytes.mid(5, end - 5);
        }
    }
    f.station = command.unit;
    f.command = hostLinkCode(command.header);
    f.commandText = hostLinkCommandText(command.header);
    hl::ReplyDecoder decoder =
        asked && asked->hostLinkReply ? *asked->hostLinkReply : hl::ReplyDecoder(command);
    decoder.feed(bytes);
    if (decoder.status() == comms::FrameStatus::NeedMore && decoder.takeDelimiterRequest()) {
        // A part of a reply in parts; the host's CR asks for the next.
        const int part = asked && asked->hostLinkReply ? asked->parts + 1 : 1;
        f.data = partText(part);
        if (asked) {
            asked->hostLinkReply = decoder;
            asked->parts = part;
        }
        return f;
    }
    m_pending.erase(wire);
    const hl::Reply &reply = decoder.reply();
    if (reply.frame.header == "IC" && decoder.status() == comms::FrameStatus::Failed &&
        decoder.error().kind == comms::ProtocolError::Kind::DeviceError) {
        // Not an end code: the PLC has no such command.
        f.command = hostLinkCode(reply.frame.header);
        f.commandText = hostLinkCommandText(reply.frame.header);
        f.problem = decoder.error().message;
        return f;
    }
    if (!verdict(decoder, bytes.size(), &hl::endCodeText, f))
        return f;
    const QByteArray &h = reply.frame.header;
    if (!reply.words.empty())
        f.data = wordsText(reply.words);
    else if (!reply.flags.empty())
        f.data = bitsText(reply.flags, int(reply.flags.size()));
    else if (h == "MS")
        f.data = QStringLiteral("%1 %2").arg(hex4(reply.status),
                                             hostLinkModeText(hl::modeOfStatus(reply.status)));
    else if (h == "MM")
        f.data = hex2(reply.model) + u'h';
    else if (h == "TS" && !reply.frame.text.isEmpty())
        f.data = quoted(reply.frame.text);
    return f;
}

} // namespace rung::network
