#include "comms/slave/host_link_responder.h"

#include "comms/protocol/ascii_hex.h"
#include "model/image/bcd.h"

namespace rung::comms::slave {

namespace {

using model::ProtocolSpace;
using namespace hostlink;

// Host Link C-mode headers of the CPM1 that this slave does not serve (W353 6-3): it answers
// them with 16 (not supported) rather than IC, which means "no such command".
constexpr const char *kUnserved[] = {"RL", "WL", "RJ", "WJ", "RE", "WE", "R#",
                                     "R$", "R%", "W#", "W$", "W%", "MF", "RP",
                                     "WP", "MI", "QQ", "FK", "XZ", "**", "KF"};

bool unserved(QByteArrayView header) {
    for (const char *h : kUnserved)
        if (header == QByteArrayView(h))
            return true;
    return false;
}

// Timer / counter present values are four BCD digits in the PLC's memory (W353; the
// simulator keeps them so too), and RC / WC carry that word as it is: 0150 is 150. A word
// written with a digit above 9 is no present value.
bool isBcd(std::uint16_t digits) {
    return model::fromBcd(digits).has_value();
}

} // namespace

HostLinkResponder::HostLinkResponder(const model::Target &target, const model::ProtocolMap &map,
                                     int station, std::shared_ptr<DeviceImage> image,
                                     int writeTimeoutMs)
    : Responder(target, map, station, std::move(image), writeTimeoutMs) {}

QByteArray HostLinkResponder::breakChecksum(QByteArray frame) const {
    // ... FCS(2) "*" CR: the FCS's second digit becomes another hex digit.
    const qsizetype at = frame.endsWith("*\r") ? frame.size() - 3 : frame.size() - 2;
    if (at >= 0)
        frame[at] = frame[at] == '0' ? '1' : '0';
    return frame;
}

QByteArrayList HostLinkResponder::feed(QByteArrayView bytes) {
    QByteArrayList out;
    if (!m_laterParts.isEmpty() && !bytes.isEmpty()) {
        // The master's CR asks for the next part of an answer; anything else means it gave
        // the answer up (a new command): the rest is dropped.
        if (bytes.front() == Cr) {
            out << m_laterParts.takeFirst();
            bytes = bytes.sliced(1);
        } else {
            m_laterParts.clear();
        }
    }
    m_decoder.feed(bytes);
    while (true) {
        if (m_decoder.takeDelimiterRequest())
            out << QByteArray(1, Cr);
        if (!m_decoder.discarded().ok())
            m_lastProblem = m_decoder.discarded().message;
        if (m_decoder.status() != FrameStatus::Complete)
            return out;
        const Frame command = m_decoder.command();
        if (command.unit != m_station) {
            ++m_statistics.ignored;
        } else {
            QList<QByteArray> parts = encode(respond(command));
            out << parts.takeFirst();
            m_laterParts = parts;
        }
        m_decoder.next();
    }
}

Frame HostLinkResponder::endCode(const Frame &command, int code) {
    if (code != Normal)
        ++m_statistics.refused;
    else
        ++m_statistics.answered;
    return Frame{m_replyStation, command.header, code, {}};
}

Frame HostLinkResponder::respond(const Frame &command) {
    if (m_decoder.endCode() != 0)
        return endCode(command, m_decoder.endCode());
    const QByteArray &h = command.header;
    ProtocolSpace space;
    bool isWrite = false;
    if (spaceOfHeader(h, space, isWrite))
        return isWrite ? write(command, space) : read(command, space);
    const OperatingMode mode = m_image->mode();
    if (h == "MS") {
        if (!command.text.isEmpty())
            return endCode(command, FormatError);
        // Status bits 9-8: 00 PROGRAM, 10 RUN, 11 MONITOR (W353 MS).
        const int status = mode == OperatingMode::Program ? 0x0000
                           : mode == OperatingMode::Run   ? 0x0200
                                                          : 0x0300;
        Frame reply = endCode(command, Normal);
        detail::appendHex(reply.text, status, 4);
        return reply;
    }
    if (h == "SC") {
        const auto code = detail::hexValue(command.text, 0, 2);
        if (!code || command.text.size() != 2)
            return endCode(command, FormatError);
        MappedImage::Change c;
        switch (*code) {
        case int(Mode::Program):
            c.mode = OperatingMode::Program;
            break;
        case int(Mode::Monitor):
            c.mode = OperatingMode::Monitor;
            break;
        case int(Mode::Run):
            c.mode = OperatingMode::Run;
            break;
        default:
            return endCode(command, EntryNumberError);
        }
        return change(command, c);
    }
    if (h == "MM") {
        if (!command.text.isEmpty())
            return endCode(command, FormatError);
        Frame reply = endCode(command, Normal);
        detail::appendHex(reply.text, std::max(0, m_mapped.map().modelCode), 2);
        return reply;
    }
    if (h == "TS") { // TEST: the characters come back unaltered
        Frame reply{m_replyStation, h, -1, command.text};
        ++m_statistics.answered;
        return reply;
    }
    if (h == "KS" || h == "KR")
        return force(command);
    if (h == "KC") {
        if (!command.text.isEmpty())
            return endCode(command, FormatError);
        if (mode == OperatingMode::Run)
            return endCode(command, NotInRun);
        MappedImage::Change c;
        c.commands.push_back({model::DeviceCommand::Kind::ReleaseAll, {}, 0});
        return change(command, c);
    }
    if (unserved(h))
        return endCode(command, NotSupported);
    ++m_statistics.refused;
    return Frame{m_replyStation, "IC", -1, {}}; // not a Host Link command
}

Frame HostLinkResponder::read(const Frame &command, ProtocolSpace space) {
    const Operands o = parseRead(command.text);
    if (!o.valid)
        return endCode(command, FormatError);
    if (o.count < 1)
        return endCode(command, EntryNumberError);
    const auto snapshot = m_image->snapshot();
    const MappedImage::Units units =
        m_mapped.read(*snapshot, m_image->mode(), space, o.begin, o.count);
    if (units.refusal != MappedImage::Refusal::None)
        return endCode(command, AddressOver);
    Frame reply = endCode(command, Normal);
    for (const std::uint16_t v : units.values) {
        if (space == ProtocolSpace::HostLinkCompletion)
            reply.text += v ? '1' : '0';
        else
            detail::appendHex(reply.text, v, 4);
    }
    return reply;
}

Frame HostLinkResponder::write(const Frame &command, ProtocolSpace space) {
    if (m_image->mode() == OperatingMode::Run)
        return endCode(command, NotInRun);
    Operands o = parseWrite(command.text);
    if (!o.valid)
        return endCode(command, FormatError);
    if (space == ProtocolSpace::HostLinkTimerPv)
        for (const std::uint16_t w : o.words)
            if (!isBcd(w))
                return endCode(command, EntryNumberError);
    const auto snapshot = m_image->snapshot();
    const MappedImage::Change c = m_mapped.write(*snapshot, space, o.begin, o.words);
    if (c.refusal != MappedImage::Refusal::None)
        return endCode(command, AddressOver);
    return change(command, c);
}

Frame HostLinkResponder::force(const Frame &command) {
    if (m_image->mode() == OperatingMode::Run)
        return endCode(command, NotInRun);
    const Operands o = parseForce(command.text);
    if (!o.valid)
        return endCode(command, FormatError);
    const auto d = m_mapped.device(ProtocolSpace::HostLinkIr, o.begin, o.bit);
    if (!d)
        return endCode(command, AddressOver);
    MappedImage::Change c;
    c.commands.push_back({model::DeviceCommand::Kind::Force,
                          {d->area, d->index, d->bit},
                          command.header == "KS" ? 1 : 0});
    return change(command, c);
}

Frame HostLinkResponder::change(const Frame &command, const MappedImage::Change &c) {
    const ImageChange done = apply(c);
    if (!done.done()) {
        m_lastProblem = done.message;
        return endCode(command, EntryNumberError);
    }
    if (!c.commands.empty())
        ++m_statistics.writes;
    return endCode(command, Normal);
}

} // namespace rung::comms::slave
